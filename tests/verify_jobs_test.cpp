// --jobs N of fuzz, verify and gen-instances through the real command line:
// the output (JSON, table, c lines, manifests, reproducers, shrunk findings,
// exit code) is byte-identical for 1, 2 and 4 workers apart from timings,
// and a signal with several workers still leaves a complete partial summary.
#include <gtest/gtest.h>
#include <signal.h>

#include <chrono>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>
#include <string>
#include <thread>

#include "support/cli.hpp"
#include "support/test_scale.hpp"

namespace gridlock {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const std::string kExamples = std::string(GRIDLOCK_SOURCE_DIR) + "/examples/formulas";

// Every file under dir (relative path -> content), the folder's own name
// replaced by DIR inside the texts (reproducers name their folder).
std::map<std::string, std::string> folder_files(const std::string& dir) {
  std::map<std::string, std::string> files;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    if (!e.is_regular_file()) continue;
    std::string text = test::read_file(e.path().string());
    for (size_t at = text.find(dir); at != std::string::npos; at = text.find(dir, at))
      text.replace(at, dir.size(), "DIR");
    files[fs::relative(e.path(), dir).string()] = text;
  }
  return files;
}

// j without its timings (keys "seconds" and "ms_*", at any depth).
json without_timings(json j) {
  if (j.is_object()) {
    json out = json::object();
    for (auto& [k, v] : j.items())
      if (k != "seconds" && k.rfind("ms_", 0) != 0) out[k] = without_timings(v);
    return out;
  }
  if (j.is_array())
    for (auto& v : j) v = without_timings(v);
  return j;
}

std::string replace_all(std::string s, const std::string& from, const std::string& to) {
  for (size_t at = s.find(from); at != std::string::npos; at = s.find(from, at + to.size()))
    s.replace(at, from.size(), to);
  return s;
}

TEST(VerifyJobs, FuzzFindingsAndJsonAreTheSameForEveryNumberOfWorkers) {
  const std::string seed = std::to_string(test::base_seed(7));
  const std::string count = std::to_string(test::scaled(150));
  std::string first_json, first_text;
  std::map<std::string, std::string> first_files;
  for (const std::string jobs : {"1", "2", "4"}) {
    const std::string dir = test::temp_dir() + "/found";
    const std::vector<std::string> args = {"fuzz",         "--seed",       seed,         "--count",    count,
                                           "--jobs",       jobs,           "--out",      dir,          "--break-gadget",
                                           "clause-loose", "--keep-going", "--json-out", dir + ".json"};
    auto r = test::run_gridlock(args);
    ASSERT_EQ(r.exit_code, 1) << "the broken gadget must be found, seed " << seed << "\n" << r.err;
    const std::string j = without_timings(json::parse(test::read_file(dir + ".json"))).dump();
    const std::string text = std::regex_replace(replace_all(r.out, dir, "DIR"), std::regex("/s, (.*), [0-9]+ s\n"),
                                                "/s, $1\n");
    const auto files = folder_files(dir);
    if (jobs == "1") {
      first_json = replace_all(j, dir, "DIR");
      first_text = std::regex_replace(text, std::regex(" [0-9]+/s"), "");
      first_files = files;
      EXPECT_GT(files.size(), 5u);
      continue;
    }
    EXPECT_EQ(replace_all(j, dir, "DIR"), first_json) << "--jobs " << jobs << ", seed " << seed;
    EXPECT_EQ(std::regex_replace(text, std::regex(" [0-9]+/s"), ""), first_text) << "--jobs " << jobs;
    EXPECT_EQ(files, first_files) << "--jobs " << jobs << ", seed " << seed;
  }
}

// Without --keep-going the campaign ends at the first disagreement, whichever
// worker is ahead: the same finding and the same count.
TEST(VerifyJobs, FuzzStopsAtTheSameFirstDisagreement) {
  std::string first;
  for (const std::string jobs : {"1", "2", "4"}) {
    const std::string dir = test::temp_dir() + "/found";
    auto r = test::run_gridlock({"fuzz", "--seed", "3", "--count", "400", "--jobs", jobs, "--out", dir,
                                 "--break-gadget", "order-loose", "--json"});
    ASSERT_EQ(r.exit_code, 1) << r.err;
    const std::string j = replace_all(without_timings(json::parse(r.out)).dump(), dir, "DIR");
    if (jobs == "1") first = j;
    else EXPECT_EQ(j, first) << "--jobs " << jobs;
  }
  EXPECT_EQ(json::parse(first)["findings"].size(), 1u);
}

// Timings stripped: the table's ms column and the summary's seconds.
std::string verify_table(const std::string& out) {
  return std::regex_replace(std::regex_replace(out, std::regex("  [0-9./]+(  DISAGREE|\n)"), "$1"),
                            std::regex("; [0-9.]+ s\n"), "\n");
}

