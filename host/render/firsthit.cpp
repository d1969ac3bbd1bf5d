#include "render/firsthit.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "scene/transform.h"

namespace prism {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// Bounds grow by this much (pixels) on each side: far more than the float error of
// a ray direction or of the intersection tests (about 1e-4 pixel), far less than a tile.
constexpr double kPadPixels = 0.1;

Vec3 vec(const float* p) { return {p[0], p[1], p[2]}; }

// The float camera the kernel uses, in double, for projecting world points to
// film coordinates: X = W/2 (1 + (v.r)/(|r|^2 z)), Y = H/2 (1 - (v.u)/(|u|^2 z)),
// v = P - origin, z = v.forward (forward is unit, r and u orthogonal to it).
struct Projector {
  Vec3 o, f, r, u;
  double rr, uu, w, h;
  explicit Projector(const CameraGpu& c)
      : o(vec(c.origin)), f(vec(c.forward)), r(vec(c.right)), u(vec(c.up)), w(c.width), h(c.height) {
    rr = dot(r, r);
    uu = dot(u, u);
  }
};

struct ScreenBox {
  double x0 = kInf, x1 = -kInf, y0 = kInf, y1 = -kInf;
  double zmin = kInf;  // nearest view depth (along the camera's forward axis) of the hull
  void add(double x, double y) {
    x0 = std::min(x0, x);
    x1 = std::max(x1, x);
    y0 = std::min(y0, y);
    y1 = std::max(y1, y);
  }
};

enum class Placement { Culled, Global, Tiles };

// Screen bounds of the part in front of the camera (z > 0) of the convex hull of
// `pts`, whose edges are `edges`. Its vertices are the points with z > 0 and the
// points where edges cross z = 0; near such a crossing point Q the image runs off
// to infinity in the direction of Q's offset from the camera axis, so the bounds
// open on those sides (a zero offset opens both).
Placement projectHull(const Projector& cam, const Vec3* pts, int n, const int (*edges)[2], int m, ScreenBox& box) {
  double z[8];
  bool front = false;
  for (int i = 0; i < n; ++i) {
    z[i] = dot(pts[i] - cam.o, cam.f);
    front = front || z[i] > 0;
    box.zmin = std::min(box.zmin, z[i]);
  }
  if (!front) return Placement::Culled;
  auto openTowards = [&](const Vec3& q) {
    Vec3 v = q - cam.o;
    double a = dot(v, cam.r), b = dot(v, cam.u);
    double tol = 1e-9 * (length(v) + 1e-300) * std::sqrt(std::max(cam.rr, cam.uu));
    if (a > -tol) box.x1 = kInf;
    if (a < tol) box.x0 = -kInf;
    if (b > -tol) box.y0 = -kInf;  // film y runs down
    if (b < tol) box.y1 = kInf;
  };
  for (int i = 0; i < n; ++i) {
    if (z[i] > 0) {
      Vec3 v = pts[i] - cam.o;
      double sx = dot(v, cam.r) / (cam.rr * z[i]), sy = dot(v, cam.u) / (cam.uu * z[i]);
      box.add(0.5 * cam.w * (1 + sx), 0.5 * cam.h * (1 - sy));
    } else if (z[i] == 0) {
      openTowards(pts[i]);
    }
  }
  for (int e = 0; e < m; ++e) {
    int a = edges[e][0], b = edges[e][1];
    if ((z[a] > 0 && z[b] < 0) || (z[a] < 0 && z[b] > 0)) {
      double s = z[a] / (z[a] - z[b]);
      openTowards(pts[a] + (pts[b] - pts[a]) * s);
    }
  }
  return Placement::Tiles;
}

const int kTriangleEdges[3][2] = {{0, 1}, {1, 2}, {2, 0}};
// Corners of a box numbered by bits (x, y, z); edges join corners one bit apart.
const int kBoxEdges[12][2] = {{0, 1}, {2, 3}, {4, 5}, {6, 7}, {0, 2}, {1, 3},
                              {4, 6}, {5, 7}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};

// Where one primitive goes; for Tiles, the inclusive tile rectangle.
Placement place(const ObjectGpu& ob, const Projector& cam, int tile, int tiles_x, int tiles_y, int rect[4],
                float bounds[5]) {
  if (ob.type != OBJECT_TRIANGLE && ob.type != OBJECT_SPHERE && ob.type != OBJECT_BOX)
    return Placement::Global;  // planes, and any kind this pass does not know
  // The kernels intersect in object space when has_transform is set (smooth
  // triangles keep normals, not a matrix, in world_to_object and never set it).
  const bool transformed = ob.has_transform && !(ob.type == OBJECT_TRIANGLE && (ob.flags & OBJECT_FLAG_VERTEX_NORMALS));
  Transform to_world;
  if (transformed) {
    Transform to_object;
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 4; ++c) to_object.m[r][c] = ob.world_to_object[4 * r + c];
    double det = to_object.determinant();
    if (!(std::fabs(det) > 0) || !std::isfinite(det)) return Placement::Global;
    to_world = to_object.inverse();
  }
  auto world = [&](const Vec3& q) { return transformed ? to_world.applyPoint(q) : q; };
  ScreenBox box;
  Placement p;
  if (ob.type == OBJECT_TRIANGLE) {
    Vec3 v[3] = {world(vec(ob.p)), world(vec(ob.p + 3)), world(vec(ob.p + 6))};
    p = projectHull(cam, v, 3, kTriangleEdges, 3, box);
  } else {
    Vec3 lo, hi;
    if (ob.type == OBJECT_SPHERE) {
      Vec3 c = vec(ob.p);
      double r = std::fabs(static_cast<double>(ob.p[3]));
      lo = c - Vec3::splat(r);
      hi = c + Vec3::splat(r);
    } else {
      lo = vec(ob.p);
      hi = vec(ob.p + 3);
    }
    Vec3 corners[8];
    for (int k = 0; k < 8; ++k)
      corners[k] = world({(k & 1) ? hi.x : lo.x, (k & 2) ? hi.y : lo.y, (k & 4) ? hi.z : lo.z});
    p = projectHull(cam, corners, 8, kBoxEdges, 12, box);
  }
  if (p != Placement::Tiles) return p;
  box.x0 -= kPadPixels;
  box.y0 -= kPadPixels;
  box.x1 += kPadPixels;
  box.y1 += kPadPixels;
  if (!(box.x1 >= 0 && box.x0 <= cam.w && box.y1 >= 0 && box.y0 <= cam.h)) return Placement::Culled;
  // As floats, rounded outwards (the pad dwarfs the rounding; this keeps it so).
  bounds[0] = std::nextafter(static_cast<float>(box.x0), -std::numeric_limits<float>::infinity());
  bounds[1] = std::nextafter(static_cast<float>(box.y0), -std::numeric_limits<float>::infinity());
  bounds[2] = std::nextafter(static_cast<float>(box.x1), std::numeric_limits<float>::infinity());
  bounds[3] = std::nextafter(static_cast<float>(box.y1), std::numeric_limits<float>::infinity());
  // The hull's nearest view depth, rounded down and 1e-4 nearer still: no point of
  // the primitive, so no hit, is nearer than that along any ray.
  bounds[4] = box.zmin > 0 ? std::nextafter(static_cast<float>(box.zmin * (1 - 1e-4)), 0.0f) : 0.0f;
  auto tileOf = [tile](double v, int count) {
    double t = std::floor(v / tile);
    return static_cast<int>(std::clamp(t, 0.0, static_cast<double>(count - 1)));
  };
  rect[0] = tileOf(box.x0, tiles_x);
  rect[1] = tileOf(box.y0, tiles_y);
  rect[2] = tileOf(box.x1, tiles_x);
  rect[3] = tileOf(box.y1, tiles_y);
  if (rect[0] == 0 && rect[1] == 0 && rect[2] == tiles_x - 1 && rect[3] == tiles_y - 1 && tiles_x * tiles_y > 1)
    return Placement::Global;  // covers the film: one global entry instead of one per tile
  return Placement::Tiles;
}

