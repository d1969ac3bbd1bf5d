// DeviceDescription::sameBitsShortfall: what keeps a device from giving the
// same bits as another (the renderer warns with it when such a device shares
// a frame), read from CL_DEVICE_SINGLE_FP_CONFIG.
#include <catch2/catch.hpp>

#include <string>

#include "device/device_list.h"

using namespace prism;

TEST_CASE("a device's shortfall for the same bits names what it lacks", "[device][same-bits]") {
  DeviceDescription d;
  d.correctly_rounded_divide_sqrt = true;
  d.denormals = true;
  CHECK(d.sameBitsShortfall() == nullptr);
  d.denormals = false;
  REQUIRE(d.sameBitsShortfall() != nullptr);
  CHECK(std::string(d.sameBitsShortfall()).find("subnormal") != std::string::npos);
  d.correctly_rounded_divide_sqrt = false;
  REQUIRE(d.sameBitsShortfall() != nullptr);
  CHECK(std::string(d.sameBitsShortfall()).find("division and square root") != std::string::npos);
}

TEST_CASE("PoCL's CPU devices offer what the same bits need", "[device][same-bits]") {
  // clinfo on PoCL: "Correctly-rounded divide and sqrt operations: Yes",
  // "Denormals: Yes"; the devices are read from the runtime, not assumed.
  int pocl = 0;
  for (const DeviceDescription& d : listDevices()) {
    if (d.platform_name.find("Portable Computing Language") == std::string::npos) continue;
    ++pocl;
    INFO(d.name);
    CHECK(d.sameBitsShortfall() == nullptr);
  }
  if (pocl == 0) WARN("no PoCL device here: nothing to check");
}
