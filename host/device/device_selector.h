// The form of a device selector, apart from which devices the machine has
// (device_list.h resolves it): one selector (an index, "cpu", "gpu", part of a
// name, or "" for the default), "all", or a comma-separated list of selectors
// for several devices. Checked here for both the scene loader's render.device
// and the selectors given to prismCreateContext and --device.
#pragma once

#include <string>
#include <vector>

namespace prism {

// The selector's parts: {selector} for one device or "all", else the list's
// entries. Throws std::invalid_argument (naming the selector) for an empty part
// of a list or "all" among other parts.
std::vector<std::string> deviceSelectorParts(const std::string& selector);

}  // namespace prism