template <typename T>
Buffer upload(Context& context, const std::vector<T>& v) {
  Buffer b(context, std::max<size_t>(1, v.size()) * sizeof(T));  // a buffer may not be empty
  b.writeVector(v);
  return b;
}

}  // namespace

int autoTileSize(std::size_t primitives, int width, int height) {
  constexpr double kTargetPerTile = 8;
  double ideal = std::sqrt(kTargetPerTile * width * height / std::max<double>(1, static_cast<double>(primitives)));
  int tile = 2;
  while (tile < 32 && 2 * tile <= ideal) tile *= 2;
  return tile;
}

TileBins binPrimitives(const GpuScene& scene, int tile_size) {
  const CameraGpu& c = scene.camera;
  if (c.width < 1 || c.height < 1) throw std::invalid_argument("binPrimitives: the camera has an empty film");
  if (tile_size < 0) throw std::invalid_argument("binPrimitives: negative tile size");
  TileBins bins;
  bins.tile_size = tile_size > 0 ? tile_size : autoTileSize(scene.objects.size(), c.width, c.height);
  bins.tiles_x = (c.width + bins.tile_size - 1) / bins.tile_size;
  bins.tiles_y = (c.height + bins.tile_size - 1) / bins.tile_size;
  const Projector cam(c);
  const size_t n = scene.objects.size();

  // Pass 1: each primitive's tile rectangle, and the count of entries per tile.
  std::vector<std::int32_t> rects(4 * n);
  std::vector<float> bounds(5 * n);
  std::vector<std::uint8_t> where(n);
  std::vector<std::int64_t> counts(bins.tileCount() + 1, 0);
  for (size_t k = 0; k < n; ++k) {
    Placement p =
        place(scene.objects[k], cam, bins.tile_size, bins.tiles_x, bins.tiles_y, &rects[4 * k], &bounds[5 * k]);
    where[k] = static_cast<std::uint8_t>(p);
    if (p == Placement::Culled) {
      ++bins.culled;
    } else if (p == Placement::Global) {
      bins.global_prims.push_back(static_cast<std::int32_t>(k));
    } else {
      const std::int32_t* r = &rects[4 * k];
      for (int ty = r[1]; ty <= r[3]; ++ty)
        for (int tx = r[0]; tx <= r[2]; ++tx) ++counts[static_cast<size_t>(ty) * bins.tiles_x + tx];
    }
  }
  // Prefix sums give each tile's start; pass 2 fills in primitive order, so every
  // tile's list is ascending.
  std::int64_t total = 0;
  bins.tile_start.resize(bins.tileCount() + 1);
  for (size_t t = 0; t <= bins.tileCount(); ++t) {
    std::int64_t c_t = counts[t];
    if (total > std::numeric_limits<std::int32_t>::max())
      throw std::runtime_error("binPrimitives: more than 2^31 tile entries; use larger tiles");
    bins.tile_start[t] = static_cast<std::int32_t>(total);
    counts[t] = total;  // becomes the fill cursor
    total += c_t;
  }
  bins.tile_prims.resize(static_cast<size_t>(total));
  bins.tile_bounds.resize(4 * static_cast<size_t>(total));
  bins.tile_depths.resize(static_cast<size_t>(total));
  for (size_t k = 0; k < n; ++k) {
    if (where[k] != static_cast<std::uint8_t>(Placement::Tiles)) continue;
    const std::int32_t* r = &rects[4 * k];
    for (int ty = r[1]; ty <= r[3]; ++ty)
      for (int tx = r[0]; tx <= r[2]; ++tx) {
        const size_t at = static_cast<size_t>(counts[static_cast<size_t>(ty) * bins.tiles_x + tx]++);
        bins.tile_prims[at] = static_cast<std::int32_t>(k);
        std::copy(&bounds[5 * k], &bounds[5 * k] + 4, &bins.tile_bounds[4 * at]);
        bins.tile_depths[at] = bounds[5 * k + 4];
      }
  }
  return bins;
}

