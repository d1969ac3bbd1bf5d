// The first-hit (Z-buffer) pass for a pinhole camera: per sample position, the
// depth and id of the nearest primitive, found by scan conversion on the device
// instead of tracing through an acceleration structure (kernels/firsthit.cl).
// Per batch of positions: the samples are sorted by film pixel (unless they
// come in pixel order), every primitive is projected to conservative film
// bounds, and each (primitive, 8x8-pixel block) pair tests the samples of its
// pixels with the tracer's own ray test, keeping the nearest (t, primitive) per
// sample by an atomic minimum; a resolve then gives the hits, a chunk at a
// time. Cameras with depth of field or motion blur need traced primary rays
// instead (docs/sampling.md).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "accel/accel_buffers.h"
#include "device/context.h"
#include "kernels/shared/hit_gpu.h"
#include "render/device_scan.h"
#include "render/gpu_scene.h"

namespace prism {

// How the depth + id entries are kept: one 64-bit atomic minimum per hit (Wide,
// needs cl_khr_int64_extended_atomics) or two raster passes of 32-bit ones
// (Narrow, any OpenCL 1.2 device). Auto: Wide where the device has it. Both
// give the same hits.
enum class ZBufferAtomics { Auto, Wide, Narrow };

struct FirstHitStats {
  std::size_t samples = 0;      // positions in the last batch
  std::size_t pairs = 0;        // (primitive, block) pairs it rasterised
  std::size_t others = 0;       // primitives tested through object_intersect (not plain triangles)
  bool wide_atomics = false;
};

class FirstHitPass {
 public:
  explicit FirstHitPass(Context& context, ZBufferAtomics atomics = ZBufferAtomics::Auto);

  // The scene's camera and what the kernels need besides its geometry:
  // the primitives that are not plain triangles, with their world bounds.
  // primitive_options: primitiveKernelOptions of the scene (the structure's
  // build has them: DeviceAccel::primitive_options). The device buffers are
  // kept from one call to the next, as large as the largest scene and film
  // asked: on a CPU device a fresh buffer is fresh memory, and its first
  // touch made a frame's prepare take 15 to 49 ms at times instead of 1 to 2
  // (docs/sampling.md, "prepare keeps its buffers").
  void prepare(const GpuScene& scene, const std::string& primitive_options);
  // The depth + id entries of the `count` positions k in [first, first + count)
  // (film coordinates in [0, W] x [0, H]) of the scene whose geometry is
  // uploaded in `geometry`; `xy` holds the positions from number xy_first on
  // (position k at xy[2 (k - xy_first)]). Replaces the last batch. pixel_spp > 0 says the
  // positions are in pixel order, pixel_spp to a pixel (position k in pixel
  // k / pixel_spp, row by row), which spares sorting them; 0: any order.
  void rasterize(const GeometryBuffers& geometry, const Buffer& xy, std::size_t xy_first, std::size_t first,
                 std::size_t count, int pixel_spp = 0);
  // hits[k] for positions first + k, k < count, of the last batch.
  void resolve(const GeometryBuffers& geometry, std::size_t first, std::size_t count, Buffer& hits);
  // rasterize, then resolve the whole batch.
  void run(const GeometryBuffers& geometry, const Buffer& xy, std::size_t count, Buffer& hits, int pixel_spp = 0);

  const FirstHitStats& stats() const { return m_stats; }
  // Device memory it holds now, and the part of it that grows with a batch's
  // samples (directions, slots, entries).
  std::size_t deviceBytes() const;
  std::size_t batchBytes() const;

 private:
  Context& m_context;
  ZBufferAtomics m_atomics;
  DeviceScan m_scan;
  cl_kernel m_count_cells = nullptr, m_sort_samples = nullptr, m_pixel_dirs = nullptr, m_bound = nullptr,
            m_emit = nullptr, m_row_far_kernel = nullptr, m_raster = nullptr, m_resolve = nullptr;
  bool m_wide = false;
  int m_width = 0, m_height = 0;
  std::size_t m_prims = 0, m_others = 0, m_batch = 0;
  int m_pixel_spp = 0;  // the last batch's pixel_spp
  FirstHitStats m_stats;
  // The film's width in 8x8 blocks, the last column padded, and the cells of
  // all its blocks.
  std::size_t blocksX() const;
  std::size_t cellCount() const;
  // Sorted batches count their samples into m_cell_count, which must start at
  // zero. firsthit_sort_samples leaves it zero again, so it is filled only
  // when a film has more cells than were last zeroed, the buffer is new, or
  // a batch was cut short: its fill was most of a pixel-order frame's
  // prepare, which never reads it (docs/sampling.md).
  void ensureCellCountsZero(std::size_t cells);
  std::size_t m_zero_cells = 0;  // the leading cells of m_cell_count known to be zero

  Buffer m_camera, m_other_prims, m_other_boxes, m_cell_count, m_cell_start, m_dirs, m_slot_of, m_entries,
      m_cells, m_block_count, m_pair_start, m_pairs, m_least_t, m_row_far;
};

// `--first-hit auto`'s choice: whether the Z-buffer should beat tracing the
// primary rays of `samples` positions through a BVH, by a cost model calibrated
// with `prism-bench firsthit` on PoCL (docs/sampling.md has the figures): the
// pass costs about a per-sample part plus a per-primitive part, tracing about a
// per-sample part, so it pays while primitives <= kZBufferPrimsPerSample x
// samples; an unbounded primitive (a plane) is tested at every sample, which
// counts as kUnboundedAsPrims x samples primitives.
constexpr double kZBufferPrimsPerSample = 0.2;
constexpr double kUnboundedAsPrims = 0.35;
bool zbufferPays(const GpuScene& scene, std::uint64_t samples);

// Convenience for tests and tools: prepares, uploads and runs in one call.
std::vector<HitGpu> firstHits(Context& context, const GpuScene& scene, const std::vector<float>& sample_xy,
                              ZBufferAtomics atomics = ZBufferAtomics::Auto, int pixel_spp = 0);

}  // namespace prism
