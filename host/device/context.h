// One OpenCL device with its context, in-order queue and compiled programs.
// Programs are built once per (entry file, options) and kept in memory; their
// binaries also go to the on-disk ProgramCache. Everything else in prism reaches
// OpenCL through this class and Buffer.
#pragma once

#include <CL/cl.h>

#include <map>
#include <set>
#include <memory>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

#include "device/cl_error.h"
#include "device/device_list.h"
#include "device/kernel_profile.h"
#include "device/program_cache.h"

namespace prism {

class Context;

// A device buffer owned by one Context.
class Buffer {
 public:
  Buffer() = default;
  Buffer(Context& context, size_t bytes);
  Buffer(Buffer&& other) noexcept { *this = std::move(other); }
  Buffer& operator=(Buffer&& other) noexcept;
  Buffer(const Buffer&) = delete;
  Buffer& operator=(const Buffer&) = delete;
  ~Buffer();

  cl_mem handle() const { return m_mem; }
  size_t bytes() const { return m_bytes; }
  void write(const void* data, size_t bytes, size_t offset = 0);
  void read(void* data, size_t bytes, size_t offset = 0) const;
  // Grows (never shrinks) to at least `bytes`; contents are not kept.
  void reserve(Context& context, size_t bytes);
  // Enqueues filling `bytes` from `offset` (both multiples of the pattern's size)
  // with a repeated pattern of 1, 2, 4, ... 128 bytes.
  void fill(const void* pattern, size_t pattern_bytes, size_t bytes, size_t offset = 0);
  // Enqueues copying `bytes` from this buffer at `offset` into `to` at `to_offset`.
  void copyTo(Buffer& to, size_t bytes, size_t offset = 0, size_t to_offset = 0) const;

  template <typename T, typename Allocator>
  void writeVector(const std::vector<T, Allocator>& v) {
    if (!v.empty()) write(v.data(), v.size() * sizeof(T));
  }
  template <typename T>
  std::vector<T> readVector(size_t count) const {
    std::vector<T> v(count);
    if (count) read(v.data(), count * sizeof(T));
    return v;
  }

 private:
  cl_mem m_mem = nullptr;
  cl_command_queue m_queue = nullptr;
  size_t m_bytes = 0;
};

// A kernel bound to its arguments and launched over `count` work-items (the
// kernel must ignore ids >= count: the global size is rounded up to the
// work-group size queried from the device).
class KernelLaunch {
 public:
  KernelLaunch(Context& context, cl_kernel kernel) : m_context(context), m_kernel(kernel) {}

  KernelLaunch& arg(const Buffer& b) {
    cl_mem mem = b.handle();
    return raw(sizeof(cl_mem), &mem);
  }
  template <typename T>
  KernelLaunch& arg(const T& value) {
    static_assert(std::is_trivially_copyable<T>::value, "kernel arguments are plain data");
    return raw(sizeof(T), &value);
  }
  void run(size_t count);

 private:
  KernelLaunch& raw(size_t size, const void* value);
  Context& m_context;
  cl_kernel m_kernel;
  cl_uint m_index = 0;
};

// Whether compiled programs go into prism's disk cache (ProgramCache). PoCL
// caches every build itself (POCL_CACHE_DIR, unless POCL_KERNEL_CACHE=0), and
// fetching a PoCL program's binary compiles each of its kernels once more, for a
// work-group size no launch uses: 1.7 s of a 5.1 s cold start of the default
// render, against 0.12 s that the binary saves a warm one. So by default a device
// whose driver caches its builds is left to that cache.
enum class BinaryCache { UnlessDriverCaches, Always };

// Whether the device's driver keeps its own cache of program builds (PoCL's).
bool driverCachesBuilds(const DeviceDescription& device);

class Context {
 public:
  // use_disk_cache false (--no-cache): prism's disk cache is neither read nor written.
  Context(const DeviceDescription& device, bool use_disk_cache,
          BinaryCache binaries = BinaryCache::UnlessDriverCaches);
  ~Context();
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;

  const DeviceDescription& device() const { return m_device; }
  cl_context handle() const { return m_context; }
  cl_command_queue queue() const { return m_queue; }

  // The kernel `name` from program `entry_file` (a path under kernels/) built with
  // `options` appended to prism's standard build options.
  cl_kernel kernel(const std::string& entry_file, const std::string& name, const std::string& options = "");
  // Same, for a program given as text (test probes); `name` keys the cache.
  cl_kernel kernelFromText(const std::string& text, const std::string& program_name, const std::string& kernel_name,
                           const std::string& options = "");
  KernelLaunch launch(cl_kernel kernel) { return KernelLaunch(*this, kernel); }
  // KernelLaunch::run: the work-group size of a kernel's launches (64, or
  // less where the kernel or device allows less; a multiple of the preferred
  // one where it can be), asked of the driver once per kernel.
  size_t localSize(cl_kernel kernel);
  // KernelLaunch::run: whether this is the kernel's first launch (then it
  // keeps the launch's event for takeFirstLaunchSeconds).
  bool firstLaunch(cl_kernel kernel);
  void keepFirstLaunch(cl_event event);
  void finish();

  // Seconds spent building or loading programs since the last call.
  double takeBuildSeconds();
  // Seconds the kernels launched for the first time since the last call waited
  // between submission and start: a driver compiles a kernel for its launch
  // there (PoCL specialises it for the work-group size, about 0.1-0.6 s each),
  // so it is start-up cost, not tracing. Waits for those launches to finish.
  double takeFirstLaunchSeconds();

  // Device times of the launches made while it is started.
  KernelProfile& profile() { return m_profile; }

 private:
  struct Program {
    cl_program program = nullptr;
    std::map<std::string, cl_kernel> kernels;
  };
  Program& program(const std::string& key_name, const std::string& source, const std::string& options);
  cl_program buildProgram(const std::string& source, const std::string& options, const std::string& name);

  DeviceDescription m_device;
  cl_context m_context = nullptr;
  cl_command_queue m_queue = nullptr;
  bool m_use_disk_cache;
  ProgramCache m_disk_cache;
  std::map<std::string, Program> m_programs;  // key: name + options
  std::mutex m_mutex;
  double m_build_seconds = 0;
  std::set<cl_kernel> m_launched;         // kernels launched at least once
  std::map<cl_kernel, size_t> m_local_sizes;  // their work-group sizes
  std::vector<cl_event> m_first_launches; // their first launches' events, until taken
  std::mutex m_launch_mutex;              // guards the three above
  KernelProfile m_profile;
};

}  // namespace prism
