// gridlock.Formula (DIMACS, LSAT check, generators, CaDiCaL), to_lsat and
// its assignment maps, compile and the reduction's certificates (cnf/,
// reductions/).
#include "cnf/dimacs.hpp"
#include "cnf/formula.hpp"
#include "cnf/generate.hpp"
#include "cnf/lsat.hpp"
#include "cnf/sat_solver.hpp"
#include "common/internal/atomic_file.hpp"
#include "python/bindings.hpp"
#include "reductions/compile.hpp"
#include "reductions/to_lsat.hpp"

namespace gridlock::python {
namespace {

Formula make_formula(int num_vars, const std::vector<std::vector<int>>& clauses,
                     const std::vector<std::string>& comments) {
  Formula f{num_vars, clauses, comments};
  if (std::string problem = validate(f); !problem.empty()) raise("Formula: " + problem);
  return f;
}

Formula read_file(const std::string& path, bool strict_count) {
  Formula f;
  DimacsOptions opt;
  opt.strict_count = strict_count;
  check(read_dimacs_file(path, f, opt));
  return f;
}

Formula parse_text(const std::string& text, const std::string& name, bool strict_count) {
  Formula f;
  DimacsOptions opt;
  opt.strict_count = strict_count;
  check(read_dimacs_string(text, name, f, opt));
  return f;
}

const Formula& valid(const Formula& f) {
  if (std::string problem = validate(f); !problem.empty()) raise("Formula: " + problem);
  return f;
}

LsatForm form_arg(const std::string& form) {
  if (form == "exact3") return LsatForm::Exact3;
  if (form == "<=3") return LsatForm::AtMost3;
  raise("form must be 'exact3' or '<=3', not '" + form + "'");
}

py::dict sat_solve(const Formula& f, const py::object& timeout, int64_t conflicts) {
  SatLimits lim;
  if (!timeout.is_none()) lim.seconds = timeout.cast<double>();
  lim.conflicts = conflicts;
  const Formula& g = valid(f);
  const SatResult r = run_interruptible([&] { return solve_sat(g, lim); });
  py::dict d;
  d["status"] = sat_status_name(r.status);
  d["model"] = r.status == Verdict::Yes ? py::object(literals_list(r.model, f.num_vars)) : py::object(py::none());
  d["seconds"] = r.seconds;
  d["solver"] = sat_solver_name();
  return d;
}

void bind_formula_class(py::module_& m) {
  py::class_<Formula>(m, "Formula", "A CNF formula as DIMACS writes it: variables 1..num_vars, literals v and -v")
      .def(py::init(&make_formula), py::arg("num_vars") = 0, py::arg("clauses") = std::vector<std::vector<int>>{},
           py::arg("comments") = std::vector<std::string>{})
      .def_readwrite("num_vars", &Formula::num_vars)
      .def_readwrite("clauses", &Formula::clauses)
      .def_readwrite("comments", &Formula::comments)
      .def_static("read", &read_file, py::arg("path"), py::arg("strict_count") = true)
      .def_static("parse", &parse_text, py::arg("text"), py::arg("name") = "<string>", py::arg("strict_count") = true)
      .def("to_dimacs", [](const Formula& f) { return to_dimacs(valid(f)); })
      .def(
          "write",
          [](const Formula& f, const std::string& path) { check(write_file_atomic(path, to_dimacs(valid(f)))); },
          py::arg("path"))
      .def(
          "is_lsat", [](const Formula& f, const std::string& form) { return is_lsat(valid(f), form_arg(form)); },
          py::arg("form") = "<=3")
      .def(
          "satisfies",
          [](const Formula& f, const py::object& model) {
            return satisfies(valid(f), assignment_arg(model, f.num_vars));
          },
          py::arg("model"), "True iff the assignment (DIMACS literals; unnamed variables false) satisfies every clause")
      .def("__eq__", [](const Formula& a, const Formula& b) { return a == b; })
      .def("__repr__", [](const Formula& f) { return "<gridlock.Formula: " + summary(f) + ">"; });
}

void bind_generators(py::module_& m) {
  m.def(
      "random_ksat",
      [](int n, int m_, int k, uint64_t seed) {
        return random_ksat(KSatParams{.n = n, .m = m_, .k = k, .seed = seed});
      },
      py::arg("n"), py::arg("m"), py::arg("k") = 3, py::arg("seed") = 1);
  m.def(
      "random_lsat",
      [](int n, int m_, int min_len, int max_len, uint64_t seed) {
        return random_lsat(LsatParams{.n = n, .m = m_, .min_len = min_len, .max_len = max_len, .seed = seed});
      },
      py::arg("n"), py::arg("m"), py::arg("min_len") = 3, py::arg("max_len") = 3, py::arg("seed") = 1);
  m.def(
      "planted_ksat",
      [](int n, int m_, int k, uint64_t seed) {
        return planted_ksat(PlantedParams{.n = n, .m = m_, .k = k, .seed = seed});
      },
      py::arg("n"), py::arg("m"), py::arg("k") = 3, py::arg("seed") = 1);
  m.def("sat_solve", &sat_solve, py::arg("formula"), py::arg("timeout") = py::none(), py::arg("conflicts") = -1);
}

py::dict lsat_stats(const ToLsatStats& s) {
  py::dict d;
  d["identity"] = s.identity;
  d["in_vars"] = s.in_vars;
  d["in_clauses"] = s.in_clauses;
  d["tautologies"] = s.tautologies;
  d["duplicate_clauses"] = s.duplicate_clauses;
  d["empty_clauses"] = s.empty_clauses;
  d["split_clauses"] = s.split_clauses;
  d["links"] = s.links;
  d["out_vars"] = s.out_vars;
  d["out_clauses"] = s.out_clauses;
  return d;
}

void bind_to_lsat(py::module_& m) {
  py::class_<LsatReduction>(m, "LsatReduction", "3-SAT -> LSAT<=3 (reductions/to_lsat.hpp) with its assignment maps")
      .def_property_readonly("output", &LsatReduction::output)
      .def_property_readonly("stats", [](const LsatReduction& r) { return lsat_stats(r.stats()); })
      .def(
          "lift_to_source",
          [](const LsatReduction& r, const py::object& model) {
            return literals_list(r.lift_to_source(assignment_arg(model, r.output().num_vars)), r.source_vars());
          },
          py::arg("model"), "An assignment of the output (DIMACS literals) to one of the input")
      .def(
          "lift_to_target",
          [](const LsatReduction& r, const py::object& model) {
            return literals_list(r.lift_to_target(assignment_arg(model, r.source_vars())), r.output().num_vars);
          },
          py::arg("model"), "An assignment of the input to one of the output")
      .def("__repr__", [](const LsatReduction& r) { return "<gridlock.LsatReduction: " + summary(r.output()) + ">"; });
  m.def(
      "to_lsat",
      [](const Formula& f, bool passthrough, bool keep_duplicates) {
        return reduce_to_lsat(valid(f), ToLsatOptions{.passthrough = passthrough, .keep_duplicates = keep_duplicates});
      },
      py::arg("formula"), py::arg("passthrough") = true, py::arg("keep_duplicates") = false);
}

py::dict compile_stats(const CompileStats& s) {
  py::dict d;
  d["nodes"] = s.nodes;
  d["edges"] = s.edges;
  d["operations"] = s.ops;
  d["couplings"] = s.couplings;
  d["vertical_operations"] = s.vertical_ops;
  d["max_coupling"] = s.max_coupling;
  d["oversize"] = s.oversize;
  return d;
}

// compiled.lift(assignment=...) -> order (discrete) or times (continuous);
// compiled.lift(order=... | times=...) -> the assignment (literals).
py::object lift(const CompiledFormula& c, const py::object& assignment, const py::object& order,
                const py::object& times) {
  const bool continuous = c.model == TimeModel::Continuous;
  if (!assignment.is_none()) {
    if (!order.is_none() || !times.is_none()) raise("lift: give assignment= alone, or order= / times= alone");
    const std::vector<bool> value = assignment_arg(assignment, c.num_vars);
    if (continuous) return times_dict(c.instance, times_from_assignment(c, value));
    return order_names(c.instance, schedule_from_assignment(c, value));
  }
  if (continuous && !order.is_none()) raise("lift: a continuous instance takes times=, not order=");
  if (!continuous && !times.is_none()) raise("lift: a discrete instance takes order=, not times=");
  const Schedule s = schedule_arg(c.instance, order, times);
  const std::vector<bool> value = continuous ? assignment_from_times(c, s) : assignment_from_schedule(c, s.order);
  return literals_list(value, c.num_vars);
}

void bind_compile(py::module_& m) {
  py::class_<CompiledFormula>(m, "Compiled", "A formula compiled to a lattice instance, with its certificate maps")
      .def_property_readonly(
          "instance", [](const CompiledFormula& c) -> const Instance& { return c.instance; },
          py::return_value_policy::reference_internal)
      .def_property_readonly("model", [](const CompiledFormula& c) { return time_model_name(c.model); })
      .def_readonly("num_vars", &CompiledFormula::num_vars)
      .def_readonly("num_clauses", &CompiledFormula::num_clauses)
      .def_property_readonly("stats", [](const CompiledFormula& c) { return compile_stats(c.stats); })
      .def("lift", &lift, py::arg("assignment") = py::none(), py::arg("order") = py::none(),
           py::arg("times") = py::none())
      .def("__repr__", [](const CompiledFormula& c) {
        return "<gridlock.Compiled: " + std::string(time_model_name(c.model)) + ", " + std::to_string(c.stats.nodes) +
               " nodes, " + std::to_string(c.stats.couplings) + " couplings>";
      });
  m.def(
      "compile",
      [](const Formula& f, const std::string& model) {
        if (model != "discrete" && model != "continuous")
          raise("model must be discrete or continuous, not '" + model + "'");
        return compile_formula(valid(f), Mutation::None,
                               model == "discrete" ? TimeModel::Discrete : TimeModel::Continuous);
      },
      py::arg("formula"), py::arg("model") = "discrete");
}

}  // namespace

void bind_cnf(py::module_& m) {
  bind_formula_class(m);
  bind_generators(m);
  bind_to_lsat(m);
  bind_compile(m);
}

}  // namespace gridlock::python
