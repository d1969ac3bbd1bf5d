// Scenes the acceleration-structure tests share: a mixed analytic + mesh scene
// with every primitive kind (transformed, degenerate, semitransparent, planes,
// triangles lying on the octree's and the BSP's splitting planes), procedural
// meshes, and the real meshes in tests/data/meshes through the plugins.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "accel_workloads.h"
#include "kernels/shared/material_gpu.h"
#include "kernels/shared/object_gpu.h"
#include "scene/primitives/primitive_kind.h"
#include "scene_format/scene_loader.h"
#include "support/test_data.h"

namespace prism::test {

struct AccelScene {
  std::string name;
  std::vector<ObjectGpu> objects;
  std::vector<MaterialGpu> materials;  // empty: all opaque
};

using prism_test::loadTestMesh;

// A structure's nodes as the kernels read them: past the two header words
// (the scene's box).
template <typename T>
const T* nodesOf(const DeviceAccel& a) {
  return reinterpret_cast<const T*>(a.nodes.data() + 2);
}

inline ObjectGpu identityObject(int type, int material) {
  ObjectGpu g{};
  g.type = type;
  g.material = material;
  g.world_to_object[0] = g.world_to_object[5] = g.world_to_object[10] = 1;
  return g;
}

inline MaterialGpu materialWithTransmit(float transmit) {
  MaterialGpu m{};
  m.transmit = transmit;
  m.ior = 1;
  return m;
}

// Appends the objects of a scene-format objects array (their records, then
// their data records after every primitive), through each kind's own flatten.
inline void appendFromJson(std::vector<ObjectGpu>& objects, const std::string& objects_json,
                           const std::vector<int>& materials) {
  Scene scene = parseScene(R"({"objects": )" + objects_json + "}", "objects");
  std::vector<std::vector<float>> sides;
  const std::size_t first = objects.size();
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    const Object& o = scene.objects[i];
    const PrimitiveKind& kind = primitiveKind(o.type);
    for (std::size_t part = 0; part < o.primitiveCount(); ++part) {
      ObjectGpu g = identityObject(kind.gpu_type, materials[i % materials.size()]);
      sides.emplace_back();
      kind.flatten(o, part, FlattenSettings{}, g, sides.back());
      if (!o.transform.isIdentity()) {
        const Transform inv = o.transform.inverse();
        for (int r = 0; r < 3; ++r)
          for (int c = 0; c < 4; ++c) g.world_to_object[4 * r + c] = static_cast<float>(inv.m[r][c]);
        g.has_transform = 1;
      }
      objects.push_back(g);
    }
  }
  for (std::size_t i = 0; i < sides.size(); ++i) {
    if (sides[i].empty()) continue;
    const std::size_t record = appendSideData(sides[i], objects);
    setSideDataOffset(objects[first + i], static_cast<int>(record - (first + i)));
  }
}

