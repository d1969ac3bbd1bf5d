#include "bench_options.h"

#include <cstdio>
#include <iostream>
#include <stdexcept>

namespace prism::bench {

int parseBenchOptions(const std::vector<std::string>& args, const char* name, const char* usage,
                      const OptionHandler& handle) {
  for (std::size_t i = 1; i < args.size(); ++i) {
    const std::string& a = args[i];
    try {
      if (a == "--help" || a == "-h") {
        std::cout << usage;
        return 0;
      }
      handle(a, [&]() -> std::string {
        if (i + 1 >= args.size()) throw std::invalid_argument(a + " needs a value");
        return args[++i];
      });
    } catch (const std::exception& e) {  // std::stoi and friends throw their own kinds
      std::cerr << "prism-bench " << name << ": " << e.what() << "\n\n" << usage;
      return 2;
    }
  }
  return -1;
}

void parseSize(const std::string& option, const std::string& text, int* width, int* height) {
  if (std::sscanf(text.c_str(), "%dx%d", width, height) != 2 || *width < 1 || *height < 1)
    throw std::invalid_argument(option + ": expected WxH, got '" + text + "'");
}

}  // namespace prism::bench
