// PLY body reader; see ply_body.h.
#include "ply/ply_body.h"

#include <array>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "ply/ply_sources.h"

namespace prism_plugins {

namespace {

// double -> float without undefined behaviour: values beyond float's range
// become infinities (which the host then refuses as non-finite positions).
float toFloat(double v) {
  if (v > std::numeric_limits<float>::max()) return std::numeric_limits<float>::infinity();
  if (v < -std::numeric_limits<float>::max()) return -std::numeric_limits<float>::infinity();
  return static_cast<float>(v);  // NaN stays NaN
}

// Where the vertex attributes prism uses sit among a vertex row's properties.
struct VertexLayout {
  int xyz[3] = {-1, -1, -1};
  int normal[3] = {-1, -1, -1};
  int color[3] = {-1, -1, -1};
  double color_scale = 1;  // 1/255 for uchar colours, 1/65535 for ushort
  int uv[2] = {-1, -1};

  bool has(const int (&slots)[3]) const { return slots[0] >= 0 && slots[1] >= 0 && slots[2] >= 0; }
};

// Finds the first of several spellings of each of N coordinates.
template <std::size_t N>
bool findAll(const PlyElement& e, const std::array<std::array<const char*, N>, 4>& spellings, int (&out)[N]) {
  for (const auto& names : spellings) {
    bool found = true;
    for (std::size_t i = 0; i < N; ++i) {
      out[i] = names[i] != nullptr ? e.find(names[i]) : -1;
      found = found && out[i] >= 0 && !e.properties[out[i]].is_list;
    }
    if (found) return true;
  }
  for (int& o : out) o = -1;
  return false;
}

VertexLayout vertexLayout(const PlyElement& e) {
  VertexLayout v;
  if (!findAll<3>(e, {{{"x", "y", "z"}, {nullptr, nullptr, nullptr}, {nullptr, nullptr, nullptr}, {nullptr, nullptr, nullptr}}}, v.xyz))
    parseError("element 'vertex' lacks scalar x, y and z properties", e.header_line);
  findAll<3>(e, {{{"nx", "ny", "nz"}, {"normal_x", "normal_y", "normal_z"}, {nullptr, nullptr, nullptr}, {nullptr, nullptr, nullptr}}}, v.normal);
  if (findAll<3>(e, {{{"red", "green", "blue"}, {"r", "g", "b"}, {"diffuse_red", "diffuse_green", "diffuse_blue"}, {nullptr, nullptr, nullptr}}}, v.color)) {
    PlyType t = e.properties[v.color[0]].type;
    v.color_scale = t == PlyType::UInt16 || t == PlyType::Int16 ? 1.0 / 65535 : plyIsInteger(t) ? 1.0 / 255 : 1.0;
  }
  findAll<2>(e, {{{"u", "v"}, {"s", "t"}, {"texture_u", "texture_v"}, {"texture_s", "texture_t"}}}, v.uv);
  return v;
}

// The list property holding a face's (or strip's) vertex indices.
int indexList(const PlyElement& e) {
  int i = e.find("vertex_indices");
  if (i < 0) i = e.find("vertex_index");
  if (i < 0 || !e.properties[i].is_list)
    parseError("element '" + e.name + "' has no vertex_indices list", e.header_line);
  if (!plyIsInteger(e.properties[i].type))
    throw PluginFailure(PRISM_PLUGIN_ERROR_UNSUPPORTED, "element '" + e.name + "' stores vertex indices as floats",
                        e.header_line);
  return i;
}

template <typename Source>
class BodyReader {
 public:
  BodyReader(Source& source, const PlyHeader& header, SinkWriter& sink) : m_in(source), m_header(header), m_sink(sink) {
    if (const PlyElement* v = header.find("vertex")) m_vertex_count = v->count;
    if (m_vertex_count > 0xffffffffull) parseError("more than 2^32-1 vertices", header.find("vertex")->header_line);
  }

  void read() {
    for (const PlyElement& e : m_header.elements) {
      if (e.name == "vertex") readVertices(e);
      else if (e.name == "face") readPolygons(e, false);
      else if (e.name == "tristrips") readPolygons(e, true);
      else skipElement(e);
    }
    if (!m_in.atEnd()) m_sink.warning("data after the last element ignored");
  }

 private:
  // Reads the row's property `p` when it is a list: its count, bounded by what is left.
  std::uint64_t listCount(const PlyProperty& p, const PlyRowPlace& place) {
    std::int64_t n = m_in.integer(p.count_type);
    if (n < 0 || static_cast<std::uint64_t>(n) > m_in.valuesLeftBound())
      parseError(place.describe() + ": list '" + p.name + "' claims " + std::to_string(n) +
                     " entries, more than the data left holds",
                 m_in.line(), m_in.offset());
    return static_cast<std::uint64_t>(n);
  }

