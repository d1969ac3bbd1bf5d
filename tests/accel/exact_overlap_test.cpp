// The primitive/cell overlap test the octree and BSP builders use
// (host/accel/exact_predicates.h): exact at boundaries, where float-based
// tests lose or wrongly keep primitives. Closed cells: touching counts.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "accel/exact_predicates.h"
#include "accel/prim_ref.h"
#include "scene/primitives/primitive_kind.h"
#include "accel/accel_scenes.h"

using namespace prism;
using namespace prism::test;

namespace {

ObjectGpu triangle(std::initializer_list<float> v) {
  ObjectGpu g = identityObject(OBJECT_TRIANGLE, 0);
  int i = 0;
  for (float x : v) g.p[i++] = x;
  return g;
}

bool meets(const ObjectGpu& ob, const CellBox& cell) {
  Aabb b;
  REQUIRE(objectBounds(ob, &b));
  std::size_t tests = 0;
  return overlapsCell(ob, b, cell, &tests);
}

const CellBox kUnit{{0, 0, 0}, {1, 1, 1}};
const CellBox kRight{{1, 0, 0}, {2, 1, 1}};  // shares the face x = 1 with kUnit

}  // namespace

TEST_CASE("a triangle lying exactly on a shared cell face is kept in both cells", "[accel][exact]") {
  ObjectGpu on_face = triangle({1, 0.2f, 0.2f, 1, 0.8f, 0.3f, 1, 0.4f, 0.9f});
  CHECK(meets(on_face, kUnit));
  CHECK(meets(on_face, kRight));
}

TEST_CASE("a triangle touching a cell only at a vertex or along an edge meets it", "[accel][exact]") {
  // Vertex exactly on the corner (1, 1, 1), the rest outside.
  CHECK(meets(triangle({1, 1, 1, 2, 1.5f, 1, 1.5f, 2, 2}), kUnit));
  // Edge lying on the cell's edge x = 1, y = 1 (from z = 0.2 to 0.7), rest outside.
  CHECK(meets(triangle({1, 1, 0.2f, 1, 1, 0.7f, 2, 2, 0.5f}), kUnit));
}

TEST_CASE("a triangle whose box overlaps the cell but which passes beside it is rejected", "[accel][exact]") {
  // Cuts the corner region x + y > 2.1 near (1, 1): its box overlaps [0,1]^3,
  // the triangle itself stays outside by 0.1.
  ObjectGpu t = triangle({2.1f, 0, 0.5f, 0, 2.1f, 0.5f, 2.1f, 2.1f, 0.5f});
  Aabb b;
  REQUIRE(objectBounds(t, &b));
  CHECK(b.lo[0] < 1);
  CHECK(b.lo[1] < 1);
  CHECK_FALSE(meets(t, kUnit));
  // Moved to x + y = 2 exactly through the corner edge (1, 1, z): touching, kept.
  CHECK(meets(triangle({2, 0, 0.5f, 0, 2, 0.5f, 2, 2, 0.5f}), kUnit));
}

TEST_CASE("a triangle one float step outside a cell face is rejected", "[accel][exact]") {
  float x = std::nextafter(1.0f, 2.0f);
  CHECK_FALSE(meets(triangle({x, 0.2f, 0.2f, x, 0.8f, 0.3f, 2, 0.4f, 0.9f}), kUnit));
  CHECK(meets(triangle({x, 0.2f, 0.2f, x, 0.8f, 0.3f, 2, 0.4f, 0.9f}), kRight));
}

TEST_CASE("degenerate triangles are judged as the segment or point they are", "[accel][exact]") {
  // Collinear, crossing the cell's face x = 1 from outside at y = z = 0.5.
  CHECK(meets(triangle({0.5f, 0.5f, 0.5f, 1.5f, 0.5f, 0.5f, 1.2f, 0.5f, 0.5f}), kRight));
  // Collinear, passing beside the cell.
  CHECK_FALSE(meets(triangle({2, 1.5f, 0.5f, 3, 1.5f, 0.5f, 2.5f, 1.5f, 0.5f}), kRight));
  // A point on the cell's corner and one just outside.
  CHECK(meets(triangle({1, 1, 1, 1, 1, 1, 1, 1, 1}), kUnit));
  float x = std::nextafter(1.0f, 2.0f);
  CHECK_FALSE(meets(triangle({x, 1, 1, x, 1, 1, x, 1, 1}), kUnit));
}

TEST_CASE("spheres are tested by exact squared distance to the cell", "[accel][exact]") {
  ObjectGpu s = identityObject(OBJECT_SPHERE, 0);
  // Centre (2, 2, 1) at distance sqrt(2) from the cell's edge (1, 1, z): radius
  // 1.5 reaches, 1.4 does not, though the box of either overlaps the cell.
  s.p[0] = 2;
  s.p[1] = 2;
  s.p[2] = 1;
  s.p[3] = 1.5f;
  CHECK(meets(s, kUnit));
  s.p[3] = 1.4f;
  CHECK_FALSE(meets(s, kUnit));
  // Touching a face exactly: centre (3, 0.5, 0.5), radius 1 touches x = 2 of kRight.
  s.p[0] = 3;
  s.p[1] = 0.5f;
  s.p[2] = 0.5f;
  s.p[3] = 1;
  CHECK(meets(s, kRight));
  CHECK_FALSE(meets(s, kUnit));
}

