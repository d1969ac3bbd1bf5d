// The polygon kind's checks and device record, for the objects made of
// polygons besides the polygon itself: meshes whose faces stay polygons
// ("polygons": true) and polyhedra given by their faces.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "kernels/shared/object_gpu.h"
#include "scene/primitives/inside_test.h"
#include "scene/vec3.h"

namespace prism {

struct PolygonCheck {
  std::string problem;          // "" when the vertices make a polygon prism renders as one
  std::size_t vertex = SIZE_MAX;  // the vertex the problem is about, if one is
  bool zero_area = false;         // the problem is that it has no area
  bool convex = false;
};

// Planar (every vertex within 1e-6 of its size of the mean plane), of
// non-zero area and simple (no edges cross or touch, no vertex repeats).
PolygonCheck checkPolygon(const std::vector<Vec3>& verts);

// The record of the polygon `verts` (checked) with inside test `test`; its
// vertices go to `side`. Throws std::invalid_argument for left-right on a
// non-convex polygon.
void flattenPolygon(const std::vector<Vec3>& verts, InsideTest test, ObjectGpu& g, std::vector<float>& side);

}  // namespace prism
