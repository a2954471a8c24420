// docs/model.md's worked cases: every claim the page makes about an instance
// under examples/instances/model-*.grid, checked with the exact simulator
// (all orders for discrete claims, a grid of start times for "every schedule"
// claims) and with find_collision for Colliding Schedule. Also checks that
// the page and the folder name the same instances.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

#include "collide/collide.hpp"
#include "lattice/schedule.hpp"
#include "lattice/simulate.hpp"
#include "support/instance_io.hpp"

namespace gridlock {
namespace {

Instance load(const std::string& name) { return test::load_example(name); }

std::optional<Collision> run_order(const Instance& inst, const std::vector<std::string>& names) {
  std::vector<CouplingId> order;
  auto err = parse_order(inst, names, "test", 0, order);
  EXPECT_FALSE(err);
  Simulator sim(inst);
  return sim.run_order(order).collision;
}

std::optional<Collision> run_times(const Instance& inst, const std::vector<std::pair<std::string, Rational>>& t) {
  Schedule s;
  s.start.assign(inst.couplings().size(), Rational(0));
  for (const auto& [name, v] : t) s.start[inst.find_coupling(name)] = v;
  Simulator sim(inst);
  return sim.run(s).collision;
}

// Start times of two couplings on a grid of quarters in [0, 3]: a "every
// schedule collides" claim must hold on each.
std::vector<std::pair<Rational, Rational>> start_grid() {
  std::vector<std::pair<Rational, Rational>> out;
  for (int a = 0; a <= 12; ++a)
    for (int b = 0; b <= 12; ++b) out.emplace_back(Rational(a, 4), Rational(b, 4));
  return out;
}

void expect_colliding_yes(const Instance& inst) {
  for (TimeModel m : {TimeModel::Discrete, TimeModel::Continuous}) {
    CollideResult r = find_collision(inst, m);
    EXPECT_TRUE(r.collides) << (m == TimeModel::Discrete ? "discrete" : "continuous");
  }
}

TEST(ModelDoc, Case1TwoGrowthsEveryScheduleCollides) {
  Instance inst = load("model-case1-two-growths.grid");
  for (const auto& order : {std::vector<std::string>{"g1", "g2"}, std::vector<std::string>{"g2", "g1"}}) {
    auto c = run_order(inst, order);
    ASSERT_TRUE(c);
    EXPECT_EQ(c->time, Rational(1));
  }
  for (const auto& [a, b] : start_grid()) {
    EXPECT_TRUE(run_times(inst, {{"g1", a}, {"g2", b}})) << a.str() << " " << b.str();
  }
  expect_colliding_yes(inst);
}

TEST(ModelDoc, Case2OrderGadget) {
  Instance inst = load("model-case2-order-gadget.grid");
  EXPECT_FALSE(run_order(inst, {"a", "b"}));
  auto c = run_order(inst, {"b", "a"});
  ASSERT_TRUE(c);
  EXPECT_EQ(c->kind, Collision::Kind::Node);
  EXPECT_EQ(c->time, Rational(0));
  EXPECT_FALSE(run_times(inst, {{"a", Rational(0)}, {"b", Rational(0)}}));
  expect_colliding_yes(inst);
}

TEST(ModelDoc, Case3BlockCoupledIsFree) {
  Instance inst = load("model-case3-block.grid");
  EXPECT_FALSE(run_order(inst, {"Q"}));
  EXPECT_FALSE(run_times(inst, {{"Q", Rational(0)}}));
  for (TimeModel m : {TimeModel::Discrete, TimeModel::Continuous}) EXPECT_FALSE(find_collision(inst, m).collides);
}

TEST(ModelDoc, Case4ContractionFreesTheCell) {
  Instance inst = load("model-case4-contract-then-grow.grid");
  EXPECT_FALSE(run_order(inst, {"c", "g"}));
  auto c = run_order(inst, {"g", "c"});
  ASSERT_TRUE(c);
  EXPECT_EQ(c->kind, Collision::Kind::Node);
  EXPECT_EQ(c->time, Rational(0));
  // Lock-step: the grown node follows the contracting node's far face.
  EXPECT_FALSE(run_times(inst, {{"c", Rational(0)}, {"g", Rational(0)}}));
  EXPECT_FALSE(run_times(inst, {{"c", Rational(0)}, {"g", Rational(1, 2)}}));
  auto early = run_times(inst, {{"c", Rational(1, 2)}, {"g", Rational(0)}});
  ASSERT_TRUE(early);
  EXPECT_EQ(early->time, Rational(0));
  expect_colliding_yes(inst);
}

TEST(ModelDoc, Case5PushIntoGrowthAtExactMoments) {
  Instance inst = load("model-case5-push-into-growth.grid");
  for (const auto& order : {std::vector<std::string>{"e", "g"}, std::vector<std::string>{"g", "e"}}) {
    auto c = run_order(inst, order);
    ASSERT_TRUE(c);
    EXPECT_EQ(c->kind, Collision::Kind::Node);
    EXPECT_EQ(c->time, Rational(1));
  }
  auto both = run_times(inst, {{"e", Rational(0)}, {"g", Rational(0)}});
  ASSERT_TRUE(both);
  EXPECT_EQ(both->time, Rational(1, 2));
  auto late_g = run_times(inst, {{"e", Rational(0)}, {"g", Rational(1, 2)}});
  ASSERT_TRUE(late_g);
  EXPECT_EQ(late_g->time, Rational(3, 4));
  auto late_e = run_times(inst, {{"e", Rational(1, 2)}, {"g", Rational(0)}});
  ASSERT_TRUE(late_e);
  EXPECT_EQ(late_e->time, Rational(3, 4));
  for (const auto& [a, b] : start_grid()) {
    EXPECT_TRUE(run_times(inst, {{"e", a}, {"g", b}})) << a.str() << " " << b.str();
  }
  expect_colliding_yes(inst);
}

// The page names exactly the model-*.grid files of examples/instances/, and
// each one has a test above (its number is one of the cases tested).
TEST(ModelDoc, PageAndInstancesAgree) {
  const std::filesystem::path root(GRIDLOCK_SOURCE_DIR);
  std::ifstream page(root / "docs" / "model.md");
  ASSERT_TRUE(page) << "docs/model.md is missing";
  std::stringstream text;
  text << page.rdbuf();
  std::set<std::string> named;
  const std::string body = text.str();
  const std::regex file_re(R"(model-case[0-9]+-[a-z0-9-]+\.grid)");
  for (auto it = std::sregex_iterator(body.begin(), body.end(), file_re); it != std::sregex_iterator(); ++it) {
    named.insert(it->str());
  }
  std::set<std::string> present;
  for (const auto& entry : std::filesystem::directory_iterator(root / "examples" / "instances")) {
    std::string name = entry.path().filename().string();
    if (name.rfind("model-case", 0) == 0) present.insert(name);
  }
  EXPECT_EQ(named, present);
  EXPECT_EQ(present.size(), 5U) << "a new worked case needs its test in this file";
}

}  // namespace
}  // namespace gridlock
