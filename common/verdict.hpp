// The one answer type of every decision in gridlock: the SAT solver on a
// formula, the discrete and continuous solvers on an instance, the gap
// checker, each check of the verification harness, and the command line's
// status line. One type, so no layer translates between its own copies.
#pragma once

namespace gridlock {

// Yes: the question's answer is yes and a witness goes with it (a model, a
// schedule). No: proven no. Unknown: a limit was hit (time, nodes, conflicts,
// a stop request) before either was established.
enum class Verdict { Yes, No, Unknown };

// "YES", "NO", "UNKNOWN": the word of the status line `s ...`.
constexpr const char* verdict_name(Verdict v) {
  return v == Verdict::Yes ? "YES" : v == Verdict::No ? "NO" : "UNKNOWN";
}

// SAT-competition exit codes: 10 for yes, 20 for no, 0 for unknown.
constexpr int exit_code(Verdict v) { return v == Verdict::Yes ? 10 : v == Verdict::No ? 20 : 0; }

}  // namespace gridlock
