// One axis, any couplings: the group pairs (collide/internal/collide_pairs.hpp,
// one_axis_group_pairs; the proof is docs/collide.md, "One axis, any
// couplings").
#include <array>
#include <optional>
#include <utility>
#include <vector>

#include "collide/internal/collide_pairs.hpp"
#include "collide/internal/row_groups.hpp"

namespace gridlock {

std::optional<std::vector<std::pair<uint32_t, uint32_t>>> one_axis_group_pairs(const Instance& inst,
                                                                               const Regions& regions) {
  const std::optional<int> axis = inst.moving_axis();
  if (!axis) return std::nullopt;
  const std::vector<RegionForm> forms = region_forms(inst, regions);
  const int m = 2 * *axis, c = 2 - m;  // faces m, m + 1 move along the axis; face c names the row
  // A unit: a node whose width never changes (no operation of its own
  // moves one of its faces against the other).
  auto unit = [&](uint32_t r) {
    const RegionForm& F = forms[r];
    return F.own == kNone && F.base[m + 1] - F.base[m] == 1;
  };
  return row_group_pairs(
      forms.size(),
      [&](uint32_t r) {
        return std::array<int64_t, 3>{forms[r].base[c], forms[r].base[m], forms[r].base[m + 1]};
      },
      unit);
}

}  // namespace gridlock
