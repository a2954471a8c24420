#include "tools/animation_files.hpp"

#include <tuple>

#include "reductions/compile.hpp"
#include "render/animation_page.hpp"
#include "tools/cli_common.hpp"
#include "verify/verify.hpp"

namespace gridlock {

Animation write_animation(const std::string& path, const Instance& inst, const Schedule& s, const std::string& title) {
  Animation a = build_animation(inst, s);
  cli::write_text_file(path, animation_html(inst, s, a, title));
  return a;
}

std::vector<std::string> write_result_animations(const VerifyResult& r, const std::string& dir) {
  std::vector<std::string> files;
  const Instance& inst = r.instance();
  auto one = [&](const std::vector<CouplingId>& order, const std::string& file, const std::string& what) {
    const std::string path = dir + "/" + file;
    write_animation(path, inst, schedule_from_order(order), r.name + ": " + what);
    files.push_back(path);
  };
  for (auto [names, file, what] :
       {std::tuple{&r.sat_schedule, "sat-schedule.html", "CaDiCaL's model lifted"},
        std::tuple{&r.solver_schedule, "solver-schedule.html", "the exact solver's order"}}) {
    std::vector<CouplingId> order;
    if (names->empty() || parse_order(inst, *names, r.name, 0, order)) continue;
    one(order, file, what);
  }
  if (files.empty() && inst.couplings().size() > 0)
    one(schedule_from_assignment(r.compiled, std::vector<bool>(static_cast<size_t>(r.lsat.num_vars) + 1, false)),
        "all-false-schedule.html", "the all-false assignment lifted");
  return files;
}

}  // namespace gridlock
