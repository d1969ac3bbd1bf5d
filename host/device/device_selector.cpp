#include "device/device_selector.h"

#include <algorithm>
#include <cctype>
#include <stdexcept>

namespace prism {
namespace {

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

}  // namespace

std::vector<std::string> deviceSelectorParts(const std::string& selector) {
  if (selector.find(',') == std::string::npos) return {selector};
  std::vector<std::string> parts;
  size_t begin = 0;
  for (;;) {
    const size_t end = selector.find(',', begin);
    parts.push_back(selector.substr(begin, end == std::string::npos ? std::string::npos : end - begin));
    const std::string& part = parts.back();
    if (part.empty() || lower(part) == "all")
      throw std::invalid_argument("devices '" + selector +
                                  "': each comma-separated part names one device (an index, cpu, gpu or part of a "
                                  "name); 'all' stands alone");
    if (end == std::string::npos) break;
    begin = end + 1;
  }
  return parts;
}

}  // namespace prism
