// The message for a byte an input reader refuses (the .grid, DIMACS,
// schedule and model readers share it; the caller adds "FILE:LINE: ").
// Every refusal keeps the form "binary input: byte 0xNN at column C" that
// scripts match on, and says more where a user can act on it:
//   - a UTF-8 byte-order mark (EF BB BF) at the start of line 1, which some
//     editors write: named as such, with the way out;
//   - a byte >= 0x80 elsewhere outside a comment: UTF-8 is read in comments
//     only (names and numbers are ASCII).
#pragma once

#include <cstdio>
#include <string>
#include <string_view>

namespace gridlock {

// line: the whole line as read (without its '\n'); k: the index of the
// refused byte in it; line_no: its 1-based line. O(1).
inline std::string refused_byte_message(std::string_view line, size_t k, long line_no) {
  const auto b = static_cast<unsigned char>(line[k]);
  char hex[8];
  std::snprintf(hex, sizeof hex, "0x%02x", b);
  std::string msg = std::string("binary input: byte ") + hex + " at column " + std::to_string(k + 1);
  if (line_no == 1 && k == 0 && line.substr(0, 3) == "\xef\xbb\xbf")
    return msg + " (a UTF-8 byte-order mark: save the file without one)";
  if (b >= 0x80) return msg + " (UTF-8 is read in comments only)";
  return msg;
}

}  // namespace gridlock
