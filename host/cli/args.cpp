// Parsing and number conversion for the command line. Numbers are checked strictly:
// the whole text must be the number, with no sign where none makes sense.
#include "args.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <limits>

namespace prism_cli {
namespace {

const OptionSpec* findSpec(const std::vector<OptionSpec>& specs, const std::string& name) {
  for (const auto& spec : specs) {
    if (spec.name == name || (!spec.alias.empty() && spec.alias == name)) return &spec;
  }
  return nullptr;
}

size_t editDistance(const std::string& a, const std::string& b) {
  std::vector<size_t> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    size_t diagonal = row[0];
    row[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      const size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0u : 1u)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

// Typos are common enough ("--sample", "--maxdepth") that a hint pays for itself.
std::string suggestion(const std::vector<OptionSpec>& specs, const std::string& name) {
  const OptionSpec* best = nullptr;
  size_t best_distance = 3;
  for (const auto& spec : specs) {
    const size_t d = editDistance(name, spec.name);
    if (d < best_distance) {
      best = &spec;
      best_distance = d;
    }
  }
  return best ? " (did you mean '" + best->name + "'?)" : "";
}

uint64_t parseUnsigned(const std::string& name, const std::string& text, uint64_t min, uint64_t max) {
  const std::string expected = min > 0 ? "a positive integer" : "a non-negative integer";
  if (text.empty() || text[0] < '0' || text[0] > '9') {
    throw UsageError(name + ": expected " + expected + ", got '" + text + "'");
  }
  errno = 0;
  char* end = nullptr;
  const unsigned long long value = std::strtoull(text.c_str(), &end, 10);
  if (*end != '\0') throw UsageError(name + ": expected " + expected + ", got '" + text + "'");
  if (errno == ERANGE || value > max || value < min) {
    throw UsageError(name + ": " + text + " is out of range (" + std::to_string(min) + " to " +
                     std::to_string(max) + ")");
  }
  return value;
}

}  // namespace

std::optional<std::string> ParsedArgs::text(const std::string& name) const {
  const auto it = m_values.find(name);
  if (it == m_values.end()) return std::nullopt;
  return it->second;
}

std::optional<uint32_t> ParsedArgs::uint32(const std::string& name, uint32_t min) const {
  const auto value = text(name);
  if (!value) return std::nullopt;
  return static_cast<uint32_t>(parseUnsigned(name, *value, min, std::numeric_limits<uint32_t>::max()));
}

std::optional<uint64_t> ParsedArgs::uint64(const std::string& name) const {
  const auto value = text(name);
  if (!value) return std::nullopt;
  return parseUnsigned(name, *value, 0, std::numeric_limits<uint64_t>::max());
}

// The float readers take strtof's rounding as the number meant: an underflow
// (1e-50) is zero or a subnormal, not an error; an overflow is infinite and
// refused.
std::optional<float> ParsedArgs::nonNegativeFloat(const std::string& name) const {
  const auto value = text(name);
  if (!value) return std::nullopt;
  char* end = nullptr;
  const float number = std::strtof(value->c_str(), &end);
  if (value->empty() || *end != '\0' || !std::isfinite(number) || number < 0.0f) {
    throw UsageError(name + ": expected a non-negative number, got '" + *value + "'");
  }
  return number;
}

std::optional<std::array<float, 3>> ParsedArgs::triple(const std::string& name) const {
  const auto value = text(name);
  if (!value) return std::nullopt;
  std::array<float, 3> out{};
  const char* p = value->c_str();
  for (int k = 0; k < 3; ++k) {
    char* end = nullptr;
    out[k] = std::strtof(p, &end);
    const char expected_end = k < 2 ? ',' : '\0';
    if (end == p || *end != expected_end || !std::isfinite(out[k]))
      throw UsageError(name + ": expected three numbers X,Y,Z, got '" + *value + "'");
    p = end + 1;
  }
  return out;
}

std::optional<float> ParsedArgs::floatBetween(const std::string& name, float low, float high) const {
  const auto value = text(name);
  if (!value) return std::nullopt;
  char* end = nullptr;
  const float number = std::strtof(value->c_str(), &end);
  if (value->empty() || *end != '\0' || !(number > low && number < high)) {
    throw UsageError(name + ": expected a number between " + std::to_string(static_cast<int>(low)) + " and " +
                     std::to_string(static_cast<int>(high)) + ", got '" + *value + "'");
  }
  return number;
}

ParsedArgs parseArgs(const std::vector<std::string>& args, const std::vector<OptionSpec>& specs,
                     const std::string& command) {
  ParsedArgs parsed;
  bool options_done = false;
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    if (options_done || arg.size() < 2 || arg[0] != '-') {
      parsed.m_positionals.push_back(arg);
      continue;
    }
    if (arg == "--") {
      options_done = true;
      continue;
    }
    const size_t equals = arg.find('=');
    const std::string name = arg.substr(0, equals);
    const OptionSpec* spec = findSpec(specs, name);
    if (!spec) {
      throw UsageError("unknown option '" + name + "' for '" + command + "'" + suggestion(specs, name));
    }
    if (!spec->takes_value) {
      if (equals != std::string::npos) throw UsageError(spec->name + " takes no value (got '" + arg + "')");
      parsed.m_values[spec->name] = "";
      continue;
    }
    if (equals != std::string::npos) {
      parsed.m_values[spec->name] = arg.substr(equals + 1);
    } else if (i + 1 < args.size()) {
      parsed.m_values[spec->name] = args[++i];
    } else {
      throw UsageError(spec->name + " needs a value");
    }
  }
  return parsed;
}

}  // namespace prism_cli
