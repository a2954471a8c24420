// Discrete or continuous time: the two models of the paper (docs/model.md,
// "Discrete and continuous schedules"), the one enum every layer uses
// (compile_formula's target, find_collision's model, verify's selection).
#pragma once

#include <optional>
#include <string_view>

namespace gridlock {

enum class TimeModel { Discrete, Continuous };

// "discrete" or "continuous". O(1).
constexpr const char* time_model_name(TimeModel m) { return m == TimeModel::Continuous ? "continuous" : "discrete"; }

// The model named s ("discrete", "continuous"), or nullopt. O(|s|).
constexpr std::optional<TimeModel> parse_time_model(std::string_view s) {
  if (s == "discrete") return TimeModel::Discrete;
  if (s == "continuous") return TimeModel::Continuous;
  return std::nullopt;
}

// A non-empty selection of models: which of the two a command checks
// (verify, fuzz: "discrete", "continuous" or "both").
struct TimeModels {
  bool discrete = true, continuous = false;

  static constexpr TimeModels only(TimeModel m) { return {m == TimeModel::Discrete, m == TimeModel::Continuous}; }
  static constexpr TimeModels both() { return {true, true}; }
  constexpr bool has(TimeModel m) const { return m == TimeModel::Discrete ? discrete : continuous; }
  constexpr bool operator==(const TimeModels&) const = default;
  // "discrete", "continuous" or "both".
  constexpr const char* name() const {
    return discrete && continuous ? "both" : continuous ? "continuous" : "discrete";
  }
  // The selection named s (a model's name or "both"), or nullopt. O(|s|).
  static constexpr std::optional<TimeModels> parse(std::string_view s) {
    if (s == "both") return both();
    if (auto m = parse_time_model(s)) return only(*m);
    return std::nullopt;
  }
};

}  // namespace gridlock
