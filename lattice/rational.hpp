// Rational: exact time and coordinates, never floating point in a verdict.
//
// A value num/den with den > 0 and gcd(num, den) == 1, both 64-bit.
// Comparisons go through 128-bit products, so they never overflow.
// Arithmetic that would overflow 64 bits throws std::overflow_error; callers
// that read user input check ranges first (see lattice/schedule.hpp).
#pragma once

#include <cstdint>
#include <numeric>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

namespace gridlock {

class Rational {
 public:
  constexpr Rational() = default;
  constexpr Rational(int64_t n) : num_(n) {}  // NOLINT: integers are rationals
  Rational(int64_t n, int64_t d) { set(static_cast<__int128>(n), static_cast<__int128>(d)); }

  int64_t num() const { return num_; }
  int64_t den() const { return den_; }
  bool is_integer() const { return den_ == 1; }

  // Parses "7", "-3", "3/2", "-10/4" (reduced). Rejects anything else,
  // zero denominators and values whose parts do not fit in 64 bits.
  static std::optional<Rational> parse(std::string_view text);
  std::string str() const {
    return den_ == 1 ? std::to_string(num_) : std::to_string(num_) + "/" + std::to_string(den_);
  }
  // For drawing only (SVG coordinates); never used in a verdict.
  double approx() const { return static_cast<double>(num_) / static_cast<double>(den_); }

  friend Rational operator+(const Rational& a, const Rational& b) {
    Rational r;
    r.set(static_cast<__int128>(a.num_) * b.den_ + static_cast<__int128>(b.num_) * a.den_,
          static_cast<__int128>(a.den_) * b.den_);
    return r;
  }
  friend Rational operator-(const Rational& a, const Rational& b) { return a + Rational(-b.num_, b.den_); }
  friend Rational operator*(const Rational& a, const Rational& b) {
    Rational r;
    r.set(static_cast<__int128>(a.num_) * b.num_, static_cast<__int128>(a.den_) * b.den_);
    return r;
  }
  friend Rational operator/(const Rational& a, const Rational& b) {
    if (b.num_ == 0) throw std::domain_error("rational division by zero");
    Rational r;
    r.set(static_cast<__int128>(a.num_) * b.den_, static_cast<__int128>(a.den_) * b.num_);
    return r;
  }
  friend bool operator==(const Rational& a, const Rational& b) { return a.num_ == b.num_ && a.den_ == b.den_; }
  friend auto operator<=>(const Rational& a, const Rational& b) {
    __int128 l = static_cast<__int128>(a.num_) * b.den_, r = static_cast<__int128>(b.num_) * a.den_;
    return l < r ? std::strong_ordering::less : l > r ? std::strong_ordering::greater : std::strong_ordering::equal;
  }

 private:
  static __int128 gcd128(__int128 a, __int128 b) {
    if (a < 0) a = -a;
    if (b < 0) b = -b;
    while (b != 0) {
      __int128 t = a % b;
      a = b;
      b = t;
    }
    return a;
  }
  void set(__int128 n, __int128 d) {
    if (d == 0) throw std::domain_error("rational with zero denominator");
    if (d < 0) n = -n, d = -d;
    __int128 g = gcd128(n, d);
    if (g > 1) n /= g, d /= g;
    constexpr __int128 lim = static_cast<__int128>(INT64_MAX);
    if (n > lim || n < -lim || d > lim) throw std::overflow_error("rational overflow");
    num_ = static_cast<int64_t>(n);
    den_ = static_cast<int64_t>(d);
  }
  int64_t num_ = 0;
  int64_t den_ = 1;
};

inline std::optional<Rational> Rational::parse(std::string_view text) {
  auto parse_int = [](std::string_view s, bool allow_sign) -> std::optional<int64_t> {
    if (s.empty()) return std::nullopt;
    bool neg = false;
    size_t i = 0;
    if (allow_sign && (s[0] == '-' || s[0] == '+')) neg = s[0] == '-', i = 1;
    if (i == s.size()) return std::nullopt;
    __int128 v = 0;
    for (; i < s.size(); ++i) {
      if (s[i] < '0' || s[i] > '9') return std::nullopt;
      v = v * 10 + (s[i] - '0');
      if (v > static_cast<__int128>(INT64_MAX)) return std::nullopt;
    }
    return static_cast<int64_t>(neg ? -v : v);
  };
  size_t slash = text.find('/');
  auto n = parse_int(text.substr(0, slash), true);
  if (!n) return std::nullopt;
  if (slash == std::string_view::npos) return Rational(*n);
  auto d = parse_int(text.substr(slash + 1), false);
  if (!d || *d == 0) return std::nullopt;
  return Rational(*n, *d);
}

}  // namespace gridlock
