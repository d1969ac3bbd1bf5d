// Scenes and rays for exercising the acceleration structures (not part of
// libprism: workloads/CMakeLists.txt), defined once
// and used by both the correctness tests (tests/accel) and prism-bench, so the
// two always look at the same kind of work:
//   - procedural meshes (a subdivided sphere, a random triangle soup) to fill
//     the range of sizes the shared meshes leave open;
//   - camera rays framing a box, shadow rays from hits towards a light, and
//     incoherent rays with random origins and directions.
#pragma once

#include <cstdint>
#include <vector>

#include "accel/prim_ref.h"
#include "accel/scene_geometry.h"
#include "kernels/shared/hit_gpu.h"
#include "kernels/shared/object_gpu.h"
#include "render/ray_queries.h"
#include "scene/mesh.h"

namespace prism {

// One TRIANGLE object per mesh triangle, in file order, untransformed.
std::vector<ObjectGpu> trianglesFromMesh(const TriangleMesh& mesh, int material = 0);
// The mesh untransformed as a scene flattens it: compact triangles
// (accel/scene_geometry.h), numbered in file order, material 0.
SceneGeometry geometryFromMesh(const TriangleMesh& mesh);

// Loop-free icosphere: the icosahedron's faces split `subdivisions` times,
// 20 * 4^subdivisions triangles, vertices pushed onto the sphere.
TriangleMesh icosphere(int subdivisions, float cx, float cy, float cz, float radius);

// `count` random triangles of size about `size` scattered in the unit cube.
TriangleMesh triangleSoup(std::size_t count, std::uint64_t seed, float size);

// A bumpy torus of about `triangles` triangles (a closed, curved surface
// like a scanned model, at any size): a grid of nu x nv quads, two triangles each.
TriangleMesh bumpyTorus(std::size_t triangles);

// Node visits of a BVH (buildAccel's flattened 8-wide nodes, with or without
// k-DOP bounds; not over moving primitives): per ray, the inner nodes and the
// leaves whose bounds meet the ray between tmin and its closest hit (tmax on a
// miss) in exact arithmetic, which every traversal order must visit to
// confirm that hit, and the analytic objects in those leaves it must test
// (with k-DOP bounds, those whose own slabs it meets there). Means over the
// rays; NaN for a structure that is no such BVH.
struct BvhVisits {
  double inner = 0, leaves = 0, objects = 0;
};
BvhVisits bvhNodeVisits(const DeviceAccel& accel, const std::vector<QueryRay>& rays, const std::vector<HitGpu>& hits);

// Box of the bounded objects (planes ignored).
Aabb boundsOf(const std::vector<ObjectGpu>& objects);

// width x height unit-direction pinhole rays through pixel centres from a
// point outside `box` looking at its centre, framing it (fov 40 degrees).
std::vector<QueryRay> cameraRays(const Aabb& box, int width, int height);

// Rays with origins uniform in `box` grown by half its size in each direction
// and directions uniform on the sphere; tmax = inf.
std::vector<QueryRay> randomRays(const Aabb& box, std::size_t count, std::uint64_t seed);

// From each hit of `rays` towards `light` (a segment ending just before it),
// starting a small offset off the surface; misses give no shadow ray.
std::vector<QueryRay> shadowRays(const std::vector<QueryRay>& rays, const std::vector<HitGpu>& hits,
                                 const float light[3]);

}  // namespace prism
