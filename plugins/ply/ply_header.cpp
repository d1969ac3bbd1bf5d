// PLY header parsing; see ply_header.h.
#include "ply/ply_header.h"

#include <algorithm>

#include "common/plugin_failure.h"
#include "common/text_numbers.h"

namespace prism_plugins {

namespace {

struct TypeName {
  const char* name;
  PlyType type;
};
// Both the PLY 1.0 names and the sized aliases later writers use.
const TypeName kTypeNames[] = {
    {"char", PlyType::Int8},     {"int8", PlyType::Int8},       {"uchar", PlyType::UInt8},
    {"uint8", PlyType::UInt8},   {"short", PlyType::Int16},     {"int16", PlyType::Int16},
    {"ushort", PlyType::UInt16}, {"uint16", PlyType::UInt16},   {"int", PlyType::Int32},
    {"int32", PlyType::Int32},   {"uint", PlyType::UInt32},     {"uint32", PlyType::UInt32},
    {"float", PlyType::Float32}, {"float32", PlyType::Float32}, {"double", PlyType::Float64},
    {"float64", PlyType::Float64},
};

bool parseType(std::string_view name, PlyType& out) {
  for (const TypeName& t : kTypeNames)
    if (name == t.name) {
      out = t.type;
      return true;
    }
  return false;
}

// The fewest bytes one row of `e` can take in the body.
std::uint64_t minimumRowBytes(const PlyElement& e, PlyFormat format) {
  std::uint64_t bytes = 0;
  for (const PlyProperty& p : e.properties) {
    if (format == PlyFormat::Ascii)
      bytes += 2;  // one digit and one separator (a list's count alone, for an empty list)
    else
      bytes += plySize(p.is_list ? p.count_type : p.type);
  }
  return bytes;
}

}  // namespace

std::size_t plySize(PlyType t) {
  switch (t) {
    case PlyType::Int8: case PlyType::UInt8: return 1;
    case PlyType::Int16: case PlyType::UInt16: return 2;
    case PlyType::Int32: case PlyType::UInt32: case PlyType::Float32: return 4;
    case PlyType::Float64: return 8;
  }
  return 0;
}

bool plyIsInteger(PlyType t) { return t != PlyType::Float32 && t != PlyType::Float64; }

int PlyElement::find(std::string_view property) const {
  for (std::size_t i = 0; i < properties.size(); ++i)
    if (properties[i].name == property) return static_cast<int>(i);
  return -1;
}

const PlyElement* PlyHeader::find(std::string_view element) const {
  for (const PlyElement& e : elements)
    if (e.name == element) return &e;
  return nullptr;
}

PlyHeader parsePlyHeader(std::string_view bytes) {
  PlyHeader h;
  std::size_t pos = 0;
  std::uint64_t line_number = 0;
  bool have_format = false;
  bool ended = false;
  while (!ended) {
    if (pos >= bytes.size()) parseError("the header has no end_header line", line_number);
    if (pos > kMaxHeaderBytes)
      parseError("no end_header within the first " + std::to_string(kMaxHeaderBytes) + " bytes", line_number);
    // Header lines end in "\n", "\r\n" or "\r".
    std::size_t end = pos;
    while (end < bytes.size() && bytes[end] != '\n' && bytes[end] != '\r') ++end;
    std::string_view line = bytes.substr(pos, end - pos);
    pos = end;
    if (pos < bytes.size() && bytes[pos] == '\r') ++pos;
    if (pos < bytes.size() && bytes[pos] == '\n') ++pos;  // after '\r' too: "\r\n" is one break
    ++line_number;
    if (line.find('\0') != std::string_view::npos) parseError("binary data inside the header", line_number);

    std::string_view rest = line;
    std::string_view keyword = nextToken(rest);
    if (line_number == 1) {
      if (keyword != "ply" || !trimmed(rest).empty()) parseError("not a PLY file: the first line is not 'ply'", 1);
      continue;
    }
    if (keyword == "format") {
      std::string_view kind = nextToken(rest), version = nextToken(rest);
      if (have_format) parseError("a second format line", line_number);
      if (kind == "ascii") h.format = PlyFormat::Ascii;
      else if (kind == "binary_little_endian") h.format = PlyFormat::BinaryLittleEndian;
      else if (kind == "binary_big_endian") h.format = PlyFormat::BinaryBigEndian;
      else parseError("unknown format '" + std::string(quoted(kind)) + "'", line_number);
      if (version != "1.0" && version != "1") parseError("unknown PLY version '" + std::string(quoted(version)) + "'", line_number);
      if (!nextToken(rest).empty()) parseError("extra words on the format line", line_number);
      have_format = true;
    } else if (keyword == "comment" || keyword == "obj_info") {
      // free text
    } else if (keyword == "element") {
      PlyElement e;
      e.name = std::string(nextToken(rest));
      std::int64_t count = -1;
      std::string_view count_text = nextToken(rest);
      if (e.name.empty() || !parseInt(count_text, count) || count < 0 || !nextToken(rest).empty())
        parseError("expected 'element <name> <count>'", line_number);
      if (h.find(e.name) != nullptr) parseError("element '" + e.name + "' declared twice", line_number);
      e.count = static_cast<std::uint64_t>(count);
      e.header_line = line_number;
      h.elements.push_back(std::move(e));
    } else if (keyword == "property") {
      if (h.elements.empty()) parseError("a property before any element", line_number);
      PlyProperty p;
      std::string_view type = nextToken(rest);
      if (type == "list") {
        p.is_list = true;
        if (!parseType(nextToken(rest), p.count_type) || !plyIsInteger(p.count_type))
          parseError("a list's count type must be an integer type", line_number);
        type = nextToken(rest);
      }
      if (!parseType(type, p.type)) parseError("unknown property type '" + std::string(quoted(type)) + "'", line_number);
      p.name = std::string(nextToken(rest));
      if (p.name.empty() || !nextToken(rest).empty()) parseError("expected 'property <type> <name>'", line_number);
      PlyElement& e = h.elements.back();
      if (e.find(p.name) >= 0) parseError("property '" + p.name + "' declared twice in '" + e.name + "'", line_number);
      e.properties.push_back(std::move(p));
    } else if (keyword == "end_header") {
      if (!trimmed(rest).empty()) parseError("extra words after end_header", line_number);
      ended = true;
    } else {
      parseError("unknown header line starting '" + std::string(quoted(keyword)) +
                     "' (expected format, element, property, comment, obj_info or end_header)",
                 line_number);
    }
  }
  if (!have_format) parseError("the header has no format line", line_number);
  h.body_offset = pos;
  h.body_line = line_number + 1;

  // Every row must consume at least one byte, or a huge count would spin
  // without reading; and all rows together must fit in what is left.
  std::uint64_t available = bytes.size() - pos;
  std::uint64_t needed = 0;
  for (const PlyElement& e : h.elements) {
    if (e.properties.empty() && e.count > 0)
      parseError("element '" + e.name + "' has rows but no properties", e.header_line);
    std::uint64_t row = minimumRowBytes(e, h.format);
    std::uint64_t slack = h.format == PlyFormat::Ascii ? 1 : 0;  // the last row may lack its line break
    if (row > 0 && e.count > (available + slack) / row)
      parseError("element '" + e.name + "' claims " + std::to_string(e.count) + " rows, more than the " +
                     std::to_string(available) + " bytes after the header can hold",
                 e.header_line);
    needed += e.count * row;
    if (needed > available + slack)
      parseError("the elements declared need more than the " + std::to_string(available) +
                     " bytes after the header",
                 e.header_line);
  }
  return h;
}

}  // namespace prism_plugins
