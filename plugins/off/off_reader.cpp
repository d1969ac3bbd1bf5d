// OFF reader; see off_reader.h.
#include "off/off_reader.h"

#include <cstdint>
#include <string>
#include <vector>

#include "common/text_numbers.h"
#include "off/off_tokens.h"

namespace prism_plugins {

namespace {

struct OffLayout {
  bool texcoords = false;  // ST prefix: s t per vertex
  bool colors = false;     // C prefix: a colour per vertex
  bool normals = false;    // N prefix: nx ny nz per vertex
  bool four_d = false;     // 4 prefix: x y z w
  bool dimension = false;  // n prefix: the dimension follows the keyword
};

// "[ST][C][N][4][n]OFF" -> layout; false if `t` is not such a keyword.
bool parseKeyword(std::string_view t, OffLayout& k) {
  auto take = [&t](std::string_view prefix) {
    if (t.substr(0, prefix.size()) != prefix) return false;
    t.remove_prefix(prefix.size());
    return true;
  };
  k.texcoords = take("ST");
  k.colors = take("C");
  k.normals = take("N");
  k.four_d = take("4");
  k.dimension = take("n");
  return t == "OFF";
}

class OffReader {
 public:
  OffReader(std::string_view text, SinkWriter& sink) : m_tokens(text), m_sink(sink) {}

  void read() {
    readHeader();
    readVertices();
    readFaces();
    if (!m_tokens.atEnd()) {
      m_tokens.next();
      m_sink.warning("data after the last face ignored", m_tokens.line());
    }
  }

 private:
  std::string_view token(const char* what) {
    std::string_view t = m_tokens.next();
    if (t.empty()) parseError(std::string("the file ends where ") + what + " should be", m_tokens.line());
    return t;
  }
  std::int64_t integer(const char* what) {
    std::string_view t = token(what);
    std::int64_t v = 0;
    if (!parseInt(t, v))
      parseError(std::string(what) + ": '" + std::string(quoted(t)) + "' is not an integer", m_tokens.line());
    return v;
  }
  float number(const char* what) {
    std::string_view t = token(what);
    float v = 0;
    if (!parseFloat(t, v))
      parseError(std::string(what) + ": '" + std::string(quoted(t)) + "' is not a finite decimal number",
                 m_tokens.line());
    return v;
  }

  void readHeader() {
    std::string_view first = m_tokens.next();
    if (first.empty()) parseError("no OFF data (only blank lines or comments)", m_tokens.line());
    std::int64_t vertex_count = 0;
    if (parseKeyword(first, m_layout)) {
      std::uint64_t keyword_line = m_tokens.line();
      if (m_layout.dimension) {
        std::int64_t dim = integer("the dimension after nOFF");
        if (dim != 3 || m_layout.four_d)
          throw PluginFailure(PRISM_PLUGIN_ERROR_UNSUPPORTED,
                              "nOFF with dimension " + std::to_string(dim + (m_layout.four_d ? 1 : 0)) +
                                  ": prism reads 3-D OFF only",
                              m_tokens.line());
      } else if (m_layout.four_d) {
        throw PluginFailure(PRISM_PLUGIN_ERROR_UNSUPPORTED, "4OFF holds 4-D vertices: prism reads 3-D OFF only",
                            keyword_line);
      }
      if (m_tokens.peekSameLine()) {
        std::string_view peek = OffTokens(m_tokens).next();
        if (peek == "BINARY")
          throw PluginFailure(PRISM_PLUGIN_ERROR_UNSUPPORTED, "binary OFF is not supported", keyword_line);
      }
      vertex_count = integer("the vertex count");
    } else if (!parseInt(first, vertex_count)) {
      parseError("expected an OFF keyword or the vertex count, found '" + std::string(quoted(first)) + "'",
                 m_tokens.line());
    }
    std::int64_t face_count = integer("the face count");
    if (m_tokens.peekSameLine()) integer("the edge count");  // optional, and unused
    if (vertex_count < 0 || face_count < 0) parseError("negative vertex or face count", m_tokens.line());

    // Each number takes at least one character and one separator.
    std::uint64_t numbers_per_vertex = 3 + (m_layout.normals ? 3 : 0) + (m_layout.texcoords ? 2 : 0);
    std::uint64_t budget = m_tokens.remainingBytes() / 2 + 1;  // numbers the rest of the file can hold
    auto nv = static_cast<std::uint64_t>(vertex_count), nf = static_cast<std::uint64_t>(face_count);
    if (nv > 0xffffffffull || nv > budget / numbers_per_vertex || nf > budget / 4 ||
        nv * numbers_per_vertex + nf * 4 > budget)
      parseError("the header promises " + std::to_string(nv) + " vertices and " + std::to_string(nf) +
                     " faces, more than the " + std::to_string(m_tokens.remainingBytes()) +
                     " bytes left in the file can hold",
                 m_tokens.line());
    m_vertex_count = nv;
    m_face_count = nf;
    m_sink.begin(nv, nf);
  }

