// Output conventions of every decision command (SAT-competition style).
//
//   c comment lines (statistics, explanations)
//   s STATUS          exactly one status line
//   v witness lines   (a schedule, an assignment)
//
// Exit codes: 10 yes, 20 no, 0 unknown (a limit was hit), 1 error.
// With --json the same content is printed as one JSON object instead:
//   {"command": ..., "status": ..., "comments": [...], "witness": [...], ...}
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "common/verdict.hpp"
#include "tools/user_error.hpp"

namespace gridlock {

struct Collision;
struct Regions;
class Instance;
struct Schedule;

class Answer {
 public:
  Answer(std::string command, bool json) : command_(std::move(command)), json_mode_(json) {}

  // A "c" line. In text mode it is printed at once (so long runs show
  // progress); in JSON mode it is collected into "comments".
  void comment(const std::string& line);
  // A "v" line: one witness item (e.g. a coupling name, a literal).
  void witness(const std::string& item);
  // Print every witness item on its own "v" line instead of packing them
  // (for items such as "NAME TIME" that a reader takes one per line).
  void witness_one_per_line() { one_per_line_ = true; }
  // Extra structured data for --json (ignored in text mode).
  nlohmann::json& data() { return data_; }
  bool json() const { return json_mode_; }

  // Prints "s <status_text>" and the witness (or the JSON object) and returns
  // the exit code for verdict. status_text defaults to YES / NO / UNKNOWN.
  int finish(Verdict verdict, const std::string& status_text = "");

 private:
  std::string command_;
  bool json_mode_;
  bool one_per_line_ = false;
  std::vector<std::string> comments_;
  std::vector<std::string> witness_;
  nlohmann::json data_ = nlohmann::json::object();
};

// The JSON record of a collision ("kind", "time", "regions" or "cycle",
// "moving"), shared by check and collide.
nlohmann::json collision_json(const Instance& inst, const Regions& regions, const Collision& c);

// Draws the configuration of schedule s at the collision's moment, the
// colliding nodes marked, to an SVG file (throws UserError if unwritable).
void write_collision_svg(const std::string& path, const Instance& inst, const Schedule& s, const Collision& c);

}  // namespace gridlock
