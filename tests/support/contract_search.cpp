#include "support/contract_search.hpp"

#include <cstdint>
#include <stdexcept>

namespace gridlock::test {

namespace {

// Every contract gap as a list of (coupling, sign) terms.
struct CouplingGap {
  int64_t size = 0;
  std::vector<std::pair<CouplingId, int>> terms;
};

std::vector<CouplingGap> coupling_gaps(const CompiledFormula& c) {
  std::vector<CouplingGap> out;
  for (const GadgetPlacement& g : c.gadgets) {
    for (const GapSpec& s : g.contract.gaps) {
      CouplingGap cg{s.size, {}};
      for (const GapTerm& t : s.terms) {
        OpId op = c.instance.find_op(t.op);
        if (op == kNone) throw std::logic_error("contract names unknown operation " + t.op);
        cg.terms.emplace_back(c.instance.ops()[op].coupling, t.sign);
      }
      out.push_back(std::move(cg));
    }
    // In discrete time a separation is the order gap 0 + first - second.
    for (const Separation& s : g.contract.separations) {
      CouplingGap cg{0, {}};
      for (auto [name, sign] : {std::pair{s.first, +1}, std::pair{s.second, -1}}) {
        OpId op = c.instance.find_op(name);
        if (op == kNone) throw std::logic_error("contract names unknown operation " + name);
        cg.terms.emplace_back(c.instance.ops()[op].coupling, sign);
      }
      out.push_back(std::move(cg));
    }
  }
  return out;
}

bool violates(const std::vector<CouplingGap>& gaps, const std::vector<char>& done) {
  for (const CouplingGap& g : gaps) {
    int64_t s = g.size;
    for (auto [q, sign] : g.terms) s += done[q] ? sign : 0;
    if (s < 0) return true;
  }
  return false;
}

}  // namespace

bool order_breaks_contracts(const CompiledFormula& c, const std::vector<CouplingId>& order) {
  auto gaps = coupling_gaps(c);
  std::vector<char> done(c.instance.couplings().size(), 0);
  for (CouplingId q : order) {
    done[q] = 1;
    if (violates(gaps, done)) return true;
  }
  return false;
}

bool contract_schedule_exists(const CompiledFormula& c, std::vector<CouplingId>* witness) {
  const size_t k = c.instance.couplings().size();
  if (k > 22) throw std::invalid_argument("contract_schedule_exists: too many couplings");
  auto gaps = coupling_gaps(c);
  const uint32_t full = (uint32_t{1} << k) - 1;
  // reach[s]: 0 unknown, 1 reachable; parent[s]: the coupling added last.
  std::vector<char> reach(size_t{full} + 1, 0);
  std::vector<uint8_t> last(size_t{full} + 1, 0);
  std::vector<uint32_t> stack{0};
  reach[0] = 1;
  std::vector<char> done(k);
  while (!stack.empty()) {
    uint32_t s = stack.back();
    stack.pop_back();
    for (size_t q = 0; q < k; ++q) {
      uint32_t t = s | (uint32_t{1} << q);
      if (t == s || reach[t]) continue;
      for (size_t i = 0; i < k; ++i) done[i] = (t >> i) & 1;
      if (violates(gaps, done)) continue;
      reach[t] = 1;
      last[t] = static_cast<uint8_t>(q);
      stack.push_back(t);
    }
  }
  if (!reach[full]) return false;
  if (witness) {
    witness->clear();
    for (uint32_t s = full; s != 0; s &= ~(uint32_t{1} << last[s])) witness->insert(witness->begin(), last[s]);
  }
  return true;
}

}  // namespace gridlock::test
