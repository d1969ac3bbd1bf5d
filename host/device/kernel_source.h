// Assembles the full text of a kernel program: the entry file with its
// `#include "..."` lines replaced by the included files (each at most once), with
// #line markers so compiler messages point at the right file. Sources come from
// the embedded copy, or from $PRISM_KERNEL_DIR when it is set (development).
#pragma once

#include <string>

namespace prism {

// Text of one kernel file (relative to kernels/); throws DeviceError if missing.
std::string kernelFileText(const std::string& path);

// The entry file with its includes resolved. `prelude` is prepended verbatim
// (test probes use it to compile extra code against the kernel headers).
std::string assembleKernelSource(const std::string& entry_path, const std::string& prelude = "");

// Same as assembleKernelSource, for a probe whose own text is given rather than
// read from kernels/ (its includes still resolve against kernels/).
std::string assembleKernelText(const std::string& text, const std::string& name);

}  // namespace prism
