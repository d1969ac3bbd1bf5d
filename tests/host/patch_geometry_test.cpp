// Bezier patches on the host: the .bpt reader on the teapot and on broken
// files, the de Casteljau cuts against direct evaluation, the flatness bound
// as a true bound, and successive subdivision's promises — every triangle
// within the tolerance of the surface, no cracks where patches meet, and the
// triangle count growing as the tolerance falls the way a C2 surface must
// (error ~ h^2, so count ~ 1 / tolerance).
#include <catch2/catch.hpp>

#include <cmath>
#include <map>
#include <random>
#include <set>
#include <tuple>

#include "scene/patches/bpt_file.h"
#include "scene/patches/patch_subdivision.h"
#include "support/test_data.h"

using namespace prism;

namespace {

const std::vector<BezierPatch>& teapot() {
  static const std::vector<BezierPatch> patches = readBptFile(prism_test::testDataDir() + "/patches/teapot.bpt");
  return patches;
}

std::string bptError(const std::string& text) {
  try {
    parseBpt(text, "f.bpt");
  } catch (const PatchFileError& e) {
    return e.what();
  }
  return "";
}

std::string points(int n) {
  std::string s;
  for (int i = 0; i < n; ++i) s += std::to_string(i) + " 0.5 " + std::to_string(i % 4) + "\n";
  return s;
}

Vec3 meshVertex(const TriangleMesh& m, std::uint32_t i) {
  return {m.positions[3 * i], m.positions[3 * i + 1], m.positions[3 * i + 2]};
}

}  // namespace

TEST_CASE("the teapot's .bpt file reads as 32 bicubic patches, and broken files are refused with the line",
          "[patches][host]") {
  REQUIRE(teapot().size() == 32);
  // Its first patch starts at the rim: (1.4, 0, 2.4), as the file says.
  CHECK(teapot()[0].at(0, 0) == Vec3{1.4, 0.0, 2.4});
  CHECK(bptError("1\n3 3\n" + points(16)).empty());
  CHECK_THAT(bptError("1\n2 3\n" + points(12)), Catch::Contains("f.bpt:2") && Catch::Contains("only bicubic"));
  CHECK_THAT(bptError("2\n3 3\n" + points(16)), Catch::Contains("the file ends"));
  CHECK_THAT(bptError("1\n3 3\n" + points(15) + "1 nan 2\n"), Catch::Contains("f.bpt:18") && Catch::Contains("finite"));
  CHECK_THAT(bptError("1\n3 3\n" + points(15) + "1 2e300 2\n"), Catch::Contains("1e15"));
  CHECK_THAT(bptError("1\n3 3\n" + points(16) + "7\n"), Catch::Contains("more after the 1 patches"));
  CHECK_THAT(bptError("0\n"), Catch::Contains("number of patches"));
  CHECK_THAT(bptError("99999999999\n"), Catch::Contains("number of patches"));
  CHECK_THAT(bptError(""), Catch::Contains("the file ends"));
  CHECK_THROWS_WITH(readBptFile("/dev/zero"), Catch::Contains("not a regular file"));
  CHECK_THROWS_WITH(readBptFile("/nonexistent.bpt"), Catch::Contains("no such file"));
}

TEST_CASE("a cut-out piece of a patch is the patch over that rectangle, and halves share their cut",
          "[patches][host]") {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u01(0, 1);
  for (const BezierPatch& patch : teapot()) {
    const double u0 = 0.5 * u01(rng), u1 = u0 + 0.5 * u01(rng) + 1e-3, v0 = 0.5 * u01(rng),
                 v1 = v0 + 0.5 * u01(rng) + 1e-3;
    const BezierPatch piece = subPatch(patch, u0, u1, v0, v1);
    for (int k = 0; k < 10; ++k) {
      const double s = u01(rng), t = u01(rng);
      const PatchPoint a = evaluate(piece, s, t), b = evaluate(patch, u0 + s * (u1 - u0), v0 + t * (v1 - v0));
      CHECK(length(a.p - b.p) < 1e-12);
      // The chain rule: the piece's derivatives are the patch's times the interval.
      CHECK(length(a.du - b.du * (u1 - u0)) < 1e-11);
      CHECK(length(a.dv - b.dv * (v1 - v0)) < 1e-11);
    }
    for (bool along_u : {true, false}) {
      BezierPatch first, second;
      splitPatch(patch, along_u, first, second);
      for (int k = 0; k < 4; ++k) CHECK((along_u ? first.at(3, k) == second.at(0, k) : first.at(k, 3) == second.at(k, 0)));
      const PatchPoint a = evaluate(second, 0.25, 0.75);
      const PatchPoint b = evaluate(patch, along_u ? 0.625 : 0.25, along_u ? 0.75 : 0.875);
      CHECK(length(a.p - b.p) < 1e-12);
    }
  }
}

TEST_CASE("the flatness bound bounds the distance between a patch and its two corner triangles", "[patches][host]") {
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> u01(0, 1);
  int tight = 0;
  for (const BezierPatch& patch : teapot()) {
    const double bound = flatnessBound(patch);
    double worst = 0;
    for (int k = 0; k < 400; ++k) {
      const double u = u01(rng), v = u01(rng);
      // The triangles (p00, p30, p33) for u >= v and (p00, p33, p03) above, at (u, v).
      const Vec3 &a = patch.at(0, 0), &b = patch.at(3, 0), &c = patch.at(0, 3), &d = patch.at(3, 3);
      const Vec3 flat = u >= v ? a + (b - a) * u + (d - b) * v : a + (c - a) * v + (d - c) * u;
      worst = std::max(worst, length(evaluate(patch, u, v).p - flat));
    }
    CHECK(worst <= bound * (1 + 1e-12));
    tight += worst > bound / 8;  // and the bound is not vacuous
  }
  CHECK(tight >= 16);
}

