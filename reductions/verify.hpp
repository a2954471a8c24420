// End-to-end verification of the reduction on one formula (issue 6).
//
// For a CNF formula F: answer "is F satisfiable?" three ways and compare.
//  1. CaDiCaL on F (the model is checked against F).
//  2. If F is not LSAT<=3, reduce it with to-lsat to G (else G = F); compile
//     G into a lattice instance I; the exact discrete solver on I.
//  3. The linear-time gap checker on I (continuous model): every compiled
//     instance is expected to be YES, the paper's point that continuous time
//     is easy.
// Certificates are checked both ways: F's model -> G's assignment -> a
// schedule of I -> the simulator; the solver's schedule -> an assignment of
// G -> an assignment of F -> F.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "cnf/formula.hpp"
#include "lattice/instance.hpp"

namespace gridlock {

enum class Tri { Yes, No, Unknown };
const char* tri_name(Tri t);  // "YES", "NO", "UNKNOWN"

struct VerifyOptions {
  double solve_seconds = 60;        // limit of the exact solver (then UNKNOWN)
  uint64_t max_states = 0;          // limit of the exact solver; 0 = none
  std::string break_gadget;         // test only: compile with a broken gadget
};

struct VerifyResult {
  std::string name;
  Formula source, lsat;             // F and G
  bool reduced = false;             // G came from to-lsat
  Instance instance;
  size_t nodes = 0, ops = 0, couplings = 0;
  Tri sat = Tri::Unknown, discrete = Tri::Unknown, continuous = Tri::Unknown;
  // Certificates: 1 checked and valid, 0 not applicable, -1 checked and INVALID.
  int sat_witness = 0;              // F's model -> schedule -> simulator
  int solver_witness = 0;           // solver's schedule -> assignment -> F
  std::vector<std::string> sat_schedule, solver_schedule;  // coupling names
  double ms_sat = 0, ms_compile = 0, ms_solve = 0, ms_gaps = 0;
  uint64_t solver_states = 0;
  bool agree = false;               // everything consistent (UNKNOWN is not a disagreement)
  std::string problem;              // what disagreed, if anything
};

// Runs the whole check. Never throws for a formula with clauses of any
// length (longer ones go through to-lsat); limits give UNKNOWN.
VerifyResult verify_formula(const Formula& f, const std::string& name, const VerifyOptions& opt);

// Writes a reproducer for r into dir (created): formula.cnf, lsat.cnf,
// instance.grid, sat-schedule.txt, solver-schedule.txt, README.txt with what
// disagreed, and run.sh with the command that replays it. Returns dir.
std::string write_reproducer(const VerifyResult& r, const std::string& dir);

}  // namespace gridlock
