// OBJ reader; see obj_reader.h.
#include "obj/obj_reader.h"

#include <sys/stat.h>

#include <cstdint>
#include <cstring>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "common/text_numbers.h"
#include "obj/mtl_library.h"

namespace prism_plugins {

namespace {

constexpr std::uint32_t kUnset = 0xffffffffu;

// Statements of the OBJ spec (and common extensions) that prism does not use.
const std::set<std::string_view> kIgnoredStatements = {
    "vp", "cstype", "deg", "bmat", "step", "curv", "curv2", "surf", "parm", "trim", "hole", "scrv", "sp", "end",
    "con", "mg", "bevel", "c_interp", "d_interp", "lod", "usemap", "maplib", "shadow_obj", "trace_obj", "ctech",
    "stech", "call", "csh", "vw", "vc", "t"};

bool isRegularFile(const std::string& path) {
  struct stat st {};
  return stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode);
}

std::string folderOf(const std::string& path) {
  std::size_t slash = path.find_last_of('/');
  return slash == std::string::npos ? std::string() : path.substr(0, slash + 1);
}

// A per-vertex attribute that OBJ gives per face corner (vt or vn).
class CornerAttribute {
 public:
  CornerAttribute(const char* name, std::size_t width) : m_name(name), m_width(width) {}

  std::vector<float>& values() { return m_values; }
  std::size_t count() const { return m_values.size() / m_width; }

  void noteCorner(std::uint32_t vertex, std::uint32_t value) {
    if (value == kUnset) {
      m_some_missing = true;
      return;
    }
    m_used = true;
    if (m_of_vertex.size() <= vertex) m_of_vertex.resize(vertex + 1, kUnset);
    std::uint32_t& mine = m_of_vertex[vertex];
    if (mine == kUnset) {
      mine = value;
    } else if (mine != value && !m_conflict) {
      // Different indices may still hold equal values (exporters duplicate them).
      for (std::size_t i = 0; i < m_width; ++i)
        if (m_values[mine * m_width + i] != m_values[value * m_width + i]) {
          m_conflict = true;
          m_conflict_vertex = vertex;
        }
    }
  }

  // A corner names a value that does not exist: keep the mesh, drop this
  // attribute (readers such as OpenMesh and tinyobjloader accept such files).
  void markDangling(std::uint64_t line) {
    if (m_dangling_line == 0) m_dangling_line = line;
  }

  // Emits one value per vertex through `emit`, or explains why not.
  template <typename Emit>
  void finish(std::size_t vertex_count, SinkWriter& sink, Emit emit) {
    if (m_dangling_line != 0) {
      sink.warning(std::string("face corners name ") + m_name + " that are not defined: " + m_name + " ignored",
                   m_dangling_line);
      return;
    }
    if (!m_used) return;
    if (m_conflict) {
      sink.warning(std::string(m_name) + " differ between the faces that share vertex " +
                   std::to_string(m_conflict_vertex + 1) + ": " + m_name + " ignored");
      return;
    }
    if (m_some_missing) {
      sink.warning(std::string("some face corners have ") + m_name + " and some do not: " + m_name + " ignored");
      return;
    }
    m_of_vertex.resize(vertex_count, kUnset);
    for (std::uint32_t v : m_of_vertex) {
      if (v == kUnset) {
        float zero[3] = {0, 0, 0};
        emit(zero);  // a vertex no face uses
      } else {
        emit(&m_values[v * m_width]);
      }
    }
  }

 private:
  const char* m_name;
  std::size_t m_width;
  std::vector<float> m_values;
  std::vector<std::uint32_t> m_of_vertex;
  bool m_used = false, m_some_missing = false, m_conflict = false;
  std::uint64_t m_dangling_line = 0;
  std::uint32_t m_conflict_vertex = 0;
};

class ObjReader {
 public:
  ObjReader(std::string_view text, const std::string& base_dir, SinkWriter& sink)
      : m_text(text), m_base_dir(base_dir), m_sink(sink) {}

  void read() {
    checkIsText();
    countStatements();
    m_sink.begin(m_hint_vertices, m_hint_faces);
    while (nextStatement()) statement();
    finish();
  }

 private:
  // --- lines ---------------------------------------------------------------
  void checkIsText() {
    std::size_t nul = m_text.find('\0');
    if (nul == std::string_view::npos) return;
    std::uint64_t line = 1;
    for (std::size_t i = 0; i < nul; ++i) line += m_text[i] == '\n';
    parseError("NUL bytes in the file: not OBJ text (UTF-16 or binary?)", line);
  }

