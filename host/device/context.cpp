#include "device/context.h"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#include "device/checked_transfers.h"
#include "device/host_pages.h"
#include "device/kernel_source.h"

namespace prism {
namespace {

// Strict IEEE math (no -cl-fast-relaxed-math) keeps images bit-identical run to
// run; see PERF-NOTES.md. Every program gets these.
const char* kStandardOptions = "-cl-std=CL1.2";
// And, where the device offers it, IEEE's division and square root, which with
// the kernels' own elementary functions (kernels/common/same_bits_math.h) make
// one device's image the same bits as another's.
const char* kCorrectlyRoundedOption = "-cl-fp32-correctly-rounded-divide-sqrt";

// Zero-sized OpenCL buffers are invalid; empty scenes still bind a buffer.
constexpr size_t kMinBufferBytes = 16;

std::string buildLog(cl_program program, cl_device_id device) {
  size_t size = 0;
  clGetProgramBuildInfo(program, device, CL_PROGRAM_BUILD_LOG, 0, nullptr, &size);
  std::string log(size, '\0');
  clGetProgramBuildInfo(program, device, CL_PROGRAM_BUILD_LOG, size, log.data(), nullptr);
  while (!log.empty() && (log.back() == '\0' || log.back() == '\n')) log.pop_back();
  return log;
}

std::vector<unsigned char> programBinary(cl_program program) {
  size_t size = 0;
  if (clGetProgramInfo(program, CL_PROGRAM_BINARY_SIZES, sizeof(size), &size, nullptr) != CL_SUCCESS || size == 0)
    return {};
  std::vector<unsigned char> binary(size);
  unsigned char* ptr = binary.data();
  if (clGetProgramInfo(program, CL_PROGRAM_BINARIES, sizeof(ptr), &ptr, nullptr) != CL_SUCCESS) return {};
  return binary;
}

}  // namespace

// ---- Buffer ------------------------------------------------------------------

namespace {

void CL_CALLBACK freeBufferPages(cl_mem, void* pages) {
  const HostPages* owned = static_cast<const HostPages*>(pages);
  freeHostPages(*owned);
  delete owned;
}

// A CPU device's buffer of a huge page or more, in host memory of huge pages
// that OpenCL uses as the buffer's storage (docs/devices.md, "Where a buffer's
// memory lives"). OpenCL calls freeBufferPages when it destroys the buffer:
// after the Buffer goes and once the commands that use it are done. Null where
// the device or the memory declines. Not under Oclgrind's uninitialised-value
// checker (PRISM_HOST_TRANSFERS): it takes a buffer made from host memory to
// be written whole, which would hide the reads it is there to find.
cl_mem hostPagesBuffer(Context& context, size_t bytes) {
  if (!(context.device().type & CL_DEVICE_TYPE_CPU) || bytes < kHugePageBytes || checkedTransfers()) return nullptr;
  const HostPages pages = allocateHostPages(bytes);
  if (!pages.data) return nullptr;
  cl_int status = CL_SUCCESS;
  cl_mem mem = clCreateBuffer(context.handle(), CL_MEM_READ_WRITE | CL_MEM_USE_HOST_PTR, bytes, pages.data, &status);
  if (status == CL_SUCCESS) {
    auto owned = std::make_unique<HostPages>(pages);
    if (clSetMemObjectDestructorCallback(mem, freeBufferPages, owned.get()) == CL_SUCCESS) {
      owned.release();  // freeBufferPages deletes it
      return mem;
    }
    clReleaseMemObject(mem);  // nothing has used it yet: its pages can go now
  }
  freeHostPages(pages);
  return nullptr;
}

}  // namespace

Buffer::Buffer(Context& context, size_t bytes) : m_queue(context.queue()), m_bytes(std::max(bytes, kMinBufferBytes)) {
  m_mem = hostPagesBuffer(context, m_bytes);
  if (m_mem) return;
  cl_int status = CL_SUCCESS;
  m_mem = clCreateBuffer(context.handle(), CL_MEM_READ_WRITE, m_bytes, nullptr, &status);
  if (status != CL_SUCCESS) throwClError(status, "clCreateBuffer", __FILE__, __LINE__);
}

Buffer& Buffer::operator=(Buffer&& other) noexcept {
  if (this != &other) {
    if (m_mem) releaseBuffer(m_mem);
    m_mem = std::exchange(other.m_mem, nullptr);
    m_queue = other.m_queue;
    m_bytes = std::exchange(other.m_bytes, 0);
  }
  return *this;
}

Buffer::~Buffer() {
  if (m_mem) releaseBuffer(m_mem);  // cannot throw from a destructor; a failure here only leaks
}

void Buffer::write(const void* data, size_t bytes, size_t offset) {
  if (bytes == 0) return;
  // A host write of part of a buffer would hide the rest from Oclgrind's checker.
  if (checkedTransfers() && (offset != 0 || bytes != m_bytes)) return checkedWrite(m_queue, m_mem, offset, data, bytes);
  PRISM_CL_CHECK(clEnqueueWriteBuffer(m_queue, m_mem, CL_TRUE, offset, bytes, data, 0, nullptr, nullptr));
}

void Buffer::read(void* data, size_t bytes, size_t offset) const {
  if (bytes == 0) return;
  PRISM_CL_CHECK(clEnqueueReadBuffer(m_queue, m_mem, CL_TRUE, offset, bytes, data, 0, nullptr, nullptr));
}

void Buffer::copyTo(Buffer& to, size_t bytes, size_t offset, size_t to_offset) const {
  if (bytes == 0) return;
  if (checkedTransfers()) return checkedCopy(m_queue, m_mem, offset, to.m_mem, to_offset, bytes);
  PRISM_CL_CHECK(clEnqueueCopyBuffer(m_queue, m_mem, to.m_mem, offset, to_offset, bytes, 0, nullptr, nullptr));
}

void Buffer::fill(const void* pattern, size_t pattern_bytes, size_t bytes, size_t offset) {
  if (bytes == 0) return;
  if (checkedTransfers()) {
    std::vector<unsigned char> bytes_out(bytes);
    for (size_t i = 0; i < bytes; ++i) bytes_out[i] = static_cast<const unsigned char*>(pattern)[i % pattern_bytes];
    return write(bytes_out.data(), bytes, offset);
  }
  PRISM_CL_CHECK(clEnqueueFillBuffer(m_queue, m_mem, pattern, pattern_bytes, offset, bytes, 0, nullptr, nullptr));
}

void Buffer::reserve(Context& context, size_t bytes) {
  if (m_mem && bytes <= m_bytes) return;
  *this = Buffer(context, bytes);
}

// ---- KernelLaunch --------------------------------------------------------------

KernelLaunch& KernelLaunch::raw(size_t size, const void* value) {
  PRISM_CL_CHECK(clSetKernelArg(m_kernel, m_index, size, value));
  ++m_index;
  return *this;
}

void KernelLaunch::run(size_t count) {
  if (count == 0) return;
  const size_t local = m_context.localSize(m_kernel);
  size_t global = (count + local - 1) / local * local;
  KernelProfile& profile = m_context.profile();
  const bool first = m_context.firstLaunch(m_kernel);
  cl_event event = nullptr;
  PRISM_CL_CHECK(clEnqueueNDRangeKernel(m_context.queue(), m_kernel, 1, nullptr, &global, &local, 0, nullptr,
                                        profile.enabled() || first ? &event : nullptr));
  if (!event) return;
  if (first) {
    if (profile.enabled()) clRetainEvent(event);  // held by both
    m_context.keepFirstLaunch(event);
  }
  if (profile.enabled()) profile.record(m_kernel, event);
}

// ---- Context -------------------------------------------------------------------

bool driverCachesBuilds(const DeviceDescription& device) {
  if (device.platform_name.find("Portable Computing Language") == std::string::npos) return false;
  const char* cache = std::getenv("POCL_KERNEL_CACHE");
  return !(cache && std::string(cache) == "0");
}

Context::Context(const DeviceDescription& device, bool use_disk_cache, BinaryCache binaries)
    : m_device(device),
      m_use_disk_cache(use_disk_cache && (binaries == BinaryCache::Always || !driverCachesBuilds(device))) {
  cl_int status = CL_SUCCESS;
  cl_context_properties props[] = {CL_CONTEXT_PLATFORM, reinterpret_cast<cl_context_properties>(device.platform), 0};
  m_context = clCreateContext(props, 1, &device.device, nullptr, nullptr, &status);
  if (status != CL_SUCCESS) throwClError(status, "clCreateContext", __FILE__, __LINE__);
  // Profiling costs nothing until a render asks for it (KernelProfile).
  m_queue = clCreateCommandQueue(m_context, device.device, CL_QUEUE_PROFILING_ENABLE, &status);
  if (status != CL_SUCCESS) {
    clReleaseContext(m_context);
    throwClError(status, "clCreateCommandQueue", __FILE__, __LINE__);
  }
}

Context::~Context() {
  m_profile.discard();  // its events hold the queue
  for (cl_event e : m_first_launches) clReleaseEvent(e);
  for (auto& [key, p] : m_programs) {
    for (auto& [name, k] : p.kernels) clReleaseKernel(k);
    clReleaseProgram(p.program);
  }
  if (m_queue) clReleaseCommandQueue(m_queue);
  if (m_context) clReleaseContext(m_context);
}

void Context::finish() { PRISM_CL_CHECK(clFinish(m_queue)); }

size_t Context::localSize(cl_kernel kernel) {
  {
    std::lock_guard<std::mutex> lock(m_launch_mutex);
    auto known = m_local_sizes.find(kernel);
    if (known != m_local_sizes.end()) return known->second;
  }
  size_t kernel_max = 0;
  PRISM_CL_CHECK(clGetKernelWorkGroupInfo(kernel, m_device.device, CL_KERNEL_WORK_GROUP_SIZE, sizeof(kernel_max),
                                          &kernel_max, nullptr));
  size_t multiple = 1;
  clGetKernelWorkGroupInfo(kernel, m_device.device, CL_KERNEL_PREFERRED_WORK_GROUP_SIZE_MULTIPLE, sizeof(multiple),
                           &multiple, nullptr);
  // 64 work-items suit both CPU (PoCL is insensitive, PERF-NOTES) and GPUs, as
  // long as the device and kernel allow it.
  size_t local = std::min<size_t>({64, kernel_max, m_device.max_work_group_size});
  if (multiple > 1 && multiple <= local) local -= local % multiple;
  local = std::max<size_t>(local, 1);
  std::lock_guard<std::mutex> lock(m_launch_mutex);
  m_local_sizes[kernel] = local;
  return local;
}

bool Context::firstLaunch(cl_kernel kernel) {
  std::lock_guard<std::mutex> lock(m_launch_mutex);
  return m_launched.insert(kernel).second;
}

void Context::keepFirstLaunch(cl_event event) {
  std::lock_guard<std::mutex> lock(m_launch_mutex);
  m_first_launches.push_back(event);
}

double Context::takeFirstLaunchSeconds() {
  std::lock_guard<std::mutex> lock(m_launch_mutex);
  double seconds = 0;
  for (cl_event e : m_first_launches) {
    cl_ulong submit = 0, start = 0;
    if (clWaitForEvents(1, &e) == CL_SUCCESS &&
        clGetEventProfilingInfo(e, CL_PROFILING_COMMAND_SUBMIT, sizeof submit, &submit, nullptr) == CL_SUCCESS &&
        clGetEventProfilingInfo(e, CL_PROFILING_COMMAND_START, sizeof start, &start, nullptr) == CL_SUCCESS &&
        start > submit)
      seconds += static_cast<double>(start - submit) * 1e-9;
    clReleaseEvent(e);
  }
  m_first_launches.clear();
  return seconds;
}

double Context::takeBuildSeconds() {
  std::lock_guard<std::mutex> lock(m_mutex);
  return std::exchange(m_build_seconds, 0.0);
}

cl_kernel Context::kernel(const std::string& entry_file, const std::string& name, const std::string& options) {
  std::lock_guard<std::mutex> lock(m_mutex);
  auto key = entry_file + '\n' + options;
  auto it = m_programs.find(key);
  Program& p = it != m_programs.end() ? it->second : program(key, assembleKernelSource(entry_file), options);
  auto kit = p.kernels.find(name);
  if (kit != p.kernels.end()) return kit->second;
  cl_int status = CL_SUCCESS;
  cl_kernel k = clCreateKernel(p.program, name.c_str(), &status);
  if (status != CL_SUCCESS) throw DeviceError("kernel '" + name + "' not found in " + entry_file);
  p.kernels[name] = k;
  return k;
}

cl_kernel Context::kernelFromText(const std::string& text, const std::string& program_name,
                                  const std::string& kernel_name, const std::string& options) {
  std::lock_guard<std::mutex> lock(m_mutex);
  auto key = "text:" + program_name + '\n' + options;
  auto it = m_programs.find(key);
  Program& p = it != m_programs.end() ? it->second : program(key, assembleKernelText(text, program_name), options);
  auto kit = p.kernels.find(kernel_name);
  if (kit != p.kernels.end()) return kit->second;
  cl_int status = CL_SUCCESS;
  cl_kernel k = clCreateKernel(p.program, kernel_name.c_str(), &status);
  if (status != CL_SUCCESS) throw DeviceError("kernel '" + kernel_name + "' not found in " + program_name);
  p.kernels[kernel_name] = k;
  return k;
}

Context::Program& Context::program(const std::string& key, const std::string& source, const std::string& options) {
  auto start = std::chrono::steady_clock::now();
  Program p;
  p.program = buildProgram(source, options, key.substr(0, key.find('\n')));
  m_build_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return m_programs.emplace(key, std::move(p)).first->second;
}

cl_program Context::buildProgram(const std::string& source, const std::string& extra_options, const std::string& name) {
  std::string options = kStandardOptions;
  if (m_device.correctly_rounded_divide_sqrt) options += std::string(" ") + kCorrectlyRoundedOption;
  if (!extra_options.empty()) options += " " + extra_options;
  const std::string cache_key = m_disk_cache.keyFor(m_device, options, source);
  cl_int status = CL_SUCCESS;

  if (m_use_disk_cache) {
    if (auto binary = m_disk_cache.load(cache_key)) {
      const unsigned char* ptr = binary->data();
      size_t size = binary->size();
      cl_int binary_status = CL_SUCCESS;
      cl_program program =
          clCreateProgramWithBinary(m_context, 1, &m_device.device, &size, &ptr, &binary_status, &status);
      if (status == CL_SUCCESS && binary_status == CL_SUCCESS &&
          clBuildProgram(program, 1, &m_device.device, options.c_str(), nullptr, nullptr) == CL_SUCCESS)
        return program;
      if (program) clReleaseProgram(program);  // any failure is a cache miss
    }
  }

  const char* text = source.c_str();
  size_t length = source.size();
  cl_program program = clCreateProgramWithSource(m_context, 1, &text, &length, &status);
  if (status != CL_SUCCESS) throwClError(status, "clCreateProgramWithSource", __FILE__, __LINE__);
  status = clBuildProgram(program, 1, &m_device.device, options.c_str(), nullptr, nullptr);
  if (status != CL_SUCCESS) {
    std::string log = buildLog(program, m_device.device);
    clReleaseProgram(program);
    throw KernelBuildError("kernel program " + name + " failed to build on '" + m_device.name + "' (" +
                           clErrorName(status) + ") with options '" + options + "':\n" + log);
  }
  if (m_use_disk_cache) m_disk_cache.store(cache_key, programBinary(program));
  return program;
}

}  // namespace prism
