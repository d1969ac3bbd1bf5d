// OpenCL platform and device enumeration, and selection of one device from a
// user's selector string (index, "cpu", "gpu", or a name substring).
#pragma once

#include <CL/cl.h>

#include <cstdint>
#include <string>
#include <vector>

namespace prism {

struct DeviceDescription {
  unsigned index = 0;  // position over all platforms, in enumeration order
  cl_platform_id platform = nullptr;
  cl_device_id device = nullptr;
  std::string name, vendor, platform_name, platform_version, driver_version, opencl_c_version;
  cl_device_type type = 0;
  unsigned compute_units = 0;
  std::uint64_t global_memory_bytes = 0;
  std::uint64_t max_alloc_bytes = 0;  // CL_DEVICE_MAX_MEM_ALLOC_SIZE: the largest single buffer
  std::size_t max_work_group_size = 1;
  std::string extensions;  // CL_DEVICE_EXTENSIONS, space-separated
  // CL_DEVICE_SINGLE_FP_CONFIG: whether float division and sqrt can be asked
  // to round correctly, and whether subnormals are kept. With both, a kernel
  // that uses only kernels/common/same_bits_math.h gives the same bits here
  // as on any other such device.
  bool correctly_rounded_divide_sqrt = false;
  bool denormals = false;

  bool hasExtension(const std::string& name) const;
  // What keeps this device from giving the same bits as any other (a phrase
  // for a warning), or null when nothing does.
  const char* sameBitsShortfall() const;
};

// Every device of every platform; empty when no OpenCL runtime is installed.
std::vector<DeviceDescription> listDevices();

// Picks a device: "" = the first GPU, else the first device; a decimal index;
// "cpu" / "gpu"; or a case-insensitive substring of the name. Throws DeviceError
// listing the devices when nothing matches.
DeviceDescription selectDevice(const std::string& selector);

// The devices one frame is dealt out over: "all" (every device, in index
// order), a comma-separated list of selectors as above ("0,2", "gpu,cpu"; no
// device twice), or one selector. Throws DeviceError as selectDevice does.
std::vector<DeviceDescription> selectDevices(const std::string& selector);

}  // namespace prism
