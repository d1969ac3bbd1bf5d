#include "device/kernel_profile.h"

#include <algorithm>
#include <map>

#include "device/cl_error.h"

namespace prism {

KernelProfile::~KernelProfile() { release(); }

void KernelProfile::release() {
  for (auto& [kernel, event] : m_events) clReleaseEvent(event);
  m_events.clear();
}

void KernelProfile::discard() {
  m_enabled = false;
  release();
}

void KernelProfile::start() {
  release();
  m_enabled = true;
}

void KernelProfile::record(cl_kernel kernel, cl_event event) { m_events.emplace_back(kernel, event); }

std::vector<KernelTime> KernelProfile::stop() {
  m_enabled = false;
  std::map<cl_kernel, KernelTime> by_kernel;
  for (auto& [kernel, event] : m_events) {
    PRISM_CL_CHECK(clWaitForEvents(1, &event));
    cl_ulong begin = 0, end = 0;
    PRISM_CL_CHECK(clGetEventProfilingInfo(event, CL_PROFILING_COMMAND_START, sizeof begin, &begin, nullptr));
    PRISM_CL_CHECK(clGetEventProfilingInfo(event, CL_PROFILING_COMMAND_END, sizeof end, &end, nullptr));
    KernelTime& t = by_kernel[kernel];
    t.seconds += end > begin ? static_cast<double>(end - begin) * 1e-9 : 0.0;
    ++t.launches;
  }
  release();
  std::vector<KernelTime> out;
  for (auto& [kernel, t] : by_kernel) {
    char name[256] = {0};
    clGetKernelInfo(kernel, CL_KERNEL_FUNCTION_NAME, sizeof name - 1, name, nullptr);
    t.name = name;
    out.push_back(t);
  }
  std::sort(out.begin(), out.end(), [](const KernelTime& a, const KernelTime& b) { return a.seconds > b.seconds; });
  return out;
}

void mergeKernelTimes(std::vector<KernelTime>& into, const std::vector<KernelTime>& more) {
  for (const KernelTime& m : more) {
    auto same = std::find_if(into.begin(), into.end(), [&](const KernelTime& k) { return k.name == m.name; });
    if (same == into.end()) {
      into.push_back(m);
    } else {
      same->seconds += m.seconds;
      same->launches += m.launches;
    }
  }
  std::stable_sort(into.begin(), into.end(), [](const KernelTime& a, const KernelTime& b) { return a.seconds > b.seconds; });
}

}  // namespace prism