  void readVertices() {
    bool all_rgb = m_layout.colors;
    std::vector<float> colors;
    if (m_layout.colors) colors.reserve(3 * m_vertex_count);
    std::vector<float> tail;  // the numbers after xyz [normal] on a vertex's line
    for (std::uint64_t v = 0; v < m_vertex_count; ++v) {
      float x = number("a vertex coordinate"), y = number("a vertex coordinate"), z = number("a vertex coordinate");
      m_sink.position(x, y, z);
      if (m_layout.normals) {
        float nx = number("a vertex normal"), ny = number("a vertex normal"), nz = number("a vertex normal");
        m_sink.normal(nx, ny, nz);
      }
      tail.clear();
      while (m_tokens.peekSameLine() && tail.size() < 8) tail.push_back(number("a vertex colour or texture coordinate"));
      if (m_tokens.peekSameLine()) parseError("vertex " + std::to_string(v) + " has too many numbers", m_tokens.line());
      std::size_t want_st = m_layout.texcoords ? 2 : 0;
      if (tail.size() < want_st) parseError("vertex " + std::to_string(v) + " lacks its texture coordinates", m_tokens.line());
      std::size_t color_numbers = tail.size() - want_st;
      if (!m_layout.colors && color_numbers > 0)
        parseError("vertex " + std::to_string(v) + " has " + std::to_string(3 + color_numbers) +
                       " numbers on its line; this OFF variant has " + std::to_string(3 + want_st) +
                       (m_layout.normals ? " after the normal" : ""),
                   m_tokens.line());
      if (m_layout.colors) {
        if (color_numbers == 3 || color_numbers == 4) {
          // Integer colours (0..255) and float colours (0..1) both occur.
          float scale = (tail[0] > 1 || tail[1] > 1 || tail[2] > 1) ? 1.0f / 255 : 1.0f;
          colors.insert(colors.end(), {tail[0] * scale, tail[1] * scale, tail[2] * scale});
        } else if (color_numbers == 1) {
          all_rgb = false;  // a colour-map index: prism has no colour map
        } else {
          parseError("vertex " + std::to_string(v) + " has " + std::to_string(color_numbers) +
                         " colour numbers; expected 1, 3 or 4",
                     m_tokens.line());
        }
      }
      if (want_st) m_sink.texcoord(tail[color_numbers], tail[color_numbers + 1]);
    }
    if (all_rgb) {
      for (std::size_t i = 0; i + 2 < colors.size(); i += 3) m_sink.color(colors[i], colors[i + 1], colors[i + 2]);
    } else if (m_layout.colors) {
      m_sink.warning("colour-map indices instead of colours: vertex colours ignored");
    }
  }

  void readFaces() {
    std::vector<std::uint32_t> corners;
    for (std::uint64_t f = 0; f < m_face_count; ++f) {
      std::int64_t n = integer("a face's corner count");
      std::uint64_t face_line = m_tokens.line();
      if (n < 3) parseError("face " + std::to_string(f) + " has " + std::to_string(n) + " corners; at least 3 are needed", face_line);
      if (static_cast<std::uint64_t>(n) > m_tokens.remainingBytes() / 2 + 1)
        parseError("face " + std::to_string(f) + " claims " + std::to_string(n) + " corners, more than the file holds", face_line);
      corners.resize(static_cast<std::size_t>(n));
      for (std::int64_t k = 0; k < n; ++k) {
        std::int64_t index = integer("a face's vertex index");
        if (index < 0 || static_cast<std::uint64_t>(index) >= m_vertex_count)
          parseError("face " + std::to_string(f) + " uses vertex " + std::to_string(index) + ", but there are " +
                         std::to_string(m_vertex_count) + " vertices (numbered from 0)",
                     m_tokens.line());
        corners[static_cast<std::size_t>(k)] = static_cast<std::uint32_t>(index);
      }
      // Up to 4 colour numbers (RGB[A] or one colour-map index) may follow on the line.
      int extra = 0;
      while (m_tokens.peekSameLine()) {
        if (++extra > 4)
          parseError("face " + std::to_string(f) + " has more than 4 numbers after its " + std::to_string(n) +
                         " indices (does its corner count lie?)",
                     m_tokens.line());
        number("a face colour");
      }
      m_sink.face(corners.data(), static_cast<std::uint32_t>(n), -1);
    }
  }

  OffTokens m_tokens;
  SinkWriter& m_sink;
  OffLayout m_layout;
  std::uint64_t m_vertex_count = 0;
  std::uint64_t m_face_count = 0;
};

}  // namespace

void readOff(std::string_view text, SinkWriter& sink) { OffReader(text, sink).read(); }

bool looksLikeOff(std::string_view head) {
  OffTokens tokens(head);
  OffLayout layout;
  return parseKeyword(tokens.next(), layout);
}

}  // namespace prism_plugins
