#include "embree_reference.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>
#include <thread>

namespace prism::bench {
namespace {

using Clock = std::chrono::steady_clock;

constexpr std::size_t kChunk = 4096;  // rays a thread takes at a time
constexpr std::size_t kPacket = 8;    // rays of rtcIntersect8
static_assert(kChunk % kPacket == 0, "a chunk is a whole number of packets, so that packets are k..k+7");

// Runs body(first, last) over [0, n) in chunks on `threads` threads.
template <typename F>
void parallelChunks(std::size_t n, int threads, F body) {
  std::atomic<std::size_t> next{0};
  auto worker = [&] {
    for (;;) {
      std::size_t first = next.fetch_add(kChunk);
      if (first >= n) return;
      body(first, std::min(n, first + kChunk));
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(worker);
  worker();
  for (std::thread& t : pool) t.join();
}

RTCRay makeRay(const QueryRay& q) {
  RTCRay r;
  r.org_x = q.ox;
  r.org_y = q.oy;
  r.org_z = q.oz;
  r.tnear = q.tmin;
  r.dir_x = q.dx;
  r.dir_y = q.dy;
  r.dir_z = q.dz;
  r.time = 0;
  r.tfar = q.tmax;
  r.mask = 0xFFFFFFFFu;
  r.id = 0;
  r.flags = 0;
  return r;
}

// Runs body(context, first, last) over chunks of [0, n) on `threads` threads,
// each with its own intersect context flagged `flags`; returns the seconds.
template <typename F>
double timedChunks(std::size_t n, int threads, RTCIntersectContextFlags flags, F body) {
  auto start = Clock::now();
  parallelChunks(n, threads, [&](std::size_t first, std::size_t last) {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    context.flags = flags;
    body(&context, first, last);
  });
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// Rays [first, last) of at most kPacket into a packet; lanes past `last` are
// left out by `valid`.
void makeRay8(const std::vector<QueryRay>& rays, std::size_t first, std::size_t last, RTCRay8& r, int* valid) {
  for (std::size_t l = 0; l < kPacket; ++l) {
    const std::size_t k = first + l;
    valid[l] = k < last ? -1 : 0;
    const QueryRay& q = rays[k < last ? k : first];
    r.org_x[l] = q.ox;
    r.org_y[l] = q.oy;
    r.org_z[l] = q.oz;
    r.tnear[l] = q.tmin;
    r.dir_x[l] = q.dx;
    r.dir_y[l] = q.dy;
    r.dir_z[l] = q.dz;
    r.time[l] = 0;
    r.tfar[l] = q.tmax;
    r.mask[l] = 0xFFFFFFFFu;
    r.id[l] = 0;
    r.flags[l] = 0;
  }
}

HitGpu toHit(float tfar, unsigned geom, unsigned prim, float u, float v) {
  if (geom == RTC_INVALID_GEOMETRY_ID) return HitGpu{INFINITY, -1, 0, 0};
  return HitGpu{tfar, static_cast<int>(prim), u, v};
}

}  // namespace

struct EmbreeReference::Impl {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  int threads = 1;
  std::atomic<long long> bytes{0};  // what the device holds now, by its memory monitor
};

namespace {

// Embree reports each allocation (bytes > 0) and release (bytes < 0).
bool countBytes(void* user, ssize_t bytes, bool /*post*/) {
  static_cast<std::atomic<long long>*>(user)->fetch_add(bytes);
  return true;
}

}  // namespace

EmbreeReference::EmbreeReference(const std::vector<float>& positions, const std::vector<std::uint32_t>& indices,
                                 int threads)
    : m_impl(std::make_unique<Impl>()) {
  m_impl->threads = std::max(1, threads);
  std::string config = "threads=" + std::to_string(m_impl->threads);
  m_impl->device = rtcNewDevice(config.c_str());
  if (!m_impl->device) throw std::runtime_error("Embree: rtcNewDevice failed");
  rtcSetDeviceMemoryMonitorFunction(m_impl->device, countBytes, &m_impl->bytes);
  m_impl->scene = rtcNewScene(m_impl->device);
  RTCGeometry geom = rtcNewGeometry(m_impl->device, RTC_GEOMETRY_TYPE_TRIANGLE);
  const std::size_t vertex_count = positions.size() / 3, triangle_count = indices.size() / 3;
  auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                        3 * sizeof(float), vertex_count));
  auto* i = static_cast<unsigned*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                           3 * sizeof(unsigned), triangle_count));
  if (vertex_count) std::memcpy(v, positions.data(), positions.size() * sizeof(float));
  if (triangle_count) std::memcpy(i, indices.data(), indices.size() * sizeof(unsigned));
  rtcCommitGeometry(geom);
  rtcAttachGeometry(m_impl->scene, geom);
  rtcReleaseGeometry(geom);
  auto start = Clock::now();
  rtcCommitScene(m_impl->scene);
  m_build_seconds = std::chrono::duration<double>(Clock::now() - start).count();
  m_bytes = static_cast<std::size_t>(std::max(0LL, m_impl->bytes.load()));
}

