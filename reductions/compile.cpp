#include "reductions/compile.hpp"

#include <algorithm>
#include <cstdint>
#include <stdexcept>

#include "gadgets/canvas.hpp"
#include "gadgets/clause_gadget.hpp"
#include "gadgets/order_gadget.hpp"
#include "gadgets/separation_gadget.hpp"
#include "gadgets/variable_gadget.hpp"

namespace gridlock {

namespace {

constexpr int64_t kSpineX = -2;

std::string var_name(int v) { return "x" + std::to_string(v); }
std::string literal_name(int lit) { return (lit < 0 ? "~" : "") + var_name(var_of(lit)); }

}  // namespace

uint64_t compiled_node_count(const Formula& f, ReductionModel model) {
  if (f.num_vars < 1) return 0;
  uint64_t literals = 0;
  for (const auto& c : f.clauses) literals += c.size();
  const auto n = static_cast<uint64_t>(f.num_vars), m = static_cast<uint64_t>(f.clauses.size());
  // The continuous reduction's separation gadget has two nodes more than
  // the order gadget it replaces.
  return 43 * n + 5 * literals + 15 * m - (model == ReductionModel::Continuous ? 9 : 11);
}

const char* reduction_model_name(ReductionModel m) {
  return m == ReductionModel::Continuous ? "continuous" : "discrete";
}

CompiledFormula compile_formula(const Formula& f, Mutation mutation, ReductionModel model) {
  if (auto e = validate(f); !e.empty()) throw std::invalid_argument("compile: " + e);
  if (uint64_t nodes = compiled_node_count(f, model); nodes > static_cast<uint64_t>(kMaxNodes))
    throw std::invalid_argument("the compiled instance would have " + std::to_string(nodes) +
                                " nodes (43n + 5L + 15m - 11), more than the .grid format's limit of " +
                                std::to_string(kMaxNodes));
  for (size_t h = 0; h < f.clauses.size(); ++h)
    if (f.clauses[h].empty())
      throw std::invalid_argument("clause " + std::to_string(h + 1) +
                                  " is empty; the reduction needs at least one literal per clause");
  const int n = f.num_vars;
  const size_t m = f.clauses.size();

  Canvas canvas;
  CompiledFormula out;
  out.num_vars = n;
  out.num_clauses = m;
  out.model = model;
  // Coupling contents, by name, in a fixed order.
  std::vector<std::string> coupling_names;
  std::vector<std::vector<std::string>> coupling_ops;
  auto new_coupling = [&](const std::string& name) {
    coupling_names.push_back(name);
    coupling_ops.emplace_back();
    return coupling_names.size() - 1;
  };
  std::vector<size_t> c_true(static_cast<size_t>(n)), c_false(c_true), c_y(c_true), c_z(c_true), c_u(m);
  for (int v = 1; v <= n; ++v) {
    auto i = static_cast<size_t>(v - 1);
    c_true[i] = new_coupling(var_name(v) + ":T");
    c_false[i] = new_coupling(var_name(v) + ":F");
  }
  for (int v = 1; v <= n; ++v) c_y[static_cast<size_t>(v - 1)] = new_coupling("y" + std::to_string(v));
  for (int v = 1; v <= n; ++v) c_z[static_cast<size_t>(v - 1)] = new_coupling("z" + std::to_string(v));
  for (size_t h = 0; h < m; ++h) c_u[h] = new_coupling("u" + std::to_string(h + 1));

  int64_t row = 0;
  auto place = [&](const GadgetPlacement& p) {
    // Arm from the spine to the attach node.
    canvas.node({-1, p.attach_row});
    canvas.edge({kSpineX, p.attach_row}, {-1, p.attach_row});
    canvas.edge({-1, p.attach_row}, {0, p.attach_row});
    row = p.top_row + 2;  // one empty row between gadgets
    out.gadgets.push_back(p);
  };

  // Variable gadgets.
  for (int v = 1; v <= n; ++v) {
    auto i = static_cast<size_t>(v - 1);
    VariableOps ops{var_name(v) + ".T", var_name(v) + ".F", var_name(v) + ".y", var_name(v) + ".z"};
    coupling_ops[c_true[i]].push_back(ops.set_true);
    coupling_ops[c_false[i]].push_back(ops.set_false);
    coupling_ops[c_y[i]].push_back(ops.y);
    coupling_ops[c_z[i]].push_back(ops.z);
    place(place_variable_gadget(canvas, row, ops, mutation));
  }
  // Clause gadgets. The operation of literal l is performed when l becomes
  // false: it joins x:F for l = x and x:T for l = ~x.
  for (size_t h = 0; h < m; ++h) {
    const std::string prefix = "C" + std::to_string(h + 1) + ".";
    std::vector<std::string> lit_ops;
    for (int lit : f.clauses[h]) {
      std::string name = prefix + literal_name(lit);
      while (std::find(lit_ops.begin(), lit_ops.end(), name) != lit_ops.end()) name += "'";
      lit_ops.push_back(name);
      auto i = static_cast<size_t>(var_of(lit) - 1);
      coupling_ops[lit > 0 ? c_false[i] : c_true[i]].push_back(name);
    }
    std::string release = prefix + "u";
    coupling_ops[c_u[h]].push_back(release);
    place(place_clause_gadget(canvas, row, lit_ops, release, mutation));
  }
  // Order gadgets along the chain; in the continuous model the link
  // y_n < z_1 (k = n - 1) is a separation gadget.
  const size_t separated_link = model == ReductionModel::Continuous && n >= 1 ? static_cast<size_t>(n - 1) : SIZE_MAX;
  std::vector<size_t> chain;
  for (size_t i = 0; i < c_y.size(); ++i) chain.push_back(c_y[i]);
  for (size_t i = 0; i < c_z.size(); ++i) chain.push_back(c_z[i]);
  for (size_t h = 0; h < m; ++h) chain.push_back(c_u[h]);
  for (size_t k = 0; k + 1 < chain.size(); ++k) {
    const std::string prefix = "O" + std::to_string(k + 1) + ".";
    std::string first = prefix + coupling_names[chain[k]], second = prefix + coupling_names[chain[k + 1]];
    coupling_ops[chain[k]].push_back(first);
    coupling_ops[chain[k + 1]].push_back(second);
    if (k == separated_link) place(place_separation_gadget(canvas, row, first, second, mutation));
    else place(place_order_gadget(canvas, row, first, second, mutation));
  }
  // The spine: rows 0 .. last used row (a single node for an empty formula).
  const int64_t top = std::max<int64_t>(row - 2, 0);
  canvas.path({kSpineX, 0}, {kSpineX, top});
  canvas.anchor({kSpineX, 0});
  for (size_t q = 0; q < coupling_names.size(); ++q)
    if (!coupling_ops[q].empty()) canvas.couple(coupling_names[q], coupling_ops[q]);

  out.instance = canvas.build();
  const Instance& inst = out.instance;
  auto id = [&](size_t q) { return inst.find_coupling(coupling_names[q]); };
  for (int v = 0; v < n; ++v) {
    auto i = static_cast<size_t>(v);
    out.set_true.push_back(id(c_true[i]));
    out.set_false.push_back(id(c_false[i]));
    out.y.push_back(id(c_y[i]));
    out.z.push_back(id(c_z[i]));
  }
  for (size_t h = 0; h < m; ++h) out.release.push_back(id(c_u[h]));

  CompileStats& s = out.stats;
  s.nodes = inst.num_nodes();
  s.edges = inst.edges().size();
  s.ops = inst.ops().size();
  s.couplings = inst.couplings().size();
  s.variable_gadgets = static_cast<size_t>(n);
  s.clause_gadgets = m;
  s.separation_gadgets = separated_link != SIZE_MAX ? 1 : 0;
  s.order_gadgets = (chain.empty() ? 0 : chain.size() - 1) - s.separation_gadgets;
  for (const Operation& op : inst.ops()) s.vertical_ops += !is_horizontal(op.dir);
  s.rows = static_cast<size_t>(top + 1);
  s.literals = num_literals(f);
  for (const Coupling& q : inst.couplings()) {
    if (q.ops.size() > s.max_coupling) {
      s.max_coupling = q.ops.size();
      s.max_coupling_name = q.name;
    }
    if (q.ops.size() > 3) {
      std::string what = q.name;
      if (q.name.size() > 2 && q.name[q.name.size() - 2] == ':') {
        std::string v = q.name.substr(0, q.name.size() - 2);
        what = "literal " + (q.name.back() == 'T' ? "~" + v : v) + " occurs " + std::to_string(q.ops.size() - 1) +
               " times: coupling " + q.name;
      }
      s.oversize.push_back(what + " has " + std::to_string(q.ops.size()) + " operations");
    }
  }
  return out;
}

std::vector<CouplingId> schedule_from_assignment(const CompiledFormula& c, const std::vector<bool>& value) {
  if (value.size() <= static_cast<size_t>(c.num_vars))
    throw std::invalid_argument("schedule_from_assignment: assignment has too few variables");
  std::vector<CouplingId> order;
  order.reserve(c.instance.couplings().size());
  const auto n = static_cast<size_t>(c.num_vars);
  for (size_t i = 0; i < n; ++i) order.push_back(value[i + 1] ? c.set_true[i] : c.set_false[i]);
  order.insert(order.end(), c.y.begin(), c.y.end());
  order.insert(order.end(), c.z.begin(), c.z.end());
  order.insert(order.end(), c.release.begin(), c.release.end());
  for (size_t i = 0; i < n; ++i) order.push_back(value[i + 1] ? c.set_false[i] : c.set_true[i]);
  return order;
}

std::vector<bool> assignment_from_schedule(const CompiledFormula& c, const std::vector<CouplingId>& order) {
  const size_t k = c.instance.couplings().size();
  if (order.size() != k) throw std::invalid_argument("assignment_from_schedule: not a full order");
  std::vector<size_t> pos(k, k);
  for (size_t i = 0; i < order.size(); ++i) {
    if (order[i] >= k || pos[order[i]] != k) throw std::invalid_argument("assignment_from_schedule: not a permutation");
    pos[order[i]] = i;
  }
  std::vector<bool> value(static_cast<size_t>(c.num_vars) + 1, false);
  for (size_t i = 0; i < static_cast<size_t>(c.num_vars); ++i) value[i + 1] = pos[c.set_true[i]] < pos[c.set_false[i]];
  return value;
}

Schedule times_from_assignment(const CompiledFormula& c, const std::vector<bool>& value) {
  if (value.size() <= static_cast<size_t>(c.num_vars))
    throw std::invalid_argument("times_from_assignment: assignment has too few variables");
  Schedule s;
  s.start.assign(c.instance.couplings().size(), Rational(2));
  for (size_t i = 0; i < static_cast<size_t>(c.num_vars); ++i) {
    s.start[value[i + 1] ? c.set_true[i] : c.set_false[i]] = Rational(0);
    s.start[c.y[i]] = Rational(1);
  }
  return s;
}

std::vector<bool> assignment_from_times(const CompiledFormula& c, const Schedule& s) {
  if (s.start.size() != c.instance.couplings().size())
    throw std::invalid_argument("assignment_from_times: not a start time per coupling");
  std::vector<bool> value(static_cast<size_t>(c.num_vars) + 1, false);
  if (c.num_vars == 0) return value;
  const Rational& yn = s.start[c.y.back()];
  for (size_t i = 0; i < static_cast<size_t>(c.num_vars); ++i) value[i + 1] = s.start[c.set_true[i]] <= yn;
  return value;
}

std::vector<std::string> describe_compiled(const CompiledFormula& c) {
  const CompileStats& s = c.stats;
  std::vector<std::string> lines;
  lines.push_back("instance: " + std::to_string(s.nodes) + " nodes, " + std::to_string(s.edges) + " edges, " +
                  std::to_string(s.ops) + " operations (" +
                  (s.vertical_ops ? "expansions, " + std::to_string(s.vertical_ops) + " of them vertical"
                                  : std::string("horizontal expansions")) +
                  "), " + std::to_string(s.couplings) + " couplings, " + std::to_string(s.rows) + " rows");
  lines.push_back("model: " + std::string(reduction_model_name(c.model)) + " time" +
                  (c.model == ReductionModel::Continuous ? " (the link y_n < z_1 is a separation gadget)" : ""));
  lines.push_back("gadgets: " + std::to_string(s.variable_gadgets) + " variable, " + std::to_string(s.clause_gadgets) +
                  " clause, " + std::to_string(s.order_gadgets) + " order" +
                  (c.model == ReductionModel::Continuous ? ", " + std::to_string(s.separation_gadgets) + " separation"
                                                         : std::string()));
  if (c.num_vars >= 1) {
    const auto n = static_cast<long long>(c.num_vars), m = static_cast<long long>(c.num_clauses),
               L = static_cast<long long>(s.literals);
    const bool cont = c.model == ReductionModel::Continuous;
    lines.push_back("size formulas (n=" + std::to_string(n) + ", m=" + std::to_string(m) + ", L=" + std::to_string(L) +
                    "): nodes " +
                    (cont ? "43n+5L+15m-9 = " + std::to_string(43 * n + 5 * L + 15 * m - 9)
                          : "43n+5L+15m-11 = " + std::to_string(43 * n + 5 * L + 15 * m - 11)) +
                    ", operations 8n+L+3m-2 = " + std::to_string(8 * n + L + 3 * m - 2) +
                    ", couplings 4n+m = " + std::to_string(4 * n + m));
  }
  lines.push_back("largest coupling: " + s.max_coupling_name + " with " + std::to_string(s.max_coupling) +
                  " operations" + (s.max_coupling <= 3 ? " (at most 3, as the paper's theorem needs)" : ""));
  for (const auto& o : s.oversize) lines.push_back("coupling above 3: " + o);
  return lines;
}

}  // namespace gridlock
