// The parallel campaigns (common/internal/ordered_pool.hpp, verify/campaign.hpp,
// verify/instance_set.hpp with jobs > 1), in process: the same seeded
// campaign gives the same events, tallies, findings and files with 1, 2 and
// 4 workers; a stop request with several workers leaves a consistent partial
// tally. These tests run no gridlock binary, so that the ThreadSanitizer
// build (scripts/test.sh) compiles only the libraries and this file.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "cnf/dimacs.hpp"
#include "common/internal/ordered_pool.hpp"
#include "common/limits.hpp"
#include "support/test_scale.hpp"
#include "verify/campaign.hpp"
#include "verify/instance_set.hpp"

namespace gridlock {
namespace {

const std::vector<unsigned> kJobs = {1, 2, 4};

// A stop request the test itself makes (what SIGINT does in the command
// line), cleared again whatever happens.
struct StopRequest {
  void request() { stop_signal().store(2); }
  ~StopRequest() { stop_signal().store(0); }
};

// --- the ordered pool itself --------------------------------------------------

// Work of uneven length (later items often finish first) is taken in order.
TEST(OrderedPool, TakesEveryResultInIndexOrder) {
  for (unsigned jobs : kJobs) {
    std::vector<uint64_t> taken;
    run_in_order(
        jobs, 200,
        [](uint64_t i, unsigned) -> std::optional<uint64_t> {
          std::this_thread::sleep_for(std::chrono::microseconds((i * 7919) % 300));
          return i * i;
        },
        [&](uint64_t i, uint64_t& r) {
          EXPECT_EQ(r, i * i);
          taken.push_back(i);
          return true;
        });
    ASSERT_EQ(taken.size(), 200u) << "jobs " << jobs;
    for (uint64_t i = 0; i < taken.size(); ++i) EXPECT_EQ(taken[i], i) << "jobs " << jobs;
  }
}

// Each worker index is used by one thread at a time (per-worker state needs
// no lock), and workers stay within a bounded window ahead of take.
TEST(OrderedPool, WorkerStateIsNeverShared) {
  for (unsigned jobs : kJobs) {
    std::vector<int> busy(jobs, 0);  // each touched only by its worker: a race would show under TSan
    std::atomic<uint64_t> taken{0}, furthest{0};
    run_in_order(
        jobs, 300,
        [&](uint64_t i, unsigned w) -> std::optional<int> {
          EXPECT_LT(w, jobs);
          EXPECT_EQ(busy[w]++, 0);
          uint64_t f = furthest.load();
          while (i > f && !furthest.compare_exchange_weak(f, i)) {
          }
          EXPECT_LT(i, taken.load() + 4 * uint64_t{jobs} + 1) << "worker ran beyond its window";
          --busy[w];
          return static_cast<int>(w);
        },
        [&](uint64_t i, int&) {
          taken = i + 1;
          return true;
        });
    EXPECT_EQ(taken.load(), 300u);
  }
}

// take returning false, and work returning nullopt, end the run there.
TEST(OrderedPool, TakeFalseAndNulloptEndTheRun) {
  for (unsigned jobs : kJobs) {
    uint64_t last = 0, n = 0;
    run_in_order(
        jobs, 1000, [](uint64_t i, unsigned) -> std::optional<uint64_t> { return i; },
        [&](uint64_t i, uint64_t&) {
          last = i;
          ++n;
          return i < 37;
        });
    EXPECT_EQ(last, 37u);
    EXPECT_EQ(n, 38u);
    n = 0;
    run_in_order(
        jobs, 1000,
        [](uint64_t i, unsigned) -> std::optional<uint64_t> {
          if (i >= 50) return std::nullopt;
          return i;
        },
        [&](uint64_t, uint64_t&) { return ++n > 0; });
    EXPECT_EQ(n, 50u) << "jobs " << jobs;
  }
}

// An exception of work(i) reaches the caller when item i's turn comes: the
// earlier items are all taken first.
TEST(OrderedPool, AWorkersExceptionComesInItsTurn) {
  for (unsigned jobs : kJobs) {
    uint64_t n = 0;
    EXPECT_THROW(run_in_order(
                     jobs, 1000,
                     [](uint64_t i, unsigned) -> std::optional<uint64_t> {
                       if (i == 20) throw std::runtime_error("item 20");
                       return i;
                     },
                     [&](uint64_t, uint64_t&) { return ++n > 0; }),
                 std::runtime_error);
    EXPECT_EQ(n, 20u) << "jobs " << jobs;
    n = 0;
    EXPECT_THROW(run_in_order(
                     jobs, 1000, [](uint64_t i, unsigned) -> std::optional<uint64_t> { return i; },
                     [&](uint64_t i, uint64_t&) {
                       if (i == 9) throw std::logic_error("take 9");
                       return ++n > 0;
                     }),
                 std::logic_error);
    EXPECT_EQ(n, 9u);
  }
}

// A stop request while take waits ends the run; results taken before it
// are all there.
TEST(OrderedPool, AStopRequestEndsTheRun) {
  for (unsigned jobs : {2u, 4u}) {
    StopRequest stop;
    uint64_t n = 0;
    run_in_order(
        jobs, 1'000'000,
        [](uint64_t, unsigned) -> std::optional<int> {
          if (stop_requested()) return std::nullopt;
          std::this_thread::sleep_for(std::chrono::microseconds(200));
          return 1;
        },
        [&](uint64_t i, int&) {
          if (i == 30) stop.request();
          return ++n > 0;
        });
    EXPECT_GE(n, 31u);
    EXPECT_LT(n, 31u + 4 * jobs + 1);
  }
}

TEST(OrderedPool, AvailableCoresIsAtLeastOne) { EXPECT_GE(available_cores(), 1u); }

// --- campaigns ------------------------------------------------------------------

FuzzCampaign seeded_fuzz(uint64_t seed, uint64_t count) {
  FuzzCampaign c;
  c.formulas.seed = seed;
  c.formulas.min_vars = 3;
  c.formulas.max_vars = 5;
  c.verify.solve_seconds = 30;
  c.verify.max_states = 2'000'000;
  c.last = count;
  return c;
}

// Everything a fuzz campaign reports, as text: events in order, then the tally.
std::string fuzz_record(const FuzzCampaign& c) {
  std::string rec;
  FuzzEvents ev;
  ev.disagreement = [&](uint64_t i, const VerifyResult& r) {
    rec += "disagree " + std::to_string(i) + ": " + r.problem + "\n";
  };
  ev.finding = [&](const FuzzFinding& f, const VerifyResult& shrunk) {
    rec += "finding " + std::to_string(f.index) + " in " + std::to_string(f.shrink.tries) + " tries: " + f.problem +
           "\n" + to_dimacs(f.shrunk) + to_dimacs(shrunk.lsat);
  };
  ev.progress = [&](const FuzzTally& t) { rec += "progress " + std::to_string(t.formulas) + "\n"; };
  const FuzzTally t = run_fuzz_campaign(c, ev);
  rec += "tally " + std::to_string(t.formulas) + " " + std::to_string(t.sat) + " " + std::to_string(t.unsat) + " " +
         std::to_string(t.unknown) + " " + std::to_string(t.certificates) + " " + std::to_string(t.no_certified) + " " +
         std::to_string(t.disagreements) + " " + std::to_string(t.findings.size()) +
         (t.interrupted ? " interrupted" : "") + "\n";
  for (const FuzzFinding& f : t.findings) rec += to_dimacs(f.original) + to_dimacs(f.shrunk);
  return rec;
}

TEST(ParallelFuzz, SameRecordForOneTwoAndFourWorkers) {
  const uint64_t seed = test::base_seed(11);
  FuzzCampaign c = seeded_fuzz(seed, static_cast<uint64_t>(test::scaled(60)) + 8);
  c.first = 1;  // a shard: every formula i with i % 2 == 1
  c.step = 2;
  std::string first;
  for (unsigned jobs : kJobs) {
    c.jobs = jobs;
    const std::string rec = fuzz_record(c);
    if (jobs == 1) first = rec;
    else EXPECT_EQ(rec, first) << "jobs " << jobs << ", seed " << seed;
  }
  EXPECT_NE(first.find("progress 1\n"), std::string::npos);
}

// A broken gadget makes formulas disagree: the findings (shrunk in the
// workers), the order they are reported in, and where a campaign without
// keep_going stops, are the same for every number of workers.
TEST(ParallelFuzz, FindingsAndFirstStopAreTheSameForEveryNumberOfWorkers) {
  const uint64_t seed = test::base_seed(3);
  for (bool keep_going : {true, false}) {
    FuzzCampaign c = seeded_fuzz(seed, 12);
    c.verify.mutation = Mutation::ClauseLoose;
    c.keep_going = keep_going;
    std::string first;
    for (unsigned jobs : kJobs) {
      c.jobs = jobs;
      const std::string rec = fuzz_record(c);
      if (jobs == 1) first = rec;
      else EXPECT_EQ(rec, first) << "jobs " << jobs << ", keep_going " << keep_going << ", seed " << seed;
    }
    EXPECT_NE(first.find("finding "), std::string::npos) << "the broken gadget was not found, seed " << seed;
  }
}

// A stop request in the middle of a campaign with several workers: the tally
// is marked interrupted and adds up (every formula counted was reported).
TEST(ParallelFuzz, AStopRequestLeavesAConsistentPartialTally) {
  for (unsigned jobs : {2u, 4u}) {
    StopRequest stop;
    FuzzCampaign c = seeded_fuzz(test::base_seed(8), 100000);
    c.jobs = jobs;
    uint64_t reported = 0;
    FuzzEvents ev;
    ev.progress = [&](const FuzzTally& t) {
      reported = t.formulas;
      if (t.formulas == 25) stop.request();
    };
    const FuzzTally t = run_fuzz_campaign(c, ev);
    EXPECT_TRUE(t.interrupted);
    EXPECT_GE(t.formulas, 25u);
    EXPECT_LT(t.formulas, 100000u);
    EXPECT_EQ(t.formulas, reported);
    EXPECT_EQ(t.sat + t.unsat, t.formulas);
  }
}

std::string verify_record(const std::vector<Formula>& formulas, const std::vector<std::string>& names,
                          const VerifyCampaign& c) {
  std::string rec;
  VerifyEvents ev;
  ev.start = [&](size_t i) { rec += "start " + std::to_string(i) + "\n"; };
  ev.result = [&](size_t i, const VerifyResult& r, FormulaStatus s) {
    rec += std::to_string(i) + " " + formula_status_name(s) + " " + verdict_name(r.sat) + " " +
           verdict_name(r.discrete) + " " + std::to_string(r.nodes) + " " + std::to_string(r.solver_states) + " " +
           std::to_string(r.witnesses_checked()) + " " + r.problem + "\n";
  };
  const VerifyTally t = run_verify_campaign(formulas, names, c, ev);
  rec += "tally " + std::to_string(t.formulas) + " " + std::to_string(t.agree) + " " + std::to_string(t.disagree) +
         " " + std::to_string(t.certificates) + " " + std::to_string(t.no_certified) + "\n";
  return rec;
}

TEST(ParallelVerify, SameRecordForOneTwoAndFourWorkers) {
  const uint64_t seed = test::base_seed(21);
  FuzzParams p;
  p.seed = seed;
  p.max_vars = 5;
  std::vector<Formula> formulas;
  std::vector<std::string> names;
  for (uint64_t i = 0; i < 30; ++i) {
    formulas.push_back(fuzz_formula(p, i));
    names.push_back("f" + std::to_string(i) + ".cnf");
  }
  VerifyCampaign c;
  c.verify.solve_seconds = 30;
  c.shard = {0, 1};
  std::string first;
  for (unsigned jobs : kJobs) {
    c.jobs = jobs;
    const std::string rec = verify_record(formulas, names, c);
    if (jobs == 1) first = rec;
    else EXPECT_EQ(rec, first) << "jobs " << jobs << ", seed " << seed;
  }
  EXPECT_NE(first.find("tally 30 30 0"), std::string::npos) << first;
}

// Every file gen-instances would write (name and text, in order), the
// events and the tally.
std::string set_record(const InstanceSetPlan& plan) {
  std::string rec;
  InstanceSetEvents ev;
  ev.labelling = [&](const std::string& name, const InstanceSetTally& t) {
    rec += "labelling " + name + " " + std::to_string(t.instances.size()) + "\n";
  };
  ev.skipped = [&](const std::string& name) { rec += "skipped " + name + "\n"; };
  ev.write = [&](const std::string& file, const std::string& text) { rec += "file " + file + "\n" + text; };
  ev.instance = [&](const SetInstance& e) { rec += "instance " + e.name + " " + std::to_string(e.index) + "\n"; };
  const InstanceSetTally t = make_instance_set(plan, ev);
  rec += "tally " + std::to_string(t.yes) + " " + std::to_string(t.no) + " " + std::to_string(t.skipped) + "\n";
  return rec;
}

TEST(ParallelInstanceSet, SameFilesForOneTwoAndFourWorkers) {
  InstanceSetPlan plan;
  plan.seed = test::base_seed(4);
  plan.vars = 6;
  plan.threshold = 6;
  plan.lsat = 3;
  plan.models = {TimeModel::Discrete};
  InstanceSetPlan mix = plan;  // drawn until 3 YES and 2 NO are kept
  mix.want_yes = 3;
  mix.want_no = 2;
  for (const InstanceSetPlan* base : {&plan, &mix}) {
    InstanceSetPlan pl = *base;
    std::string first;
    for (unsigned jobs : kJobs) {
      pl.jobs = jobs;
      const std::string rec = set_record(pl);
      if (jobs == 1) first = rec;
      else EXPECT_EQ(rec, first) << "jobs " << jobs << ", seed " << plan.seed << (pl.mix() ? ", mix" : "");
    }
    EXPECT_NE(first.find(".nocert\n"), std::string::npos) << "no NO instance, seed " << plan.seed;
  }
}

}  // namespace
}  // namespace gridlock
