// Value sources for the PLY body reader: the same row-reading code runs over
// ascii text (one row per line) or binary data (either byte order). Each
// source is bounded by the bytes it was given and throws PluginFailure at the
// end of data instead of reading past it.
#pragma once

#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <string_view>

#include "common/plugin_failure.h"
#include "common/text_numbers.h"
#include "ply/ply_header.h"

namespace prism_plugins {

// Where a value is being read, for messages.
struct PlyRowPlace {
  const std::string* element = nullptr;
  std::uint64_t row = 0;
  std::string describe() const { return "element '" + *element + "', row " + std::to_string(row); }
};

class PlyAsciiSource {
 public:
  PlyAsciiSource(std::string_view body, std::uint64_t first_line) : m_body(body), m_line(first_line - 1) {}

  void beginRow(const PlyRowPlace& place) {
    m_place = place;
    for (;;) {
      if (m_pos >= m_body.size()) parseError("the file ends before " + place.describe(), m_line);
      std::size_t end = m_pos;
      while (end < m_body.size() && m_body[end] != '\n' && m_body[end] != '\r') ++end;
      m_rest = m_body.substr(m_pos, end - m_pos);
      m_pos = end;
      if (m_pos < m_body.size() && m_body[m_pos] == '\r') ++m_pos;
      if (m_pos < m_body.size() && m_body[m_pos] == '\n') ++m_pos;
      ++m_line;
      if (!trimmed(m_rest).empty()) return;  // blank lines between rows are tolerated
    }
  }
  void endRow() {
    if (!nextToken(m_rest).empty()) parseError(m_place.describe() + " has more values than its properties", m_line);
  }
  double number(PlyType type) {
    std::string_view t = token();
    if (plyIsInteger(type)) return static_cast<double>(integer(type, t));
    float v = 0;
    if (!parseFloat(t, v))
      parseError(m_place.describe() + ": '" + std::string(quoted(t)) + "' is not a finite decimal number", m_line);
    return v;
  }
  std::int64_t integer(PlyType type) { return integer(type, token()); }
  // Upper bound on the values left in the row (each takes 2 bytes).
  std::uint64_t valuesLeftBound() const { return m_rest.size() / 2 + 1; }
  void skip(PlyType type, std::uint64_t n) {
    for (std::uint64_t i = 0; i < n; ++i) number(type);
  }
  bool atEnd() {
    while (m_pos < m_body.size() && (isBlank(m_body[m_pos]) || m_body[m_pos] == '\n')) ++m_pos;
    return m_pos >= m_body.size();
  }
  std::uint64_t line() const { return m_line; }
  std::uint64_t offset() const { return 0; }

 private:
  std::string_view token() {
    std::string_view t = nextToken(m_rest);
    if (t.empty()) parseError(m_place.describe() + " has fewer values than its properties", m_line);
    return t;
  }
  std::int64_t integer(PlyType type, std::string_view t) {
    std::int64_t v = 0;
    if (!parseInt(t, v)) parseError(m_place.describe() + ": '" + std::string(quoted(t)) + "' is not an integer", m_line);
    std::int64_t lo = 0, hi = 0;
    switch (type) {
      case PlyType::Int8: lo = -128; hi = 127; break;
      case PlyType::UInt8: hi = 255; break;
      case PlyType::Int16: lo = -32768; hi = 32767; break;
      case PlyType::UInt16: hi = 65535; break;
      case PlyType::Int32: lo = std::numeric_limits<std::int32_t>::min(); hi = std::numeric_limits<std::int32_t>::max(); break;
      default: hi = std::numeric_limits<std::uint32_t>::max(); break;  // uint32 (floats never get here)
    }
    if (v < lo || v > hi) parseError(m_place.describe() + ": " + std::to_string(v) + " does not fit its type", m_line);
    return v;
  }

  std::string_view m_body;
  std::size_t m_pos = 0;
  std::uint64_t m_line;
  std::string_view m_rest;
  PlyRowPlace m_place;
};

class PlyBinarySource {
 public:
  PlyBinarySource(std::string_view body, std::size_t body_offset, bool big_endian)
      : m_body(body), m_body_offset(body_offset), m_swap(big_endian != hostIsBigEndian()) {}

  void beginRow(const PlyRowPlace& place) { m_place = place; }
  void endRow() {}
  double number(PlyType type) {
    switch (type) {
      case PlyType::Int8: return read<std::int8_t>();
      case PlyType::UInt8: return read<std::uint8_t>();
      case PlyType::Int16: return read<std::int16_t>();
      case PlyType::UInt16: return read<std::uint16_t>();
      case PlyType::Int32: return read<std::int32_t>();
      case PlyType::UInt32: return read<std::uint32_t>();
      case PlyType::Float32: return read<float>();
      case PlyType::Float64: return read<double>();
    }
    return 0;
  }
  std::int64_t integer(PlyType type) { return static_cast<std::int64_t>(number(type)); }  // integer types only
  std::uint64_t valuesLeftBound() const { return m_body.size() - m_pos; }
  void skip(PlyType type, std::uint64_t n) {
    std::uint64_t bytes = n * plySize(type);
    if (n > m_body.size() || bytes > m_body.size() - m_pos) truncated();
    m_pos += static_cast<std::size_t>(bytes);
  }
  bool atEnd() const { return m_pos >= m_body.size(); }
  std::uint64_t line() const { return 0; }
  std::uint64_t offset() const { return m_body_offset + m_pos; }
  std::uint64_t bytesLeft() const { return m_body.size() - m_pos; }

 private:
  static bool hostIsBigEndian() {
    const std::uint16_t probe = 1;
    unsigned char first;
    std::memcpy(&first, &probe, 1);
    return first == 0;
  }
  [[noreturn]] void truncated() const {
    parseError("the file ends inside " + m_place.describe(), 0, m_body_offset + m_pos);
  }
  template <typename T>
  T read() {
    if (sizeof(T) > m_body.size() - m_pos) truncated();
    unsigned char raw[sizeof(T)];
    std::memcpy(raw, m_body.data() + m_pos, sizeof(T));
    m_pos += sizeof(T);
    if (m_swap)
      for (std::size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(raw[i], raw[sizeof(T) - 1 - i]);
    T value;
    std::memcpy(&value, raw, sizeof(T));
    return value;
  }

  std::string_view m_body;
  std::size_t m_body_offset;
  bool m_swap;
  std::size_t m_pos = 0;
  PlyRowPlace m_place;
};

}  // namespace prism_plugins
