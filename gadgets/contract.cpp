#include "gadgets/contract.hpp"

#include <algorithm>
#include <stdexcept>

namespace gridlock {

namespace {

const Rational& start_of(const std::map<std::string, Rational>& start, const std::string& op) {
  auto it = start.find(op);
  if (it == start.end()) throw std::invalid_argument("collides_continuous: no start time for " + op);
  return it->second;
}

Rational progress(const Rational& t, const Rational& t0) {
  Rational p = t - t0;
  return std::clamp(p, Rational(0), Rational(1));
}

}  // namespace

bool GadgetContract::collides_continuous(const std::map<std::string, Rational>& start) const {
  for (const GapSpec& g : gaps) {
    std::vector<Rational> breaks;
    for (const GapTerm& t : g.terms) {
      breaks.push_back(start_of(start, t.op));
      breaks.push_back(start_of(start, t.op) + Rational(1));
    }
    if (breaks.empty() && g.size < 0) return true;
    for (const Rational& at : breaks) {
      Rational size(g.size);
      for (const GapTerm& t : g.terms) size = size + Rational(t.sign) * progress(at, start_of(start, t.op));
      if (size < Rational(0)) return true;
    }
  }
  for (const Separation& s : separations)
    if (start_of(start, s.second) < start_of(start, s.first) + Rational(1)) return true;
  return false;
}

std::string GadgetContract::str() const {
  std::string s;
  for (const GapSpec& g : gaps) {
    if (!s.empty()) s += "; ";
    s += std::to_string(g.size);
    for (const GapTerm& t : g.terms) s += (t.sign > 0 ? " + " : " - ") + t.op;
    s += " >= 0";
  }
  for (const Separation& sep : separations) {
    if (!s.empty()) s += "; ";
    s += "t(" + sep.second + ") >= t(" + sep.first + ") + 1";
  }
  return s;
}

}  // namespace gridlock
