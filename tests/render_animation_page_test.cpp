// The animation page (render/animation_page.hpp) and gridlock animate end to
// end: the page is self-contained, bad input is an
// error, and in a real headless Chromium the collision is drawn where the
// simulator says, with no script error. Skipped (visibly) without chromium.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "cnf/dimacs.hpp"
#include "lattice/animation.hpp"
#include "lattice/grid_format.hpp"
#include "lattice/simulate.hpp"
#include "reductions/compile.hpp"
#include "render/animation_page.hpp"
#include "render/viewer/assets.hpp"
#include "support/cli.hpp"
#include "verify/verify.hpp"

namespace gridlock {
namespace {

using test::run_gridlock;

const std::string kExamples = std::string(GRIDLOCK_SOURCE_DIR) + "/examples/instances/";

TEST(AnimateCommand, PageIsSelfContained) {
  std::string dir = test::temp_dir();
  auto r = run_gridlock({"animate", kExamples + "tiny-sat.grid", "--solve", "-o", dir + "/v.html"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("c collision-free; the player stops at 15"), std::string::npos) << r.out;
  std::string html = test::read_file(dir + "/v.html");
  EXPECT_NE(html.find("<script type=\"application/json\" id=\"data\">"), std::string::npos);
  // Nothing fetched: no external script, style, font or image; the only URL
  // is the SVG namespace, which is a name, not a download.
  for (const char* bad : {"<script src", "<link", "@import", "url(", "https://", "@font-face", "<img"})
    EXPECT_EQ(html.find(bad), std::string::npos) << bad;
  size_t pos = 0;
  while ((pos = html.find("http://", pos)) != std::string::npos) {
    EXPECT_EQ(html.compare(pos, 26, "http://www.w3.org/2000/svg"), 0) << html.substr(pos, 40);
    ++pos;
  }
}

// The page is the viewer's template with its stylesheet, script and data
// inlined: every mark of the template is gone, the files' text is there
// whole, and the frame-time harness (render/viewer/bench.js) is not.
TEST(AnimationPage, InlinesTheViewerFilesAndNoHarness) {
  Instance inst;
  ASSERT_FALSE(read_instance_file(kExamples + "model-case2-order-gadget.grid", inst));
  Schedule s = schedule_from_order({inst.find_coupling("b"), inst.find_coupling("a")});
  const std::string page = animation_html(inst, s, build_animation(inst, s), "t");
  for (const char* mark : {"__GRIDLOCK_", "viewer.css", "viewer.js", "<link", "<script src", "id=\"data\"></script>"})
    EXPECT_EQ(page.find(mark), std::string::npos) << mark;
  EXPECT_NE(page.find(std::string(viewer::css)), std::string::npos);
  EXPECT_NE(page.find(std::string(viewer::script)), std::string::npos);
  EXPECT_NE(page.find("<script type=\"application/json\" id=\"data\">{\""), std::string::npos);
  const std::string harness = test::read_file(std::string(GRIDLOCK_SOURCE_DIR) + "/render/viewer/bench.js");
  EXPECT_NE(harness.find("runBench"), std::string::npos);
  for (const char* bench : {"runBench", "bench="}) EXPECT_EQ(page.find(bench), std::string::npos) << bench;
  // The embedded text is the repository's file, byte for byte.
  EXPECT_EQ(std::string(viewer::script),
            test::read_file(std::string(GRIDLOCK_SOURCE_DIR) + "/render/viewer/viewer.js"));
  EXPECT_EQ(std::string(viewer::css), test::read_file(std::string(GRIDLOCK_SOURCE_DIR) + "/render/viewer/viewer.css"));
}

TEST(AnimateCommand, BadInputIsAnError) {
  std::string dir = test::temp_dir();
  auto none = run_gridlock({"animate", kExamples + "model-case2-order-gadget.grid", "-o", dir + "/v.html"});
  EXPECT_EQ(none.exit_code, 1);
  EXPECT_NE(none.err.find("gridlock: error: give exactly one of --order, --order-file, --times, --solve"),
            std::string::npos)
      << none.err;
  auto bad = run_gridlock(
      {"animate", kExamples + "model-case2-order-gadget.grid", "--order", "a zz", "-o", dir + "/v.html"});
  EXPECT_EQ(bad.exit_code, 1);
  EXPECT_NE(bad.err.find("gridlock: error: --order"), std::string::npos) << bad.err;
  EXPECT_FALSE(std::filesystem::exists(dir + "/v.html"));
}

// --- the browser ---

std::string chromium_path() {
  for (const char* p : {"/usr/bin/chromium", "/usr/bin/chromium-browser", "/usr/bin/google-chrome"})
    if (std::filesystem::exists(p)) return p;
  return "";
}

// Runs headless Chromium on url; returns stdout (the DOM with --dump-dom).
std::string run_chromium(const std::string& chromium, const std::string& what, const std::string& url) {
  std::string profile = test::temp_dir();
  std::string cmd = "timeout 120 " + chromium +
                    " --headless --no-sandbox --disable-gpu --disable-quic --no-first-run"
                    " --disable-background-networking --disable-component-update --disable-sync"
                    " --user-data-dir=" +
                    profile +
                    " --window-size=1000,700 --virtual-time-budget=3000"
                    " --run-all-compositor-stages-before-draw " +
                    what + " '" + url + "' 2>/dev/null";
  std::string out;
  FILE* f = popen(cmd.c_str(), "r");
  if (!f) return out;
  char buf[65536];
  for (size_t n; (n = fread(buf, 1, sizeof buf, f)) > 0;) out.append(buf, n);
  pclose(f);
  return out;
}

nlohmann::json page_state(const std::string& dom);

// The page's state after loading url; a browser that starts too slowly on a
// loaded machine (no DOM within the time limit) is given two more tries.
nlohmann::json load_state(const std::string& chromium, const std::string& url) {
  nlohmann::json st;
  for (int attempt = 0; attempt < 3 && !st.is_object(); ++attempt)
    st = page_state(run_chromium(chromium, "--dump-dom", url));
  return st;
}

nlohmann::json page_state(const std::string& dom) {
  const std::string open = "<pre id=\"state\">";
  size_t a = dom.find(open);
  if (a == std::string::npos) return nullptr;
  a += open.size();
  size_t b = dom.find("</pre>", a);
  std::string text = dom.substr(a, b - a);
  // The DOM dump escapes &, < and > in text.
  for (auto [from, to] :
       {std::pair<std::string, std::string>{"&quot;", "\""}, {"&lt;", "<"}, {"&gt;", ">"}, {"&amp;", "&"}})
    for (size_t p; (p = text.find(from)) != std::string::npos;) text.replace(p, from.size(), to);
  return nlohmann::json::parse(text, nullptr, false);
}

// Opens page (written for inst and schedule s) at the collision's stop
// moment and checks that the collision is drawn where the simulator says.
void expect_collision_drawn(const std::string& chromium, const std::string& page, const Instance& inst,
                            const Schedule& s, const std::string& png) {
  // What the simulator says, by its own path: the collision, the moment the
  // page stops at, and both regions' exact rectangles then.
  Simulator sim(inst);
  auto col = sim.run(s).collision;
  ASSERT_TRUE(col.has_value());
  ASSERT_EQ(col->kind, Collision::Kind::Node);
  Rational stop = collision_draw_time(s, *col);
  std::vector<RectQ> conf = configuration_at(inst, s, stop);
  const std::string url = "file://" + page + "#t=" + stop.str();
  for (int attempt = 0; attempt < 3 && !std::filesystem::exists(png); ++attempt)
    run_chromium(chromium, "--screenshot=" + png, url);
  EXPECT_TRUE(std::filesystem::exists(png) && std::filesystem::file_size(png) > 1000) << "no screenshot " << png;
  nlohmann::json st = load_state(chromium, url);
  ASSERT_TRUE(st.is_object()) << "the page wrote no state";
  EXPECT_TRUE(st["errors"].empty()) << st["errors"].dump();
  EXPECT_EQ(st["t"], stop.str());
  // The colliding regions and their overlap, in grid units: as the simulator says.
  for (auto [key, reg] : {std::pair<const char*, uint32_t>{"a", col->a}, {"b", col->b}}) {
    const RectQ& q = conf[reg];
    const auto& g = st[key]["grid"];
    EXPECT_NEAR(g[0].get<double>(), q.xlo.approx(), 1e-9) << key;
    EXPECT_NEAR(g[1].get<double>(), q.xhi.approx(), 1e-9) << key;
    EXPECT_NEAR(g[2].get<double>(), q.ylo.approx(), 1e-9) << key;
    EXPECT_NEAR(g[3].get<double>(), q.yhi.approx(), 1e-9) << key;
    EXPECT_EQ(st[key]["label"].get<std::string>().rfind(region_label(inst, sim.regions(), reg), 0), 0u)
        << st[key]["label"];
  }
  const RectQ &A = conf[col->a], &B = conf[col->b];
  Rational ox0 = std::max(A.xlo, B.xlo), ox1 = std::min(A.xhi, B.xhi), oy0 = std::max(A.ylo, B.ylo),
           oy1 = std::min(A.yhi, B.yhi);
  ASSERT_TRUE(ox0 < ox1 && oy0 < oy1) << "the simulator's regions do not overlap at the stop moment";
  ASSERT_TRUE(st["overlap"].is_object()) << "the page draws no overlap";
  const auto& og = st["overlap"]["grid"];
  EXPECT_NEAR(og[0].get<double>(), ox0.approx(), 1e-9);
  EXPECT_NEAR(og[1].get<double>(), ox1.approx(), 1e-9);
  EXPECT_NEAR(og[2].get<double>(), oy0.approx(), 1e-9);
  EXPECT_NEAR(og[3].get<double>(), oy1.approx(), 1e-9);
  // In pixels: the shaded element's rendered box is the overlap's box under
  // the page's transform, it lies in the window (the page centres the
  // collision), and it is what the browser hits there.
  const auto& want = st["overlap"]["px"];
  const auto& drawn = st["overlap"]["drawn"];
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(drawn[i].get<double>(), want[i].get<double>(), 1.0) << i;
  EXPECT_GT(want[2].get<double>() - want[0].get<double>(), 5.0);
  EXPECT_GE(want[0].get<double>(), 0.0);
  EXPECT_LE(want[3].get<double>(), 700.0);
  EXPECT_EQ(st["overlap"]["at_centre"], "overlap");
}

TEST(AnimateBrowser, CollisionDrawnWhereTheSimulatorSays) {
  const std::string chromium = chromium_path();
  if (chromium.empty())
    GTEST_SKIP() << "chromium is not installed (scripts/setup.sh installs it): browser test skipped";
  std::string dir = test::temp_dir();
  {
    SCOPED_TRACE("two growths, continuous");
    test::write_file(dir + "/t1", "g1 0\ng2 1/2\n");
    Instance inst;
    ASSERT_FALSE(read_instance_file(kExamples + "model-case1-two-growths.grid", inst));
    Schedule s;
    ASSERT_FALSE(read_times_file(inst, dir + "/t1", s));
    auto r = run_gridlock(
        {"animate", kExamples + "model-case1-two-growths.grid", "--times", dir + "/t1", "-o", dir + "/case1.html"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    expect_collision_drawn(chromium, dir + "/case1.html", inst, s, dir + "/case1.png");
  }
  {
    SCOPED_TRACE("order gadget, discrete b a");
    Instance inst;
    ASSERT_FALSE(read_instance_file(kExamples + "model-case2-order-gadget.grid", inst));
    Schedule s = schedule_from_order({inst.find_coupling("b"), inst.find_coupling("a")});
    auto r = run_gridlock(
        {"animate", kExamples + "model-case2-order-gadget.grid", "--order", "b a", "-o", dir + "/case2.html"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    expect_collision_drawn(chromium, dir + "/case2.html", inst, s, dir + "/case2.png");
  }
  {
    // A deep part tree: a row of 2k+1 nodes with an expansion on every
    // other edge (k nested parts), hanging from a second row at its left
    // end; a node hangs from the second row just past the first row's right
    // end. Two expansions push the row into it.
    SCOPED_TRACE("chain of 150 nested parts");
    const int k = 150, N = 2 * k;
    std::string g = "p grid " + std::to_string((N + 1) + (N + 3) + 1) + " " + std::to_string(N + (N + 2) + 2) + " " +
                    std::to_string(k) + " 0\n";
    for (int x = 0; x <= N; ++x) g += "n " + std::to_string(x) + " 0\n";
    for (int x = 0; x <= N + 2; ++x) g += "n " + std::to_string(x) + " 1\n";
    g += "n " + std::to_string(N + 2) + " 0\n";
    for (int x = 0; x < N; ++x) g += "e " + std::to_string(x) + " 0 " + std::to_string(x + 1) + " 0\n";
    for (int x = 0; x < N + 2; ++x) g += "e " + std::to_string(x) + " 1 " + std::to_string(x + 1) + " 1\n";
    g += "e 0 0 0 1\ne " + std::to_string(N + 2) + " 1 " + std::to_string(N + 2) + " 0\n";
    for (int i = 0; i < k; ++i) g += "o a" + std::to_string(i) + " expand " + std::to_string(2 * i) + " 0 +x\n";
    test::write_file(dir + "/chain.grid", g);
    Instance inst;
    ASSERT_FALSE(read_instance_file(dir + "/chain.grid", inst));
    std::vector<CouplingId> order;
    std::string names;
    for (int i = k - 1; i >= 0; --i) {
      order.push_back(inst.find_coupling("a" + std::to_string(i)));
      names += "a" + std::to_string(i) + " ";
    }
    Schedule s = schedule_from_order(order);
    Animation a = build_animation(inst, s);
    EXPECT_EQ(a.parts.size(), static_cast<size_t>(k) + 1);
    auto r = run_gridlock({"animate", dir + "/chain.grid", "--order", names, "-o", dir + "/chain.html"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    expect_collision_drawn(chromium, dir + "/chain.html", inst, s, dir + "/chain.png");
  }
  {
    // A compiled formula (1 041 nodes): the page verify --pictures writes
    // beside its still picture, for the all-false schedule of tiny-unsat.
    SCOPED_TRACE("verify --pictures, tiny-unsat");
    const std::string cnf = std::string(GRIDLOCK_SOURCE_DIR) + "/examples/formulas/tiny-unsat.cnf";
    auto r = run_gridlock({"verify", cnf, "--pictures", dir + "/pics"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    Formula f;
    ASSERT_FALSE(read_dimacs_file(cnf, f, {}));
    VerifyResult v = verify_formula(f, cnf, VerifyOptions{});
    ASSERT_EQ(v.sat, Verdict::No);
    Schedule s = schedule_from_order(
        schedule_from_assignment(v.compiled, std::vector<bool>(static_cast<size_t>(v.lsat.num_vars) + 1, false)));
    expect_collision_drawn(chromium, dir + "/pics/tiny-unsat-collision.html", v.instance(), s, dir + "/unsat.png");
  }
}

// Before the collision nothing is shaded, and the running couplings listed
// are the simulator's moving ones.
TEST(AnimateBrowser, BeforeTheCollisionNoOverlap) {
  const std::string chromium = chromium_path();
  if (chromium.empty())
    GTEST_SKIP() << "chromium is not installed (scripts/setup.sh installs it): browser test skipped";
  std::string dir = test::temp_dir();
  test::write_file(dir + "/t1", "g1 0\ng2 1/2\n");
  auto r = run_gridlock(
      {"animate", kExamples + "model-case1-two-growths.grid", "--times", dir + "/t1", "-o", dir + "/view.html"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  nlohmann::json st = load_state(chromium, "file://" + dir + "/view.html#t=1/4");
  ASSERT_TRUE(st.is_object());
  EXPECT_TRUE(st["errors"].empty()) << st["errors"].dump();
  EXPECT_TRUE(st["overlap"].is_null());
  EXPECT_EQ(st["running"], nlohmann::json::array({"g1"}));
  nlohmann::json late = load_state(chromium, "file://" + dir + "/view.html#t=5/8");
  ASSERT_TRUE(late.is_object());
  EXPECT_EQ(late["running"], nlohmann::json::array({"g1", "g2"}));
}

// Hostile names (issue 20): a title and a file name holding "</script>",
// "<!--<script>", quotes and ampersands leave the page working (before: the
// page stopped: the HTML parser read the embedded JSON as script data) and
// are shown as the text they are.
TEST(AnimateBrowser, HostileNamesKeepThePageWorking) {
  const std::string chromium = chromium_path();
  if (chromium.empty())
    GTEST_SKIP() << "chromium is not installed (scripts/setup.sh installs it): browser test skipped";
  std::string dir = test::temp_dir();
  const std::string grid = dir + "/x<!--<script>'\"&.grid";
  std::filesystem::copy_file(kExamples + "model-case1-two-growths.grid", grid);
  test::write_file(dir + "/t1", "g1 0\ng2 1/2\n");
  const std::string title = "</script><!--<script>alert(1)</script> & \"q\" 'r' -->";
  for (bool given : {true, false}) {
    SCOPED_TRACE(given ? "--title" : "file name in the default title");
    std::vector<std::string> args = {"animate", grid, "--times", dir + "/t1", "-o", dir + "/view.html"};
    if (given) args.insert(args.end(), {"--title", title});
    auto r = run_gridlock(args);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const std::string html = test::read_file(dir + "/view.html");
    EXPECT_EQ(html.find("<!--<script>"), std::string::npos);
    const std::string dom = run_chromium(chromium, "--dump-dom", "file://" + dir + "/view.html#t=5/8");
    nlohmann::json st = page_state(dom);
    ASSERT_TRUE(st.is_object()) << "the page wrote no state: it stopped working";
    EXPECT_TRUE(st["errors"].empty()) << st["errors"].dump();
    EXPECT_EQ(st["running"], nlohmann::json::array({"g1", "g2"}));
    const std::string shown = given ? "&lt;/script&gt;&lt;!--&lt;script&gt;alert(1)&lt;/script&gt; &amp;"
                                    : "x&lt;!--&lt;script&gt;'\"&amp;.grid";
    EXPECT_NE(dom.find("<h1 id=\"title\">"), std::string::npos);
    EXPECT_NE(dom.find(shown), std::string::npos) << dom.substr(0, 2000);
  }
}

// The frame-time harness works when added to a page (as
// scripts/viewer_bench.sh adds it), and a shipped page ignores #bench.
TEST(AnimateBrowser, BenchHarnessOnlyWhereAdded) {
  const std::string chromium = chromium_path();
  if (chromium.empty())
    GTEST_SKIP() << "chromium is not installed (scripts/setup.sh installs it): browser test skipped";
  std::string dir = test::temp_dir();
  test::write_file(dir + "/t1", "g1 0\ng2 1/2\n");
  auto r = run_gridlock(
      {"animate", kExamples + "model-case1-two-growths.grid", "--times", dir + "/t1", "-o", dir + "/view.html"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  nlohmann::json shipped = load_state(chromium, "file://" + dir + "/view.html#bench=20&nostart");
  ASSERT_TRUE(shipped.is_object());
  EXPECT_TRUE(shipped["errors"].empty()) << shipped["errors"].dump();
  EXPECT_FALSE(shipped.contains("bench")) << shipped.dump();
  std::string page = test::read_file(dir + "/view.html");
  const size_t end = page.rfind("</body>");
  ASSERT_NE(end, std::string::npos);
  page.insert(end, "<script>\n" + test::read_file(std::string(GRIDLOCK_SOURCE_DIR) + "/render/viewer/bench.js") +
                       "</script>\n");
  test::write_file(dir + "/bench.html", page);
  for (const bool full : {false, true}) {
    nlohmann::json st = load_state(chromium, "file://" + dir + "/bench.html#bench=20" + (full ? "&full" : ""));
    ASSERT_TRUE(st.is_object());
    EXPECT_TRUE(st["errors"].empty()) << st["errors"].dump();
    ASSERT_TRUE(st["bench"].is_object()) << st.dump();
    EXPECT_EQ(st["bench"]["frames"], 20);
    EXPECT_EQ(st["bench"]["full"], full);
    EXPECT_GT(st["bench"]["ms_per_frame"].get<double>(), 0.0);
    EXPECT_EQ(st["t"], "0");  // back at the start after the frames
  }
}

}  // namespace
}  // namespace gridlock
