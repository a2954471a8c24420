#include "reductions/compile.hpp"

#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <utility>

#include "common/assert.hpp"
#include "gadgets/internal/canvas.hpp"
#include "gadgets/internal/clause_gadget.hpp"
#include "gadgets/internal/order_gadget.hpp"
#include "gadgets/internal/separation_gadget.hpp"
#include "gadgets/internal/variable_gadget.hpp"

namespace gridlock {

namespace {

constexpr int64_t kSpineX = -2;

std::string var_name(int v) { return "x" + std::to_string(v); }
std::string literal_name(int lit) { return (lit < 0 ? "~" : "") + var_name(var_of(lit)); }

}  // namespace

uint64_t compiled_node_count(const Formula& f, TimeModel model) {
  if (f.num_vars < 1) return 0;
  uint64_t literals = 0;
  for (const auto& c : f.clauses) literals += c.size();
  const auto n = static_cast<uint64_t>(f.num_vars), m = static_cast<uint64_t>(f.clauses.size());
  // The continuous reduction's separation gadget has two nodes more than
  // the order gadget it replaces.
  return 43 * n + 5 * literals + 15 * m - (model == TimeModel::Continuous ? 9 : 11);
}

namespace {

// The couplings of the compiled instance as names and operation names,
// indexed in the order they are created (the order canvas.couple sees them):
// x_v:T and x_v:F per variable, then y_v, then z_v, then u_h per clause.
// The gadgets add the operations.
struct CouplingPlan {
  std::vector<std::string> names;
  std::vector<std::vector<std::string>> ops;
  std::vector<size_t> c_true, c_false, c_y, c_z, c_u;  // by variable - 1, by clause
  size_t add(const std::string& name) {
    names.push_back(name);
    ops.emplace_back().reserve(3);  // one gadget operation and two order links: one allocation
    return names.size() - 1;
  }
};

// The empty couplings of a formula of n variables and m clauses.
CouplingPlan plan_couplings(int n, size_t m) {
  CouplingPlan cp;
  cp.names.reserve(4 * static_cast<size_t>(n) + m);
  cp.ops.reserve(4 * static_cast<size_t>(n) + m);
  cp.c_true.resize(static_cast<size_t>(n)), cp.c_false = cp.c_y = cp.c_z = cp.c_true, cp.c_u.resize(m);
  for (int v = 1; v <= n; ++v) {
    auto i = static_cast<size_t>(v - 1);
    cp.c_true[i] = cp.add(var_name(v) + ":T");
    cp.c_false[i] = cp.add(var_name(v) + ":F");
  }
  for (int v = 1; v <= n; ++v) cp.c_y[static_cast<size_t>(v - 1)] = cp.add("y" + std::to_string(v));
  for (int v = 1; v <= n; ++v) cp.c_z[static_cast<size_t>(v - 1)] = cp.add("z" + std::to_string(v));
  for (size_t h = 0; h < m; ++h) cp.c_u[h] = cp.add("u" + std::to_string(h + 1));
  return cp;
}

// Stacks gadgets bottom to top: place() joins a placed gadget's attach node
// to the spine by an arm, records it in gadgets, and moves row past it
// (one empty row between gadgets); row is where the next gadget goes.
struct GadgetStack {
  Canvas& canvas;
  std::vector<GadgetPlacement>& gadgets;
  int64_t row = 0;
  void place(GadgetPlacement p) {  // taken by value: the contract's names are moved, not copied
    // Arm from the spine to the attach node.
    canvas.node({-1, p.attach_row});
    canvas.edge({kSpineX, p.attach_row}, {-1, p.attach_row});
    canvas.edge({-1, p.attach_row}, {0, p.attach_row});
    row = p.top_row + 2;  // one empty row between gadgets
    gadgets.push_back(std::move(p));
  }
};

// One variable gadget per variable, its operations x_v.T, x_v.F, x_v.y,
// x_v.z joining x_v:T, x_v:F, y_v, z_v.
void place_variable_gadgets(GadgetStack& stack, CouplingPlan& cp, int n, Mutation mutation) {
  for (int v = 1; v <= n; ++v) {
    auto i = static_cast<size_t>(v - 1);
    VariableOps ops{var_name(v) + ".T", var_name(v) + ".F", var_name(v) + ".y", var_name(v) + ".z"};
    cp.ops[cp.c_true[i]].push_back(ops.set_true);
    cp.ops[cp.c_false[i]].push_back(ops.set_false);
    cp.ops[cp.c_y[i]].push_back(ops.y);
    cp.ops[cp.c_z[i]].push_back(ops.z);
    stack.place(place_variable_gadget(stack.canvas, stack.row, ops, mutation));
  }
}

// One clause gadget per clause. The operation of literal l is performed when
// l becomes false: it joins x:F for l = x and x:T for l = ~x; the release
// C_h.u joins u_h.
void place_clause_gadgets(GadgetStack& stack, CouplingPlan& cp, const Formula& f, Mutation mutation) {
  for (size_t h = 0; h < f.clauses.size(); ++h) {
    const std::string prefix = "C" + std::to_string(h + 1) + ".";
    std::vector<std::string> lit_ops;
    for (int lit : f.clauses[h]) {
      std::string name = prefix + literal_name(lit);
      while (std::find(lit_ops.begin(), lit_ops.end(), name) != lit_ops.end()) name += "'";
      lit_ops.push_back(name);
      auto i = static_cast<size_t>(var_of(lit) - 1);
      cp.ops[lit > 0 ? cp.c_false[i] : cp.c_true[i]].push_back(name);
    }
    std::string release = prefix + "u";
    cp.ops[cp.c_u[h]].push_back(release);
    stack.place(place_clause_gadget(stack.canvas, stack.row, lit_ops, release, mutation));
  }
}

// Order gadgets along the chain y_1 .. y_n, z_1 .. z_n, u_1 .. u_m, link k
// (0-based) ordering chain[k] before chain[k + 1]; link separated_link
// (SIZE_MAX: none) is a separation gadget instead. Returns the chain's length.
size_t place_order_chain(GadgetStack& stack, CouplingPlan& cp, size_t separated_link, Mutation mutation) {
  std::vector<size_t> chain;
  for (size_t i = 0; i < cp.c_y.size(); ++i) chain.push_back(cp.c_y[i]);
  for (size_t i = 0; i < cp.c_z.size(); ++i) chain.push_back(cp.c_z[i]);
  for (size_t h = 0; h < cp.c_u.size(); ++h) chain.push_back(cp.c_u[h]);
  for (size_t k = 0; k + 1 < chain.size(); ++k) {
    const std::string prefix = "O" + std::to_string(k + 1) + ".";
    std::string first = prefix + cp.names[chain[k]], second = prefix + cp.names[chain[k + 1]];
    cp.ops[chain[k]].push_back(first);
    cp.ops[chain[k + 1]].push_back(second);
    if (k == separated_link) stack.place(place_separation_gadget(stack.canvas, stack.row, first, second, mutation));
    else stack.place(place_order_gadget(stack.canvas, stack.row, first, second, mutation));
  }
  return chain.size();
}

// Fills out.stats from out.instance, the formula, the separated link (as in
// place_order_chain), the chain's length and the spine's top row.
void fill_stats(CompiledFormula& out, const Formula& f, size_t separated_link, size_t chain_size, int64_t top) {
  const Instance& inst = out.instance;
  CompileStats& s = out.stats;
  s.nodes = inst.num_nodes();
  s.edges = inst.edges().size();
  s.ops = inst.ops().size();
  s.couplings = inst.couplings().size();
  s.variable_gadgets = static_cast<size_t>(f.num_vars);
  s.clause_gadgets = f.clauses.size();
  s.separation_gadgets = separated_link != SIZE_MAX ? 1 : 0;
  s.order_gadgets = (chain_size == 0 ? 0 : chain_size - 1) - s.separation_gadgets;
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
}

}  // namespace

std::string empty_clause_message(size_t h) {
  return "clause " + std::to_string(h + 1) + " is empty; the reduction needs at least one literal per clause";
}

CompiledFormula compile_formula(const Formula& f, Mutation mutation, TimeModel model) {
  if (auto e = validate(f); !e.empty()) throw std::invalid_argument("compile: " + e);
  if (uint64_t nodes = compiled_node_count(f, model); nodes > static_cast<uint64_t>(kMaxNodes))
    throw std::invalid_argument("the compiled instance would have " + std::to_string(nodes) +
                                " nodes (43n + 5L + 15m - 11), more than the .grid format's limit of " +
                                std::to_string(kMaxNodes));
  for (size_t h = 0; h < f.clauses.size(); ++h)
    if (f.clauses[h].empty()) throw std::invalid_argument(empty_clause_message(h));
  const int n = f.num_vars;
  const size_t m = f.clauses.size();

  Canvas canvas;
  CompiledFormula out;
  out.num_vars = n;
  out.num_clauses = m;
  out.model = model;
  CouplingPlan cp = plan_couplings(n, m);
  out.gadgets.reserve(3 * static_cast<size_t>(n) + 2 * m);  // n + m gadgets and 2n + m - 1 links
  // A tree: as many edges (plain and expansions) as nodes, less one.
  canvas.reserve(static_cast<size_t>(compiled_node_count(f, model)));
  GadgetStack stack{canvas, out.gadgets};
  place_variable_gadgets(stack, cp, n, mutation);
  place_clause_gadgets(stack, cp, f, mutation);
  // In the continuous model the link y_n < z_1 (k = n - 1) is a separation gadget.
  const size_t separated_link = model == TimeModel::Continuous && n >= 1 ? static_cast<size_t>(n - 1) : SIZE_MAX;
  const size_t chain_size = place_order_chain(stack, cp, separated_link, mutation);
  // The spine: rows 0 .. last used row (a single node for an empty formula).
  const int64_t top = std::max<int64_t>(stack.row - 2, 0);
  canvas.path({kSpineX, 0}, {kSpineX, top});
  canvas.anchor({kSpineX, 0});
  for (size_t q = 0; q < cp.names.size(); ++q)
    if (!cp.ops[q].empty()) canvas.couple(cp.names[q], std::move(cp.ops[q]));  // cp.ops is not read again

  out.instance = canvas.build();
  const Instance& inst = out.instance;
  auto id = [&](size_t q) { return inst.find_coupling(cp.names[q]); };
  for (int v = 0; v < n; ++v) {
    auto i = static_cast<size_t>(v);
    out.set_true.push_back(id(cp.c_true[i]));
    out.set_false.push_back(id(cp.c_false[i]));
    out.y.push_back(id(cp.c_y[i]));
    out.z.push_back(id(cp.c_z[i]));
  }
  for (size_t h = 0; h < m; ++h) out.release.push_back(id(cp.c_u[h]));
  fill_stats(out, f, separated_link, chain_size, top);
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
  GRIDLOCK_REQUIRE(order.size() == k, "assignment_from_schedule: not a full order");
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

}  // namespace gridlock
