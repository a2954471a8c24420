// Campaigns beyond one machine: the shards' --json-out files, combined by
// `gridlock merge`, equal the unsharded run field by field apart from times;
// the recipes (GNU parallel, locally and through --sshloginfile; the Slurm
// array script run by hand) produce mergeable shards.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "support/cli.hpp"

namespace gridlock {
namespace {

using nlohmann::json;
using test::run_gridlock;

const std::string kFormulas = std::string(GRIDLOCK_SOURCE_DIR) + "/examples/formulas/";

// Drops the fields that measure time (seconds, ms_*) at any depth.
json without_times(const json& j) {
  if (j.is_object()) {
    json out = json::object();
    for (const auto& [k, v] : j.items())
      if (k != "seconds" && k.rfind("ms_", 0) != 0) out[k] = without_times(v);
    return out;
  }
  if (j.is_array()) {
    json out = json::array();
    for (const auto& v : j) out.push_back(without_times(v));
    return out;
  }
  return j;
}

json read_json(const std::string& path) { return json::parse(test::read_file(path)); }

// Field by field, so that a failure names the field.
void expect_same(const json& unsharded, const json& merged) {
  json a = without_times(unsharded), b = without_times(merged);
  for (const auto& [k, v] : a.items()) EXPECT_EQ(v, b.value(k, json())) << "field " << k;
  for (const auto& [k, v] : b.items()) EXPECT_TRUE(a.contains(k)) << "extra field " << k;
}

TEST(Merge, FuzzFourShardsEqualUnsharded) {
  std::string dir = test::temp_dir();
  std::vector<std::string> common = {"fuzz",       "--seed", "11",           "--count", "60",
                                     "--max-vars", "5",      "--keep-going", "--out",   dir + "/fail"};
  auto whole = common;
  whole.push_back("--json");
  auto u = run_gridlock(whole);
  ASSERT_EQ(u.exit_code, 0) << u.err;
  std::vector<std::string> merge = {"merge", "-o", dir + "/merged.json"};
  for (int k = 0; k < 4; ++k) {
    auto a = common;
    a.insert(a.end(), {"--shard", std::to_string(k) + "/4", "--json-out", dir + "/s" + std::to_string(k) + ".json"});
    auto r = run_gridlock(a);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    merge.push_back(dir + "/s" + std::to_string(k) + ".json");
  }
  auto m = run_gridlock(merge);
  ASSERT_EQ(m.exit_code, 0) << m.err;
  json un = json::parse(u.out), me = read_json(dir + "/merged.json");
  EXPECT_EQ(un["formulas"], 60);
  expect_same(un, me);
}

// With a broken gadget every shard finds disagreements; the merged findings
// are the unsharded ones in index order, and merge exits 1 as fuzz does.
TEST(Merge, FuzzFindingsMergeInOrder) {
  std::string dir = test::temp_dir();
  std::vector<std::string> common = {
      "fuzz",           "--seed",       "3",     "--count",    "12", "--max-vars", "4", "--keep-going",
      "--break-gadget", "clause-loose", "--out", dir + "/fail"};
  auto whole = common;
  whole.insert(whole.end(), {"--json-out", dir + "/whole.json"});
  auto u = run_gridlock(whole);
  ASSERT_EQ(u.exit_code, 1) << u.err;
  std::vector<std::string> merge = {"merge", "-o", dir + "/merged.json"};
  for (int k = 0; k < 4; ++k) {
    auto a = common;
    a.insert(a.end(), {"--shard", std::to_string(k) + "/4", "--json-out", dir + "/s" + std::to_string(k) + ".json"});
    run_gridlock(a);
    merge.push_back(dir + "/s" + std::to_string(k) + ".json");
  }
  auto m = run_gridlock(merge);
  EXPECT_EQ(m.exit_code, 1) << m.err;
  json un = read_json(dir + "/whole.json"), me = read_json(dir + "/merged.json");
  EXPECT_GT(un["disagreements"].get<int>(), 1);
  expect_same(un, me);
  // Each finding's folder holds animations of its schedules beside the reproducer.
  for (const auto& f : un["findings"]) {
    const std::string folder = f["folder"].get<std::string>();
    bool any = false;
    for (const char* page : {"/sat-schedule.html", "/solver-schedule.html", "/all-false-schedule.html"})
      any = any || std::filesystem::exists(folder + page);
    EXPECT_TRUE(any) << "no animation in " << folder;
  }
}

TEST(Merge, VerifyFourShardsEqualUnsharded) {
  std::string dir = test::temp_dir();
  std::vector<std::string> common = {"verify",
                                     kFormulas + "tiny-sat.cnf",
                                     kFormulas + "tiny-unsat.cnf",
                                     kFormulas + "lsat-sat.cnf",
                                     kFormulas + "unsat-3cnf.cnf",
                                     kFormulas + "uf20-01.cnf",
                                     "--reproducers",
                                     dir + "/rep"};
  auto whole = common;
  whole.push_back("--json");
  auto u = run_gridlock(whole);
  ASSERT_EQ(u.exit_code, 0) << u.err;
  std::vector<std::string> merge = {"merge", "-o", dir + "/merged.json"};
  for (int k = 0; k < 4; ++k) {
    auto a = common;
    a.insert(a.end(), {"--shard", std::to_string(k) + "/4", "--json-out", dir + "/v" + std::to_string(k) + ".json"});
    auto r = run_gridlock(a);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    merge.push_back(dir + "/v" + std::to_string(k) + ".json");
  }
  auto m = run_gridlock(merge);
  ASSERT_EQ(m.exit_code, 0) << m.err;
  json un = json::parse(u.out), me = read_json(dir + "/merged.json");
  EXPECT_EQ(un["summary"]["formulas"], 5);
  expect_same(un, me);
}

TEST(Merge, GenInstancesThreeShardsEqualUnsharded) {
  std::string dir = test::temp_dir();
  std::vector<std::string> common = {
      "gen-instances",           "--vars", "6", "--threshold", "3", "--lsat", "2", "--seed", "3", "--formula",
      kFormulas + "tiny-sat.cnf"};
  auto whole = common;
  whole.insert(whole.end(), {"-o", dir + "/whole"});
  ASSERT_EQ(run_gridlock(whole).exit_code, 0);
  std::vector<std::string> merge = {"merge", "-o", dir + "/merged.json"};
  for (int k = 0; k < 3; ++k) {
    auto a = common;
    a.insert(a.end(), {"-o", dir + "/shared", "--shard", std::to_string(k) + "/3", "--json-out",
                       dir + "/g" + std::to_string(k) + ".json"});
    auto r = run_gridlock(a);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    merge.push_back(dir + "/g" + std::to_string(k) + ".json");
  }
  ASSERT_EQ(run_gridlock(merge).exit_code, 0);
  expect_same(read_json(dir + "/whole/manifest.json"), read_json(dir + "/merged.json"));
  // The shards share one folder: every instance file of the whole run is there.
  const json whole_manifest = read_json(dir + "/whole/manifest.json");  // outlives the loop
  for (const auto& e : whole_manifest["instances"])
    EXPECT_TRUE(std::filesystem::exists(dir + "/shared/" + e["instance"].get<std::string>())) << e["instance"];
}

TEST(Merge, IncompleteOrMixedShardsAreErrors) {
  std::string dir = test::temp_dir();
  for (int k = 0; k < 2; ++k)
    run_gridlock({"fuzz", "--seed", "1", "--count", "6", "--shard", std::to_string(k) + "/3", "--json-out",
                  dir + "/s" + std::to_string(k) + ".json"});
  run_gridlock({"fuzz", "--seed", "2", "--count", "6", "--shard", "2/3", "--json-out", dir + "/other.json"});
  auto missing = run_gridlock({"merge", dir + "/s0.json", dir + "/s1.json"});
  EXPECT_EQ(missing.exit_code, 1);
  EXPECT_NE(missing.err.find("gridlock: error: merge: shard 2/3 is missing"), std::string::npos) << missing.err;
  auto mixed = run_gridlock({"merge", dir + "/s0.json", dir + "/s1.json", dir + "/other.json"});
  EXPECT_EQ(mixed.exit_code, 1);
  EXPECT_NE(mixed.err.find("shards of different runs"), std::string::npos) << mixed.err;
  auto twice = run_gridlock({"merge", dir + "/s0.json", dir + "/s0.json"});
  EXPECT_NE(twice.err.find("given twice"), std::string::npos) << twice.err;
  test::write_file(dir + "/junk.json", "{not json");
  auto junk = run_gridlock({"merge", dir + "/junk.json"});
  EXPECT_EQ(junk.exit_code, 1);
  EXPECT_NE(junk.err.find("gridlock: error: " + dir + "/junk.json: not a JSON object"), std::string::npos) << junk.err;
}

// --- the recipes of docs/verify.md, run for real ---

int sh(const std::string& cmd) {
  int rc = std::system(cmd.c_str());
  return WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
}

void expect_merge_equals_unsharded(const std::string& dir, const std::string& glob) {
  auto u = run_gridlock({"fuzz", "--seed", "9", "--count", "40", "--keep-going", "--out", dir + "/u", "--json"});
  ASSERT_EQ(u.exit_code, 0) << u.err;
  ASSERT_EQ(sh(std::string(GRIDLOCK_BINARY) + " merge " + glob + " -o " + dir + "/merged.json 2>/dev/null"), 0);
  expect_same(json::parse(u.out), read_json(dir + "/merged.json"));
}

TEST(Recipes, GnuParallelLocallyAndThroughSshloginfile) {
  if (sh("command -v parallel >/dev/null 2>&1") != 0)
    GTEST_SKIP() << "GNU parallel is not installed (scripts/setup.sh installs it): recipe test skipped";
  std::string dir = test::temp_dir();
  const std::string g = GRIDLOCK_BINARY;
  ASSERT_EQ(sh("cd " + dir + " && parallel --will-cite " + g +
               " fuzz --seed 9 --count 40 --keep-going --shard {}/4 --out fail --json-out local-{}.json"
               " ::: 0 1 2 3 >/dev/null"),
            0);
  expect_merge_equals_unsharded(dir, dir + "/local-*.json");
  // Across hosts: the same command through --sshloginfile; ':' is this
  // machine (a real file lists user@host lines; the binary and the output
  // folder must then be on a shared file system, or use --return).
  test::write_file(dir + "/hosts", ":\n");
  ASSERT_EQ(sh("cd " + dir + " && parallel --will-cite --sshloginfile hosts --workdir . " + g +
               " fuzz --seed 9 --count 40 --keep-going --shard {}/4 --out fail --json-out " + dir +
               "/ssh-{}.json ::: 0 1 2 3 >/dev/null"),
            0);
  expect_merge_equals_unsharded(dir, dir + "/ssh-*.json");
}

TEST(Recipes, SlurmArrayScriptByHand) {
  std::string dir = test::temp_dir();
  const std::string script = std::string(GRIDLOCK_SOURCE_DIR) + "/examples/slurm-fuzz.sbatch";
  for (int k = 0; k < 4; ++k) {
    std::string cmd = "cd " + dir;
    cmd += " && GRIDLOCK=" GRIDLOCK_BINARY " SEED=9 COUNT=40 OUT=res SLURM_ARRAY_TASK_ID=" + std::to_string(k);
    cmd += " SLURM_ARRAY_TASK_COUNT=4 bash " + script + " >/dev/null";
    ASSERT_EQ(sh(cmd), 0);
  }
  expect_merge_equals_unsharded(dir, dir + "/res/fuzz-*.json");
}

}  // namespace
}  // namespace gridlock
