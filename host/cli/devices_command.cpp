// `prism devices`: what OpenCL sees, in the numbering `--device N` uses.
#include <cstdio>
#include <string>
#include <vector>

#include "args.h"
#include "commands.h"
#include "help_text.h"
#include "prism.h"

namespace prism_cli {
namespace {

const char* typeName(PrismDeviceType type) {
  switch (type) {
    case PRISM_DEVICE_CPU: return "CPU";
    case PRISM_DEVICE_GPU: return "GPU";
    case PRISM_DEVICE_ACCELERATOR: return "accelerator";
    default: return "other";
  }
}

std::string formatBytes(uint64_t bytes) {
  char text[32];
  const double gib = static_cast<double>(bytes) / (1024.0 * 1024.0 * 1024.0);
  if (gib >= 1.0) {
    std::snprintf(text, sizeof text, "%.1f GiB", gib);
  } else {
    std::snprintf(text, sizeof text, "%.0f MiB", static_cast<double>(bytes) / (1024.0 * 1024.0));
  }
  return text;
}

void printDevice(const PrismDeviceInfo& info, bool is_default) {
  std::printf("[%u] %s%s\n", static_cast<unsigned>(info.index), info.name, is_default ? "  (default)" : "");
  std::printf("    type:          %s\n", typeName(info.type));
  std::printf("    vendor:        %s\n", info.vendor);
  std::printf("    platform:      %s\n", info.platform);
  std::printf("    compute units: %u\n", static_cast<unsigned>(info.compute_units));
  std::printf("    global memory: %s\n", formatBytes(info.global_memory_bytes).c_str());
  std::printf("    OpenCL C:      %s\n", info.opencl_c_version);
  std::printf("    driver:        %s\n", info.driver_version);
}

}  // namespace

int runDevices(const std::vector<std::string>& args) {
  const ParsedArgs parsed = parseArgs(args, {{"--help", "-h", false}}, "prism devices");
  if (parsed.has("--help")) {
    std::fputs(kDevicesHelp, stdout);
    return kExitOk;
  }
  if (!parsed.positionals().empty()) {
    throw UsageError("'prism devices' takes no arguments (got '" + parsed.positionals().front() + "')");
  }

  uint32_t count = 0;
  if (prismGetDeviceCount(&count) != PRISM_OK) return failWithLastError();
  if (count == 0) {
    printError(
        "no OpenCL devices found. prism needs an OpenCL runtime; to render on the CPU, "
        "install PoCL:\n  sudo apt-get install pocl-opencl-icd\n"
        "GPUs need their vendor's OpenCL driver ('clinfo' shows what OpenCL sees).");
    return kExitFailure;
  }

  std::vector<PrismDeviceInfo> devices(count);
  for (uint32_t i = 0; i < count; ++i) {
    if (prismGetDeviceInfo(i, &devices[i]) != PRISM_OK) return failWithLastError();
  }
  // Mirrors prismCreateContext's documented default: the first GPU, else device 0.
  uint32_t default_index = 0;
  for (uint32_t i = 0; i < count; ++i) {
    if (devices[i].type == PRISM_DEVICE_GPU) {
      default_index = i;
      break;
    }
  }
  for (uint32_t i = 0; i < count; ++i) printDevice(devices[i], i == default_index);
  std::printf("\nChoose one with 'prism render --device N' (or cpu, gpu, or part of its name);\n"
              "share each frame over several with --device all or a list such as --device 0,2.\n");
  return kExitOk;
}

}  // namespace prism_cli
