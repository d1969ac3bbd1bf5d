// Bicubic patches in the kernels: the analytic method (Newton iteration on
// pieces, in float) against successive subdivision along each ray in double
// (the kind's reference), and the triangles of successive subdivision against
// the analytic surface, within the tolerance they were made to — the two
// methods the classic literature names, holding each other to account.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>

#include "render/ray_queries.h"
#include "scene/patches/bpt_file.h"
#include "scene_format/scene_loader.h"
#include "support/reference_geometry.h"
#include "support/shared_context.h"
#include "support/test_data.h"

using namespace prism;
using namespace prism::test;

namespace {

std::string teapotPath() { return prism_test::testDataDir() + "/patches/teapot.bpt"; }

Scene teapotScene(const std::string& method, const std::string& extra = "") {
  return parseScene(R"({"objects": [{"type": "patches", "file": ")" + teapotPath() + R"(", "method": ")" + method +
                        "\"" + extra + "}]}",
                    "teapot");
}

RayGpu toGpu(const RefRay& r) {
  RayGpu g{};
  g.ox = float(r.o.x), g.oy = float(r.o.y), g.oz = float(r.o.z);
  g.dx = float(r.d.x), g.dy = float(r.d.y), g.dz = float(r.d.z);
  g.tmin = float(r.tmin);
  g.tmax = INFINITY;
  g.kind = RAY_KIND_PRIMARY;
  return g;
}

// Rays from all round at points of the surface (and a little beside it), in
// the float-rounded form the device sees.
std::vector<RefRay> raysAtTeapot(int n, std::uint64_t seed) {
  const std::vector<BezierPatch> patches = readBptFile(teapotPath());
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u01(0, 1), s11(-1, 1);
  std::vector<RefRay> rays;
  while (static_cast<int>(rays.size()) < n) {
    const BezierPatch& p = patches[rng() % patches.size()];
    const Vec3 target = evaluate(p, u01(rng), u01(rng)).p + Vec3{s11(rng), s11(rng), s11(rng)} * 0.05;
    Vec3 dir{s11(rng), s11(rng), s11(rng)};
    if (length(dir) < 0.1 || length(dir) > 1) continue;
    RefRay r;
    r.o = target - dir * (8 / length(dir));
    r.d = dir * (0.5 + u01(rng));  // unnormalised on purpose
    const RayGpu g = toGpu(r);
    r.o = {g.ox, g.oy, g.oz};
    r.d = {g.dx, g.dy, g.dz};
    rays.push_back(r);
  }
  return rays;
}

// Whether rays beside this one (by `delta` across it, four ways) agree with
// it on hit or miss and on where, within `jump` deltas along it: otherwise it
// passes too close to a silhouette or an edge for float and double (or a
// surface and its approximation) to be compared.
bool clearCut(const Object& ob, const RefRay& r, double delta, double jump = 100) {
  const std::optional<double> t = referenceIntersect(ob, r);
  const Vec3 d = normalize(r.d);
  const Vec3 a = normalize(cross(d, std::fabs(d.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0})), b = cross(d, a);
  for (const Vec3& side : {a, a * -1.0, b, b * -1.0}) {
    RefRay s = r;
    s.o = r.o + side * delta;
    const std::optional<double> ts = referenceIntersect(ob, s);
    if (ts.has_value() != t.has_value()) return false;
    if (t && std::fabs(*ts - *t) * length(r.d) > jump * delta) return false;
  }
  return true;
}

// |cos| of the angle between the ray and the surface normal at the device's
// hit (the piece it names, at its (u, v)).
double incidence(const Object& patches, const HitGpu& hit, const RefRay& ray) {
  const PatchPiece& piece = patches.pieces->at(static_cast<std::size_t>(hit.prim));
  return std::fabs(dot(patchNormal(piece.patch, hit.u, hit.v), normalize(ray.d)));
}

}  // namespace

