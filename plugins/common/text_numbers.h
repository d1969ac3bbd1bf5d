// Strict, locale-independent number parsing for text mesh formats: a token is
// a number only if the whole token is one. This rejects what tolerant readers
// silently turn into 0 or NaN: "3.1+e2", "1.#IND", "nan", "inf", "two".
// Plus whitespace tokenising helpers shared by the OBJ, PLY and OFF readers.
#pragma once

#include <charconv>
#include <cstdint>
#include <limits>
#include <string_view>
#include <system_error>

namespace prism_plugins {

inline bool isBlank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

// Splits off the next run of non-blank characters from `rest` (which must not
// hold line breaks). Returns an empty view at the end.
inline std::string_view nextToken(std::string_view& rest) {
  std::size_t i = 0;
  while (i < rest.size() && isBlank(rest[i])) ++i;
  std::size_t j = i;
  while (j < rest.size() && !isBlank(rest[j])) ++j;
  std::string_view token = rest.substr(i, j - i);
  rest.remove_prefix(j);
  return token;
}

inline std::string_view trimmed(std::string_view s) {
  while (!s.empty() && isBlank(s.front())) s.remove_prefix(1);
  while (!s.empty() && isBlank(s.back())) s.remove_suffix(1);
  return s;
}

// Decimal float with optional sign and exponent ("-.5", "2.e1", "+1E2").
// Denormals are accepted (strtof-style underflow is not an error here).
inline bool parseFloat(std::string_view token, float& out) {
  const char* b = token.data();
  const char* e = b + token.size();
  bool negative = false;
  if (b != e && (*b == '+' || *b == '-')) {
    negative = *b == '-';
    ++b;
  }
  // from_chars also reads "nan", "inf" and "infinity": only digits or '.' may start a number.
  if (b == e || !((*b >= '0' && *b <= '9') || *b == '.')) return false;
  float value = 0;
  auto result = std::from_chars(b, e, value, std::chars_format::general);
  if (result.ptr != e) return false;
  if (result.ec == std::errc::result_out_of_range) {
    double wide = 0;
    auto again = std::from_chars(b, e, wide, std::chars_format::general);
    if (again.ec != std::errc() || again.ptr != e) return false;
    if (!(wide < static_cast<double>(std::numeric_limits<float>::min()))) return false;  // too large for float
    value = static_cast<float>(wide);
  } else if (result.ec != std::errc()) {
    return false;
  }
  out = negative ? -value : value;
  return true;
}

// Decimal integer with optional sign.
inline bool parseInt(std::string_view token, std::int64_t& out) {
  const char* b = token.data();
  const char* e = b + token.size();
  bool negative = false;
  if (b != e && (*b == '+' || *b == '-')) {
    negative = *b == '-';
    ++b;
  }
  if (b == e || *b < '0' || *b > '9') return false;
  std::uint64_t magnitude = 0;
  auto result = std::from_chars(b, e, magnitude);
  if (result.ec != std::errc() || result.ptr != e) return false;
  if (magnitude > static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max())) return false;
  out = negative ? -static_cast<std::int64_t>(magnitude) : static_cast<std::int64_t>(magnitude);
  return true;
}

// Shortens a token for an error message (it may be a megabyte of garbage).
inline std::string_view quoted(std::string_view token) { return token.substr(0, 40); }

}  // namespace prism_plugins
