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

}  // namespace prism
