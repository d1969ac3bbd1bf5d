// A small command-line parser for prism's commands: options with values written as
// `--flag value` or `--flag=value`, switches, and positional arguments. Every mistake
// becomes a UsageError whose message names the option at fault.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace prism_cli {

// A mistake in the command line itself; main() turns it into exit code 2.
class UsageError : public std::runtime_error {
 public:
  explicit UsageError(const std::string& message) : std::runtime_error(message) {}
};

struct OptionSpec {
  std::string name;   // "--width"
  std::string alias;  // "-o", or "" for none
  bool takes_value;
};

class ParsedArgs {
 public:
  bool has(const std::string& name) const { return m_values.count(name) != 0; }
  // The option's value, or nullopt when it was not given.
  std::optional<std::string> text(const std::string& name) const;
  // Typed values; the bounds are inclusive. Errors name the option and echo the text.
  std::optional<uint32_t> uint32(const std::string& name, uint32_t min) const;
  std::optional<uint64_t> uint64(const std::string& name) const;
  std::optional<float> nonNegativeFloat(const std::string& name) const;
  // Three comma-separated finite numbers, "X,Y,Z".
  std::optional<std::array<float, 3>> triple(const std::string& name) const;
  // A finite number strictly between `low` and `high`.
  std::optional<float> floatBetween(const std::string& name, float low, float high) const;
  const std::vector<std::string>& positionals() const { return m_positionals; }

 private:
  friend ParsedArgs parseArgs(const std::vector<std::string>&, const std::vector<OptionSpec>&,
                              const std::string&);
  std::map<std::string, std::string> m_values;  // by canonical name; a switch maps to ""
  std::vector<std::string> m_positionals;
};

// `command` ("prism render") appears in messages. A later repeat of an option wins;
// "--" ends the options.
ParsedArgs parseArgs(const std::vector<std::string>& args, const std::vector<OptionSpec>& specs,
                     const std::string& command);

}  // namespace prism_cli
