// The OpenCL sources of kernels/, embedded at build time (cmake/EmbedKernels.cmake).
#pragma once

#include <vector>

namespace prism {

struct EmbeddedKernelFile {
  const char* path;  // relative to kernels/, e.g. "extend.cl" or "shared/ray_gpu.h"
  const char* text;
};

const std::vector<EmbeddedKernelFile>& embeddedKernelFiles();

}  // namespace prism
