// The first-hit (Z-buffer) pass for a pinhole camera: per sample position, the
// depth and id of the nearest primitive, found without tracing through an
// acceleration structure. The host bins primitives into screen tiles by their
// projected bounds (counting sort, O(primitives + entries)); kernels/firsthit.cl
// then tests each sample against its tile's candidates with the tracer's exact
// intersection routine. Cameras with depth of field or motion blur need traced
// primary rays instead (docs/sampling.md).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "device/context.h"
#include "kernels/shared/hit_gpu.h"
#include "render/gpu_scene.h"

namespace prism {

// Primitives binned into square screen tiles of the scene's film
// (scene.camera.width x height).
struct TileBins {
  int tile_size = 0;  // pixels per tile side
  int tiles_x = 0, tiles_y = 0;
  std::vector<std::int32_t> tile_start;    // tiles_x * tiles_y + 1 offsets into tile_prims, row by row
  std::vector<std::int32_t> tile_prims;    // each tile's candidates, ascending primitive index
  // Per entry of tile_prims, 4 floats: the candidate's padded screen bounds
  // x0, y0, x1, y1 (film coordinates; infinite where its image is unbounded). The
  // kernel skips a candidate whose bounds miss the sample before any ray test.
  std::vector<float> tile_bounds;
  // Per entry: a lower bound on the candidate's view depth (distance along the
  // camera's forward axis; 0 where it reaches the camera plane). The kernel skips a
  // candidate that cannot come nearer than the hit it already has.
  std::vector<float> tile_depths;
  std::vector<std::int32_t> global_prims;  // candidates of every tile: planes, primitives crossing the camera plane
  std::size_t culled = 0;                  // behind the camera or off the film: in no list

  std::size_t tileCount() const { return static_cast<std::size_t>(tiles_x) * tiles_y; }
};

// Tile side chosen from the number of primitives to bin: about 8 candidates a
// tile on average, a power of two in 2..32 pixels.
int autoTileSize(std::size_t primitives, int width, int height);

// Bins each primitive by the screen bounds of a convex hull of it: a triangle's
// three vertices; a sphere's or box's object-space bounding box mapped by its
// transform (eight corners). Where the hull crosses the camera plane its image is
// unbounded, and the bounds open towards where the crossing points lie; a hull
// entirely behind the camera, or whose bounds miss the film, is culled. Planes go
// to the global list. tile_size 0: autoTileSize.
TileBins binPrimitives(const GpuScene& scene, int tile_size = 0);

// The pass on one device: upload the bins once (prepare), then run it on
// batches of sample positions already on the device.
class FirstHitPass {
 public:
  explicit FirstHitPass(Context& context);
  void prepare(const GpuScene& scene, int tile_size = 0);
  const TileBins& bins() const { return m_bins; }
  // hits[k] for the `count` positions xy[2k], xy[2k+1] (film coordinates in
  // [0, W] x [0, H]); `objects` holds the scene's ObjectGpu array.
  void run(const Buffer& objects, const Buffer& xy, int count, Buffer& hits);

 private:
  Context& m_context;
  cl_kernel m_kernel;
  TileBins m_bins;
  Buffer m_camera, m_tile_start, m_tile_prims, m_tile_bounds, m_tile_depths, m_global_prims;
};

// Convenience for tests and tools: bins, uploads and runs in one call.
std::vector<HitGpu> firstHits(Context& context, const GpuScene& scene, const std::vector<float>& sample_xy,
                              int tile_size = 0);

}  // namespace prism
