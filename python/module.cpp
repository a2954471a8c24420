// The extension module gridlock._core: the helpers every binding file
// shares (bindings.hpp) and the module definition. The public names and the
// result dataclasses are in python/gridlock/__init__.py.
#include <set>

#include "python/bindings.hpp"

namespace gridlock::python {

namespace {
PyObject* error_type = nullptr;  // gridlock.Error, created once per process
}

void register_errors(py::module_& m) {
  error_type = PyErr_NewExceptionWithDoc(
      "gridlock.Error",
      "Bad input or a bad argument: str() is 'FILE:LINE: what is wrong', as the command line prints it; "
      "attributes file, line (0: not tied to a line) and message.",
      PyExc_Exception, nullptr);
  m.attr("Error") = py::handle(error_type);
  // By value: pybind11 stores translators as void (*)(std::exception_ptr).
  py::register_exception_translator([](std::exception_ptr p) {  // NOLINT(performance-unnecessary-value-param)
    auto set = [](const Diagnostic& d) {
      py::object err = py::reinterpret_borrow<py::object>(error_type)(d.str());
      err.attr("file") = d.file;
      err.attr("line") = d.line;
      err.attr("message") = d.message;
      PyErr_SetObject(error_type, err.ptr());
    };
    try {
      if (p) std::rethrow_exception(p);
    } catch (const InputError& e) {
      set(e.diagnostic);
    } catch (const std::invalid_argument& e) {
      set(Diagnostic{"", 0, e.what()});
    }
  });
}

py::object fraction(const Rational& r) {
  static py::object fraction_type = py::module_::import("fractions").attr("Fraction");
  return fraction_type(r.num(), r.den());
}

Rational to_rational(py::handle v) {
  if (py::isinstance<py::str>(v)) {
    const std::string text = v.cast<std::string>();
    if (auto r = Rational::parse(text)) return *r;
    raise("'" + text + "' is not an exact time (an integer or a fraction a/b)");
  }
  if (py::isinstance<py::float_>(v) || !py::hasattr(v, "numerator") || !py::hasattr(v, "denominator"))
    raise("times are exact: give an int, a fractions.Fraction or a string 'a/b', not " +
          std::string(py::str(py::repr(v))));
  try {
    return Rational(v.attr("numerator").cast<int64_t>(), v.attr("denominator").cast<int64_t>());
  } catch (const py::cast_error&) {
    raise("time " + std::string(py::str(v)) + " does not fit 64 bits");
  }
}

py::list order_names(const Instance& inst, const std::vector<CouplingId>& order) {
  py::list names;
  for (CouplingId q : order) names.append(inst.couplings()[q].name);
  return names;
}

py::dict times_dict(const Instance& inst, const Schedule& s) {
  py::dict times;
  for (CouplingId q = 0; q < s.start.size(); ++q) times[py::str(inst.couplings()[q].name)] = fraction(s.start[q]);
  return times;
}

namespace {

Schedule times_arg(const Instance& inst, const py::dict& times) {
  Schedule s;
  s.start.assign(inst.couplings().size(), Rational(0));
  std::vector<bool> given(inst.couplings().size(), false);
  for (auto [key, value] : times) {
    const std::string name = py::str(key);
    const CouplingId q = inst.find_coupling(name);
    if (q == kNone) raise("times: no coupling named '" + name + "'");
    s.start[q] = to_rational(value);
    given[q] = true;
  }
  for (CouplingId q = 0; q < given.size(); ++q)
    if (!given[q]) raise("times: no start time for coupling '" + inst.couplings()[q].name + "'");
  if (auto problem = check_schedule_bounds(inst, s)) raise("times: " + *problem);
  return s;
}

}  // namespace

Schedule schedule_arg(const Instance& inst, const py::object& order, const py::object& times) {
  if (order.is_none() == times.is_none())
    raise("give exactly one of order= (coupling names) and times= ({name: time})");
  if (!times.is_none()) return times_arg(inst, times.cast<py::dict>());
  if (py::isinstance<py::str>(order)) raise("order: give a list of coupling names, not one string");
  std::vector<CouplingId> ids;
  check(parse_order(inst, order.cast<std::vector<std::string>>(), "order", 0, ids));
  return schedule_from_order(ids);
}

py::dict collision_dict(const Instance& inst, const Regions& regions, const Collision& c) {
  py::dict d;
  d["kind"] = c.kind == Collision::Kind::Node ? "node" : "cycle";
  d["time"] = fraction(c.time);
  if (c.kind == Collision::Kind::Node) {
    d["regions"] = py::make_tuple(region_label(inst, regions, c.a), region_label(inst, regions, c.b));
  } else {
    py::list cycle;
    for (NodeId w : c.cycle) cycle.append(inst.node_label(w));
    d["cycle"] = cycle;
  }
  d["moving"] = order_names(inst, c.moving);
  return d;
}

std::vector<bool> assignment_arg(const py::handle& literals, int num_vars) {
  std::vector<bool> value(static_cast<size_t>(num_vars) + 1, false);
  std::set<int> seen;
  for (py::handle h : literals) {
    const int lit = h.cast<int>();
    const int var = lit < 0 ? -lit : lit;
    if (lit == 0 || var > num_vars)
      raise("assignment: literal " + std::to_string(lit) + " is not one of 1.." + std::to_string(num_vars) +
            " or its negation");
    if (!seen.insert(var).second) raise("assignment: variable " + std::to_string(var) + " given twice");
    value[static_cast<size_t>(var)] = lit > 0;
  }
  return value;
}

py::list literals_list(const std::vector<bool>& value, int num_vars) {
  py::list out;
  for (int v = 1; v <= num_vars; ++v) out.append(value[static_cast<size_t>(v)] ? v : -v);
  return out;
}

}  // namespace gridlock::python

PYBIND11_MODULE(_core, m) {
  m.doc() = "gridlock's C++ library (docs/python.md); use the package gridlock, not this module";
  gridlock::python::register_errors(m);
  gridlock::python::bind_lattice(m);
  gridlock::python::bind_solver(m);
  gridlock::python::bind_cnf(m);
  gridlock::python::bind_verify(m);
}
