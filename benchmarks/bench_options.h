// The option loop the prism-bench subcommands share: each option goes to the
// subcommand's handler with a way to take its value; --help prints the usage;
// a missing or bad value, or an unknown option (the handler throws
// std::invalid_argument), is reported as "prism-bench NAME: ..." with the
// usage, exit status 2.
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace prism::bench {

using OptionValue = std::function<std::string()>;
using OptionHandler = std::function<void(const std::string& option, const OptionValue& value)>;

// -1: parsed, go on; otherwise the status to exit with (0 after --help, 2 after a usage error).
int parseBenchOptions(const std::vector<std::string>& args, const char* name, const char* usage,
                      const OptionHandler& handle);

// "WxH" (--size), both at least 1; throws std::invalid_argument naming `option`.
void parseSize(const std::string& option, const std::string& text, int* width, int* height);

}  // namespace prism::bench
