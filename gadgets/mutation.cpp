#include "gadgets/mutation.hpp"

namespace gridlock {

namespace {
constexpr Mutation kAll[] = {Mutation::None,           Mutation::VariableLooseY, Mutation::ClauseLoose,
                             Mutation::ClauseTight,    Mutation::OrderLoose,     Mutation::OrderDropRelease,
                             Mutation::SeparationLoose};
}

const char* mutation_name(Mutation m) {
  switch (m) {
    case Mutation::None: return "none";
    case Mutation::VariableLooseY: return "variable-loose-y";
    case Mutation::ClauseLoose: return "clause-loose";
    case Mutation::ClauseTight: return "clause-tight";
    case Mutation::OrderLoose: return "order-loose";
    case Mutation::OrderDropRelease: return "order-drop-release";
    case Mutation::SeparationLoose: return "separation-loose";
  }
  return "?";
}

std::optional<Mutation> parse_mutation(const std::string& s) {
  for (Mutation m : kAll)
    if (s == mutation_name(m)) return m;
  return std::nullopt;
}

std::vector<Mutation> all_mutations() { return {std::begin(kAll) + 1, std::end(kAll)}; }

}  // namespace gridlock
