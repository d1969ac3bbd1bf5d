#include "scene/json_reader.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "scene/scene_error.h"

namespace prism {

std::string join(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

std::string formatNumber(double x) {
  if (!std::isfinite(x)) return std::isnan(x) ? "nan" : (x > 0 ? "inf" : "-inf");
  if (x == std::floor(x) && std::fabs(x) < 1e15) return std::to_string(static_cast<long long>(x));
  return Json(x).dump();  // shortest round-trip form
}

std::string formatVec(const Vec3& v) {
  return "[" + formatNumber(v.x) + ", " + formatNumber(v.y) + ", " + formatNumber(v.z) + "]";
}

// Bounded so a huge or deeply nested input cannot produce a huge message (or
// recurse deeply).
std::string describe(const Json& v, int depth) {
  switch (v.type()) {
    case Json::value_t::null:
      return "null";
    case Json::value_t::boolean:
      return v.get<bool>() ? "true" : "false";
    case Json::value_t::number_integer:
      return std::to_string(v.get<long long>());
    case Json::value_t::number_unsigned:
      return std::to_string(v.get<unsigned long long>());
    case Json::value_t::number_float:
      return formatNumber(v.get<double>());
    case Json::value_t::string: {
      std::string s = v.get<std::string>();
      const bool cut = s.size() > 40;
      if (cut) s.resize(40);
      return Json(s).dump(-1, ' ', false, Json::error_handler_t::replace) + (cut ? "..." : "");
    }
    case Json::value_t::array: {
      if (v.size() > 16 || depth >= 2) {
        if (depth > 0) return "[...]";
        return "an array of " + std::to_string(v.size()) + " elements";
      }
      std::string out = "[";
      for (std::size_t i = 0; i < v.size(); ++i) out += (i ? ", " : "") + describe(v[i], depth + 1);
      return out + "]";
    }
    case Json::value_t::object:
      return depth > 0 ? "{...}" : "an object";
    default:
      return "an unsupported value";
  }
}

std::string member(const std::string& path, const std::string& key) {
  return path.empty() ? key : path + "." + key;
}

std::string element(const std::string& path, std::size_t i) { return path + "[" + std::to_string(i) + "]"; }

void JsonReader::fail(const std::string& path, const std::string& what) const {
  throw SceneError(prefix() + (path.empty() ? "" : path + ": ") + what);
}

void JsonReader::expected(const std::string& path, const std::string& what, const Json& got) const {
  fail(path, "expected " + what + ", got " + describe(got));
}

const Json& JsonReader::require(const Json& obj, const std::string& path, const char* key) const {
  const Json* v = find(obj, key);
  if (!v) fail(path, std::string("missing required key '") + key + "'");
  return *v;
}

void JsonReader::checkObject(const Json& v, const std::string& path, std::initializer_list<const char*> known) const {
  checkObject(v, path, std::vector<std::string>(known.begin(), known.end()));
}

void JsonReader::checkObject(const Json& v, const std::string& path, const std::vector<std::string>& known) const {
  if (!v.is_object()) expected(path, "an object", v);
  for (auto it = v.begin(); it != v.end(); ++it) {
    if (std::find(known.begin(), known.end(), it.key()) == known.end() && m_warnings)
      m_warnings->push_back(prefix() + path + ": unknown key '" + it.key() + "' (ignored)");
  }
}

double JsonReader::number(const Json& v, const std::string& path, const char* what, Check ok) const {
  if (!v.is_number()) expected(path, what, v);
  const double x = v.get<double>();
  if (!std::isfinite(x) || (ok && !ok(x))) expected(path, what, v);
  return x;
}

long long JsonReader::integer(const Json& v, const std::string& path, long long lo, long long hi) const {
  const std::string what = "an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
  if (!v.is_number()) expected(path, what, v);
  const double x = v.get<double>();
  if (!std::isfinite(x) || x != std::floor(x) || x < lo || x > hi) expected(path, what, v);
  return static_cast<long long>(x);
}

std::string JsonReader::string(const Json& v, const std::string& path, const std::string& what) const {
  if (!v.is_string()) expected(path, what, v);
  return v.get<std::string>();
}

Vec3 JsonReader::vec3(const Json& v, const std::string& path, const char* what, Check ok) const {
  if (!v.is_array() || v.size() != 3) expected(path, "an array of 3 numbers", v);
  return {number(v[0], element(path, 0), what, ok), number(v[1], element(path, 1), what, ok),
          number(v[2], element(path, 2), what, ok)};
}

Vec3 JsonReader::nonZeroVec3(const Json& v, const std::string& path) const {
  const Vec3 r = vec3(v, path);
  if (r == Vec3()) expected(path, "a non-zero vector", v);
  return r;
}

std::vector<double> JsonReader::numbers(const Json& v, const std::string& path, std::size_t count) const {
  if (!v.is_array() || v.size() != count) expected(path, "an array of " + std::to_string(count) + " numbers", v);
  std::vector<double> out(count);
  for (std::size_t i = 0; i < count; ++i) out[i] = number(v[i], element(path, i));
  return out;
}

std::string JsonReader::filePath(const std::string& file) const {
  std::filesystem::path resolved(file);
  if (resolved.is_relative() && !m_base_dir.empty()) resolved = std::filesystem::path(m_base_dir) / resolved;
  return resolved.string();
}

}  // namespace prism
