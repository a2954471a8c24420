// gridlock as a library, end to end on one formula, with nothing but the
// installed (public) headers:
//   read a DIMACS formula -> reduce it to LSAT<=3 -> compile it to a lattice
//   instance -> render it -> look for a colliding schedule -> solve
//   Discrete Collision-free Schedule exactly -> simulate the solver's order
//   -> lift it back to an assignment of the input -> verify the whole chain
//   (CaDiCaL, both witnesses, the NO certificate) independently.
// Usage: gridlock_api FORMULA.cnf [PICTURE.svg]
// Prints one line per step; exits 10 (satisfiable), 20 (unsatisfiable),
// 0 (the solver hit its limit) or 1 (error), like the gridlock command line.
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include "cnf/dimacs.hpp"
#include "cnf/formula.hpp"
#include "collide/collide.hpp"
#include "common/limits.hpp"
#include "lattice/simulate.hpp"
#include "reductions/compile.hpp"
#include "reductions/to_lsat.hpp"
#include "render/picture.hpp"
#include "solver/solve.hpp"
#include "verify/verify.hpp"

namespace {

// Colliding Schedule: is there a schedule that causes a collision? (The
// compiled instances are built so that some schedule collides.)
void show_collide(const gridlock::Instance& inst) {
  const gridlock::Deadline deadline(10);
  try {
    const gridlock::CollideResult c = gridlock::find_collision(inst, gridlock::TimeModel::Discrete,
                                                               gridlock::CollideMethod::Auto, &deadline);
    std::cout << "collide   " << (c.collides ? "a colliding order exists" : "no schedule collides") << " ("
              << c.algorithm << ")\n";
  } catch (const gridlock::LimitReached&) {
    std::cout << "collide   unknown (10 s limit)\n";
  }
}

// The simulator runs the solver's order (an independent check of its YES).
bool show_simulate(const gridlock::Instance& inst, const std::vector<gridlock::CouplingId>& order) {
  gridlock::Simulator simulator(inst);
  const gridlock::SimResult run = simulator.run_order(order);
  if (run.collision) {
    std::cerr << "gridlock_api: error: the solver's order collides\n";
    return false;
  }
  std::cout << "simulate  " << order.size() << " couplings in the solver's order, no collision (" << run.stats.intervals
            << " intervals)\n";
  return true;
}

// verify: the reduction checked on this formula by independent paths.
bool show_verify(const gridlock::Formula& formula, const std::string& name) {
  gridlock::VerifyOptions options;
  options.solve_seconds = 60;
  const gridlock::VerifyResult v = gridlock::verify_formula(formula, name, options);
  std::cout << "verify    " << (v.agree ? "agree" : "DISAGREE: " + v.problem) << ": CaDiCaL "
            << gridlock::verdict_name(v.sat) << ", solver " << gridlock::verdict_name(v.discrete) << ", "
            << v.witnesses_checked() << " witnesses/certificates checked\n";
  return v.agree;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2 && argc != 3) {
    std::cerr << "usage: gridlock_api FORMULA.cnf [PICTURE.svg]\n";
    return 1;
  }
  gridlock::Formula formula;
  if (auto err = gridlock::read_dimacs_file(argv[1], formula)) {
    std::cerr << "gridlock_api: error: " << err->str() << "\n";  // errors are values; the program prints them
    return 1;
  }
  std::cout << "read      " << gridlock::summary(formula) << "\n";

  const gridlock::LsatReduction lsat = gridlock::reduce_to_lsat(formula);
  std::cout << "to-lsat   " << gridlock::summary(lsat.output()) << "\n";

  const gridlock::CompiledFormula compiled = gridlock::compile_formula(lsat.output());
  std::cout << "compile   " << compiled.stats.nodes << " nodes, " << compiled.stats.couplings << " couplings\n";

  const std::string svg = gridlock::render_svg(compiled.instance);
  std::cout << "render    SVG of the instance, " << svg.size() << " bytes";
  if (argc == 3) {
    std::ofstream(argv[2]) << svg;
    std::cout << " -> " << argv[2];
  }
  std::cout << "\n";

  show_collide(compiled.instance);

  gridlock::SolveOptions options;
  options.seconds = 60;
  const gridlock::SolveResult result = gridlock::solve_discrete(compiled.instance, options);
  std::cout << "solve     " << gridlock::verdict_name(result.status) << " (" << result.stats.engine << ")\n";
  if (result.status == gridlock::Verdict::Unknown) return 0;

  if (!show_verify(formula, argv[1])) return 1;
  if (result.status == gridlock::Verdict::No) return 20;

  if (!show_simulate(compiled.instance, result.order)) return 1;
  // The lifted assignment is evaluated on the input formula.
  const std::vector<bool> lsat_value = gridlock::assignment_from_schedule(compiled, result.order);
  const std::vector<bool> value = lsat.lift_to_source(lsat_value);
  if (!gridlock::satisfies(formula, value)) {
    std::cerr << "gridlock_api: error: the lifted assignment does not satisfy the formula\n";
    return 1;
  }
  std::cout << "lift      v";
  for (int lit : gridlock::model_literals(value, formula.num_vars)) std::cout << " " << lit;
  std::cout << " 0 (satisfies the formula)\n";
  return 10;
}
