#include "device/device_list.h"
#include "device/device_selector.h"

#include <algorithm>
#include <cctype>
#include <sstream>

#include "device/cl_error.h"

namespace prism {
namespace {

std::string platformString(cl_platform_id p, cl_platform_info what) {
  size_t size = 0;
  PRISM_CL_CHECK(clGetPlatformInfo(p, what, 0, nullptr, &size));
  std::string s(size, '\0');
  PRISM_CL_CHECK(clGetPlatformInfo(p, what, size, s.data(), nullptr));
  while (!s.empty() && s.back() == '\0') s.pop_back();
  return s;
}

std::string deviceString(cl_device_id d, cl_device_info what) {
  size_t size = 0;
  PRISM_CL_CHECK(clGetDeviceInfo(d, what, 0, nullptr, &size));
  std::string s(size, '\0');
  PRISM_CL_CHECK(clGetDeviceInfo(d, what, size, s.data(), nullptr));
  while (!s.empty() && s.back() == '\0') s.pop_back();
  return s;
}

template <typename T>
T deviceValue(cl_device_id d, cl_device_info what) {
  T value{};
  PRISM_CL_CHECK(clGetDeviceInfo(d, what, sizeof(T), &value, nullptr));
  return value;
}

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

std::string describeAll(const std::vector<DeviceDescription>& devices) {
  std::ostringstream os;
  for (const auto& d : devices) os << "\n  " << d.index << ": " << d.name << " (" << d.platform_name << ")";
  return os.str();
}

}  // namespace

bool DeviceDescription::hasExtension(const std::string& name) const {
  std::istringstream words(extensions);
  for (std::string w; words >> w;)
    if (w == name) return true;
  return false;
}

const char* DeviceDescription::sameBitsShortfall() const {
  if (!correctly_rounded_divide_sqrt) return "does not round division and square root correctly";
  if (!denormals) return "flushes subnormal floats";
  return nullptr;
}

std::vector<DeviceDescription> listDevices() {
  cl_uint platform_count = 0;
  // With no ICD installed the loader reports CL_PLATFORM_NOT_FOUND_KHR: that is
  // "no devices", not an error.
  if (clGetPlatformIDs(0, nullptr, &platform_count) != CL_SUCCESS || platform_count == 0) return {};
  std::vector<cl_platform_id> platforms(platform_count);
  PRISM_CL_CHECK(clGetPlatformIDs(platform_count, platforms.data(), nullptr));

  std::vector<DeviceDescription> result;
  for (cl_platform_id p : platforms) {
    cl_uint device_count = 0;
    if (clGetDeviceIDs(p, CL_DEVICE_TYPE_ALL, 0, nullptr, &device_count) != CL_SUCCESS) continue;
    std::vector<cl_device_id> devices(device_count);
    PRISM_CL_CHECK(clGetDeviceIDs(p, CL_DEVICE_TYPE_ALL, device_count, devices.data(), nullptr));
    for (cl_device_id d : devices) {
      DeviceDescription desc;
      desc.index = static_cast<unsigned>(result.size());
      desc.platform = p;
      desc.device = d;
      desc.name = deviceString(d, CL_DEVICE_NAME);
      desc.vendor = deviceString(d, CL_DEVICE_VENDOR);
      desc.platform_name = platformString(p, CL_PLATFORM_NAME);
      desc.platform_version = platformString(p, CL_PLATFORM_VERSION);
      desc.driver_version = deviceString(d, CL_DRIVER_VERSION);
      desc.opencl_c_version = deviceString(d, CL_DEVICE_OPENCL_C_VERSION);
      desc.type = deviceValue<cl_device_type>(d, CL_DEVICE_TYPE);
      desc.compute_units = deviceValue<cl_uint>(d, CL_DEVICE_MAX_COMPUTE_UNITS);
      desc.global_memory_bytes = deviceValue<cl_ulong>(d, CL_DEVICE_GLOBAL_MEM_SIZE);
      desc.max_alloc_bytes = deviceValue<cl_ulong>(d, CL_DEVICE_MAX_MEM_ALLOC_SIZE);
      desc.max_work_group_size = deviceValue<size_t>(d, CL_DEVICE_MAX_WORK_GROUP_SIZE);
      desc.extensions = deviceString(d, CL_DEVICE_EXTENSIONS);
      const auto fp = deviceValue<cl_device_fp_config>(d, CL_DEVICE_SINGLE_FP_CONFIG);
      desc.correctly_rounded_divide_sqrt = (fp & CL_FP_CORRECTLY_ROUNDED_DIVIDE_SQRT) != 0;
      desc.denormals = (fp & CL_FP_DENORM) != 0;
      result.push_back(desc);
    }
  }
  return result;
}

DeviceDescription selectDevice(const std::string& selector) {
  std::vector<DeviceDescription> devices = listDevices();
  if (devices.empty())
    throw DeviceError(
        "no OpenCL device found: install an OpenCL driver (on Debian: apt-get install pocl-opencl-icd)");

  const std::string want = lower(selector);
  if (want.empty()) {
    for (const auto& d : devices)
      if (d.type & CL_DEVICE_TYPE_GPU) return d;
    return devices.front();
  }
  if (std::all_of(want.begin(), want.end(), [](unsigned char c) { return std::isdigit(c); })) {
    unsigned long index = std::stoul(want);
    if (index < devices.size()) return devices[index];
    throw DeviceError("device '" + selector + "': no device with that index; devices are:" + describeAll(devices));
  }
  if (want == "cpu" || want == "gpu") {
    cl_device_type type = want == "cpu" ? CL_DEVICE_TYPE_CPU : CL_DEVICE_TYPE_GPU;
    for (const auto& d : devices)
      if (d.type & type) return d;
    throw DeviceError("device '" + selector + "': no " + want + " device; devices are:" + describeAll(devices));
  }
  for (const auto& d : devices)
    if (lower(d.name).find(want) != std::string::npos) return d;
  throw DeviceError("device '" + selector + "': no device name contains '" + selector + "'; devices are:" +
                    describeAll(devices));
}

std::vector<DeviceDescription> selectDevices(const std::string& selector) {
  if (lower(selector) == "all") {
    std::vector<DeviceDescription> devices = listDevices();
    if (devices.empty())
      throw DeviceError(
          "no OpenCL device found: install an OpenCL driver (on Debian: apt-get install pocl-opencl-icd)");
    return devices;
  }
  std::vector<std::string> parts;
  try {
    parts = deviceSelectorParts(selector);
  } catch (const std::invalid_argument& e) {
    throw DeviceError(e.what());
  }
  std::vector<DeviceDescription> chosen;
  for (const std::string& part : parts) {
    DeviceDescription d = selectDevice(part);
    for (const DeviceDescription& c : chosen)
      if (c.index == d.index)
        throw DeviceError("devices '" + selector + "': device " + std::to_string(d.index) + " (" + d.name +
                          ") is named twice");
    chosen.push_back(std::move(d));
  }
  return chosen;
}

}  // namespace prism
