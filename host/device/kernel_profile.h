// Device time of each kernel launched while profiling is on, read from the
// queue's profiling events and summed by kernel name: where a render's time goes
// on the device (`prism render --stats`).
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include <CL/cl.h>

namespace prism {

struct KernelTime {
  std::string name;
  double seconds = 0;  // summed over the launches, from their profiling events
  std::uint64_t launches = 0;
};

// Adds `more` into `into` by kernel name (the devices of one frame), longest first.
void mergeKernelTimes(std::vector<KernelTime>& into, const std::vector<KernelTime>& more);

class KernelProfile {
 public:
  KernelProfile() = default;
  KernelProfile(const KernelProfile&) = delete;
  KernelProfile& operator=(const KernelProfile&) = delete;
  ~KernelProfile();

  bool enabled() const { return m_enabled; }
  // Forgets what was recorded and records from now on.
  void start();
  // Keeps `event` (of a launch of `kernel`) until stop().
  void record(cl_kernel kernel, cl_event event);
  // Waits for the recorded launches and returns their times by kernel, longest
  // first; records no more.
  std::vector<KernelTime> stop();
  // Drops what was recorded and records no more.
  void discard();

 private:
  void release();
  bool m_enabled = false;
  std::vector<std::pair<cl_kernel, cl_event>> m_events;
};

}  // namespace prism
