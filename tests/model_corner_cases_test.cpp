// Hand-written corner cases of MODEL.md (a hand audit),
// each answer derived by hand from MODEL.md before the command line was run:
// touching versus overlapping, contraction pulling (not pushing), lock-step
// growths and pushes, cycles broken and kept, couplings, vertical operations,
// the cycle-before-node tie. The files live in tests/data/model_corners/. End to
// end: the real `gridlock` on each file, every witness fed back to `check`.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "support/cli.hpp"

namespace gridlock {
namespace {

using test::run_gridlock;

const std::string kDir = std::string(GRIDLOCK_DATA_DIR) + "/model_corners/";

// Exit codes: 10 yes, 20 no.
struct Expected {
  const char* file;
  int solve_discrete, solve_continuous, collide_discrete, collide_continuous;
};

const std::vector<Expected>& cases() {
  static const std::vector<Expected> all = {
      {"A01-single-node", 10, 10, 20, 20},
      {"A02-expand-pair", 10, 10, 20, 20},
      {"A03-contract-pair", 10, 10, 20, 20},
      {"A04-grow-free", 10, 10, 20, 20},
      {"A05-grow-into-still", 20, 20, 10, 10},
      {"A06-push-into-unjoined", 20, 20, 10, 10},
      {"A07-corner-touch", 10, 10, 20, 20},
      {"A08-slide-along-face", 10, 10, 20, 20},
      {"A09-push-until-touch", 10, 10, 20, 20},
      {"A10-contract-pulls-into", 20, 20, 10, 10},
      {"A11-contract-pushwrong", 10, 10, 20, 20},
      {"A12-ring-coupled", 10, 10, 20, 20},
      {"A13-ring-uncoupled", 20, 10, 10, 10},
      {"A14-block-contract-one", 20, 20, 10, 10},
      {"A15-block-contract-two", 10, 10, 20, 20},
      {"A16-block-expand-contract", 20, 20, 10, 10},
      {"A17-block-expand-reverse-named", 10, 10, 20, 20},
      {"A18-grow-perp-leave", 20, 20, 10, 10},
      {"B01-grow-lockstep-push", 10, 10, 10, 10},
      {"B02-grow-lockstep-push-coupled", 10, 10, 20, 20},
      {"B03-growths-gap2", 10, 10, 20, 20},
      {"B04-vertical-case4", 10, 10, 10, 10},
      {"C01-expand-contract-lockstep", 10, 10, 10, 10},
      {"C02-expand-contract-lockstep-coupled", 10, 10, 20, 20},
      {"C03-tie-cycle-and-node", 20, 20, 10, 10},
      {"C04-case5-coupled", 20, 20, 10, 10},
  };
  return all;
}

std::string path_of(const char* name) { return kDir + name + ".grid"; }

// Runs a decision command, checks its exit code, and feeds a witness back to
// `check` (which must agree: a collision-free witness runs free, a colliding
// one collides).
void decide_and_replay(const std::string& file, const std::vector<std::string>& cmd, int want, bool times,
                       int witness_want) {
  std::vector<std::string> args = cmd;
  args.insert(args.begin() + 1, file);
  auto r = run_gridlock(args);
  ASSERT_EQ(r.exit_code, want) << file << " " << cmd[0] << "\n" << r.out << r.err;
  if (r.exit_code != 10) return;
  std::string witness = test::write_file(test::temp_dir() + "/w", r.out);
  auto c = run_gridlock({"check", file, times ? "--times" : "--order-file", witness});
  EXPECT_EQ(c.exit_code, witness_want) << file << " " << cmd[0] << " witness\n" << r.out << c.out << c.err;
}

TEST(ModelCorners, EveryDeciderGivesTheHandDerivedAnswer) {
  for (const Expected& e : cases()) {
    const std::string f = path_of(e.file);
    decide_and_replay(f, {"solve"}, e.solve_discrete, false, 10);
    decide_and_replay(f, {"solve", "--model", "continuous"}, e.solve_continuous, true, 10);
    decide_and_replay(f, {"collide", "--model", "discrete"}, e.collide_discrete, false, 20);
    decide_and_replay(f, {"collide", "--model", "continuous"}, e.collide_continuous, true, 20);
  }
}

struct CheckCase {
  const char* file;
  std::vector<std::string> schedule;  // {"--order", "a b"} or {"--times", file text}
  int want;
  const char* line;  // expected 'c ...' line of a NO, or "" for YES
};

TEST(ModelCorners, CheckReportsTheHandDerivedMoment) {
  const std::vector<CheckCase> cases = {
      {"B01-grow-lockstep-push",
       {"--order", "g e"},
       20,
       "c node collision at time 0 between node (1,0) and node grown by g"},
      {"B01-grow-lockstep-push", {"--order", "e g"}, 10, ""},
      {"B01-grow-lockstep-push", {"--times", "g 1/4\ne 0\n"}, 10, ""},
      {"B01-grow-lockstep-push", {"--times", "g 0\ne 1/4\n"}, 20, "c node collision at time 0 between"},
      {"B01-grow-lockstep-push", {"--times", "g 0\ne 0\n"}, 10, ""},
      {"B04-vertical-case4", {"--order", "c g"}, 10, ""},
      {"B04-vertical-case4",
       {"--order", "g c"},
       20,
       "c node collision at time 0 between node (0,1) and node grown by g"},
      {"C01-expand-contract-lockstep", {"--order", "k a"}, 10, ""},
      {"C01-expand-contract-lockstep",
       {"--order", "a k"},
       20,
       "c node collision at time 0 between node (1,0) and node (2,0)"},
      {"C01-expand-contract-lockstep", {"--times", "a 0\nk 0\n"}, 10, ""},
      {"C01-expand-contract-lockstep", {"--times", "a 1/3\nk 0\n"}, 10, ""},
      {"C01-expand-contract-lockstep", {"--times", "a 0\nk 1/3\n"}, 20, "c node collision at time 0 between"},
      {"C03-tie-cycle-and-node", {"--order", "a"}, 20, "c cycle collision at time 0"},
      {"C04-case5-coupled", {"--order", "Q"}, 20, "c node collision at time 1/2 between node (1,0) and node grown by g"},
      {"C04-case5-coupled", {"--times", "Q 7/3\n"}, 20, "c node collision at time 17/6 between"},
      {"A13-ring-uncoupled", {"--times", "a -5/2\nb -5/2\n"}, 10, ""},
      {"A13-ring-uncoupled", {"--times", "a 0\nb 1/2\n"}, 20, "c cycle collision at time 0"},
      {"A14-block-contract-one", {"--order", "k"}, 20, "c cycle collision at time 0"},
      {"A10-contract-pulls-into", {"--order", "k"}, 20, "c node collision at time 0 between"},
  };
  for (const CheckCase& c : cases) {
    std::vector<std::string> args = {"check", path_of(c.file), c.schedule[0]};
    if (c.schedule[0] == "--times") args.push_back(test::write_file(test::temp_dir() + "/t", c.schedule[1]));
    else args.push_back(c.schedule[1]);
    auto r = run_gridlock(args);
    EXPECT_EQ(r.exit_code, c.want) << c.file << " " << c.schedule[1] << "\n" << r.out << r.err;
    if (c.want == 20) {
      EXPECT_NE(r.out.find(c.line), std::string::npos) << c.file << " " << c.schedule[1] << "\n" << r.out;
    }
  }
}

// The gap checker (horizontal-only) agrees with the exact continuous solver.
TEST(ModelCorners, GapsAgreeWithTheContinuousSolverOnHorizontalCases) {
  for (const char* name :
       {"A02-expand-pair", "A03-contract-pair", "A06-push-into-unjoined", "A09-push-until-touch",
        "A11-contract-pushwrong", "A12-ring-coupled", "A13-ring-uncoupled", "B03-growths-gap2",
        "C01-expand-contract-lockstep", "C02-expand-contract-lockstep-coupled", "C04-case5-coupled"}) {
    auto g = run_gridlock({"gaps", path_of(name)});
    auto s = run_gridlock({"solve", path_of(name), "--model", "continuous"});
    EXPECT_EQ(g.exit_code, s.exit_code) << name << "\n" << g.out << g.err;
    EXPECT_TRUE(g.exit_code == 10 || g.exit_code == 20) << name << g.err;
  }
}

}  // namespace
}  // namespace gridlock
