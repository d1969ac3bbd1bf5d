#include "device/checked_transfers.h"

#include <algorithm>
#include <cstdlib>
#include <map>
#include <mutex>
#include <string>

#include "device/cl_error.h"

namespace prism {
namespace {

// Byte by byte: the transfers of the small scenes the check runs are small, and
// a byte kernel needs no alignment. A few work-items, each a strided run.
const char* const kCopySource = R"(
__kernel void checked_copy(__global const uchar* from, ulong from_offset, __global uchar* to, ulong to_offset,
                           ulong bytes) {
  for (ulong i = get_global_id(0); i < bytes; i += get_global_size(0)) to[to_offset + i] = from[from_offset + i];
}
)";
constexpr size_t kCopyItems = 64;

struct CopyKernel {
  cl_program program = nullptr;
  cl_kernel kernel = nullptr;
};

std::mutex g_mutex;                         // the kernels below, and launching them
std::map<cl_context, CopyKernel> g_kernels;  // one per context, kept for the process

cl_kernel copyKernel(cl_command_queue queue) {
  cl_context context = nullptr;
  cl_device_id device = nullptr;
  PRISM_CL_CHECK(clGetCommandQueueInfo(queue, CL_QUEUE_CONTEXT, sizeof context, &context, nullptr));
  PRISM_CL_CHECK(clGetCommandQueueInfo(queue, CL_QUEUE_DEVICE, sizeof device, &device, nullptr));
  CopyKernel& k = g_kernels[context];
  if (k.kernel) return k.kernel;
  cl_int status = CL_SUCCESS;
  const char* source = kCopySource;
  k.program = clCreateProgramWithSource(context, 1, &source, nullptr, &status);
  if (status != CL_SUCCESS) throwClError(status, "clCreateProgramWithSource", __FILE__, __LINE__);
  PRISM_CL_CHECK(clBuildProgram(k.program, 1, &device, "-cl-std=CL1.2", nullptr, nullptr));
  k.kernel = clCreateKernel(k.program, "checked_copy", &status);
  if (status != CL_SUCCESS) throwClError(status, "clCreateKernel", __FILE__, __LINE__);
  return k.kernel;
}

}  // namespace

bool checkedTransfers() {
  static const bool on = [] {
    const char* v = std::getenv("PRISM_HOST_TRANSFERS");
    return v && std::string(v) == "1";
  }();
  return on;
}

void checkedCopy(cl_command_queue queue, cl_mem from, size_t from_offset, cl_mem to, size_t to_offset, size_t bytes) {
  if (bytes == 0) return;
  const std::lock_guard<std::mutex> lock(g_mutex);
  cl_kernel kernel = copyKernel(queue);
  const cl_ulong args[3] = {from_offset, to_offset, bytes};
  PRISM_CL_CHECK(clSetKernelArg(kernel, 0, sizeof from, &from));
  PRISM_CL_CHECK(clSetKernelArg(kernel, 1, sizeof args[0], &args[0]));
  PRISM_CL_CHECK(clSetKernelArg(kernel, 2, sizeof to, &to));
  PRISM_CL_CHECK(clSetKernelArg(kernel, 3, sizeof args[1], &args[1]));
  PRISM_CL_CHECK(clSetKernelArg(kernel, 4, sizeof args[2], &args[2]));
  const size_t items = std::min(bytes, kCopyItems);
  PRISM_CL_CHECK(clEnqueueNDRangeKernel(queue, kernel, 1, nullptr, &items, nullptr, 0, nullptr, nullptr));
  PRISM_CL_CHECK(clFinish(queue));
}

void checkedWrite(cl_command_queue queue, cl_mem to, size_t offset, const void* data, size_t bytes) {
  if (bytes == 0) return;
  cl_context context = nullptr;
  PRISM_CL_CHECK(clGetCommandQueueInfo(queue, CL_QUEUE_CONTEXT, sizeof context, &context, nullptr));
  cl_int status = CL_SUCCESS;
  // Written whole, so its shadow memory is exactly these bytes, all written.
  cl_mem staging = clCreateBuffer(context, CL_MEM_READ_WRITE, bytes, nullptr, &status);
  if (status != CL_SUCCESS) throwClError(status, "clCreateBuffer", __FILE__, __LINE__);
  struct Release {
    cl_mem m;
    ~Release() { releaseBuffer(m); }
  } release{staging};
  PRISM_CL_CHECK(clEnqueueWriteBuffer(queue, staging, CL_TRUE, 0, bytes, data, 0, nullptr, nullptr));
  checkedCopy(queue, staging, 0, to, offset, bytes);
}

void releaseBuffer(cl_mem buffer) {
  if (!checkedTransfers()) clReleaseMemObject(buffer);
}

}  // namespace prism
