// Deals the units of a frame (ranges of its sample sequence) out to several
// devices as each becomes free, so a faster device takes more of them; a device
// that fails (DeviceError) is retired with a warning and its unit goes back to
// the others. Which device traced a unit never changes its result: a unit's
// samples depend on their keys alone (render/device_tracer.h).
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace prism {

// One device's part of a frame.
struct DeviceShare {
  std::string device;           // its name
  std::uint64_t units = 0;      // units it finished (that count: none once it failed)
  std::uint64_t samples = 0;    // primary samples in them
  double busy_seconds = 0;      // wall time spent in its units
  bool failed = false;          // retired mid-frame; its unfinished unit went to the others
  std::string failure;          // why
};

struct DealResult {
  std::vector<std::size_t> owner;     // per unit: the device that finished it
  std::vector<std::string> warnings;  // one per retired device
  bool cancelled = false;
};

// unit(device, u) traces unit u on device `device`; it may throw. A DeviceError
// retires the device (its unit, and the units it had finished, are dealt
// again: nothing is read back from a device that failed); any other exception (a
// cancellation, a limit in the user's terms) stops the frame and is rethrown
// once every device has stopped. progress(units finished, units) is called on
// the calling thread; returning false cancels: no unit starts after that, and
// the result says so. With one device the units run in order on the calling
// thread and a failure is rethrown as it came. Throws the last failure when
// every device has failed.
using UnitFn = std::function<void(std::size_t device, std::size_t unit)>;
DealResult dealUnits(std::vector<DeviceShare>& devices, const std::vector<std::uint64_t>& unit_samples,
                     const UnitFn& unit, const std::function<bool(std::size_t done, std::size_t units)>& progress);

}  // namespace prism