TEST_CASE("boxes overlap cells by intervals, touching included", "[accel][exact]") {
  ObjectGpu b = identityObject(OBJECT_BOX, 0);
  float lo[3] = {1, 0.2f, 0.2f}, hi[3] = {1.5f, 0.4f, 0.4f};
  for (int a = 0; a < 3; ++a) {
    b.p[a] = lo[a];
    b.p[3 + a] = hi[a];
  }
  CHECK(meets(b, kUnit));  // its face lies on x = 1
  CHECK(meets(b, kRight));
  b.p[0] = std::nextafter(1.0f, 2.0f);
  CHECK_FALSE(meets(b, kUnit));
}

TEST_CASE("transformed objects (by their kind's object-space box) and planes get conservative or no bounds", "[accel][exact]") {
  AccelScene scene = mixedScene(0);
  int transformed = 0, planes = 0;
  for (std::size_t i = 0, n = primitiveCount(scene.objects); i < n; ++i) {  // not the data records after them
    const ObjectGpu& ob = scene.objects[i];
    Aabb b;
    bool bounded = objectBounds(ob, &b);
    if (ob.type == OBJECT_PLANE) {
      CHECK_FALSE(bounded);
      ++planes;
    } else if (ob.has_transform) {
      REQUIRE(bounded);
      ++transformed;
      // Points of the object-space unit shape, mapped to world by the inverse
      // of world_to_object (solved in double), lie in the box.
      double m[3][3], t[3];
      for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) m[r][c] = ob.world_to_object[4 * r + c];
        t[r] = ob.world_to_object[4 * r + 3];
      }
      double det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                   m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
      REQUIRE(det != 0);
      std::mt19937 rng(3);
      std::uniform_real_distribution<double> u(-1, 1);
      // The object-space box of the shape, by its kind (the unit sphere's and
      // box's: [-1, 1]^3; a quadric's clip box; a polyhedron's exact box).
      double centre[3], half[3], lo[3], hi[3];
      REQUIRE(primitiveKindOfGpu(ob.type)->local_bounds(ob, objectSideData(ob), lo, hi));
      for (int a = 0; a < 3; ++a) {
        centre[a] = 0.5 * (lo[a] + hi[a]);
        half[a] = 0.5 * (hi[a] - lo[a]);
      }
      int inside = 0;
      for (int k = 0; k < 2000; ++k) {
        double q[3] = {u(rng), u(rng), u(rng)};
        if (ob.type == OBJECT_SPHERE && q[0] * q[0] + q[1] * q[1] + q[2] * q[2] > 1) continue;
        if (k % 7 == 0) {  // some on the surface, where the box is tight
          double l = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2]);
          if (ob.type == OBJECT_SPHERE) {
            for (double& x : q) x /= l;
          } else {
            q[k % 3] = q[k % 3] < 0 ? -1 : 1;
          }
        }
        for (int a = 0; a < 3; ++a) q[a] = centre[a] + half[a] * q[a];
        // Solve m w = q - t by Cramer's rule.
        double rhs[3] = {q[0] - t[0], q[1] - t[1], q[2] - t[2]}, w[3];
        for (int c = 0; c < 3; ++c) {
          double a[3][3];
          for (int r = 0; r < 3; ++r)
            for (int cc = 0; cc < 3; ++cc) a[r][cc] = cc == c ? rhs[r] : m[r][cc];
          w[c] = (a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
                  a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0])) /
                 det;
        }
        ++inside;
        for (int a = 0; a < 3; ++a) {
          CHECK(w[a] >= b.lo[a]);
          CHECK(w[a] <= b.hi[a]);
        }
      }
      CHECK(inside > 0);
    }
  }
  CHECK(planes == 2);
  CHECK(transformed == 12 + 5 + 1);  // spheres and boxes, quadrics, a polyhedron
}

TEST_CASE("perfect-split bounds clip a triangle to the cell", "[accel][exact]") {
  ObjectGpu t = triangle({-1, 0.5f, 0.5f, 3, 0.5f, 0.5f, 1, 0.5f, 4});
  Aabb b;
  REQUIRE(objectBounds(t, &b));
  Aabb c = clippedBounds(t, b, kUnit);
  REQUIRE_FALSE(c.empty());
  for (int a = 0; a < 3; ++a) {
    CHECK(c.lo[a] >= std::nextafter(float(kUnit.lo[a]), -1.0f));
    CHECK(c.hi[a] <= std::nextafter(float(kUnit.hi[a]), 2.0f));
  }
  CHECK(c.lo[1] <= 0.5f);
  CHECK(c.hi[1] >= 0.5f);
  CHECK(c.hi[1] - c.lo[1] < 1e-5f);  // flat in y
}