// Every kind of primitive, in a box about [-1, 2]^3: a triangle soup, an
// icosphere (shared edges and vertices: exact ties), spheres, boxes, scaled
// and rotated spheres and boxes, two planes, degenerate triangles,
// axis-aligned triangles lying exactly on x = 0.5, y = 0.5, z = 0.5 (the
// centre planes of a unit cube cell), and quadrics open and capped, placed by
// transforms or by their coefficients, and polygons (one on x, y, z = 0.5
// planes' neighbourhood, one convex, one not), and convex polyhedra (one
// placed by a transform, one by its planes), and the teapot's Bezier patches
// (pieces for Newton iteration). Materials 1 and 2 are semitransparent.
inline AccelScene mixedScene(std::size_t soup = 1500) {
  AccelScene s;
  s.name = "mixed";
  s.materials = {materialWithTransmit(0), materialWithTransmit(0.5f), materialWithTransmit(0.25f)};
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<float> u01(0, 1);
  auto material = [&] { return static_cast<int>(rng() % 3); };

  for (ObjectGpu& g : trianglesFromMesh(triangleSoup(soup, 11, 0.08f))) {
    g.material = material();
    s.objects.push_back(g);
  }
  for (ObjectGpu& g : trianglesFromMesh(icosphere(3, 0.3f, 0.6f, 0.4f, 0.35f))) {
    g.material = material();
    s.objects.push_back(g);
  }
  for (int i = 0; i < 40; ++i) {
    ObjectGpu g = identityObject(OBJECT_SPHERE, material());
    g.p[0] = u01(rng);
    g.p[1] = u01(rng);
    g.p[2] = u01(rng);
    g.p[3] = 0.01f + 0.06f * u01(rng);
    s.objects.push_back(g);
  }
  for (int i = 0; i < 25; ++i) {
    ObjectGpu g = identityObject(OBJECT_BOX, material());
    for (int a = 0; a < 3; ++a) {
      float c = u01(rng), h = 0.01f + 0.05f * u01(rng);
      g.p[a] = c - h;
      g.p[3 + a] = c + h;
    }
    s.objects.push_back(g);
  }
  // Transformed: world_to_object of a scale then rotation about z then translation.
  for (int i = 0; i < 12; ++i) {
    ObjectGpu g = identityObject(i % 2 ? OBJECT_BOX : OBJECT_SPHERE, material());
    if (g.type == OBJECT_SPHERE) {
      g.p[3] = 1;
    } else {
      for (int a = 0; a < 3; ++a) {
        g.p[a] = -1;
        g.p[3 + a] = 1;
      }
    }
    float sx = 0.02f + 0.08f * u01(rng), sy = 0.02f + 0.08f * u01(rng), sz = 0.02f + 0.08f * u01(rng);
    float ang = 6.2831853f * u01(rng), c = std::cos(ang), sn = std::sin(ang);
    float tx = u01(rng), ty = u01(rng), tz = u01(rng);
    // object-to-world M = T R S; world-to-object = S^-1 R^T T^-1.
    float r[3][3] = {{c, -sn, 0}, {sn, c, 0}, {0, 0, 1}};
    float inv_s[3] = {1 / sx, 1 / sy, 1 / sz};
    float t[3] = {tx, ty, tz};
    for (int row = 0; row < 3; ++row) {
      float off = 0;
      for (int col = 0; col < 3; ++col) {
        g.world_to_object[4 * row + col] = inv_s[row] * r[col][row];
        off -= g.world_to_object[4 * row + col] * t[col];
      }
      g.world_to_object[4 * row + 3] = off;
    }
    g.has_transform = 1;
    s.objects.push_back(g);
  }
  // Planes: a floor and a tilted wall, far from the rest.
  ObjectGpu floor = identityObject(OBJECT_PLANE, 0);
  floor.p[1] = -1;
  floor.p[4] = 1;
  s.objects.push_back(floor);
  ObjectGpu wall = identityObject(OBJECT_PLANE, 1);
  wall.p[2] = -1.5f;
  float n[3] = {0.1f, 0.2f, 1};
  float l = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  for (int a = 0; a < 3; ++a) wall.p[3 + a] = n[a] / l;
  s.objects.push_back(wall);
  // Degenerate triangles: a point, a segment (collinear), a repeated vertex.
  float degenerate[3][9] = {{0.2f, 0.2f, 0.2f, 0.2f, 0.2f, 0.2f, 0.2f, 0.2f, 0.2f},
                            {0.1f, 0.1f, 0.1f, 0.3f, 0.3f, 0.3f, 0.5f, 0.5f, 0.5f},
                            {0.7f, 0.1f, 0.3f, 0.7f, 0.1f, 0.3f, 0.9f, 0.4f, 0.3f}};
  for (auto& v : degenerate) {
    ObjectGpu g = identityObject(OBJECT_TRIANGLE, 0);
    for (int k = 0; k < 9; ++k) g.p[k] = v[k];
    s.objects.push_back(g);
  }
  // Triangles in the planes x, y, z = 0.5 (and on each other's edges).
  for (int axis = 0; axis < 3; ++axis)
    for (int k = 0; k < 4; ++k) {
      ObjectGpu g = identityObject(OBJECT_TRIANGLE, material());
      float lo = 0.1f + 0.2f * k, hi = lo + 0.25f;
      float pts[3][2] = {{lo, lo}, {hi, lo}, {lo, hi}};
      for (int v = 0; v < 3; ++v) {
        g.p[3 * v + axis] = 0.5f;
        g.p[3 * v + (axis + 1) % 3] = pts[v][0];
        g.p[3 * v + (axis + 2) % 3] = pts[v][1];
      }
      s.objects.push_back(g);
    }
  // Quadrics, polygons, polyhedra and the teapot's patch pieces last: their
  // data records close the array.
  appendFromJson(s.objects, R"([
      {"type": "cylinder", "radius": 0.08, "height": 0.3, "transform": {"translate": [0.2, 0.6, 0.8]}},
      {"type": "cylinder", "radius": 0.06, "height": 0.4, "capped": false,
       "transform": [{"rotate": {"axis": [1, 0, 1], "angle": 50}}, {"translate": [0.5, 0.5, 0.5]}]},
      {"type": "cone", "radius": 0.1, "height": 0.2, "transform": {"translate": [0.8, 0.2, 0.3]}},
      {"type": "paraboloid", "radius": 0.1, "height": 0.15, "capped": false, "transform": {"translate": [0.3, 0.3, 0.2]}},
      {"type": "hyperboloid", "radius": 0.05, "top_radius": 0.1, "height": 0.12, "transform": {"translate": [0.7, 0.8, 0.6]}},
      {"type": "quadric", "coefficients": [1, 1, 1, 0, 0, 0, -1, -1.2, -0.8, 0.7675], "capped": true,
       "clip": {"min": [0.45, 0.55, 0.35], "max": [0.55, 0.65, 0.45]}},
      {"type": "quadric", "coefficients": [5, -5, 0, 0, 0, 0, -5, 2, -1, 1.8],
       "clip": {"min": [0.4, 0.1, 0.6], "max": [0.6, 0.3, 0.9]}},
      {"type": "polygon", "vertices": [[0.1, 0.9, 0.1], [0.4, 0.9, 0.1], [0.4, 0.9, 0.2], [0.2, 0.9, 0.2],
                                       [0.2, 0.9, 0.35], [0.1, 0.9, 0.35]]},
      {"type": "polygon", "vertices": [[0.6, 0.1, 0.1], [0.9, 0.15, 0.23], [0.85, 0.4, 0.26], [0.7, 0.45, 0.21],
                                       [0.55, 0.3, 0.12]], "inside_test": "left-right"},
      {"type": "polygon", "vertices": [[0.3, 0.5, 0.5], [0.5, 0.5, 0.5], [0.5, 0.7, 0.5], [0.4, 0.6, 0.5],
                                       [0.3, 0.7, 0.5]], "inside_test": "radial"},
      {"type": "polyhedron", "planes": [[1, 1, 1, -0.1], [1, 1, -1, -0.1], [1, -1, 1, -0.1], [1, -1, -1, -0.1],
                                         [-1, 1, 1, -0.1], [-1, 1, -1, -0.1], [-1, -1, 1, -0.1], [-1, -1, -1, -0.1]],
       "transform": {"translate": [0.15, 0.15, 0.85]}},
      {"type": "polyhedron", "planes": [[1, 0, 0, -0.95], [-1, 0, 0, 0.85], [0, 1, 0, -0.95], [0, -1, 0, 0.8],
                                         [0, 0, 1, -0.95], [0, 0, -1, 0.8], [1, 1, 1, -2.75]]},
      {"type": "patches", "file": ")" + prism_test::testDataDir() + R"(/patches/teapot.bpt", "method": "analytic",
       "transform": [{"scale": 0.1}, {"rotate": {"axis": [1, 1, 0], "angle": 30}}, {"translate": [2.3, 0.5, 0.5]}]}])",
                {0, 1, 2});
  return s;
}

inline AccelScene meshScene(const std::string& name, const TriangleMesh& mesh) {
  AccelScene s;
  s.name = name;
  s.objects = trianglesFromMesh(mesh);
  return s;
}

}  // namespace prism::test
