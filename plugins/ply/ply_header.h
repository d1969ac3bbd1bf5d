// The PLY header: format, elements, properties, parsed strictly and within a
// bounded size (a header that never reaches end_header fails after
// kMaxHeaderBytes instead of reading on forever). Element counts are checked
// against the bytes after the header, using the smallest size a row can have,
// before anyone allocates for them.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace prism_plugins {

constexpr std::size_t kMaxHeaderBytes = 1 << 20;

enum class PlyFormat { Ascii, BinaryLittleEndian, BinaryBigEndian };

enum class PlyType : std::uint8_t { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

std::size_t plySize(PlyType t);
bool plyIsInteger(PlyType t);

struct PlyProperty {
  std::string name;
  bool is_list = false;
  PlyType type = PlyType::Float32;       // the value type (list entries for lists)
  PlyType count_type = PlyType::UInt8;   // lists only
};

struct PlyElement {
  std::string name;
  std::uint64_t count = 0;
  std::vector<PlyProperty> properties;
  std::uint64_t header_line = 0;

  int find(std::string_view property) const;  // index, or -1
};

struct PlyHeader {
  PlyFormat format = PlyFormat::Ascii;
  std::vector<PlyElement> elements;
  std::size_t body_offset = 0;  // first byte after end_header and its line break
  std::uint64_t body_line = 0;  // line number of the first body line (ascii)

  const PlyElement* find(std::string_view element) const;
};

// Throws PluginFailure with the header line on anything malformed.
PlyHeader parsePlyHeader(std::string_view bytes);

}  // namespace prism_plugins