FirstHitPass::FirstHitPass(Context& context)
    : m_context(context), m_kernel(context.kernel("firsthit.cl", "firsthit")) {}

void FirstHitPass::prepare(const GpuScene& scene, int tile_size) {
  m_bins = binPrimitives(scene, tile_size);
  m_camera = Buffer(m_context, sizeof(CameraGpu));
  m_camera.write(&scene.camera, sizeof(CameraGpu));
  m_tile_start = upload(m_context, m_bins.tile_start);
  m_tile_prims = upload(m_context, m_bins.tile_prims);
  m_tile_bounds = upload(m_context, m_bins.tile_bounds);
  m_tile_depths = upload(m_context, m_bins.tile_depths);
  m_global_prims = upload(m_context, m_bins.global_prims);
}

void FirstHitPass::run(const Buffer& objects, const Buffer& xy, int count, Buffer& hits) {
  if (m_bins.tile_start.empty()) throw std::logic_error("FirstHitPass::run before prepare");
  if (count <= 0) return;
  m_context.launch(m_kernel)
      .arg(m_camera)
      .arg(objects)
      .arg(static_cast<cl_int>(m_bins.tile_size))
      .arg(static_cast<cl_int>(m_bins.tiles_x))
      .arg(static_cast<cl_int>(m_bins.tiles_y))
      .arg(m_tile_start)
      .arg(m_tile_prims)
      .arg(m_tile_bounds)
      .arg(m_tile_depths)
      .arg(m_global_prims)
      .arg(static_cast<cl_int>(m_bins.global_prims.size()))
      .arg(xy)
      .arg(static_cast<cl_int>(count))
      .arg(hits)
      .run(static_cast<size_t>(count));
}

std::vector<HitGpu> firstHits(Context& context, const GpuScene& scene, const std::vector<float>& sample_xy,
                              int tile_size) {
  const size_t count = sample_xy.size() / 2;
  if (count > static_cast<size_t>(std::numeric_limits<std::int32_t>::max()))
    throw std::invalid_argument("firstHits: too many samples for one launch");
  if (count == 0) return {};
  FirstHitPass pass(context);
  pass.prepare(scene, tile_size);
  Buffer objects = upload(context, scene.objects);
  Buffer xy = upload(context, sample_xy);
  Buffer hits(context, count * sizeof(HitGpu));
  pass.run(objects, xy, static_cast<int>(count), hits);
  return hits.readVector<HitGpu>(count);
}

}  // namespace prism
