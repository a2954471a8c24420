// verify and fuzz (verify/campaign.hpp): the records of `gridlock verify
// --json` and `gridlock fuzz --json`, with a progress callback. The
// campaigns run on a worker thread (run_interruptible); a callback takes the
// GIL for its call, and an exception it raises stops the campaign (through
// the stop request) and is raised by the call.
#include "cnf/dimacs.hpp"
#include "common/internal/ordered_pool.hpp"
#include "python/bindings.hpp"
#include "verify/campaign.hpp"
#include "verify/fuzz.hpp"

namespace gridlock::python {
namespace {

VerifyOptions verify_options(const std::string& model, double timeout, uint64_t max_states, bool direct) {
  VerifyOptions opt;
  auto m = TimeModels::parse(model);
  if (!m) raise("model must be discrete, continuous or both, not '" + model + "'");
  if (!(timeout > 0)) raise("timeout must be a positive number of seconds");
  opt.models = *m;
  opt.solve_seconds = timeout;
  opt.max_states = max_states;
  opt.direct = direct;
  return opt;
}

// The row of `gridlock verify --json` for formula i.
py::dict verify_row(const VerifyOptions& opt, size_t i, const std::string& name, const VerifyResult& r,
                    FormulaStatus status) {
  const bool with_discrete = opt.models.has(TimeModel::Discrete);
  py::dict row;
  row["index"] = i;
  row["formula"] = name;
  row["variables"] = r.source.num_vars;
  row["clauses"] = r.source.clauses.size();
  row["reduced"] = r.reduced;
  row["nodes"] = r.nodes;
  row["operations"] = r.ops;
  row["couplings"] = r.couplings;
  row["max_coupling"] = r.max_coupling;
  row["sat"] = verdict_name(r.sat);
  row["discrete"] = with_discrete ? py::object(py::str(verdict_name(r.discrete))) : py::object(py::none());
  row["continuous"] = with_discrete ? py::object(py::str(verdict_name(r.continuous))) : py::object(py::none());
  row["witnesses_checked"] = r.witnesses_checked();
  row["no_certificate"] = r.no_certificate == Check::None    ? "none"
                          : r.no_certificate == Check::Valid ? "checked"
                                                             : "rejected";
  row["continuous_no_certificate"] = r.cno_certificate == Check::None    ? "none"
                                     : r.cno_certificate == Check::Valid ? "checked"
                                                                         : "rejected";
  row["ms_certify"] = r.ms_certify;
  row["solver_states"] = r.solver_states;
  row["ms_sat"] = r.ms_sat;
  row["ms_compile"] = r.ms_compile;
  row["ms_solve"] = r.ms_solve;
  row["ms_gaps"] = r.ms_gaps;
  row["status"] = formula_status_name(status);
  row["problem"] = r.problem;
  if (opt.models.has(TimeModel::Continuous)) {
    row["continuous_nodes"] = r.cnodes;
    row["continuous_solver"] = verdict_name(r.continuous_solver);
    row["continuous_solver_conflicts"] = r.csolver_conflicts;
    row["ms_continuous_solve"] = r.ms_csolve;
  }
  return row;
}

// Calls a Python callback from the worker thread; the first exception it
// raises is kept and stops the campaign.
struct Callback {
  py::object fn;
  std::exception_ptr failure;
  template <class MakeArg>
  void operator()(MakeArg&& make_arg) {
    if (fn.is_none() || failure) return;
    py::gil_scoped_acquire gil;
    try {
      fn(make_arg());
    } catch (...) {
      failure = std::current_exception();
      stop_signal().store(SIGINT);
    }
  }
  void rethrow() {
    if (!failure) return;
    stop_signal().store(0);
    std::rethrow_exception(failure);
  }
};

// jobs: None for the cores available (as the command line), else 1..1024.
unsigned jobs_of(const py::object& jobs) {
  if (jobs.is_none()) return available_cores();
  const long long n = jobs.cast<long long>();
  if (n < 1 || n > 1024) raise("jobs: want 1 to 1024 worker threads, got " + std::to_string(n));
  return static_cast<unsigned>(n);
}

py::dict verify(const py::list& inputs, const py::object& names, const std::string& model, double timeout,
                uint64_t max_states, bool direct, const py::object& jobs, const py::object& progress) {
  VerifyCampaign c;
  c.jobs = jobs_of(jobs);
  c.verify = verify_options(model, timeout, max_states, direct);
  c.reproducers = "";
  std::vector<Formula> formulas;
  std::vector<std::string> labels;
  for (py::handle h : inputs) {
    if (py::isinstance<Formula>(h)) {
      formulas.push_back(h.cast<Formula>());
      labels.push_back("formula-" + std::to_string(labels.size()));
      continue;
    }
    const std::string path = py::str(h);
    Formula f;
    check(read_dimacs_file(path, f));
    formulas.push_back(std::move(f));
    labels.push_back(path);
  }
  if (!names.is_none()) labels = names.cast<std::vector<std::string>>();
  if (labels.size() != formulas.size()) raise("verify: give one name per formula");
  py::list rows;
  Callback cb{progress, nullptr};
  VerifyEvents ev;
  ev.result = [&](size_t i, const VerifyResult& r, FormulaStatus s) {
    py::gil_scoped_acquire gil;
    rows.append(verify_row(c.verify, i, labels[i], r, s));
    cb([&] { return rows[rows.size() - 1]; });
  };
  std::vector<std::string> stems;
  stems.reserve(labels.size());
  for (const std::string& l : labels) stems.push_back(formula_stem(l));
  const VerifyTally t = run_interruptible([&] { return run_verify_campaign(formulas, stems, c, ev); });
  cb.rethrow();
  py::dict d;
  d["command"] = "verify";
  d["model"] = c.verify.models.name();
  d["formulas"] = rows;
  d["summary"] = py::dict(py::arg("formulas") = t.formulas, py::arg("sat") = t.sat, py::arg("unsat") = t.unsat,
                          py::arg("agree") = t.agree, py::arg("unknown") = t.unknown, py::arg("disagree") = t.disagree,
                          py::arg("certificates_checked") = t.certificates,
                          py::arg("no_certificates_checked") = t.no_certified,
                          py::arg("no_certificates_rejected") = t.no_rejected);
  return d;
}

std::vector<FuzzKind> kinds_arg(const std::vector<std::string>& names) {
  std::vector<FuzzKind> kinds;
  for (const std::string& w : names) {
    if (w == "ksat") kinds.push_back(FuzzKind::Ksat);
    else if (w == "lsat") kinds.push_back(FuzzKind::Lsat);
    else if (w == "planted") kinds.push_back(FuzzKind::Planted);
    else if (w == "mix") kinds.insert(kinds.end(), {FuzzKind::Ksat, FuzzKind::Lsat, FuzzKind::Planted});
    else raise("kinds: '" + w + "' is not ksat, lsat, planted or mix");
  }
  if (kinds.empty()) raise("kinds: give at least one of ksat, lsat, planted, mix");
  return kinds;
}

py::dict tally_dict(const FuzzTally& t) {
  py::dict d;
  d["formulas"] = t.formulas;
  d["sat"] = t.sat;
  d["unsat"] = t.unsat;
  d["unknown"] = t.unknown;
  d["certificates_checked"] = t.certificates;
  d["no_certificates_checked"] = t.no_certified;
  d["disagreements"] = t.disagreements;
  d["seconds"] = t.seconds;
  return d;
}

py::dict fuzz(uint64_t count, uint64_t seed, int min_vars, int max_vars, const std::vector<std::string>& kinds,
              const std::string& model, double timeout, uint64_t max_states, bool direct, bool keep_going, double time,
              const py::object& jobs, const py::object& progress) {
  if (min_vars < 1 || max_vars > 64 || min_vars > max_vars) raise("fuzz: need 1 <= min_vars <= max_vars <= 64");
  if (count < 1) raise("fuzz: count must be at least 1");
  FuzzCampaign c;
  c.formulas = FuzzParams{.seed = seed, .min_vars = min_vars, .max_vars = max_vars, .kinds = kinds_arg(kinds)};
  c.verify = verify_options(model, timeout, max_states, direct);
  c.last = count;
  c.seconds = time;
  c.keep_going = keep_going;
  c.jobs = jobs_of(jobs);
  Callback cb{progress, nullptr};
  FuzzEvents ev;
  ev.progress = [&](const FuzzTally& t) { cb([&] { return tally_dict(t); }); };
  const FuzzTally t = run_interruptible([&] { return run_fuzz_campaign(c, ev); });
  cb.rethrow();
  py::dict d = tally_dict(t);
  d["command"] = "fuzz";
  d["seed"] = std::to_string(seed);
  py::list findings;
  for (const FuzzFinding& f : t.findings)
    findings.append(py::dict(py::arg("index") = f.index, py::arg("problem") = f.problem,
                             py::arg("shrunk_variables") = f.shrunk.num_vars,
                             py::arg("shrunk_clauses") = f.shrunk.clauses.size(),
                             py::arg("shrink_tries") = f.shrink.tries, py::arg("dimacs") = to_dimacs(f.shrunk)));
  d["findings"] = findings;
  d["status"] = t.disagreements ? "DISAGREE" : "AGREE";
  return d;
}

}  // namespace

void bind_verify(py::module_& m) {
  m.def("verify", &verify, py::arg("formulas"), py::arg("names") = py::none(), py::arg("model") = "discrete",
        py::arg("timeout") = 60.0, py::arg("max_states") = 0, py::arg("direct") = false, py::arg("jobs") = py::none(),
        py::arg("progress") = py::none());
  m.def("fuzz", &fuzz, py::arg("count") = 1000, py::arg("seed") = 1, py::arg("min_vars") = 3, py::arg("max_vars") = 6,
        py::arg("kinds") = std::vector<std::string>{"mix"}, py::arg("model") = "discrete", py::arg("timeout") = 10.0,
        py::arg("max_states") = 2000000, py::arg("direct") = false, py::arg("keep_going") = false,
        py::arg("time") = 0.0, py::arg("jobs") = py::none(), py::arg("progress") = py::none());
  m.def(
      "fuzz_formula",
      [](uint64_t seed, uint64_t index, int min_vars, int max_vars, const std::vector<std::string>& kinds) {
        if (min_vars < 1 || max_vars > 64 || min_vars > max_vars)
          raise("fuzz_formula: need 1 <= min_vars <= max_vars <= 64");
        return fuzz_formula(
            FuzzParams{.seed = seed, .min_vars = min_vars, .max_vars = max_vars, .kinds = kinds_arg(kinds)}, index);
      },
      py::arg("seed"), py::arg("index"), py::arg("min_vars") = 3, py::arg("max_vars") = 6,
      py::arg("kinds") = std::vector<std::string>{"mix"});
}

}  // namespace gridlock::python