TEST_CASE("Newton iteration on patch pieces matches successive subdivision in double", "[kernels][patches]") {
  const Scene scene = teapotScene("analytic");
  REQUIRE(scene.objects.size() == 1);
  const Object& teapot = scene.objects[0];
  REQUIRE(teapot.type == ObjectType::Patches);
  INFO(teapot.primitiveCount() << " pieces");
  const std::vector<RefRay> rays = raysAtTeapot(3000, 11);
  std::vector<RayGpu> gpu;
  for (const RefRay& r : rays) gpu.push_back(toGpu(r));
  const std::vector<HitGpu> hits = traceClosest(sharedContext(), scene, gpu, AccelKind::Bvh);
  const double size = 6.6;  // the teapot's control-point box diagonal, about
  int compared = 0, hit_both = 0, wrong_hit = 0, wrong_t = 0;
  double worst = 0;
  for (std::size_t i = 0; i < rays.size(); ++i) {
    if (!clearCut(teapot, rays[i], 1e-4 * size)) continue;
    ++compared;
    const std::optional<double> ref = referenceIntersect(teapot, rays[i]);
    const bool gpu_hit = hits[i].prim >= 0;
    if (gpu_hit != ref.has_value()) {
      ++wrong_hit;
      continue;
    }
    if (!ref) continue;
    ++hit_both;
    // Newton stops within its tolerance of the ray (float's, about 1e-4 here);
    // along the ray that is the tolerance over the cosine of the angle of incidence.
    const double err = std::fabs(hits[i].t - *ref) * length(rays[i].d);  // in scene units
    const double cosine = incidence(teapot, hits[i], rays[i]);
    worst = std::max(worst, err * cosine);
    wrong_t += err * std::max(cosine, 0.05) > 1e-4 * size;
  }
  INFO(compared << " compared, " << hit_both << " hits, " << wrong_hit << " wrong hit/miss, " << wrong_t
                << " wrong t (worst " << worst << ")");
  CHECK(compared > 2700);
  CHECK(hit_both > compared / 2);
  CHECK(wrong_hit == 0);
  CHECK(wrong_t == 0);
}

TEST_CASE("the triangles of successive subdivision lie within their tolerance of the analytic surface",
          "[kernels][patches]") {
  const Scene analytic = teapotScene("analytic");
  const std::vector<RefRay> rays = raysAtTeapot(2000, 12);
  std::vector<RayGpu> gpu;
  for (const RefRay& r : rays) gpu.push_back(toGpu(r));
  const std::vector<HitGpu> exact = traceClosest(sharedContext(), analytic, gpu, AccelKind::Bvh);
  for (double tol : {0.02, 0.005}) {
    const Scene mesh = teapotScene("subdivision", ", \"tolerance\": " + std::to_string(tol));
    REQUIRE(mesh.objects[0].type == ObjectType::Mesh);
    const std::vector<HitGpu> flat = traceClosest(sharedContext(), mesh, gpu, AccelKind::Bvh);
    int both = 0, steep = 0, beyond = 0, disagree = 0;
    double worst = 0;
    for (std::size_t i = 0; i < rays.size(); ++i) {
      const bool a = exact[i].prim >= 0, b = flat[i].prim >= 0;
      // Hit or miss may differ only within the tolerance of a silhouette:
      // rays beside it by a little more than the tolerance must not.
      if (a != b) {
        disagree += clearCut(analytic.objects[0], rays[i], 1.5 * tol);
        continue;
      }
      if (!a) continue;
      ++both;
      // A triangle point lies within tol of the surface; along a ray meeting
      // the surface at angle theta to its normal that is tol / cos(theta)
      // (to first order: away from grazing, where curvature adds to it).
      const double cosine = incidence(analytic.objects[0], exact[i], rays[i]);
      if (cosine < 0.2) continue;
      ++steep;
      const double along = std::fabs(double(flat[i].t) - exact[i].t) * length(rays[i].d);
      if (along * cosine <= 1.05 * tol + 1e-4) worst = std::max(worst, along * cosine / tol);
      // (Unless the ray passes within the tolerance of another part's
      // silhouette: rays beside it then meet the surface at other depths.)
      beyond += along * cosine > 1.05 * tol + 1e-4 && clearCut(analytic.objects[0], rays[i], 1.5 * tol, 5);
    }
    INFO("tolerance " << tol << ": " << both << " both hit, " << steep << " away from grazing, worst "
                      << worst << " tolerances (within it), " << beyond << " beyond, " << disagree
                      << " clear-cut hit/miss disagreements");
    CHECK(steep > 1000);
    CHECK(beyond == 0);
    CHECK(disagree == 0);
    // The tolerance is used, not vastly over-met: the worst error is a good part of it.
    CHECK(worst > 0.2);
  }
}