TEST_CASE("successive subdivision keeps every triangle within the tolerance of the teapot, without cracks",
          "[patches][host]") {
  const double size = patchSetSize(teapot());
  std::size_t previous = 0;
  for (double rel : {4e-3, 2e-3, 1e-3, 5e-4}) {
    const double tol = rel * size;
    const std::vector<PatchGrid> plan = planSubdivision(teapot(), tol, 1 << 24);
    const auto mesh = tessellatePatches(teapot(), plan, "teapot");
    INFO("tolerance " << tol << ": " << mesh->triangleCount() << " triangles");
    // Within the tolerance: points of each cell's triangles against the surface at the same (u, v).
    double worst = 0;
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> u01(0, 1);
    for (std::size_t k = 0; k < teapot().size(); ++k)
      for (std::size_t a = 0; a + 1 < plan[k].u.size(); ++a)
        for (std::size_t b = 0; b + 1 < plan[k].v.size(); ++b) {
          const double u0 = plan[k].u[a], u1 = plan[k].u[a + 1], v0 = plan[k].v[b], v1 = plan[k].v[b + 1];
          const Vec3 p00 = evaluate(teapot()[k], u0, v0).p, p10 = evaluate(teapot()[k], u1, v0).p,
                     p01 = evaluate(teapot()[k], u0, v1).p, p11 = evaluate(teapot()[k], u1, v1).p;
          for (int s = 0; s < 3; ++s) {
            const double x = u01(rng), y = u01(rng);
            const Vec3 flat = x >= y ? p00 + (p10 - p00) * x + (p11 - p10) * y : p00 + (p01 - p00) * y + (p11 - p01) * x;
            worst = std::max(worst, length(evaluate(teapot()[k], u0 + x * (u1 - u0), v0 + y * (v1 - v0)).p - flat));
          }
        }
    CHECK(worst <= tol);
    // No cracks: after welding equal positions, the edges only one triangle
    // uses are exactly the segments of the patch set's own boundary curves
    // (curves no other patch shares). Where two patches met with different
    // cuts, the finer side's extra segments would be open edges too.
    std::map<std::tuple<float, float, float>, std::uint32_t> weld;
    std::vector<std::uint32_t> id(mesh->vertexCount());
    for (std::uint32_t i = 0; i < id.size(); ++i) {
      const auto key = std::make_tuple(mesh->positions[3 * i], mesh->positions[3 * i + 1], mesh->positions[3 * i + 2]);
      id[i] = weld.emplace(key, static_cast<std::uint32_t>(weld.size())).first->second;
    }
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> uses;
    for (std::size_t t = 0; t < mesh->triangleCount(); ++t)
      for (int e = 0; e < 3; ++e) {
        const std::uint32_t a = id[mesh->indices[3 * t + e]], b = id[mesh->indices[3 * t + (e + 1) % 3]];
        if (a != b) ++uses[std::minmax(a, b)];
      }
    std::size_t open_edges = 0;
    for (const auto& [edge, n] : uses) open_edges += n == 1;
    std::map<std::vector<double>, int> curve_uses;  // a curve either way round
    auto curveKey = [](const BezierPatch& p, bool along_u, int side) {
      std::vector<double> fwd, back;
      for (int k = 0; k < 4; ++k) {
        const Vec3 c = along_u ? p.at(k, side ? 3 : 0) : p.at(side ? 3 : 0, k);
        const Vec3 r = along_u ? p.at(3 - k, side ? 3 : 0) : p.at(side ? 3 : 0, 3 - k);
        fwd.insert(fwd.end(), {c.x, c.y, c.z});
        back.insert(back.end(), {r.x, r.y, r.z});
      }
      return std::min(fwd, back);
    };
    for (const BezierPatch& p : teapot())
      for (bool along_u : {true, false})
        for (int side : {0, 1}) ++curve_uses[curveKey(p, along_u, side)];
    std::size_t boundary_segments = 0;
    for (std::size_t k = 0; k < teapot().size(); ++k)
      for (bool along_u : {true, false})
        for (int side : {0, 1}) {
          const std::vector<double> key = curveKey(teapot()[k], along_u, side);
          const bool collapsed = std::equal(key.begin() + 3, key.end(), key.begin(), key.end() - 3);
          if (curve_uses[key] == 1 && !collapsed) boundary_segments += (along_u ? plan[k].u : plan[k].v).size() - 1;
        }
    INFO(open_edges << " open edges, " << boundary_segments << " segments of boundary curves");
    CHECK(open_edges == boundary_segments);
    // Halving the tolerance about doubles the triangles (error ~ h^2).
    if (previous) {
      const double growth = double(mesh->triangleCount()) / previous;
      INFO("growth " << growth);
      CHECK(growth > 1.3);
      CHECK(growth < 3.0);
    }
    previous = mesh->triangleCount();
  }
}

TEST_CASE("a tolerance that needs too many triangles is refused before they are made", "[patches][host]") {
  CHECK_THROWS_AS(planSubdivision(teapot(), 1e-6 * patchSetSize(teapot()), 10000), std::length_error);
}
