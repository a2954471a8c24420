// The one parser of numeric command-line options: counts, limits, seeds,
// seconds. Every subcommand declares such options as strings
// (po::value<std::string>()) and reads them through these functions, so that
// every option rejects the same things the same way, naming the option:
//
//   gridlock: error: --count: want a whole number from 1 to 18446744073709551615, got '-3'
//
// Rejected everywhere: a sign ('-5', '+5'), anything but decimal digits
// (seconds: digits with at most one '.'), overflow, and values below the
// minimum (zero is rejected wherever it is meaningless; pass min = 0 where 0
// means something, e.g. "no limit").
//
// Adopting them in a new subcommand:
//   ("count", po::value<std::string>(), "formulas in the campaign")
//   ...
//   uint64_t n = cli::count_arg(vm, "count", 1);                 // required
//   std::optional<double> t = cli::seconds_arg_opt(vm, "timeout"); // optional
#pragma once

#include <cstdint>
#include <limits>
#include <optional>
#include <string>

#include <boost/program_options.hpp>

namespace gridlock::cli {

// A whole number min..max written in decimal digits. option is the name
// without dashes ("count"); errors say "--count: ...".
uint64_t parse_count(const std::string& option, const std::string& text, uint64_t min = 1,
                     uint64_t max = std::numeric_limits<uint64_t>::max());

// A positive number of seconds (digits, optionally one '.' and more digits),
// at least 0.001 and at most 10^9. Zero, negatives, "inf", "nan" and
// exponents are rejected.
double parse_seconds(const std::string& option, const std::string& text);

// A seed: any whole number 0 to 2^64-1 in decimal digits (no sign).
uint64_t parse_seed(const std::string& option, const std::string& text);

// The same, reading vm[option] (declared as po::value<std::string>()).
// The _opt forms return nullopt when the option is absent; the others
// require it to be present (give it a default_value or check vm.count).
uint64_t count_arg(const boost::program_options::variables_map& vm, const std::string& option, uint64_t min = 1,
                   uint64_t max = std::numeric_limits<uint64_t>::max());
std::optional<uint64_t> count_arg_opt(const boost::program_options::variables_map& vm, const std::string& option,
                                      uint64_t min = 1, uint64_t max = std::numeric_limits<uint64_t>::max());
double seconds_arg(const boost::program_options::variables_map& vm, const std::string& option);
std::optional<double> seconds_arg_opt(const boost::program_options::variables_map& vm, const std::string& option);
uint64_t seed_arg(const boost::program_options::variables_map& vm, const std::string& option);

// An int-valued count (for options stored as int by the library).
inline int int_arg(const boost::program_options::variables_map& vm, const std::string& option, int min, int max) {
  return static_cast<int>(count_arg(vm, option, static_cast<uint64_t>(min), static_cast<uint64_t>(max)));
}

}  // namespace gridlock::cli
