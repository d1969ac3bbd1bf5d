// The contexts of devices that share frames. A CPU device shares its cores with
// the host threads that drive the other devices: a GPU's wave loop launches a
// kernel every few hundred microseconds and its driver waits for each by
// spinning, so a CPU device on every core leaves that thread waiting for a core
// while the GPU idles (measured on an H200 beside PoCL on 16 cores: the shared
// frame ran at a third of the GPU's solo speed; docs/devices.md). Like Cycles,
// which drops one CPU thread per GPU, prism gives a CPU device one compute unit
// fewer per device of another kind beside it (device fission, Context).
#pragma once

#include <cstddef>
#include <memory>
#include <vector>

#include "device/context.h"
#include "device/device_list.h"

namespace prism {

// The compute units device i should use beside the others: for a CPU, its own
// less one per device that is not a CPU (at least 1); 0 (all) otherwise. CPU
// devices beside each other (several PoCL devices) keep all theirs: they share
// the same cores whatever each is given.
unsigned computeUnitsBeside(const std::vector<DeviceDescription>& devices, std::size_t i);

// One context per device, in order, each on computeUnitsBeside's units.
std::vector<std::unique_ptr<Context>> openFrameContexts(const std::vector<DeviceDescription>& devices,
                                                        bool use_disk_cache);

}  // namespace prism
