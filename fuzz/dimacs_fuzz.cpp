// libFuzzer target: the DIMACS reader, then everything downstream of it on
// what it accepts. Any input must give either a Diagnostic or a formula that
//   - validates, writes and reads back equal (the writer is the reader's
//     inverse), and passes the LSAT check without a crash;
// and, when small enough to solve by exhaustive search,
//   - gets the same answer from CaDiCaL, DPLL and the exhaustive search;
//   - reduces to an LSAT<=3 formula with the same answer, whose models map
//     back to models of the input, and the input's model maps forward.
// Any violation traps (a crash report with the input), as do sanitizer
// reports and uncaught exceptions.
#include <cstddef>
#include <cstdint>
#include <string>

#include "cnf/brute_force.hpp"
#include "cnf/dimacs.hpp"
#include "cnf/lsat.hpp"
#include "cnf/sat_solver.hpp"
#include "reductions/to_lsat.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace gridlock;
  const std::string text(reinterpret_cast<const char*>(data), size);
  Formula f;
  DimacsOptions opt;
  opt.strict_count = size % 2 == 0;  // both settings, chosen by the input
  if (read_dimacs_string(text, "fuzz.cnf", f, opt)) return 0;
  if (!validate(f).empty()) __builtin_trap();
  Formula back;
  if (read_dimacs_string(to_dimacs(f), "again.cnf", back)) __builtin_trap();
  // Comments holding control bytes other than tab cannot come from the
  // reader, so the round trip is exact.
  if (!(back == f)) __builtin_trap();
  LsatReport exact = check_lsat(f, LsatForm::Exact3, 4);
  LsatReport le3 = check_lsat(f, LsatForm::AtMost3, 4);
  if (exact.ok && !le3.ok) __builtin_trap();              // exactly-3 LSAT is a special case of LSAT<=3
  if (exact.ok && !hall_assignment(f)) __builtin_trap();  // the theorem of docs/formulas.md
  if (f.num_vars > 12 || f.clauses.size() > 200 || num_literals(f) > 800) return 0;
  const SatResult ex = exhaustive_sat(f);
  const SatResult cd = solve_sat(f);
  const SatResult dp = dpll_sat(f);
  if (cd.status != ex.status || dp.status != ex.status) __builtin_trap();
  ToLsatOptions ro;
  ro.passthrough = size % 3 != 0;
  const LsatReduction red = reduce_to_lsat(f, ro);
  if (!is_lsat(red.output(), LsatForm::AtMost3)) __builtin_trap();
  const SatResult out = solve_sat(red.output());
  if (out.status != ex.status) __builtin_trap();
  if (ex.status == Verdict::Yes) {
    if (!satisfies(f, red.lift_to_source(out.model))) __builtin_trap();
    if (!satisfies(red.output(), red.lift_to_target(ex.model))) __builtin_trap();
  }
  return 0;
}
