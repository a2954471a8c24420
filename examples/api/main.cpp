// gridlock as a library, end to end on one formula:
//   read a DIMACS formula -> reduce it to LSAT<=3 -> compile it to a lattice
//   instance -> solve Discrete Collision-free Schedule exactly -> lift the
//   schedule back to an assignment of the input -> check that assignment.
// Usage: gridlock_api FORMULA.cnf
// Prints one line per step; exits 10 (satisfiable), 20 (unsatisfiable),
// 0 (the solver hit its limit) or 1 (error), like the gridlock command line.
#include <iostream>
#include <vector>

#include "cnf/dimacs.hpp"
#include "cnf/formula.hpp"
#include "lattice/simulate.hpp"
#include "reductions/compile.hpp"
#include "reductions/to_lsat.hpp"
#include "solver/solve.hpp"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: gridlock_api FORMULA.cnf\n";
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

  gridlock::SolveOptions options;
  options.seconds = 60;
  const gridlock::SolveResult result = gridlock::solve_discrete(compiled.instance, options);
  std::cout << "solve     " << gridlock::verdict_name(result.status) << " (" << result.stats.engine << ")\n";
  if (result.status == gridlock::Verdict::Unknown) return 0;
  if (result.status == gridlock::Verdict::No) return 20;

  // The witness is checked by an independent path: the simulator runs the
  // order, and the lifted assignment is evaluated on the input formula.
  gridlock::Simulator simulator(compiled.instance);
  if (simulator.run_order(result.order).collision) {
    std::cerr << "gridlock_api: error: the solver's order collides\n";
    return 1;
  }
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
