#include "accel_workloads.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <map>
#include <memory>
#include <random>
#include <string>
#include <utility>

#include "accel/kdop_bounds.h"
#include "kernels/shared/bvh_node_gpu.h"
#include "render/gpu_scene.h"

namespace prism {
namespace {

void normalize3(double v[3]) {
  double l = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  for (int a = 0; a < 3; ++a) v[a] /= l;
}

}  // namespace

std::vector<ObjectGpu> trianglesFromMesh(const TriangleMesh& mesh, int material) {
  std::vector<ObjectGpu> out(mesh.triangleCount());
  for (std::size_t t = 0; t < out.size(); ++t) {
    ObjectGpu& g = out[t];
    g = ObjectGpu{};
    g.type = OBJECT_TRIANGLE;
    g.material = material;
    for (int k = 0; k < 3; ++k) {
      std::uint32_t v = mesh.indices[3 * t + k];
      for (int a = 0; a < 3; ++a) g.p[3 * k + a] = mesh.positions[3 * v + a];
    }
    g.world_to_object[0] = g.world_to_object[5] = g.world_to_object[10] = 1;
  }
  return out;
}

SceneGeometry geometryFromMesh(const TriangleMesh& mesh) {
  Scene scene;
  scene.materials.push_back(Material{});
  Object ob;
  ob.type = ObjectType::Mesh;
  ob.mesh = std::make_shared<const TriangleMesh>(mesh);
  ob.material = 0;
  ob.material_override = true;
  scene.objects.push_back(ob);
  return flattenScene(scene, RenderOptions::fromScene(scene));
}

TriangleMesh icosphere(int subdivisions, float cx, float cy, float cz, float radius) {
  const double p = (1 + std::sqrt(5.0)) / 2;
  std::vector<std::array<double, 3>> v = {{-1, p, 0}, {1, p, 0}, {-1, -p, 0}, {1, -p, 0}, {0, -1, p}, {0, 1, p},
                                          {0, -1, -p}, {0, 1, -p}, {p, 0, -1}, {p, 0, 1}, {-p, 0, -1}, {-p, 0, 1}};
  for (auto& x : v) normalize3(x.data());
  std::vector<std::uint32_t> f = {0, 11, 5, 0, 5,  1, 0, 1, 7, 0, 7,  10, 0, 10, 11, 1, 5, 9, 5, 11,
                                  4, 11, 10, 2, 10, 7, 6, 7, 1, 8, 3, 9, 4, 3,  4,  2, 3, 2, 6, 3,
                                  6, 8, 3, 8, 9, 4, 9, 5, 2, 4, 11, 6, 2, 10, 8,  6, 7, 9, 8, 1};
  for (int s = 0; s < subdivisions; ++s) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> mid;
    auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
      auto key = std::minmax(a, b);
      auto it = mid.find(key);
      if (it != mid.end()) return it->second;
      std::array<double, 3> m;
      for (int k = 0; k < 3; ++k) m[k] = 0.5 * (v[a][k] + v[b][k]);
      normalize3(m.data());
      v.push_back(m);
      return mid[key] = static_cast<std::uint32_t>(v.size() - 1);
    };
    std::vector<std::uint32_t> g;
    g.reserve(f.size() * 4);
    for (std::size_t t = 0; t < f.size(); t += 3) {
      std::uint32_t a = f[t], b = f[t + 1], c = f[t + 2];
      std::uint32_t ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
      for (std::uint32_t x : {a, ab, ca, b, bc, ab, c, ca, bc, ab, bc, ca}) g.push_back(x);
    }
    f.swap(g);
  }
  TriangleMesh mesh;
  mesh.source = "icosphere" + std::to_string(subdivisions);
  for (const auto& x : v) {
    mesh.positions.push_back(static_cast<float>(cx + radius * x[0]));
    mesh.positions.push_back(static_cast<float>(cy + radius * x[1]));
    mesh.positions.push_back(static_cast<float>(cz + radius * x[2]));
  }
  mesh.indices = std::move(f);
  mesh.face_count = mesh.triangleCount();
  return mesh;
}

TriangleMesh triangleSoup(std::size_t count, std::uint64_t seed, float size) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f), offset(-size, size);
  TriangleMesh mesh;
  mesh.source = "soup" + std::to_string(count);
  for (std::size_t t = 0; t < count; ++t) {
    float c[3] = {unit(rng), unit(rng), unit(rng)};
    for (int k = 0; k < 3; ++k) {
      for (int a = 0; a < 3; ++a) mesh.positions.push_back(c[a] + offset(rng));
      mesh.indices.push_back(static_cast<std::uint32_t>(3 * t + k));
    }
  }
  mesh.face_count = count;
  return mesh;
}

