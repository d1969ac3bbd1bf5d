// A recursive Whitted ray tracer in double precision over the host scene model:
// the textbook algorithm (Whitted 1980) written as plain recursion, an independent
// second method to check the wavefront kernels against. No textures.
#pragma once

#include "render/render_options.h"
#include "scene/scene.h"
#include "support/reference_geometry.h"

namespace prism::test {

struct RefHit {
  int object = -1;
  double t = INFINITY;
};

RefHit referenceClosest(const Scene& scene, const RefRay& ray);

// Colour seen along `ray` with `weight`, at recursion depth `depth`.
Vec3 referenceRadiance(const Scene& scene, const RenderOptions& options, const RefRay& ray, double weight, int depth);

// The primary ray through the centre of pixel (i, j) (DESIGN.md's camera).
RefRay referencePrimaryRay(const Scene& scene, const RenderOptions& options, int i, int j);

// Outward unit normal of an object at world point p.
Vec3 referenceNormal(const Object& object, const Vec3& p);

}  // namespace prism::test
