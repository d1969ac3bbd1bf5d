#include "scene/patches/bpt_file.h"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "scene/value_check.h"

namespace prism {
namespace {

// Whitespace-separated words with the line each is on.
class Words {
 public:
  Words(const std::string& text, std::string name) : m_text(text), m_name(std::move(name)) {}

  [[noreturn]] void fail(const std::string& what) const {
    throw PatchFileError(m_name + ":" + std::to_string(m_line) + ": " + what);
  }
  bool next(std::string& word) {
    while (m_pos < m_text.size() && std::isspace(static_cast<unsigned char>(m_text[m_pos]))) {
      if (m_text[m_pos] == '\n') ++m_line;
      ++m_pos;
    }
    if (m_pos >= m_text.size()) return false;
    const std::size_t start = m_pos;
    while (m_pos < m_text.size() && !std::isspace(static_cast<unsigned char>(m_text[m_pos]))) ++m_pos;
    word = m_text.substr(start, std::min<std::size_t>(m_pos - start, 64));
    return true;
  }
  long long integer(const char* what, long long lo, long long hi) {
    std::string w;
    if (!next(w)) fail(std::string("the file ends where ") + what + " should be");
    char* end = nullptr;
    errno = 0;
    const long long v = std::strtoll(w.c_str(), &end, 10);
    if (*end || errno || v < lo || v > hi)
      fail(std::string("expected ") + what + " (an integer from " + std::to_string(lo) + " to " + std::to_string(hi) +
           "), got '" + w + "'");
    return v;
  }
  double number(const std::string& what) {
    std::string w;
    if (!next(w)) fail("the file ends where " + what + " should be");
    char* end = nullptr;
    const double v = std::strtod(w.c_str(), &end);
    if (*end || !std::isfinite(v)) fail("expected " + what + " (a finite number), got '" + w + "'");
    return v;
  }

 private:
  const std::string& m_text;
  std::string m_name;
  std::size_t m_pos = 0;
  int m_line = 1;
};

}  // namespace

std::vector<BezierPatch> parseBpt(const std::string& text, const std::string& name) {
  Words words(text, name);
  const long long count = words.integer("the number of patches", 1, kMaxPatchesPerFile);
  std::vector<BezierPatch> patches;
  patches.reserve(std::min<std::size_t>(count, text.size() / 32 + 1));  // 16 points cannot take fewer bytes
  for (long long k = 0; k < count; ++k) {
    const std::string which = "patch " + std::to_string(k + 1) + " of " + std::to_string(count);
    const long long n = words.integer(("the u degree of " + which).c_str(), 1, 64);
    const long long m = words.integer(("the v degree of " + which).c_str(), 1, 64);
    if (n != 3 || m != 3)
      words.fail(which + " has degrees " + std::to_string(n) + " " + std::to_string(m) +
                 ": only bicubic patches (3 3) are read");
    BezierPatch p;
    for (int i = 0; i < 16; ++i) {
      const std::string at = "point " + std::to_string(i + 1) + " of " + which;
      p.p[i] = {words.number("x of " + at), words.number("y of " + at), words.number("z of " + at)};
      const std::string problem = vectorProblem(p.p[i], at.c_str());
      if (!problem.empty()) words.fail(problem);
    }
    patches.push_back(p);
  }
  std::string extra;
  if (words.next(extra)) words.fail("more after the " + std::to_string(count) + " patches the file announces: '" + extra + "'");
  return patches;
}

std::vector<BezierPatch> readBptFile(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);
  if (ec || !fs::exists(st)) throw PatchFileError(path + ": cannot open: no such file");
  if (fs::is_directory(st)) throw PatchFileError(path + ": is a folder, not a patch file");
  if (!fs::is_regular_file(st)) throw PatchFileError(path + ": is not a regular file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw PatchFileError(path + ": cannot open: " + std::strerror(errno));
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw PatchFileError(path + ": cannot read: " + std::strerror(errno));
  return parseBpt(text.str(), path);
}

}  // namespace prism