TriangleMesh bumpyTorus(std::size_t triangles) {
  const std::size_t quads = std::max<std::size_t>(triangles / 2, 8);
  // The tube's circumference is about a third of the ring's: nu = 3 nv.
  std::size_t nv = std::max<std::size_t>(3, static_cast<std::size_t>(std::lround(std::sqrt(quads / 3.0))));
  std::size_t nu = std::max<std::size_t>(3, (quads + nv / 2) / nv);
  const double two_pi = 6.283185307179586;
  TriangleMesh mesh;
  mesh.source = "torus" + std::to_string(2 * nu * nv);
  mesh.positions.reserve(3 * nu * nv);
  for (std::size_t i = 0; i < nu; ++i)
    for (std::size_t j = 0; j < nv; ++j) {
      double u = two_pi * i / nu, v = two_pi * j / nv;
      double r = 0.35 * (1 + 0.15 * std::sin(7 * u) * std::sin(5 * v));
      double x = (1 + r * std::cos(v)) * std::cos(u), y = r * std::sin(v), z = (1 + r * std::cos(v)) * std::sin(u);
      mesh.positions.push_back(static_cast<float>(x));
      mesh.positions.push_back(static_cast<float>(y));
      mesh.positions.push_back(static_cast<float>(z));
    }
  mesh.indices.reserve(6 * nu * nv);
  auto at = [&](std::size_t i, std::size_t j) { return static_cast<std::uint32_t>((i % nu) * nv + (j % nv)); };
  for (std::size_t i = 0; i < nu; ++i)
    for (std::size_t j = 0; j < nv; ++j) {
      std::uint32_t a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
      for (std::uint32_t x : {a, b, c, a, c, d}) mesh.indices.push_back(x);
    }
  mesh.face_count = mesh.triangleCount();
  return mesh;
}

Aabb boundsOf(const std::vector<ObjectGpu>& objects) {
  Aabb box;
  // The primitives only: the motion and data records after them are not
  // objects (a data record's floats may read as any type).
  const std::size_t count = primitiveCount(objects);  // (once: it scans the array)
  for (std::size_t i = 0; i < count; ++i) {
    Aabb b;
    if (objectBounds(objects[i], &b)) box.extend(b);
  }
  return box;
}

namespace {

// The part of [t0, t1] where lo <= o + t d <= hi (along one axis or one
// diagonal, o and d projected on it), in double; false when none is left.
bool clipSlab(double lo, double hi, double o, double d, double& t0, double& t1) {
  if (d == 0) return lo <= o && o <= hi;
  double a = (lo - o) / d, b = (hi - o) / d;
  if (a > b) std::swap(a, b);
  t0 = std::max(t0, a);
  t1 = std::min(t1, b);
  return t0 <= t1;
}

}  // namespace

BvhVisits bvhNodeVisits(const DeviceAccel& accel, const std::vector<QueryRay>& rays, const std::vector<HitGpu>& hits) {
  const std::string& options = accel.kernel_options;
  if (accel.kind != AccelKind::Bvh || options.find("-DPRISM_BVH_MOTION") != std::string::npos || rays.empty())
    return {NAN, NAN, NAN};
  const bool kdop = options.find("-DPRISM_BVH_KDOP") != std::string::npos;
  const bool object_kdop = options.find("-DPRISM_OBJECT_KDOP") != std::string::npos;
  const std::size_t node_floats = (7 + (kdop ? 8 : 0)) * 8;  // float8 words of a node (kernels/accel/bvh.h)
  const float* nodes = accel.nodes.size() > 2 ? accel.nodes[2].v : nullptr;
  BvhVisits sum;
  std::vector<int> stack;
  for (std::size_t r = 0; r < rays.size(); ++r) {
    const QueryRay& q = rays[r];
    const double o[3] = {q.ox, q.oy, q.oz}, d[3] = {q.dx, q.dy, q.dz};
    const double t_end = hits[r].prim >= 0 ? hits[r].t : q.tmax;
    stack.assign(1, 0);
    while (nodes && !stack.empty()) {
      const float* n = nodes + node_floats * static_cast<std::size_t>(stack.back());
      stack.pop_back();
      sum.inner += 1;
      for (int i = 0; i < BVH_WIDTH; ++i) {
        int child;
        std::memcpy(&child, n + 48 + i, sizeof child);
        if (child == 0) continue;
        double t0 = q.tmin, t1 = t_end;
        bool meets = true;
        for (int a = 0; a < 3 && meets; ++a) meets = clipSlab(n[16 * a + i], n[16 * a + 8 + i], o[a], d[a], t0, t1);
        for (int j = 0; kdop && j < BVH_KDOP_DIAGONALS && meets; ++j) {
          const float* k = n + 56 + 16 * j;
          meets = clipSlab(k[i], k[8 + i], diagonalDot(j, o[0], o[1], o[2]), diagonalDot(j, d[0], d[1], d[2]), t0, t1);
        }
        if (!meets) continue;
        if (child > 0) {
          stack.push_back(child);
          continue;
        }
        sum.leaves += 1;
        const int code = ~child, first = code >> BVH_LEAF_COUNT_BITS, count = (code & (BVH_LEAF_MAX_PACKETS - 1)) + 1;
        for (int p = first; p < first + count; ++p) {
          const TriPacketGpu& pk = accel.packets[p];
          const float* lanes = pk.v0x;  // float4 words: lane k of word w at 4 w + k
          for (int k = 0; k < PACKET_LANES; ++k) {
            if (pk.prim[k] > -2) continue;  // a triangle or an empty lane
            double u0 = q.tmin, u1 = t_end;
            bool tested = true;
            for (int j = 0; object_kdop && j < BVH_KDOP_DIAGONALS && tested; ++j)
              tested = clipSlab(lanes[8 * j + k], lanes[8 * j + 4 + k], diagonalDot(j, o[0], o[1], o[2]),
                                diagonalDot(j, d[0], d[1], d[2]), u0, u1);
            sum.objects += tested;
          }
        }
      }
    }
  }
  return {sum.inner / rays.size(), sum.leaves / rays.size(), sum.objects / rays.size()};
}

