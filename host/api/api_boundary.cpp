#include "api/api_boundary.h"

namespace prism {
namespace {
thread_local std::string t_last_error;
}

void setLastError(const std::string& message) { t_last_error = message; }
void clearLastError() { t_last_error.clear(); }
const char* lastError() { return t_last_error.c_str(); }

PrismStatus fail(PrismStatus status, const std::string& message) {
  t_last_error = message;
  return status;
}

std::string namedAfter(const char* function, const std::string& message) {
  const std::string prefix = std::string(function) + ":";
  return message.compare(0, prefix.size(), prefix) == 0 ? message : prefix + " " + message;
}

}  // namespace prism
