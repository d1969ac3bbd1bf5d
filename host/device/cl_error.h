// OpenCL error handling: every OpenCL call in host/device/ goes through
// PRISM_CL_CHECK, which throws DeviceError naming the call, its CL_* code and
// the source line. Nothing outside host/device/ includes <CL/cl.h>.
#pragma once

#include <CL/cl.h>

#include <stdexcept>
#include <string>

namespace prism {

class DeviceError : public std::runtime_error {
 public:
  explicit DeviceError(const std::string& message) : std::runtime_error(message) {}
};

// A kernel failed to compile; what() holds the compiler's log.
class KernelBuildError : public DeviceError {
 public:
  using DeviceError::DeviceError;
};

const char* clErrorName(cl_int code);
[[noreturn]] void throwClError(cl_int code, const char* call, const char* file, int line);

}  // namespace prism

#define PRISM_CL_CHECK(call)                                                          \
  do {                                                                                \
    cl_int prism_cl_status_ = (call);                                                 \
    if (prism_cl_status_ != CL_SUCCESS)                                               \
      ::prism::throwClError(prism_cl_status_, #call, __FILE__, __LINE__);             \
  } while (0)