TEST(VerifyJobs, VerifyTableJsonAndReproducersAreTheSameForEveryNumberOfWorkers) {
  std::string first_table, first_json;
  std::map<std::string, std::string> first_files;
  for (const std::string jobs : {"1", "2", "4"}) {
    const std::string dir = test::temp_dir();
    // A broken gadget: some formulas disagree, each with a reproducer.
    auto r = test::run_gridlock({"verify", kExamples, "--jobs", jobs, "--break-gadget", "clause-loose", "--reproducers",
                                 dir + "/rep", "--json-out", dir + "/v.json"});
    ASSERT_EQ(r.exit_code, 1) << r.err;
    const std::string table = replace_all(verify_table(r.out), dir, "DIR");
    const std::string j = replace_all(without_timings(json::parse(test::read_file(dir + "/v.json"))).dump(), dir,
                                      "DIR");
    const auto files = folder_files(dir + "/rep");
    if (jobs == "1") {
      first_table = table;
      first_json = j;
      first_files = files;
      EXPECT_NE(table.find("DISAGREE"), std::string::npos) << table;
      continue;
    }
    EXPECT_EQ(table, first_table) << "--jobs " << jobs;
    EXPECT_EQ(j, first_json) << "--jobs " << jobs;
    EXPECT_EQ(files, first_files) << "--jobs " << jobs;
  }
}

TEST(VerifyJobs, GenInstancesWritesTheSameSetForEveryNumberOfWorkers) {
  const std::string seed = std::to_string(test::base_seed(5));
  for (const std::vector<std::string>& extra :
       {std::vector<std::string>{"--threshold", "8", "--lsat", "4"},
        std::vector<std::string>{"--threshold", "10", "--lsat", "0", "--yes", "3", "--no", "3"}}) {
    std::string first_out;
    std::map<std::string, std::string> first_files;
    for (const std::string jobs : {"1", "2", "4"}) {
      const std::string dir = test::temp_dir() + "/set";
      std::vector<std::string> args = {"gen-instances", "-o", dir, "--vars", "8", "--seed", seed, "--jobs", jobs};
      args.insert(args.end(), extra.begin(), extra.end());
      auto r = test::run_gridlock(args);
      ASSERT_EQ(r.exit_code, 0) << r.err;
      const std::string out = replace_all(r.out, dir, "DIR");
      const auto files = folder_files(dir);
      if (jobs == "1") {
        first_out = out;
        first_files = files;
        EXPECT_TRUE(first_files.count("manifest.json"));
        continue;
      }
      EXPECT_EQ(out, first_out) << "--jobs " << jobs << ", seed " << seed;
      EXPECT_EQ(files, first_files) << "--jobs " << jobs << ", seed " << seed;
    }
  }
}

// SIGINT / SIGTERM with four workers: a complete partial summary.
TEST(VerifyJobs, SignalsWithSeveralWorkersLeaveACompletePartialSummary) {
  const std::string dir = test::temp_dir();
  {
    auto p = test::start_gridlock({"fuzz", "--json", "--jobs", "4", "--count", "100000000", "--out", dir + "/f"});
    std::this_thread::sleep_for(std::chrono::milliseconds(1500));
    kill(p.pid, SIGINT);
    auto r = test::finish_gridlock(p);
    EXPECT_EQ(r.exit_code, 130) << r.err;
    const json j = json::parse(r.out);
    EXPECT_EQ(j["interrupted"], true);
    EXPECT_GT(j["formulas"].get<uint64_t>(), 0u);
    EXPECT_LT(j["formulas"].get<uint64_t>(), 100000000u);
    EXPECT_EQ(j["sat"].get<uint64_t>() + j["unsat"].get<uint64_t>(), j["formulas"].get<uint64_t>());
  }
  {
    auto p = test::start_gridlock({"verify", "--json", "--jobs", "4",
                                   std::string(GRIDLOCK_DATA_DIR) + "/satlib/uf50-218", "--reproducers", dir + "/v"});
    std::this_thread::sleep_for(std::chrono::milliseconds(2000));
    kill(p.pid, SIGTERM);
    auto r = test::finish_gridlock(p);
    EXPECT_EQ(r.exit_code, 143) << r.err;
    const json j = json::parse(r.out);
    EXPECT_EQ(j["interrupted"], true);
    EXPECT_EQ(j["exit_code"], 143);
    EXPECT_LT(j["summary"]["formulas"].get<size_t>(), j["inputs"].get<size_t>());
    ASSERT_EQ(j["formulas"].size(), j["summary"]["formulas"].get<size_t>());
    for (size_t k = 0; k < j["formulas"].size(); ++k) EXPECT_EQ(j["formulas"][k]["index"], k);  // a prefix, in order
  }
  {
    const std::string set = dir + "/set";
    auto p = test::start_gridlock(
        {"gen-instances", "-o", set, "--jobs", "4", "--vars", "30", "--threshold", "400", "--lsat", "0"});
    std::this_thread::sleep_for(std::chrono::milliseconds(2500));
    kill(p.pid, SIGINT);
    auto r = test::finish_gridlock(p);
    EXPECT_EQ(r.exit_code, 130) << r.err;
    const json m = json::parse(test::read_file(set + "/manifest.json"));
    EXPECT_EQ(m["interrupted"], true);
    std::set<std::string> listed, present;
    for (const auto& e : m["instances"]) listed.insert(e["instance"].get<std::string>());
    for (const auto& e : fs::directory_iterator(set)) {
      EXPECT_EQ(e.path().filename().string().find(".tmp"), std::string::npos) << e.path();
      if (e.path().extension() == ".grid") present.insert(e.path().filename().string());
    }
    EXPECT_EQ(listed, present);
    EXPECT_LT(listed.size(), 400u);
  }
}

}  // namespace
}  // namespace gridlock