  // Size hints for the host: 'v' and 'f' lines, counted in one quick pass
  // (a fraction of the parse), save the host's arrays from growing by copies.
  void countStatements() {
    std::size_t i = 0;
    while (i < m_text.size()) {
      while (i < m_text.size() && (m_text[i] == ' ' || m_text[i] == '\t')) ++i;
      if (i + 1 < m_text.size() && (m_text[i + 1] == ' ' || m_text[i + 1] == '\t')) {
        if (m_text[i] == 'v') ++m_hint_vertices;
        else if (m_text[i] == 'f') ++m_hint_faces;
      }
      const void* nl = std::memchr(m_text.data() + i, '\n', m_text.size() - i);
      i = nl != nullptr ? static_cast<std::size_t>(static_cast<const char*>(nl) - m_text.data()) + 1 : m_text.size();
    }
  }

  // One physical line, without its break ("\n", "\r\n" or "\r").
  bool physicalLine(std::string_view& line) {
    if (m_pos >= m_text.size()) return false;
    std::size_t end = m_pos;
    while (end < m_text.size() && m_text[end] != '\n' && m_text[end] != '\r') ++end;
    line = m_text.substr(m_pos, end - m_pos);
    m_pos = end;
    if (m_pos < m_text.size() && m_text[m_pos] == '\r') ++m_pos;
    if (m_pos < m_text.size() && m_text[m_pos] == '\n') ++m_pos;  // after '\r' too: "\r\n" is one break
    ++m_physical_line;
    return true;
  }

  // The next logical line: physical lines joined where one ends in '\'.
  bool nextStatement() {
    std::string_view line;
    if (!physicalLine(line)) return false;
    m_line = m_physical_line;
    if (m_line == 1 && line.substr(0, 3) == "\xEF\xBB\xBF") line.remove_prefix(3);  // UTF-8 byte order mark
    std::string_view t = trimmed(line);
    if (t.empty() || t.back() != '\\') {
      m_statement = line;
      return true;
    }
    m_joined.assign(t.substr(0, t.size() - 1));
    std::string_view more;
    while (physicalLine(more)) {
      std::string_view mt = trimmed(more);
      bool continues = !mt.empty() && mt.back() == '\\';
      m_joined += ' ';
      m_joined += continues ? mt.substr(0, mt.size() - 1) : more;
      if (!continues) break;
    }
    m_statement = m_joined;
    return true;
  }

  // --- statements ----------------------------------------------------------
  void statement() {
    std::string_view rest = m_statement;
    std::string_view keyword = nextToken(rest);
    if (keyword.empty() || keyword[0] == '#') return;
    if (keyword == "v") vertex(rest);
    else if (keyword == "vn") numbersInto(rest, m_normals.values(), 3, 3, "vn");
    else if (keyword == "vt") numbersInto(rest, m_texcoords.values(), 1, 3, "vt", 2);
    else if (keyword == "f") face(rest);
    else if (keyword == "usemtl") useMaterial(trimmed(rest));
    else if (keyword == "mtllib") materialLibraries(trimmed(rest));
    else if (keyword == "g" || keyword == "o" || keyword == "s") return;
    else if (keyword == "l" || keyword == "p") warnOnce("line and point elements ('l', 'p') are not rendered: ignored");
    else if (kIgnoredStatements.count(keyword)) warnOnce("'" + std::string(keyword) + "' statements ignored");
    else unknown(keyword);
  }

  void unknown(std::string_view keyword) {
    for (char c : keyword) {
      auto u = static_cast<unsigned char>(c);
      if (u < 0x20 || u >= 0x7f) parseError("this line does not start with an OBJ statement", m_line);
    }
    warnOnce("unknown statement '" + std::string(quoted(keyword)) + "' ignored");
  }

  void warnOnce(const std::string& message) {
    if (m_warned.insert(message).second) m_sink.warning(message, m_line);
  }

  float number(std::string_view token, const char* what) {
    float v = 0;
    if (!parseFloat(token, v))
      parseError(std::string(what) + ": '" + std::string(quoted(token)) + "' is not a finite decimal number", m_line);
    return v;
  }

