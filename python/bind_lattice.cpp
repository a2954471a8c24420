// gridlock.Instance, random instances, the simulator and the animation page
// (lattice/, render/).
#include <sstream>

#include "common/internal/atomic_file.hpp"
#include "lattice/animation.hpp"
#include "lattice/grid_format.hpp"
#include "lattice/random_instance.hpp"
#include "python/bindings.hpp"
#include "render/animation_page.hpp"
#include "render/picture.hpp"

namespace gridlock::python {
namespace {

py::tuple cell(Vec2 c) { return py::make_tuple(c.x, c.y); }

Instance read_file(const std::string& path) {
  Instance inst;
  check(read_instance_file(path, inst));
  return inst;
}

Instance parse_text(const std::string& text, const std::string& name) {
  Instance inst;
  std::istringstream in(text);
  check(read_instance(in, name, inst));
  return inst;
}

std::string grid_text(const Instance& inst) {
  std::ostringstream out;
  write_instance(out, inst);
  return out.str();
}

py::list operations(const Instance& inst) {
  py::list ops;
  for (const Operation& op : inst.ops()) {
    py::dict d;
    d["name"] = op.name;
    d["kind"] = op_kind_name(op.kind);
    d["node"] = cell(inst.cells()[op.u]);
    d["dir"] = dir_name(op.dir);
    d["coupling"] = inst.couplings()[op.coupling].name;
    ops.append(d);
  }
  return ops;
}

py::dict couplings(const Instance& inst) {
  py::dict out;
  for (const Coupling& q : inst.couplings()) {
    py::list ops;
    for (OpId o : q.ops) ops.append(inst.ops()[o].name);
    out[py::str(q.name)] = ops;
  }
  return out;
}

std::string repr(const Instance& inst) {
  return "<gridlock.Instance: " + std::to_string(inst.num_nodes()) + " nodes, " + std::to_string(inst.ops().size()) +
         " operations, " + std::to_string(inst.couplings().size()) + " couplings" +
         (inst.horizontal_only() ? ", horizontal-only" : "") + ">";
}

std::string svg(const Instance& inst, const std::string& title) {
  RenderOptions ro;
  ro.title = title;
  return render_svg(inst, ro);
}

void bind_instance_class(py::module_& m) {
  py::class_<Instance>(m, "Instance", "A lattice instance (docs/model.md, the .grid format of docs/grid-format.md)")
      .def_static("read", &read_file, py::arg("path"), "Reads a .grid file; bad input raises gridlock.Error")
      .def_static("parse", &parse_text, py::arg("text"), py::arg("name") = "<string>",
                  "Reads .grid text; errors name `name` and the line")
      .def("to_grid", &grid_text, "The .grid text (Instance.parse gives the instance back exactly)")
      .def(
          "write",
          [](const Instance& inst, const std::string& path) { check(write_file_atomic(path, grid_text(inst))); },
          py::arg("path"), "Writes the .grid file (atomically, checked)")
      .def("to_svg", &svg, py::arg("title") = "", "An SVG picture")
      .def("_repr_svg_", [](const Instance& inst) { return svg(inst, ""); })
      .def("to_ascii", &render_ascii)
      .def("to_tikz", &render_tikz)
      .def_property_readonly("nodes",
                             [](const Instance& inst) {
                               py::list out;
                               for (Vec2 c : inst.cells()) out.append(cell(c));
                               return out;
                             })
      .def_property_readonly("edges",
                             [](const Instance& inst) {
                               py::list out;
                               for (const Edge& e : inst.edges())
                                 out.append(py::make_tuple(cell(inst.cells()[e.a]), cell(inst.cells()[e.b])));
                               return out;
                             })
      .def_property_readonly("operations", &operations, "[{name, kind, node, dir, coupling}]")
      .def_property_readonly("couplings", &couplings, "{coupling name: [operation names]}, in file order")
      .def_property_readonly("anchor", [](const Instance& inst) { return cell(inst.cells()[inst.anchor()]); })
      .def_property_readonly("horizontal_only", &Instance::horizontal_only)
      .def("__len__", &Instance::num_nodes)
      .def("__eq__", [](const Instance& a, const Instance& b) { return grid_text(a) == grid_text(b); })
      .def("__repr__", &repr);
}

Instance random(uint32_t nodes, uint32_t ops, uint32_t max_coupling, uint32_t extra_edge_percent, bool allow_grow,
                bool allow_contract, bool horizontal_only, bool path_shape, uint32_t spread, uint64_t seed) {
  if (nodes < 1 || nodes > kMaxNodes) raise("random_instance: nodes must be 1.." + std::to_string(kMaxNodes));
  if (max_coupling < 1) raise("random_instance: max_coupling must be at least 1");
  if (extra_edge_percent > 100) raise("random_instance: extra_edge_percent must be 0..100");
  // Named fields: the parameters may grow (other work adds instance families).
  RandomInstanceParams p;
  p.nodes = nodes;
  p.ops = ops;
  p.max_coupling = max_coupling;
  p.extra_edge_percent = extra_edge_percent;
  p.allow_grow = allow_grow;
  p.allow_contract = allow_contract;
  p.horizontal_only = horizontal_only;
  p.path_shape = path_shape;
  p.spread = spread;
  return random_instance(p, seed);
}

py::object simulate(const Instance& inst, const py::object& order, const py::object& times) {
  const Schedule s = schedule_arg(inst, order, times);
  Simulator sim(inst);
  const SimResult r = sim.run(s);
  if (!r.collision) return py::none();
  return collision_dict(inst, sim.regions(), *r.collision);
}

std::string animate(const Instance& inst, const py::object& order, const py::object& times, const std::string& title) {
  const Schedule s = schedule_arg(inst, order, times);
  return animation_html(inst, s, build_animation(inst, s), title);
}

}  // namespace

void bind_lattice(py::module_& m) {
  bind_instance_class(m);
  m.def("random_instance", &random, py::arg("nodes") = 8, py::arg("ops") = 3, py::arg("max_coupling") = 1,
        py::arg("extra_edge_percent") = 0, py::arg("allow_grow") = true, py::arg("allow_contract") = true,
        py::arg("horizontal_only") = false, py::arg("path_shape") = false, py::arg("spread") = 0, py::arg("seed") = 1);
  m.def("simulate", &simulate, py::arg("instance"), py::arg("order") = py::none(), py::arg("times") = py::none());
  m.def("animate", &animate, py::arg("instance"), py::arg("order") = py::none(), py::arg("times") = py::none(),
        py::arg("title") = "");
}

}  // namespace gridlock::python
