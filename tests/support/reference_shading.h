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

// Cook and Torrance's highlight in double precision, term for term as the 1982
// paper and Walter et al. (2007) write it: pi f (n.l) with
// f = F D G / (4 (n.l)(n.v)), D Beckmann's (distribution 0, V-cavity G) or GGX
// (1, Smith's G), F the unpolarised Fresnel reflectance for relative index eta,
// or 1 when eta <= 0. n, l, v unit; 0 when l or v is below the surface.
double referenceCookTorrance(const Vec3& n, const Vec3& l, const Vec3& v, double alpha, int distribution, double eta);

// Outward unit normal of an object at world point p.
Vec3 referenceNormal(const Object& object, const Vec3& p);

}  // namespace prism::test
