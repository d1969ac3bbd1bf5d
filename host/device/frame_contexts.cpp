#include "device/frame_contexts.h"

#include <algorithm>

namespace prism {

unsigned computeUnitsBeside(const std::vector<DeviceDescription>& devices, std::size_t i) {
  const DeviceDescription& device = devices.at(i);
  if (!(device.type & CL_DEVICE_TYPE_CPU)) return 0;
  const auto drivers = static_cast<unsigned>(std::count_if(
      devices.begin(), devices.end(), [](const DeviceDescription& d) { return !(d.type & CL_DEVICE_TYPE_CPU); }));
  if (drivers == 0) return 0;
  return device.compute_units > drivers ? device.compute_units - drivers : 1;
}

std::vector<std::unique_ptr<Context>> openFrameContexts(const std::vector<DeviceDescription>& devices,
                                                        bool use_disk_cache) {
  std::vector<std::unique_ptr<Context>> contexts;
  contexts.reserve(devices.size());
  for (std::size_t i = 0; i < devices.size(); ++i)
    contexts.push_back(std::make_unique<Context>(devices[i], use_disk_cache, BinaryCache::UnlessDriverCaches,
                                                 computeUnitsBeside(devices, i)));
  return contexts;
}

}  // namespace prism
