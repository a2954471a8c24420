#include "tools/output.hpp"

#include <iostream>

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

}  // namespace gridlock