  // Reads min..max numbers into `out`, padded with zeros to `keep` values
  // (vt's optional v) and truncated to it (vt's w is not used).
  void numbersInto(std::string_view rest, std::vector<float>& out, int min, int max, const char* what, int keep = 0) {
    float values[4] = {0, 0, 0, 0};
    int n = 0;
    for (std::string_view t = nextToken(rest); !t.empty(); t = nextToken(rest)) {
      if (n == max) parseError(std::string("'") + what + "' takes at most " + std::to_string(max) + " numbers", m_line);
      values[n++] = number(t, what);
    }
    if (n < min) parseError(std::string("'") + what + "' needs at least " + std::to_string(min) + " numbers", m_line);
    int stored = keep > 0 ? keep : n;
    out.insert(out.end(), values, values + stored);
  }

  void vertex(std::string_view rest) {
    float v[7];
    int n = 0;
    for (std::string_view t = nextToken(rest); !t.empty(); t = nextToken(rest)) {
      if (n == 7) parseError("'v' takes 3 coordinates, optionally w or r g b", m_line);
      v[n++] = number(t, "a vertex coordinate");
    }
    if (n != 3 && n != 4 && n != 6)
      parseError("'v' has " + std::to_string(n) + " numbers; expected x y z, x y z w or x y z r g b", m_line);
    if (m_vertex_count == kUnset - 1) parseError("more than 2^32-2 vertices", m_line);
    m_sink.position(v[0], v[1], v[2]);
    ++m_vertex_count;
    if (n == 6) m_colors.insert(m_colors.end(), {v[3], v[4], v[5]});
    else m_all_colored = false;
  }

  // Resolves a texture coordinate or normal index; one that points nowhere
  // drops that attribute (with a warning at the end) rather than the mesh.
  std::uint32_t resolveAttribute(std::string_view token, CornerAttribute& attribute, const char* what) {
    std::int64_t i = 0;
    if (!parseInt(token, i)) parseError(std::string(what) + " index '" + std::string(quoted(token)) + "' is not an integer", m_line);
    if (i == 0) parseError(std::string(what) + " index 0: OBJ numbers from 1", m_line);
    std::int64_t zero_based = i > 0 ? i - 1 : static_cast<std::int64_t>(attribute.count()) + i;
    if (zero_based < 0 || zero_based >= static_cast<std::int64_t>(attribute.count())) {
      attribute.markDangling(m_line);
      return kUnset;
    }
    return static_cast<std::uint32_t>(zero_based);
  }

  // Resolves one vertex index (1-based, or negative = relative to the end).
  std::uint32_t resolve(std::string_view token, std::size_t count, const char* what) {
    std::int64_t i = 0;
    if (!parseInt(token, i)) parseError(std::string(what) + " index '" + std::string(quoted(token)) + "' is not an integer", m_line);
    if (i == 0) parseError(std::string(what) + " index 0: OBJ numbers from 1", m_line);
    std::int64_t zero_based = i > 0 ? i - 1 : static_cast<std::int64_t>(count) + i;
    if (zero_based < 0 || zero_based >= static_cast<std::int64_t>(count))
      parseError(std::string(what) + " index " + std::to_string(i) + ", but " + std::to_string(count) +
                     " vertices are defined before this line",
                 m_line);
    return static_cast<std::uint32_t>(zero_based);
  }

  void face(std::string_view rest) {
    m_corners.clear();
    for (std::string_view t = nextToken(rest); !t.empty(); t = nextToken(rest)) {
      // v, v/vt, v//vn, v/vt/vn
      std::string_view parts[3];
      int n = 0;
      for (std::size_t start = 0;;) {
        std::size_t slash = t.find('/', start);
        if (n == 3) parseError("face corner '" + std::string(quoted(t)) + "' has more than v/vt/vn", m_line);
        parts[n++] = t.substr(start, slash == std::string_view::npos ? std::string_view::npos : slash - start);
        if (slash == std::string_view::npos) break;
        start = slash + 1;
      }
      std::uint32_t v = resolve(parts[0], m_vertex_count, "vertex");
      std::uint32_t vt = kUnset, vn = kUnset;
      if (n >= 2 && !parts[1].empty()) vt = resolveAttribute(parts[1], m_texcoords, "texture coordinate");
      if (n == 3) {
        if (parts[2].empty()) parseError("face corner '" + std::string(quoted(t)) + "' ends in '/'", m_line);
        vn = resolveAttribute(parts[2], m_normals, "normal");
      }
      m_texcoords.noteCorner(v, vt);
      m_normals.noteCorner(v, vn);
      m_corners.push_back(v);
    }
    if (m_corners.size() < 3)
      parseError("a face with " + std::to_string(m_corners.size()) + " corner(s); at least 3 are needed", m_line);
    if (m_corners.size() > 0xffffffffu) parseError("a face with too many corners", m_line);
    m_sink.face(m_corners.data(), static_cast<std::uint32_t>(m_corners.size()), m_material);
  }

