#include "solver/internal/z3_lemmas.hpp"

#include <algorithm>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <unordered_set>

namespace gridlock {
namespace {

[[noreturn]] void refuse(const z3::expr& e, const std::string& why) {
  throw std::runtime_error("a Z3 theory lemma has a literal that is not a difference bound (" + why +
                           "): " + e.to_string().substr(0, 200));
}

Rational numeral(const z3::expr& e) {
  auto r = Rational::parse(Z3_get_numeral_string(e.ctx(), e));
  if (!r) refuse(e, "a numeral beyond 64-bit rationals");
  return *r;
}

// Adds mult * e to (coefs, constant): e is a linear term over constants tN.
void linear(const z3::expr& e, const Rational& mult, std::map<uint32_t, Rational>& coefs, Rational& constant) {
  if (e.is_numeral()) {
    constant = constant + mult * numeral(e);
    return;
  }
  if (!e.is_app()) refuse(e, "not an application");
  const Z3_decl_kind k = e.decl().decl_kind();
  const unsigned n = e.num_args();
  switch (k) {
    case Z3_OP_ADD:
      for (unsigned i = 0; i < n; ++i) linear(e.arg(i), mult, coefs, constant);
      return;
    case Z3_OP_SUB:
      for (unsigned i = 0; i < n; ++i) linear(e.arg(i), i == 0 ? mult : Rational(0) - mult, coefs, constant);
      return;
    case Z3_OP_UMINUS: linear(e.arg(0), Rational(0) - mult, coefs, constant); return;
    case Z3_OP_TO_REAL: linear(e.arg(0), mult, coefs, constant); return;
    case Z3_OP_MUL: {
      // Every factor but one is a numeral.
      Rational m = mult;
      int term = -1;
      for (unsigned i = 0; i < n; ++i) {
        if (e.arg(i).is_numeral()) m = m * numeral(e.arg(i));
        else if (term < 0) term = static_cast<int>(i);
        else refuse(e, "a product of two unknowns");
      }
      if (term < 0) constant = constant + m;
      else linear(e.arg(static_cast<unsigned>(term)), m, coefs, constant);
      return;
    }
    case Z3_OP_UNINTERPRETED: {
      const std::string name = e.decl().name().str();
      if (n != 0 || name.size() < 2 || name[0] != 't' ||
          !std::all_of(name.begin() + 1, name.end(), [](char ch) { return ch >= '0' && ch <= '9'; }))
        refuse(e, "an unknown that is no start time");
      const auto x = static_cast<uint32_t>(std::stoul(name.substr(1)));
      coefs[x] = coefs[x] + mult;
      return;
    }
    default: refuse(e, "an operation that is not linear");
  }
}

// The literal e (a comparison or its negation) as a difference bound.
DiffLiteral literal(z3::expr e, bool negated) {
  while (e.is_app() && e.decl().decl_kind() == Z3_OP_NOT) e = e.arg(0), negated = !negated;
  if (!e.is_app() || e.num_args() != 2) refuse(e, "not a comparison");
  const Z3_decl_kind k = e.decl().decl_kind();
  if (k != Z3_OP_LE && k != Z3_OP_LT && k != Z3_OP_GE && k != Z3_OP_GT) refuse(e, "not <=, <, >= or >");
  // lhs - rhs (<= | <) 0, or rhs - lhs for >= and >.
  const bool flip = k == Z3_OP_GE || k == Z3_OP_GT;
  bool strict = k == Z3_OP_LT || k == Z3_OP_GT;
  std::map<uint32_t, Rational> coefs;
  Rational constant;
  linear(e.arg(0), Rational(flip ? -1 : 1), coefs, constant);
  linear(e.arg(1), Rational(flip ? 1 : -1), coefs, constant);
  std::erase_if(coefs, [](const auto& kv) { return kv.second == Rational(0); });
  if (coefs.size() != 2) refuse(e, std::to_string(coefs.size()) + " unknowns");
  auto pos = coefs.begin(), neg = std::next(pos);
  if (pos->second < Rational(0)) std::swap(pos, neg);
  if (pos->second + neg->second != Rational(0) || pos->second <= Rational(0)) refuse(e, "coefficients not c and -c");
  // c (t_x - t_y) + constant (<=|<) 0  <=>  t_x - t_y (<=|<) -constant / c.
  DiffLiteral d{pos->first, neg->first, (Rational(0) - constant) / pos->second, strict};
  if (negated) {
    // not (t_x - t_y <= v)  <=>  t_y - t_x < -v; not (<) gives <=.
    d = {d.y, d.x, Rational(0) - d.v, !strict};
  }
  return d;
}

// The fact a proof step concludes (its last argument).
z3::expr fact(const z3::expr& step) { return step.arg(step.num_args() - 1); }

void add_lemma(const z3::expr& step,
               std::set<std::vector<std::tuple<uint32_t, uint32_t, int64_t, int64_t, bool>>>& seen,
               std::vector<std::vector<DiffLiteral>>& out) {
  std::vector<DiffLiteral> clause;
  for (unsigned i = 0; i + 1 < step.num_args(); ++i) clause.push_back(literal(fact(step.arg(i)), true));
  const z3::expr concl = fact(step);
  if (concl.is_false()) {
    // a contradiction among the premises
  } else if (concl.is_app() && concl.decl().decl_kind() == Z3_OP_OR) {
    for (unsigned i = 0; i < concl.num_args(); ++i) clause.push_back(literal(concl.arg(i), false));
  } else {
    clause.push_back(literal(concl, false));
  }
  std::vector<std::tuple<uint32_t, uint32_t, int64_t, int64_t, bool>> key;
  key.reserve(clause.size());
  for (const DiffLiteral& d : clause) key.emplace_back(d.x, d.y, d.v.num(), d.v.den(), d.strict);
  std::sort(key.begin(), key.end());
  if (seen.insert(key).second) out.push_back(std::move(clause));
}

}  // namespace

std::vector<std::vector<DiffLiteral>> z3_theory_lemmas(const z3::expr& proof) {
  std::vector<std::vector<DiffLiteral>> out;
  std::set<std::vector<std::tuple<uint32_t, uint32_t, int64_t, int64_t, bool>>> seen;
  std::unordered_set<unsigned> visited;
  std::vector<z3::expr> stack{proof};
  while (!stack.empty()) {
    const z3::expr step = stack.back();
    stack.pop_back();
    if (!step.is_app() || !visited.insert(step.id()).second) continue;
    if (step.decl().decl_kind() == Z3_OP_PR_TH_LEMMA) add_lemma(step, seen, out);
    // Premises are every argument but the last (the fact); facts are not
    // proof steps, so only the premises are walked.
    for (unsigned i = 0; i + 1 < step.num_args(); ++i) stack.push_back(step.arg(i));
  }
  return out;
}

}  // namespace gridlock
