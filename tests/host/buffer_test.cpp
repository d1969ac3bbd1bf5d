// Device buffers: a CPU device's buffers of a huge page or more live in host
// memory of huge pages (device/host_pages.h), smaller ones and other devices'
// where the driver puts them; either way a buffer holds what it is given.
#include <catch2/catch.hpp>

#include <sys/resource.h>

#include <cstdint>
#include <vector>

#include "device/checked_transfers.h"
#include "device/context.h"
#include "device/host_pages.h"
#include "support/shared_context.h"

using namespace prism;
using namespace prism::test;

TEST_CASE("buffers on either side of a huge page keep what is written, filled and copied", "[buffer]") {
  Context& context = sharedContext();
  // Whether a buffer's storage is host pages prism gave it (docs/devices.md).
  const bool cpu = (context.device().type & CL_DEVICE_TYPE_CPU) && !checkedTransfers();
  for (size_t bytes : {kHugePageBytes - 4, kHugePageBytes, 3 * kHugePageBytes / 2 + 12}) {
    INFO(bytes << " bytes");
    const size_t words = bytes / 4;
    std::vector<std::uint32_t> expected(words);
    for (size_t i = 0; i < words; ++i) expected[i] = static_cast<std::uint32_t>(i * 2654435761u);
    Buffer a(context, bytes), b(context, bytes);
    cl_mem_flags flags = 0;
    void* host = nullptr;
    REQUIRE(clGetMemObjectInfo(a.handle(), CL_MEM_FLAGS, sizeof flags, &flags, nullptr) == CL_SUCCESS);
    REQUIRE(clGetMemObjectInfo(a.handle(), CL_MEM_HOST_PTR, sizeof host, &host, nullptr) == CL_SUCCESS);
    const bool pages = cpu && bytes >= kHugePageBytes;
    CHECK(((flags & CL_MEM_USE_HOST_PTR) != 0) == pages);
    CHECK((host != nullptr) == pages);
    CHECK(reinterpret_cast<std::uintptr_t>(host) % kHugePageBytes == 0);
    a.writeVector(expected);
    // A fill and a copy at offsets that are not page-aligned, read back whole.
    const std::uint32_t pattern = 0xdeadbeefu;
    const size_t fill_first = 1001, fill_words = words / 3;
    a.fill(&pattern, sizeof pattern, fill_words * 4, fill_first * 4);
    for (size_t i = 0; i < fill_words; ++i) expected[fill_first + i] = pattern;
    b.write(expected.data(), 4 * 16, 0);
    a.copyTo(b, (words - 16) * 4, 16 * 4, 16 * 4);
    CHECK(a.readVector<std::uint32_t>(words) == expected);
    CHECK(b.readVector<std::uint32_t>(words) == expected);
  }
}

TEST_CASE("large buffers give their memory back when they go", "[buffer]") {
  // 64 buffers of 64 MiB, each written whole: 4 GiB resident if their pages
  // outlived them.
  Context& context = sharedContext();
  auto peak_kib = [] {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return static_cast<long>(usage.ru_maxrss);
  };
  const long before = peak_kib();
  const std::uint32_t one = 1;
  for (int k = 0; k < 64; ++k) {
    Buffer big(context, std::size_t{64} << 20);
    big.fill(&one, sizeof one, big.bytes());
    std::uint32_t last = 0;
    big.read(&last, sizeof last, big.bytes() - sizeof last);
    REQUIRE(last == 1);
    REQUIRE(peak_kib() - before < 1024 * 1024);  // under 1 GiB more, at every step
  }
}