  void useMaterial(std::string_view name) {
    auto it = m_material_index.find(std::string(name));
    if (it != m_material_index.end()) {
      m_material = it->second;
      return;
    }
    m_material = -1;
    if (!name.empty()) warnOnce("material '" + std::string(name) + "' is not defined in any material library: default used");
  }

  // "mtllib a.mtl b.mtl": each file, or one name with spaces when that exists.
  void materialLibraries(std::string_view rest) {
    std::vector<std::string> names;
    if (isRegularFile(m_base_dir + std::string(rest))) {
      names.emplace_back(rest);
    } else {
      for (std::string_view t = nextToken(rest); !t.empty(); t = nextToken(rest)) names.emplace_back(t);
    }
    for (const std::string& name : names) {
      if (!m_libraries_read.insert(name).second) continue;
      MtlLibrary lib = readMtlLibrary(m_base_dir + name);
      if (!lib.found) {
        m_sink.warning("material library '" + name + "': " + lib.problem + " (default material used)", m_line);
        continue;
      }
      for (const std::string& w : lib.warnings) m_sink.warning("material library '" + name + "': " + w, m_line);
      for (const MtlMaterial& m : lib.materials) addMaterial(m, folderOf(name));
    }
  }

  void addMaterial(const MtlMaterial& m, const std::string& library_folder) {
    PrismMaterialDesc d{};
    d.struct_size = sizeof d;
    d.name = m.name.c_str();
    for (int i = 0; i < 3; ++i) d.kd[i] = m.kd[i], d.ka[i] = m.ka[i], d.ks[i] = m.ks[i];
    d.ns = m.ns;
    d.ni = m.ni;
    d.d = m.d;
    d.illum = m.illum;
    // Texture paths are relative to the library; the host resolves them
    // against the OBJ's folder, so prefix the library's own folder.
    std::string map = m.map_kd.empty() || m.map_kd[0] == '/' ? m.map_kd : library_folder + m.map_kd;
    d.map_kd = map.empty() ? nullptr : map.c_str();
    if (!map.empty() && !isRegularFile(map[0] == '/' ? map : m_base_dir + map))
      m_sink.warning("texture '" + map + "' of material '" + m.name + "' not found", m_line);
    m_sink.material(d);
    m_material_index.emplace(m.name, m_material_count++);  // the first definition of a name wins
  }

  void finish() {
    SinkWriter& sink = m_sink;
    m_normals.finish(m_vertex_count, sink, [&sink](const float* n) { sink.normal(n[0], n[1], n[2]); });
    m_texcoords.finish(m_vertex_count, sink, [&sink](const float* t) { sink.texcoord(t[0], t[1]); });
    if (m_all_colored && m_vertex_count > 0) {
      for (std::size_t i = 0; i + 2 < m_colors.size(); i += 3) sink.color(m_colors[i], m_colors[i + 1], m_colors[i + 2]);
    } else if (!m_colors.empty()) {
      sink.warning("only some vertices have colours: vertex colours ignored");
    }
  }

  std::string_view m_text;
  std::string m_base_dir;
  SinkWriter& m_sink;
  std::size_t m_pos = 0;
  std::uint64_t m_physical_line = 0;
  std::uint64_t m_line = 0;  // where the current statement starts
  std::string_view m_statement;
  std::string m_joined;

  std::uint32_t m_vertex_count = 0;
  std::uint64_t m_hint_vertices = 0, m_hint_faces = 0;
  CornerAttribute m_normals{"normals", 3};
  CornerAttribute m_texcoords{"texture coordinates", 2};
  std::vector<float> m_colors;
  bool m_all_colored = true;
  std::vector<std::uint32_t> m_corners;

  std::int32_t m_material = -1;
  std::int32_t m_material_count = 0;
  std::map<std::string, std::int32_t> m_material_index;
  std::set<std::string> m_libraries_read;
  std::set<std::string> m_warned;
};

}  // namespace

void readObj(std::string_view text, const std::string& base_dir, SinkWriter& sink) {
  ObjReader(text, base_dir, sink).read();
}

}  // namespace prism_plugins
