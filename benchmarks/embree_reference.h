// The reference column of prism-bench: the same triangles and rays through
// Intel Embree 3 (rtcIntersect1 / rtcOccluded1), traced by as many threads as
// the OpenCL device has compute units; and, for rays that travel alike, its
// packets (rtcIntersect8 / rtcOccluded8). Embree is used here and nowhere else.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "kernels/shared/hit_gpu.h"
#include "render/ray_queries.h"

namespace prism::bench {

class EmbreeReference {
 public:
  // positions: xyz per vertex; indices: 3 per triangle (primid = triangle index).
  EmbreeReference(const std::vector<float>& positions, const std::vector<std::uint32_t>& indices, int threads);
  ~EmbreeReference();
  EmbreeReference(const EmbreeReference&) = delete;
  EmbreeReference& operator=(const EmbreeReference&) = delete;

  double buildSeconds() const { return m_build_seconds; }
  // Bytes the Embree device held after the build (its memory monitor): the
  // vertex and index buffers, the BVH and its triangle leaves.
  std::size_t bytes() const { return m_bytes; }
  std::vector<HitGpu> intersect(const std::vector<QueryRay>& rays, double* seconds) const;
  std::vector<std::uint8_t> occluded(const std::vector<QueryRay>& rays, double* seconds) const;
  // The same answers, eight neighbouring rays a packet (rays k..k+7, k = 0, 8, 16, ...),
  // the context flagged coherent: Embree's way with camera and shadow rays.
  std::vector<HitGpu> intersect8(const std::vector<QueryRay>& rays, double* seconds) const;
  std::vector<std::uint8_t> occluded8(const std::vector<QueryRay>& rays, double* seconds) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> m_impl;
  double m_build_seconds = 0;
  std::size_t m_bytes = 0;
};

}  // namespace prism::bench
