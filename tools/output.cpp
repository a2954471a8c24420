#include "tools/output.hpp"

#include <iostream>

#include "lattice/simulate.hpp"
#include "render/picture.hpp"
#include "tools/cli_common.hpp"

namespace gridlock {

void Answer::comment(const std::string& line) {
  if (json_mode_) {
    comments_.push_back(line);
  } else {
    std::cout << "c " << line << '\n';
  }
}

void Answer::witness(const std::string& item) { witness_.push_back(item); }

int Answer::finish(Verdict verdict, const std::string& status_text) {
  std::string status = status_text;
  if (status.empty()) status = verdict == Verdict::Yes ? "YES" : verdict == Verdict::No ? "NO" : "UNKNOWN";
  if (json_mode_) {
    nlohmann::json out = nlohmann::json::object();
    out["command"] = command_;
    out["status"] = status;
    out["exit_code"] = exit_code(verdict);
    out["comments"] = comments_;
    out["witness"] = witness_;
    for (auto& [k, v] : data_.items()) out[k] = v;
    std::cout << out.dump() << std::endl;
  } else {
    std::cout << "s " << status << '\n';
    // Witness items are packed onto "v" lines of bounded length, as SAT
    // solvers do, so that a long schedule stays readable.
    std::string line = "v";
    for (const auto& w : witness_) {
      if ((one_per_line_ || line.size() + 1 + w.size() > 78) && line.size() > 1) {
        std::cout << line << '\n';
        line = "v";
      }
      line += ' ' + w;
    }
    if (line.size() > 1) std::cout << line << '\n';
    std::cout.flush();
  }
  return exit_code(verdict);
}

nlohmann::json collision_json(const Instance& inst, const Regions& regions, const Collision& c) {
  nlohmann::json j;
  j["kind"] = c.kind == Collision::Kind::Node ? "node" : "cycle";
  j["time"] = c.time.str();
  if (c.kind == Collision::Kind::Node) {
    j["regions"] = {region_label(inst, regions, c.a), region_label(inst, regions, c.b)};
  } else {
    for (NodeId w : c.cycle) j["cycle"].push_back(inst.node_label(w));
  }
  for (CouplingId q : c.moving) j["moving"].push_back(inst.couplings()[q].name);
  return j;
}

void write_collision_svg(const std::string& path, const Instance& inst, const Schedule& s, const Collision& c) {
  // The collision begins at c.time (touching); draw it half way to the next
  // start or end of a coupling, where the overlap shows, motion still linear.
  Rational next = c.time + Rational(1);
  for (const Rational& t : s.start)
    for (const Rational& e : {t, t + Rational(1)})
      if (c.time < e && e < next) next = e;
  RenderOptions ro;
  ro.schedule = &s;
  ro.time = c.time + (next - c.time) * Rational(1, 2);
  ro.collision = &c;
  ro.title = "collision from time " + c.time.str() + " (drawn at " + ro.time.str() + ")";
  cli::write_text_file(path, render_svg(inst, ro));
}

}  // namespace gridlock