EmbreeReference::~EmbreeReference() {
  if (m_impl->scene) rtcReleaseScene(m_impl->scene);
  if (m_impl->device) rtcReleaseDevice(m_impl->device);
}

std::vector<HitGpu> EmbreeReference::intersect(const std::vector<QueryRay>& rays, double* seconds) const {
  std::vector<HitGpu> hits(rays.size());
  RTCScene scene = m_impl->scene;
  const double s = timedChunks(rays.size(), m_impl->threads, RTC_INTERSECT_CONTEXT_FLAG_INCOHERENT,
                               [&](RTCIntersectContext* context, std::size_t first, std::size_t last) {
    for (std::size_t k = first; k < last; ++k) {
      RTCRayHit rh;
      rh.ray = makeRay(rays[k]);
      rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
      rh.hit.primID = RTC_INVALID_GEOMETRY_ID;
      rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
      rtcIntersect1(scene, context, &rh);
      hits[k] = toHit(rh.ray.tfar, rh.hit.geomID, rh.hit.primID, rh.hit.u, rh.hit.v);
    }
  });
  if (seconds) *seconds = s;
  return hits;
}

std::vector<std::uint8_t> EmbreeReference::occluded(const std::vector<QueryRay>& rays, double* seconds) const {
  std::vector<std::uint8_t> out(rays.size());
  RTCScene scene = m_impl->scene;
  const double s = timedChunks(rays.size(), m_impl->threads, RTC_INTERSECT_CONTEXT_FLAG_INCOHERENT,
                               [&](RTCIntersectContext* context, std::size_t first, std::size_t last) {
    for (std::size_t k = first; k < last; ++k) {
      RTCRay r = makeRay(rays[k]);
      rtcOccluded1(scene, context, &r);
      out[k] = r.tfar == -INFINITY ? 1 : 0;
    }
  });
  if (seconds) *seconds = s;
  return out;
}

std::vector<HitGpu> EmbreeReference::intersect8(const std::vector<QueryRay>& rays, double* seconds) const {
  std::vector<HitGpu> hits(rays.size());
  RTCScene scene = m_impl->scene;
  const double s = timedChunks(rays.size(), m_impl->threads, RTC_INTERSECT_CONTEXT_FLAG_COHERENT,
                               [&](RTCIntersectContext* context, std::size_t first, std::size_t last) {
    for (std::size_t k = first; k < last; k += kPacket) {
      const std::size_t end = std::min(last, k + kPacket);
      RTCRayHit8 rh;
      alignas(32) int valid[kPacket];  // Embree loads the mask as one 32-byte vector
      makeRay8(rays, k, end, rh.ray, valid);
      for (std::size_t l = 0; l < kPacket; ++l) {
        rh.hit.geomID[l] = RTC_INVALID_GEOMETRY_ID;
        rh.hit.primID[l] = RTC_INVALID_GEOMETRY_ID;
        rh.hit.instID[0][l] = RTC_INVALID_GEOMETRY_ID;
      }
      rtcIntersect8(valid, scene, context, &rh);
      for (std::size_t l = 0; k + l < end; ++l)
        hits[k + l] = toHit(rh.ray.tfar[l], rh.hit.geomID[l], rh.hit.primID[l], rh.hit.u[l], rh.hit.v[l]);
    }
  });
  if (seconds) *seconds = s;
  return hits;
}

std::vector<std::uint8_t> EmbreeReference::occluded8(const std::vector<QueryRay>& rays, double* seconds) const {
  std::vector<std::uint8_t> out(rays.size());
  RTCScene scene = m_impl->scene;
  const double s = timedChunks(rays.size(), m_impl->threads, RTC_INTERSECT_CONTEXT_FLAG_COHERENT,
                               [&](RTCIntersectContext* context, std::size_t first, std::size_t last) {
    for (std::size_t k = first; k < last; k += kPacket) {
      const std::size_t end = std::min(last, k + kPacket);
      RTCRay8 r;
      alignas(32) int valid[kPacket];
      makeRay8(rays, k, end, r, valid);
      rtcOccluded8(valid, scene, context, &r);
      for (std::size_t l = 0; k + l < end; ++l) out[k + l] = r.tfar[l] == -INFINITY ? 1 : 0;
    }
  });
  if (seconds) *seconds = s;
  return out;
}

}  // namespace prism::bench
