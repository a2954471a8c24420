// The solver reports progress through SolveOptions::on_progress and never
// draws itself: a listener sees search-node reports with growing counts,
// activity reports, and one finished report last; without a listener
// nothing is reported. A real solve of a random instance with a listener
// gives the same answer as without one.
#include <gtest/gtest.h>

#include <chrono>
#include <thread>
#include <vector>

#include "lattice/random_instance.hpp"
#include "solver/internal/search.hpp"
#include "solver/solve.hpp"

namespace gridlock {
namespace {

TEST(SolveProgress, ReportsThroughTheCallbackAndFinishesLast) {
  std::vector<SolveProgress> seen;
  SolveOptions opt;
  opt.on_progress = [&](const SolveProgress& p) { seen.push_back(p); };
  SearchBudget budget(opt);
  SolveStats st;
  budget.tick(st);  // before 0.5 s: nothing yet
  EXPECT_TRUE(seen.empty());
  std::this_thread::sleep_for(std::chrono::milliseconds(550));
  budget.set_depth(3);
  budget.tick(st);
  ASSERT_EQ(seen.size(), 1U);
  EXPECT_EQ(seen[0].states, 2U);
  EXPECT_EQ(seen[0].depth, 3U);
  EXPECT_GE(seen[0].seconds, 0.5);
  EXPECT_EQ(seen[0].activity, nullptr);
  EXPECT_FALSE(seen[0].finished);
  budget.show_activity("an external solver");  // within 0.5 s of the last report: skipped
  EXPECT_EQ(seen.size(), 1U);
  std::this_thread::sleep_for(std::chrono::milliseconds(550));
  budget.show_activity("an external solver");
  ASSERT_EQ(seen.size(), 2U);
  EXPECT_STREQ(seen[1].activity, "an external solver");
  budget.clear_progress();
  ASSERT_EQ(seen.size(), 3U);
  EXPECT_TRUE(seen[2].finished);
  budget.clear_progress();  // once only
  EXPECT_EQ(seen.size(), 3U);
}

TEST(SolveProgress, NoListenerNoReportAndSameAnswers) {
  SolveOptions quiet;
  SearchBudget budget(quiet);
  budget.clear_progress();  // nothing reported: nothing to finish, no listener to call
  for (uint64_t seed = 1; seed <= 40; ++seed) {
    RandomInstanceParams p;
    p.nodes = 12;
    const Instance inst = random_instance(p, seed);
    SolveOptions listened;
    listened.on_progress = [](const SolveProgress&) {};
    const SolveResult a = solve_discrete(inst, quiet), b = solve_discrete(inst, listened);
    EXPECT_EQ(a.status, b.status) << "seed " << seed;
    EXPECT_EQ(a.order, b.order) << "seed " << seed;
  }
}

}  // namespace
}  // namespace gridlock
