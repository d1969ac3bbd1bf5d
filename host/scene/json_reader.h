// Reading checked values out of the scene format's JSON, with messages that
// name the file, the JSON path and what was expected. Shared by the scene
// loader and the primitive kinds' parsers (scene/primitives/), so every value
// of every kind is read and reported the same way.
#pragma once

#include <initializer_list>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "scene/vec3.h"

namespace prism {

using Json = nlohmann::json;

std::string join(const std::vector<std::string>& names);
std::string formatNumber(double x);
std::string formatVec(const Vec3& v);
// A short, printable rendering of any value for "got ...", bounded in size.
std::string describe(const Json& v, int depth = 0);
// JSON paths: member("objects[2]", "radius") is "objects[2].radius".
std::string member(const std::string& path, const std::string& key);
std::string element(const std::string& path, std::size_t i);

class JsonReader {
 public:
  using Check = bool (*)(double);

  // `name` starts every message (empty for a fragment the C API built);
  // unknown keys are reported as warnings into `warnings`; files the scene
  // names are relative to `base_dir` (the scene file's folder).
  JsonReader(std::string name, std::vector<std::string>* warnings, std::string base_dir = "")
      : m_name(std::move(name)), m_warnings(warnings), m_base_dir(std::move(base_dir)) {}

  std::string prefix() const { return m_name.empty() ? "" : m_name + ": "; }
  // Throw SceneError (scene/scene_error.h).
  [[noreturn]] void fail(const std::string& path, const std::string& what) const;
  [[noreturn]] void expected(const std::string& path, const std::string& what, const Json& got) const;

  static const Json* find(const Json& obj, const char* key) {
    auto it = obj.find(key);
    return it == obj.end() ? nullptr : &*it;
  }
  const Json& require(const Json& obj, const std::string& path, const char* key) const;
  // v must be an object; keys outside `known` are warned about and ignored.
  void checkObject(const Json& v, const std::string& path, std::initializer_list<const char*> known) const;
  void checkObject(const Json& v, const std::string& path, const std::vector<std::string>& known) const;

  double number(const Json& v, const std::string& path, const char* what = "a finite number",
                Check ok = nullptr) const;
  long long integer(const Json& v, const std::string& path, long long lo, long long hi) const;
  std::string string(const Json& v, const std::string& path, const std::string& what) const;
  Vec3 vec3(const Json& v, const std::string& path, const char* what = "a finite number", Check ok = nullptr) const;
  Vec3 nonZeroVec3(const Json& v, const std::string& path) const;
  // An array of exactly `count` finite numbers.
  std::vector<double> numbers(const Json& v, const std::string& path, std::size_t count) const;
  // A file the scene names, relative to the scene file's folder.
  std::string filePath(const std::string& file) const;

 private:
  std::string m_name;
  std::vector<std::string>* m_warnings;
  std::string m_base_dir;
};

}  // namespace prism
