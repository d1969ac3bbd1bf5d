#include "device/kernel_source.h"

#include <cstdlib>
#include <fstream>
#include <set>
#include <sstream>

#include "device/cl_error.h"
#include "device/embedded_kernels.h"

namespace prism {
namespace {

void appendResolved(const std::string& text, const std::string& name, std::set<std::string>& seen,
                    std::ostringstream& out) {
  std::istringstream in(text);
  std::string line;
  int line_number = 0;
  out << "#line 1 \"" << name << "\"\n";
  while (std::getline(in, line)) {
    ++line_number;
    size_t start = line.find_first_not_of(" \t");
    if (start != std::string::npos && line.compare(start, 8, "#include") == 0) {
      size_t open = line.find('"', start);
      size_t close = open == std::string::npos ? open : line.find('"', open + 1);
      if (close == std::string::npos)
        throw DeviceError(name + ":" + std::to_string(line_number) + ": kernels may only #include \"file\"");
      std::string included = line.substr(open + 1, close - open - 1);
      if (seen.insert(included).second) appendResolved(kernelFileText(included), included, seen, out);
      out << "#line " << line_number + 1 << " \"" << name << "\"\n";
      continue;
    }
    out << line << "\n";
  }
}

}  // namespace

std::string kernelFileText(const std::string& path) {
  if (const char* dir = std::getenv("PRISM_KERNEL_DIR"); dir && *dir) {
    std::ifstream file(std::string(dir) + "/" + path, std::ios::binary);
    if (!file) throw DeviceError(std::string("PRISM_KERNEL_DIR=") + dir + ": cannot read kernel file " + path);
    std::ostringstream os;
    os << file.rdbuf();
    return os.str();
  }
  for (const EmbeddedKernelFile& f : embeddedKernelFiles())
    if (path == f.path) return f.text;
  throw DeviceError("no kernel file '" + path + "' is embedded in this build of prism");
}

std::string assembleKernelSource(const std::string& entry_path, const std::string& prelude) {
  return assembleKernelText(prelude + kernelFileText(entry_path), entry_path);
}

std::string assembleKernelText(const std::string& text, const std::string& name) {
  std::set<std::string> seen;
  std::ostringstream out;
  // Every program starts with the math that gives the same bits on every
  // device, so that none can use OpenCL's own functions before it.
  const std::string same_bits = "common/same_bits_math.h";
  seen.insert(same_bits);
  appendResolved(kernelFileText(same_bits), same_bits, seen, out);
  appendResolved(text, name, seen, out);
  return out.str();
}

}  // namespace prism