std::vector<QueryRay> cameraRays(const Aabb& box, int width, int height) {
  double c[3], ext = 0;
  for (int a = 0; a < 3; ++a) {
    c[a] = 0.5 * (double(box.lo[a]) + box.hi[a]);
    ext = std::max(ext, double(box.hi[a]) - box.lo[a]);
  }
  if (!(ext > 0)) ext = 1;
  // From the front, a little above and to the side, far enough to frame it.
  double dir[3] = {0.35, 0.3, 1.0};
  normalize3(dir);
  const double fov = 40.0 * 3.14159265358979323846 / 180.0;
  const double dist = 0.5 * ext * 1.8 / std::tan(fov / 2) ;
  double eye[3];
  for (int a = 0; a < 3; ++a) eye[a] = c[a] + dir[a] * dist;
  double fwd[3] = {-dir[0], -dir[1], -dir[2]};
  double right[3] = {fwd[1] * 0 - fwd[2] * 1, fwd[2] * 0 - fwd[0] * 0, fwd[0] * 1 - fwd[1] * 0};  // fwd x up(0,1,0)
  normalize3(right);
  double up[3] = {right[1] * fwd[2] - right[2] * fwd[1], right[2] * fwd[0] - right[0] * fwd[2],
                  right[0] * fwd[1] - right[1] * fwd[0]};
  const double th = std::tan(fov / 2), aspect = double(width) / height;
  std::vector<QueryRay> rays;
  rays.reserve(static_cast<std::size_t>(width) * height);
  for (int j = 0; j < height; ++j)
    for (int i = 0; i < width; ++i) {
      double x = (2 * (i + 0.5) / width - 1) * th * aspect, y = (1 - 2 * (j + 0.5) / height) * th;
      double d[3];
      for (int a = 0; a < 3; ++a) d[a] = fwd[a] + x * right[a] + y * up[a];
      normalize3(d);
      rays.push_back(QueryRay{float(eye[0]), float(eye[1]), float(eye[2]), 0.0f, float(d[0]), float(d[1]),
                              float(d[2]), INFINITY});
    }
  return rays;
}

std::vector<QueryRay> randomRays(const Aabb& box, std::size_t count, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::normal_distribution<double> normal;
  std::vector<QueryRay> rays(count);
  for (QueryRay& r : rays) {
    float o[3];
    for (int a = 0; a < 3; ++a) {
      double lo = box.lo[a], ext = double(box.hi[a]) - lo;
      o[a] = static_cast<float>(lo - 0.5 * ext + 2 * ext * unit(rng));
    }
    double d[3];
    do {
      for (double& x : d) x = normal(rng);
    } while (d[0] * d[0] + d[1] * d[1] + d[2] * d[2] < 1e-6);
    normalize3(d);
    r = QueryRay{o[0], o[1], o[2], 0.0f, float(d[0]), float(d[1]), float(d[2]), INFINITY};
  }
  return rays;
}

std::vector<QueryRay> shadowRays(const std::vector<QueryRay>& rays, const std::vector<HitGpu>& hits,
                                 const float light[3]) {
  std::vector<QueryRay> out;
  out.reserve(rays.size());
  for (std::size_t i = 0; i < rays.size(); ++i) {
    if (hits[i].prim < 0) continue;
    const QueryRay& r = rays[i];
    float p[3] = {r.ox + hits[i].t * r.dx, r.oy + hits[i].t * r.dy, r.oz + hits[i].t * r.dz};
    float mag = std::max({1.0f, std::fabs(p[0]), std::fabs(p[1]), std::fabs(p[2])});
    float d[3] = {light[0] - p[0], light[1] - p[1], light[2] - p[2]};
    float len = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    if (!(len > 0)) continue;
    // Unit direction, from a little off the surface to just before the light.
    float eps = 1e-4f * mag;
    out.push_back(QueryRay{p[0], p[1], p[2], eps, d[0] / len, d[1] / len, d[2] / len, len * (1 - 1e-4f)});
  }
  return out;
}

}  // namespace prism
