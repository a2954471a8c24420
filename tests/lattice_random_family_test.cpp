// The random shape families (lattice/random_instance.hpp,
// random_family_instance) and `gridlock random`, the real binary.
#include <gtest/gtest.h>

#include <filesystem>

#include <nlohmann/json.hpp>
#include <sstream>

#include "lattice/grid_format.hpp"
#include "lattice/random_instance.hpp"
#include "support/cli.hpp"

namespace gridlock {
namespace {

std::string text_of(const Instance& inst) {
  std::ostringstream out;
  write_instance(out, inst);
  return out.str();
}

size_t largest_coupling(const Instance& inst) {
  size_t m = 0;
  for (const Coupling& q : inst.couplings()) m = std::max(m, q.ops.size());
  return m;
}

TEST(RandomFamily, ExactCouplingCountsAtScale) {
  for (ShapeFamily fam : {ShapeFamily::Tree, ShapeFamily::Cycles, ShapeFamily::Sparse, ShapeFamily::Dense})
    for (uint32_t k : {1U, 100U, 300U, 1000U}) {
      RandomFamilyParams f;
      f.family = fam;
      f.couplings = k;
      const Instance inst = random_family_instance(f, 11);
      EXPECT_EQ(inst.couplings().size(), k) << shape_family_name(fam) << " k " << k;
      EXPECT_LE(largest_coupling(inst), 3U);
    }
}

TEST(RandomFamily, DeterministicAndSeedSensitive) {
  RandomFamilyParams f;
  f.family = ShapeFamily::Cycles;
  f.couplings = 50;
  EXPECT_EQ(text_of(random_family_instance(f, 5)), text_of(random_family_instance(f, 5)));
  EXPECT_NE(text_of(random_family_instance(f, 5)), text_of(random_family_instance(f, 6)));
}

TEST(RandomFamily, KindsAndDirectionsAreRespected) {
  for (uint64_t seed = 1; seed <= 20; ++seed) {
    RandomFamilyParams f;
    f.couplings = 60;
    f.max_coupling = 2;
    f.expand = false;
    f.horizontal_only = seed % 2 == 0;
    const Instance inst = random_family_instance(f, seed);
    bool contract = false, grow = false;
    for (const Operation& op : inst.ops()) {
      EXPECT_NE(op.kind, OpKind::Expand) << "seed " << seed;
      if (f.horizontal_only) {
        EXPECT_TRUE(op.dir == Dir::PosX || op.dir == Dir::NegX) << "seed " << seed;
      }
      contract = contract || op.kind == OpKind::Contract;
      grow = grow || op.kind == OpKind::Grow;
    }
    EXPECT_TRUE(contract && grow) << "seed " << seed << ": both allowed kinds should appear in 60 couplings";
    EXPECT_LE(largest_coupling(inst), 2U);
  }
  RandomFamilyParams none;
  none.expand = none.contract = none.grow = false;
  EXPECT_THROW(random_family_instance(none, 1), std::invalid_argument);
  RandomFamilyParams zero;
  zero.couplings = 0;
  EXPECT_THROW(random_family_instance(zero, 1), std::invalid_argument);
}

TEST(RandomFamily, ShapesDifferAsNamed) {
  // Dense shapes have more edges per node than trees (which have n - 1).
  RandomFamilyParams f;
  f.couplings = 200;
  f.family = ShapeFamily::Tree;
  const Instance tree = random_family_instance(f, 3);
  EXPECT_EQ(tree.edges().size() + 1, tree.num_nodes());
  f.family = ShapeFamily::Dense;
  const Instance dense = random_family_instance(f, 3);
  EXPECT_GT(dense.edges().size(), dense.num_nodes() + dense.num_nodes() / 4);
  ShapeFamily parsed{};
  EXPECT_TRUE(parse_shape_family("sparse", parsed));
  EXPECT_EQ(parsed, ShapeFamily::Sparse);
  EXPECT_FALSE(parse_shape_family("blob", parsed));
}

TEST(RandomCommand, WritesTheLibraryInstanceAndReplays) {
  auto r = test::run_gridlock({"random", "--family", "cycles", "--couplings", "40", "--seed", "9"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  Instance inst;
  std::istringstream in(r.out);
  auto err = read_instance(in, "out.grid", inst);
  ASSERT_FALSE(err) << err->str();
  EXPECT_EQ(inst.couplings().size(), 40U);
  RandomFamilyParams f;
  f.family = ShapeFamily::Cycles;
  f.couplings = 40;
  EXPECT_EQ(text_of(inst), text_of(random_family_instance(f, 9)));
  EXPECT_NE(r.out.find("gridlock random --family cycles --couplings 40 --max-coupling 3"), std::string::npos);
}

// A set is never written over someone else's files unasked: a folder that
// is not empty (here another set's manifest) is refused before any work,
// and --force writes into it.
TEST(RandomCommand, RefusesAFolderThatIsNotEmpty) {
  const std::string dir = test::temp_dir() + "/set";
  std::filesystem::create_directories(dir);
  const std::string theirs = test::write_file(dir + "/manifest.json", "{\"generator\": \"gridlock gen-instances\"}\n");
  auto r = test::run_gridlock({"random", "--couplings", "5", "--count", "2", "-o", dir});
  EXPECT_EQ(r.exit_code, 1) << r.out;
  EXPECT_NE(r.err.find("gridlock: error: " + dir + ": folder is not empty (give --force to write the set into it)"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(test::read_file(theirs), "{\"generator\": \"gridlock gen-instances\"}\n");
  EXPECT_FALSE(std::filesystem::exists(dir + "/tree-k5-s1.grid"));
  r = test::run_gridlock({"random", "--couplings", "5", "--count", "2", "--force", "-o", dir});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(test::read_file(theirs))["generator"], "gridlock random");
  EXPECT_TRUE(std::filesystem::exists(dir + "/tree-k5-s2.grid"));
  // A file where the folder should be is named as such.
  const std::string file = test::write_file(test::temp_dir() + "/plain", "x\n");
  r = test::run_gridlock({"random", "--couplings", "5", "--count", "2", "-o", file});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find(file + ": exists and is not a folder"), std::string::npos) << r.err;
}

TEST(RandomCommand, FolderWithLabelledManifest) {
  const std::string dir = test::temp_dir() + "/set";
  auto r = test::run_gridlock(
      {"random", "--family", "tree", "--couplings", "12", "--count", "3", "--seed", "4", "--label", "20", "-o", dir});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto m = nlohmann::json::parse(test::read_file(dir + "/manifest.json"));
  ASSERT_EQ(m["instances"].size(), 3U);
  for (const auto& e : m["instances"]) {
    const std::string answer = e["answer"];
    EXPECT_TRUE(answer == "YES" || answer == "NO") << answer;
    const std::string grid = dir + "/" + std::string(e["instance"]);
    if (answer == "YES") {  // the recorded order passes the simulator
      auto c = test::run_gridlock({"check", grid, "--order", std::string(e["order"])});
      EXPECT_EQ(c.exit_code, 10) << c.out << c.err;
    }
    auto s = test::run_gridlock({"solve", grid});
    EXPECT_EQ(s.exit_code, answer == "YES" ? 10 : 20) << s.out;
  }
}

TEST(RandomCommand, BadOptionsAreErrors) {
  auto bad = test::run_gridlock({"random", "--family", "blob"});
  EXPECT_EQ(bad.exit_code, 1);
  EXPECT_NE(bad.err.find("--family must be"), std::string::npos) << bad.err;
  auto kinds = test::run_gridlock({"random", "--kinds", "expand,fly"});
  EXPECT_EQ(kinds.exit_code, 1);
  EXPECT_NE(kinds.err.find("--kinds"), std::string::npos) << kinds.err;
  auto count = test::run_gridlock({"random", "--count", "2"});
  EXPECT_EQ(count.exit_code, 1);
  EXPECT_NE(count.err.find("needs a folder"), std::string::npos) << count.err;
}

}  // namespace
}  // namespace gridlock