  void readVertices(const PlyElement& e) {
    VertexLayout layout = vertexLayout(e);
    std::vector<double> values(e.properties.size());
    PlyRowPlace place{&e.name, 0};
    for (std::uint64_t row = 0; row < e.count; ++row) {
      place.row = row;
      m_in.beginRow(place);
      for (std::size_t i = 0; i < e.properties.size(); ++i) {
        const PlyProperty& p = e.properties[i];
        if (p.is_list) m_in.skip(p.type, listCount(p, place));
        else values[i] = m_in.number(p.type);
      }
      m_in.endRow();
      auto f = [&](int slot) { return toFloat(values[static_cast<std::size_t>(slot)]); };
      m_sink.position(f(layout.xyz[0]), f(layout.xyz[1]), f(layout.xyz[2]));
      if (layout.has(layout.normal)) m_sink.normal(f(layout.normal[0]), f(layout.normal[1]), f(layout.normal[2]));
      if (layout.has(layout.color))
        m_sink.color(toFloat(values[layout.color[0]] * layout.color_scale),
                     toFloat(values[layout.color[1]] * layout.color_scale),
                     toFloat(values[layout.color[2]] * layout.color_scale));
      if (layout.uv[0] >= 0) m_sink.texcoord(f(layout.uv[0]), f(layout.uv[1]));
    }
  }

  std::uint32_t checkedIndex(std::int64_t index, const PlyRowPlace& place) {
    if (index < 0 || static_cast<std::uint64_t>(index) >= m_vertex_count)
      parseError(place.describe() + " uses vertex " + std::to_string(index) + ", but there are " +
                     std::to_string(m_vertex_count) + " vertices (numbered from 0)",
                 m_in.line(), m_in.offset());
    return static_cast<std::uint32_t>(index);
  }

  void readPolygons(const PlyElement& e, bool strips) {
    if (e.count == 0) return;
    const int list = indexList(e);
    PlyRowPlace place{&e.name, 0};
    for (std::uint64_t row = 0; row < e.count; ++row) {
      place.row = row;
      m_in.beginRow(place);
      for (std::size_t i = 0; i < e.properties.size(); ++i) {
        const PlyProperty& p = e.properties[i];
        if (static_cast<int>(i) != list) {
          if (p.is_list) m_in.skip(p.type, listCount(p, place));
          else m_in.number(p.type);
          continue;
        }
        std::uint64_t n = listCount(p, place);
        if (strips) {
          readStrip(p, n, place);
        } else {
          if (n < 3) parseError(place.describe() + " has " + std::to_string(n) + " corners; at least 3 are needed", m_in.line(), m_in.offset());
          m_corners.resize(static_cast<std::size_t>(n));
          for (std::uint64_t k = 0; k < n; ++k) m_corners[k] = checkedIndex(m_in.integer(p.type), place);
        }
      }
      m_in.endRow();
      if (!strips) m_sink.face(m_corners.data(), static_cast<std::uint32_t>(m_corners.size()), -1);
    }
  }

  // A triangle strip: -1 restarts it; triangle k joins the last two vertices
  // with the next, flipping every other one to keep the winding. Triangles
  // with a repeated vertex (the usual way strips are stitched) are skipped.
  void readStrip(const PlyProperty& p, std::uint64_t n, const PlyRowPlace& place) {
    std::uint32_t a = 0, b = 0;
    int have = 0;
    bool odd = false;
    for (std::uint64_t k = 0; k < n; ++k) {
      std::int64_t raw = m_in.integer(p.type);
      if (raw == -1) {
        have = 0;
        odd = false;
        continue;
      }
      std::uint32_t c = checkedIndex(raw, place);
      if (have == 2) {
        std::uint32_t tri[3] = {odd ? b : a, odd ? a : b, c};
        if (a != b && b != c && a != c) m_sink.face(tri, 3, -1);
        odd = !odd;
        a = b;
        b = c;
      } else {
        (have == 0 ? a : b) = c;
        ++have;
      }
    }
  }

  void skipElement(const PlyElement& e) {
    PlyRowPlace place{&e.name, 0};
    for (std::uint64_t row = 0; row < e.count; ++row) {
      place.row = row;
      m_in.beginRow(place);
      for (const PlyProperty& p : e.properties) {
        if (p.is_list) m_in.skip(p.type, listCount(p, place));
        else m_in.number(p.type);
      }
      m_in.endRow();
    }
  }

  Source& m_in;
  const PlyHeader& m_header;
  SinkWriter& m_sink;
  std::uint64_t m_vertex_count = 0;
  std::vector<std::uint32_t> m_corners;
};

}  // namespace

void readPlyBody(std::string_view bytes, const PlyHeader& header, SinkWriter& sink) {
  std::uint64_t faces = 0;
  if (const PlyElement* f = header.find("face")) faces = f->count;
  sink.begin(header.find("vertex") != nullptr ? header.find("vertex")->count : 0, faces);
  std::string_view body = bytes.substr(header.body_offset);
  if (header.format == PlyFormat::Ascii) {
    PlyAsciiSource source(body, header.body_line);
    BodyReader<PlyAsciiSource>(source, header, sink).read();
  } else {
    PlyBinarySource source(body, header.body_offset, header.format == PlyFormat::BinaryBigEndian);
    BodyReader<PlyBinarySource>(source, header, sink).read();
  }
}

}  // namespace prism_plugins
