#include "tools/options.hpp"

#include <cmath>
#include <cstdlib>

#include "common/diagnostic.hpp"
#include "tools/user_error.hpp"

namespace gridlock::cli {

namespace {

std::string shown(const std::string& text) { return text.size() > 40 ? text.substr(0, 40) + "..." : text; }

[[noreturn]] void bad(const std::string& option, const std::string& want, const std::string& text) {
  throw UserError("--" + option + ": want " + want + ", got '" + shown(text) + "'");
}

// Digits only; false on overflow or anything else.
bool digits_to_u64(const std::string& text, uint64_t& value) {
  if (text.empty() || text.size() > 20) return false;
  value = 0;
  for (char ch : text) {
    if (ch < '0' || ch > '9') return false;
    auto d = static_cast<uint64_t>(ch - '0');
    if (value > (std::numeric_limits<uint64_t>::max() - d) / 10) return false;
    value = value * 10 + d;
  }
  return true;
}

}  // namespace

uint64_t parse_count(const std::string& option, const std::string& text, uint64_t min, uint64_t max) {
  uint64_t v = 0;
  const std::string want = "a whole number from " + std::to_string(min) + " to " + std::to_string(max);
  if (!digits_to_u64(text, v) || v < min || v > max) bad(option, want, text);
  return v;
}

double parse_seconds(const std::string& option, const std::string& text) {
  const std::string want = "a positive number of seconds (e.g. 5 or 0.5), at most 1000000000";
  int dots = 0, digits = 0;
  for (char ch : text) {
    if (ch == '.') ++dots;
    else if (ch >= '0' && ch <= '9') ++digits;
    else bad(option, want, text);
  }
  if (digits == 0 || dots > 1 || text.size() > 40) bad(option, want, text);
  const double v = std::strtod(text.c_str(), nullptr);
  if (!std::isfinite(v) || v < 0.001 || v > 1e9) bad(option, want, text);
  return v;
}

uint64_t parse_seed(const std::string& option, const std::string& text) {
  uint64_t v = 0;
  if (!digits_to_u64(text, v)) bad(option, "a seed, a whole number from 0 to 18446744073709551615", text);
  return v;
}

uint64_t count_arg(const boost::program_options::variables_map& vm, const std::string& option, uint64_t min,
                   uint64_t max) {
  return parse_count(option, vm[option].as<std::string>(), min, max);
}

std::optional<uint64_t> count_arg_opt(const boost::program_options::variables_map& vm, const std::string& option,
                                      uint64_t min, uint64_t max) {
  if (!vm.count(option)) return std::nullopt;
  return count_arg(vm, option, min, max);
}

double seconds_arg(const boost::program_options::variables_map& vm, const std::string& option) {
  return parse_seconds(option, vm[option].as<std::string>());
}

std::optional<double> seconds_arg_opt(const boost::program_options::variables_map& vm, const std::string& option) {
  if (!vm.count(option)) return std::nullopt;
  return seconds_arg(vm, option);
}

uint64_t seed_arg(const boost::program_options::variables_map& vm, const std::string& option) {
  return parse_seed(option, vm[option].as<std::string>());
}

}  // namespace gridlock::cli
