// Writer of the .grid format; read_instance(write_instance(I)) == I.
#include <ostream>

#include "lattice/grid_format.hpp"

namespace gridlock {

void write_instance(std::ostream& out, const Instance& inst, const std::vector<std::string>& comments) {
  out << "c gridlock instance (format: docs/grid-format.md)\n";
  for (const auto& c : comments) out << "c " << c << '\n';
  out << "p grid " << inst.num_nodes() << ' ' << inst.edges().size() << ' ' << inst.ops().size() << ' '
      << inst.couplings().size() << '\n';
  const auto& cells = inst.cells();
  for (const auto& c : cells) out << "n " << c.x << ' ' << c.y << '\n';
  for (const auto& e : inst.edges())
    out << "e " << cells[e.a].x << ' ' << cells[e.a].y << ' ' << cells[e.b].x << ' ' << cells[e.b].y << '\n';
  for (const auto& o : inst.ops())
    out << "o " << o.name << ' ' << op_kind_name(o.kind) << ' ' << cells[o.u].x << ' ' << cells[o.u].y << ' '
        << dir_name(o.dir) << '\n';
  for (const auto& q : inst.couplings()) {
    out << "q " << q.name;
    for (OpId o : q.ops) out << ' ' << inst.ops()[o].name;
    out << '\n';
  }
  if (inst.has_explicit_anchor()) out << "a " << cells[inst.anchor()].x << ' ' << cells[inst.anchor()].y << '\n';
}

}  // namespace gridlock
