#include "render/firsthit.h"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>

#include "accel/accel_structure.h"
#include "accel/prim_ref.h"

namespace prism {
namespace {

// Samples a work-item of firsthit_pixel_dirs (FIRSTHIT_DIR_LANES, the float8
// lanes of camera_ray_dir8).
constexpr size_t kFirstHitDirLanes = 8;
// Primitives a work-item of firsthit_bound takes (FIRSTHIT_BOUND_LANES); the
// other primitives' boxes one a work-item after them.
constexpr size_t kFirstHitBoundLanes = 8;
// Pixels a side of a raster block (FIRSTHIT_BLOCK).
constexpr size_t kBlock = 8;

template <typename T>
void upload(Context& context, Buffer& b, const std::vector<T>& v) {
  b.reserve(context, std::max<size_t>(1, v.size()) * sizeof(T));  // a buffer may not be empty
  b.writeVector(v);
}

}  // namespace

FirstHitPass::FirstHitPass(Context& context, ZBufferAtomics atomics)
    : m_context(context), m_atomics(atomics), m_scan(context) {}

void FirstHitPass::prepare(const GpuScene& scene, const std::string& primitive_options) {
  const CameraGpu& c = scene.camera;
  if (c.width < 1 || c.height < 1) throw std::invalid_argument("first hit zbuffer: the camera has an empty film");
  const DeviceDescription& device = m_context.device();
  const bool has_wide = device.hasExtension("cl_khr_int64_base_atomics") &&
                        device.hasExtension("cl_khr_int64_extended_atomics");
  if (m_atomics == ZBufferAtomics::Wide && !has_wide)
    throw std::invalid_argument("first hit zbuffer: 64-bit atomics requested, but " + device.name +
                                " lacks cl_khr_int64_extended_atomics");
  m_wide = m_atomics == ZBufferAtomics::Wide || (m_atomics == ZBufferAtomics::Auto && has_wide);
  std::string options = m_wide ? "-DPRISM_ZBUFFER_WIDE" : "";
  options += " " + primitive_options;
  m_count_cells = m_context.kernel("firsthit.cl", "firsthit_count_cells", options);
  m_sort_samples = m_context.kernel("firsthit.cl", "firsthit_sort_samples", options);
  m_pixel_dirs = m_context.kernel("firsthit.cl", "firsthit_pixel_dirs", options);
  m_bound = m_context.kernel("firsthit.cl", "firsthit_bound", options);
  m_emit = m_context.kernel("firsthit.cl", "firsthit_emit", options);
  m_row_far_kernel = m_context.kernel("firsthit.cl", "firsthit_row_far", options);
  m_raster = m_context.kernel("firsthit.cl", "firsthit_raster", options);
  m_resolve = m_context.kernel("firsthit.cl", "firsthit_resolve", options);

  m_camera.reserve(m_context, sizeof(CameraGpu));
  m_camera.write(&c, sizeof(CameraGpu));
  m_prims = scene.primitive_count;
  if (m_prims >= static_cast<size_t>(std::numeric_limits<std::int32_t>::max()))
    throw std::invalid_argument("first hit zbuffer: more than 2^31 - 1 primitives");
  // Plain triangles are bounded on the device from their vertices; every other
  // primitive by its world box from the host (unbounded: infinite, the whole film).
  std::vector<std::int32_t> other_prims;
  std::vector<float> other_boxes;
  constexpr float kInf = std::numeric_limits<float>::infinity();
  for (size_t k : notPlainTriangles(scene)) {
    const ObjectGpu& ob = scene.objects[k];
    other_prims.push_back(static_cast<std::int32_t>(k));
    Aabb b;
    if (objectBounds(ob, &b))
      other_boxes.insert(other_boxes.end(), {b.lo[0], b.lo[1], b.lo[2], b.hi[0], b.hi[1], b.hi[2]});
    else
      other_boxes.insert(other_boxes.end(), {-kInf, -kInf, -kInf, kInf, kInf, kInf});
  }
  m_others = other_prims.size();
  // The pairs' counts: two an item (facing the camera or away), items being
  // the primitives and, once more, those bounded by their host boxes.
  if (2 * (m_prims + m_others) >= static_cast<size_t>(std::numeric_limits<std::int32_t>::max()))
    throw std::invalid_argument(
        "first hit zbuffer: too many primitives (twice the primitives plus twice the non-triangles must stay below "
        "2^31); use --first-hit trace");
  upload(m_context, m_other_prims, other_prims);
  upload(m_context, m_other_boxes, other_boxes);

  m_width = c.width;
  m_height = c.height;
  const size_t cells = cellCount();
  // The counting sort's cells, reserved here so that a frame's memory check
  // counts them; their counts are zeroed by the first batch that sorts. A new
  // buffer's counts are unknown even where a later, smaller film's cells fit
  // in what the old one had zeroed.
  const cl_mem counts_before = m_cell_count.handle();
  m_cell_count.reserve(m_context, cells * sizeof(std::int32_t));
  if (m_cell_count.handle() != counts_before) m_zero_cells = 0;
  m_cell_start.reserve(m_context, (cells + 1) * sizeof(std::int32_t));
  m_slot_of.reserve(m_context, sizeof(std::int32_t));  // bound, unread, until a batch needs sorting
  const size_t items = m_prims + m_others;
  m_cells.reserve(m_context, std::max<size_t>(1, items) * 4 * sizeof(std::int32_t));
  // Front-facing primitives' block counts, then back-facing triangles'.
  m_block_count.reserve(m_context, std::max<size_t>(1, 2 * items) * sizeof(std::int32_t));
  m_pair_start.reserve(m_context, (2 * items + 1) * sizeof(std::int32_t));
  // Plain triangles come first, eight to a work-item of firsthit_bound, which
  // writes all eight lanes.
  m_least_t.reserve(m_context,
                    ((m_prims + kFirstHitBoundLanes - 1) / kFirstHitBoundLanes * kFirstHitBoundLanes + 1) * sizeof(float));
  // Left as it is: each batch's firsthit_row_far writes the block rows of its
  // pixels, the only rows its raster reads.
  m_row_far.reserve(m_context, cells / kBlock * sizeof(std::uint32_t));
  m_batch = 0;
  m_stats = FirstHitStats{};
  m_stats.others = m_others;
  m_stats.wide_atomics = m_wide;
}

void FirstHitPass::rasterize(const GeometryBuffers& geometry, const Buffer& xy, size_t xy_first, size_t first,
                             size_t count, int pixel_spp) {
  if (!m_raster) throw std::logic_error("FirstHitPass::rasterize before prepare");
  m_batch = 0;  // until this batch is rasterised
  if (count == 0) return;
  if (first + count > static_cast<size_t>(std::numeric_limits<std::int32_t>::max()))
    throw std::invalid_argument("first hit zbuffer: more than 2^31 - 1 positions in one batch");
  if (xy_first > first) throw std::logic_error("FirstHitPass::rasterize: positions before the buffer's first");
  const cl_int n = static_cast<cl_int>(count), at = static_cast<cl_int>(first);
  const cl_int in_xy = static_cast<cl_int>(first - xy_first);  // the batch's first position in xy
  const size_t cells = cellCount();

  // The samples' directions and empty entries, in cell order or, where they
  // come in pixel order, in that order (kernels/firsthit.cl).
  // Directions by component (x of every slot, then y, then z), and four
  // floats of padding that the raster's last lanes may read.
  m_dirs.reserve(m_context, (3 * count + 4) * sizeof(float));
  const float zero = 0.0f;
  m_dirs.fill(&zero, sizeof zero, 4 * sizeof(float), 3 * count * sizeof(float));
  m_entries.reserve(m_context, count * 2 * sizeof(std::uint32_t));
  // Known once the batch's sort has run (the blocking reads below wait for it).
  size_t zero_cells_after = m_zero_cells;
  if (pixel_spp > 0) {
    // Eight samples a work-item (kFirstHitDirLanes, as firsthit_pixel_dirs takes them).
    m_context.launch(m_pixel_dirs)
        .arg(m_camera)
        .arg(xy)
        .arg(in_xy)
        .arg(n)
        .arg(m_dirs)
        .arg(m_entries)
        .run((count + kFirstHitDirLanes - 1) / kFirstHitDirLanes);
  } else {
    m_slot_of.reserve(m_context, count * sizeof(std::int32_t));
    ensureCellCountsZero(cells);
    // Each sample takes its slot by counting its cell down, so a sort that
    // has run leaves every count zero; one cut short leaves counts.
    zero_cells_after = m_zero_cells;
    m_zero_cells = 0;
    m_context.launch(m_count_cells).arg(m_camera).arg(xy).arg(in_xy).arg(n).arg(m_cell_count).run(count);
    m_scan.exclusive(m_cell_count, cells, m_cell_start);
    m_context.launch(m_sort_samples)
        .arg(m_camera)
        .arg(xy)
        .arg(in_xy)
        .arg(n)
        .arg(m_cell_start)
        .arg(m_cell_count)
        .arg(m_dirs)
        .arg(m_slot_of)
        .arg(m_entries)
        .run(count);
  }
  m_pixel_spp = pixel_spp;

  // The primitives' film bounds, cut to the rows of the batch's pixels, and
  // their (primitive, block) pairs.
  size_t row_first = 0, row_last = static_cast<size_t>(m_height) - 1;
  if (pixel_spp > 0) {
    const size_t spp = static_cast<size_t>(pixel_spp), width = static_cast<size_t>(m_width);
    row_first = first / spp / width;
    row_last = std::min(row_last, (first + count - 1) / spp / width);
  }
  const size_t items = m_prims + m_others;
  KernelLaunch bound = m_context.launch(m_bound);
  bound.arg(m_camera);
  geometry.bind(bound)
      .arg(m_other_prims)
      .arg(m_other_boxes)
      .arg(static_cast<cl_int>(m_others))
      .arg(static_cast<cl_int>(row_first))
      .arg(static_cast<cl_int>(row_last))
      .arg(m_cells)
      .arg(m_block_count)
      .arg(m_least_t)
      .run((m_prims + kFirstHitBoundLanes - 1) / kFirstHitBoundLanes + m_others);
  m_scan.exclusive(m_block_count, 2 * items, m_pair_start);
  std::int32_t total = 0, front = 0;
  m_pair_start.read(&total, sizeof total, 2 * items * sizeof(std::int32_t));
  m_pair_start.read(&front, sizeof front, items * sizeof(std::int32_t));
  m_zero_cells = zero_cells_after;
  if (total >= kScanSaturated)
    throw std::runtime_error(
        "first hit zbuffer: the primitives' film bounds cover 2^31 or more 8x8-pixel blocks; use --first-hit trace");
  m_stats.samples = count;
  m_stats.pairs = static_cast<size_t>(total);
  m_batch = count;
  if (total == 0) return;
  m_pairs.reserve(m_context, static_cast<size_t>(total) * 2 * sizeof(std::int32_t));
  m_context.launch(m_emit)
      .arg(static_cast<cl_int>(items))
      .arg(m_cells)
      .arg(m_block_count)
      .arg(m_pair_start)
      .arg(m_pairs)
      .run(items);
  // The pairs of triangles facing away from the camera go last, each skipping
  // the rows of its block where the farthest depth kept by the others lies
  // nearer than any t it could return (kernels/firsthit.cl).
  const bool cull = front > 0 && front < total;
  auto raster = [&](int pass, std::int32_t pair_first, std::int32_t pair_end, bool culled) {
    KernelLaunch launch = m_context.launch(m_raster);
    launch.arg(m_camera);
    geometry.bind(launch)
        .arg(m_other_prims)
        .arg(m_cells)
        .arg(static_cast<cl_int>(pair_first))
        .arg(static_cast<cl_int>(pair_end))
        .arg(m_pairs)
        .arg(static_cast<cl_int>(std::max(pixel_spp, 0)))
        .arg(at)
        .arg(n)
        .arg(m_cell_start)
        .arg(m_dirs)
        .arg(static_cast<cl_int>(pass))
        .arg(m_least_t)
        .arg(m_row_far)
        .arg(static_cast<cl_int>(culled))
        .arg(m_entries)
        .run(static_cast<size_t>(pair_end - pair_first));
  };
  for (int pass = 0; pass < (m_wide ? 1 : 2); ++pass) {
    if (!cull) {
      raster(pass, 0, total, false);
      continue;
    }
    raster(pass, 0, front, false);
    if (pass == 0)
      m_context.launch(m_row_far_kernel)
          .arg(static_cast<cl_int>(m_width))
          .arg(static_cast<cl_int>(m_height))
          .arg(static_cast<cl_int>(row_first / kBlock))
          .arg(static_cast<cl_int>(row_last / kBlock))
          .arg(static_cast<cl_int>(std::max(pixel_spp, 0)))
          .arg(at)
          .arg(n)
          .arg(m_cell_start)
          .arg(m_entries)
          .arg(m_row_far)
          .run((row_last / kBlock - row_first / kBlock + 1) * blocksX());
    raster(pass, front, total, true);
  }
}

void FirstHitPass::resolve(const GeometryBuffers& geometry, size_t first, size_t count, Buffer& hits) {
  if (count == 0) return;
  if (first + count > m_batch) throw std::logic_error("FirstHitPass::resolve outside the rasterised batch");
  KernelLaunch resolve = m_context.launch(m_resolve);
  resolve.arg(m_camera);
  geometry.bind(resolve)
      .arg(static_cast<cl_int>(count))
      .arg(static_cast<cl_int>(m_pixel_spp > 0))  // in pixel order, sample k of the batch is in slot k
      .arg(m_slot_of)
      .arg(m_dirs)
      .arg(static_cast<cl_int>(m_batch))
      .arg(m_entries)
      .arg(static_cast<cl_int>(first))
      .arg(hits)
      .run(count);
}

void FirstHitPass::ensureCellCountsZero(size_t cells) {
  if (m_zero_cells >= cells) return;
  const std::int32_t zero = 0;
  m_cell_count.fill(&zero, sizeof zero, cells * sizeof(std::int32_t));
  m_zero_cells = cells;
}

size_t FirstHitPass::blocksX() const { return (static_cast<size_t>(m_width) + kBlock - 1) / kBlock; }

size_t FirstHitPass::cellCount() const {
  return blocksX() * ((static_cast<size_t>(m_height) + kBlock - 1) / kBlock) * kBlock * kBlock;
}

void FirstHitPass::run(const GeometryBuffers& geometry, const Buffer& xy, size_t count, Buffer& hits, int pixel_spp) {
  rasterize(geometry, xy, 0, 0, count, pixel_spp);
  resolve(geometry, 0, count, hits);
}

size_t FirstHitPass::batchBytes() const {
  return m_dirs.bytes() + m_slot_of.bytes() + m_entries.bytes();
}

size_t FirstHitPass::deviceBytes() const {
  size_t bytes = 0;
  for (const Buffer* b : {&m_camera, &m_other_prims, &m_other_boxes, &m_cell_count, &m_cell_start, &m_dirs, &m_slot_of,
                          &m_entries, &m_cells, &m_block_count, &m_pair_start, &m_pairs, &m_least_t, &m_row_far})
    bytes += b->bytes();
  return bytes;
}

bool zbufferPays(const GpuScene& scene, std::uint64_t samples) {
  const std::vector<size_t> others = notPlainTriangles(scene);
  double prims = static_cast<double>(scene.primitive_count - others.size());
  for (size_t k : others) {
    Aabb b;
    prims += objectBounds(scene.objects[k], &b) ? 1.0 : kUnboundedAsPrims * static_cast<double>(samples);
  }
  return prims <= kZBufferPrimsPerSample * static_cast<double>(samples);
}

std::vector<HitGpu> firstHits(Context& context, const GpuScene& scene, const std::vector<float>& sample_xy,
                              ZBufferAtomics atomics, int pixel_spp) {
  const size_t count = sample_xy.size() / 2;
  if (count == 0) return {};
  FirstHitPass pass(context, atomics);
  pass.prepare(scene, primitiveKernelOptions(scene.objects));
  GeometryBuffers geometry(context, scene);
  Buffer xy(context, sample_xy.size() * sizeof(float));
  xy.writeVector(sample_xy);
  Buffer hits(context, count * sizeof(HitGpu));
  pass.run(geometry, xy, count, hits, pixel_spp);
  return hits.readVector<HitGpu>(count);
}

}  // namespace prism
