// The wavefront renderer against closed-form optics and against the recursive
// double-precision reference tracer (tests/support/reference_shading.h).
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <functional>
#include <string>

#include "kernels/shared/ray_gpu.h"
#include "render/renderer.h"
#include "scene_format/scene_loader.h"
#include "support/reference_shading.h"
#include "support/shared_context.h"

using namespace prism;
using namespace prism::test;

namespace {

RenderResult renderScene(const Scene& scene, const RenderOptions& options) {
  return sharedRenderer().render(scene, options);
}

Vec3 pixel(const RenderResult& r, int i, int j) {
  const float* p = &r.rgba[4 * (static_cast<size_t>(j) * r.width + i)];
  return {p[0], p[1], p[2]};
}

double maxDiff(const Vec3& a, const Vec3& b) {
  return std::max({std::fabs(a.x - b.x), std::fabs(a.y - b.y), std::fabs(a.z - b.z)});
}

// One unit sphere, one light, no secondary rays: everything in closed form.
const char* kLitSphere = R"({
  "camera": {"position": [0, 0, 6], "look_at": [0, 0, 0], "fov": 30},
  "film": {"width": 64, "height": 48},
  "render": {"max_depth": 0, "ambient": [0.1, 0.12, 0.14], "background": [0, 0, 0]},
  "materials": {"m": {"ambient": [0.5, 0.6, 0.7], "diffuse": [0.6, 0.5, 0.4], "specular": [0.3, 0.3, 0.3],
                      "shininess": 20}},
  "lights": [{"position": [4, 5, 6], "color": [1, 0.9, 0.8], "intensity": 1.5}],
  "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "m"}]
})";

// Two facing mirrors at z = -1 and z = 1, k_refl 0.5 and a little diffuse, the
// camera between them looking at the far one, max depth 10, no weight cut-off,
// lit by `lights` (the inside of a JSON array).
std::string litMirrors(const std::string& lights) {
  return R"({
    "camera": {"position": [0, 0, 0], "look_at": [0, 0, -1], "fov": 20},
    "film": {"width": 16, "height": 12},
    "render": {"max_depth": 10, "min_weight": 0, "background": [0, 0, 0]},
    "materials": {"mirror": {"reflect": 0.5, "diffuse": [0.1, 0.1, 0.1]}},
    "lights": [)" + lights + R"(],
    "objects": [{"type": "plane", "point": [0, 0, -1], "normal": [0, 0, 1], "material": "mirror"},
                {"type": "plane", "point": [0, 0, 1], "normal": [0, 0, -1], "material": "mirror"}]
  })";
}

}  // namespace

TEST_CASE("a lit sphere's pixels equal the closed-form Phong, Blinn and Cook-Torrance values", "[render][shading]") {
  // Each variant replaces the material's "shininess" key; its highlight in closed form.
  struct Variant {
    const char* keys;
    std::function<double(const Material&, const Vec3& n, const Vec3& l, const Vec3& v)> highlight;
  };
  auto power = [](double base, double n) { return base > 0 ? std::pow(base, n) : 0.0; };
  auto cookTorrance = [](const Material& m, const Vec3& n, const Vec3& l, const Vec3& v) {
    return referenceCookTorrance(n, l, v, m.roughness, static_cast<int>(m.distribution), m.ior);
  };
  const Variant variants[] = {
      {R"("shininess": 20, "model": "phong")",  // (R·V)^n
       [&](const Material& m, const Vec3& n, const Vec3& l, const Vec3& v) {
         return power(dot(n * (2 * dot(n, l)) - l, v), m.shininess);
       }},
      {R"("shininess": 20, "model": "blinn")",  // (N·H)^n
       [&](const Material& m, const Vec3& n, const Vec3& l, const Vec3& v) {
         return power(dot(n, normalize(l + v)), m.shininess);
       }},
      {R"("model": "cook-torrance", "roughness": 0.25, "distribution": "beckmann")", cookTorrance},
      {R"("model": "cook-torrance", "roughness": 0.25, "distribution": "ggx")", cookTorrance}};
  for (const Variant& variant : variants) {
    std::string json = kLitSphere;
    json.replace(json.find("\"shininess\": 20"), 15, variant.keys);
    Scene scene = parseScene(json, "lit_sphere.json");
    RenderOptions opt = RenderOptions::fromScene(scene);
    RenderResult r = renderScene(scene, opt);

    const Material& m = scene.materials[1];
    const Light& light = scene.lights[0];
    int compared = 0, highlighted = 0;
    for (int j = 0; j < opt.height; j += 2)
      for (int i = 0; i < opt.width; i += 2) {
        // Closed form: camera ray through the pixel centre, ray-sphere root,
        // I = ka Ia + Il (kd N·L + ks highlight).
        RefRay ray = referencePrimaryRay(scene, opt, i, j);
        double b = dot(ray.o, ray.d), c = dot(ray.o, ray.o) - 1, disc = b * b - c;
        if (disc < 0.01) continue;  // missed, or too near the silhouette to call
        double t = -b - std::sqrt(disc);
        Vec3 p = ray.o + ray.d * t, n = normalize(p), v = -ray.d;
        Vec3 l = normalize(light.position - p);
        Vec3 expected = mul(m.ambient, scene.render.ambient);
        double n_dot_l = dot(n, l);
        if (n_dot_l > 0) {
          const double spec = variant.highlight(m, n, l, v);
          expected = expected + mul(light.color * light.intensity, m.diffuse * n_dot_l + m.specular * spec);
          highlighted += spec > 0.05;
        }
        INFO(variant.keys << ": pixel (" << i << ", " << j << ")");
        CHECK(maxDiff(pixel(r, i, j), expected) < 1e-3);
        CHECK(r.primid[static_cast<size_t>(j) * opt.width + i] == 0);
        CHECK(std::fabs(r.depth[static_cast<size_t>(j) * opt.width + i] - t) < 1e-4);
        ++compared;
      }
    CHECK(compared > 100);
    CHECK(highlighted > 3);  // the highlight is there to be compared
  }
}

TEST_CASE("a point in shadow gets only ambient light and behind a k_trans 0.5 sphere half the light",
          "[render][shadow]") {
  // The camera looks straight down at a floor; a sphere hangs above it, and a
  // light off to the side casts the sphere's shadow where the camera sees it.
  auto json = [](double transmit) {
    return std::string(R"({
      "camera": {"position": [0, 10, 0], "look_at": [0, 0, 0], "up": [0, 0, -1], "fov": 40},
      "film": {"width": 33, "height": 33},
      "render": {"max_depth": 0, "ambient": [0.2, 0.2, 0.2]},
      "materials": {"floor": {"diffuse": [0.5, 0.5, 0.5], "ambient": [1, 1, 1]},
                    "ball": {"diffuse": [0.1, 0.1, 0.1], "transmit": )") +
           std::to_string(transmit) + R"(}},
      "lights": [{"position": [20, 45, 0], "intensity": 1}],
      "objects": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "floor"},
                  {"type": "sphere", "center": [0, 5, 0], "radius": 0.5, "material": "ball"}]
    })";
  };
  // Find, in double, a pixel whose camera ray meets the floor at a point well
  // inside the ball's shadow.
  Scene opaque = parseScene(json(0), "shadow.json");
  RenderOptions opt = RenderOptions::fromScene(opaque);
  int si = -1, sj = -1;
  for (int j = 0; j < opt.height && si < 0; ++j)
    for (int i = 0; i < opt.width && si < 0; ++i) {
      RefRay ray = referencePrimaryRay(opaque, opt, i, j);
      RefHit hit = referenceClosest(opaque, ray);
      if (hit.object != 0) continue;
      Vec3 p = ray.o + ray.d * hit.t;
      RefRay feeler{p + Vec3{0, 1e-4, 0}, normalize(opaque.lights[0].position - p), 0, 1e9};
      auto blocked = referenceIntersect(opaque.objects[1], feeler);
      // Keep a margin from the shadow's edge.
      if (blocked && referenceIntersect(scaledAboutCentre(opaque.objects[1], 0.9), feeler)) {
        si = i;
        sj = j;
      }
    }
  REQUIRE(si >= 0);
  const int li = 1, lj = 1;  // near a corner: floor, lit, far from the shadow

  Vec3 ambient = mul(opaque.materials[1].ambient, opaque.render.ambient);
  auto direct = [&](const Scene& s, int i, int j) {
    RefRay ray = referencePrimaryRay(s, opt, i, j);
    RefHit hit = referenceClosest(s, ray);
    Vec3 p = ray.o + ray.d * hit.t;
    Vec3 l = normalize(s.lights[0].position - p);
    return s.materials[1].diffuse * dot(Vec3{0, 1, 0}, l);
  };

  RenderResult r0 = renderScene(opaque, opt);
  CHECK(maxDiff(pixel(r0, si, sj), ambient) < 1e-5);
  CHECK(maxDiff(pixel(r0, li, lj), ambient + direct(opaque, li, lj)) < 1e-4);

  Scene half = parseScene(json(0.5), "shadow_half.json");
  RenderResult r1 = renderScene(half, opt);
  CHECK(maxDiff(pixel(r1, si, sj), ambient + direct(half, si, sj) * 0.5) < 1e-4);
  CHECK(maxDiff(pixel(r1, li, lj), ambient + direct(half, li, lj)) < 1e-4);
}

TEST_CASE("adaptive depth control cuts rays whose weight falls under min_weight", "[render][depth]") {
  // Two parallel mirrors, k_refl 0.5, camera between them looking at one: every
  // primary ray bounces forever, its d-th reflection carrying weight 0.5^d.
  const char* json = R"({
    "camera": {"position": [0, 0, 0], "look_at": [0, 0, -1], "fov": 20},
    "film": {"width": 16, "height": 12},
    "render": {"max_depth": 10, "min_weight": 0, "ambient": [1, 1, 1], "background": [0, 0, 0]},
    "materials": {"mirror": {"reflect": 0.5, "ambient": [0.2, 0.2, 0.2], "diffuse": [0, 0, 0]}},
    "objects": [{"type": "plane", "point": [0, 0, -1], "normal": [0, 0, 1], "material": "mirror"},
                {"type": "plane", "point": [0, 0, 1], "normal": [0, 0, -1], "material": "mirror"}]
  })";
  Scene scene = parseScene(json, "mirrors.json");
  RenderOptions opt = RenderOptions::fromScene(scene);
  const std::uint64_t pixels = static_cast<std::uint64_t>(opt.width) * opt.height;

  RenderResult full = renderScene(scene, opt);
  for (int d = 0; d <= 10; ++d) CHECK(full.stats.rays_per_depth[d] == pixels);
  CHECK(full.stats.rays_per_depth[11] == 0);
  CHECK(full.stats.rays_by_kind[RAY_KIND_REFLECTED] == 10 * pixels);
  // Colour: the geometric series 0.2 * sum_{d=0..10} 0.5^d.
  double series = 0.2 * (1 - std::pow(0.5, 11)) / 0.5;
  CHECK(std::fabs(pixel(full, 3, 7).x - series) < 1e-5);

  opt.min_weight = 0.1;  // 0.5^3 = 0.125 passes, 0.5^4 = 0.0625 does not
  RenderResult cut = renderScene(scene, opt);
  for (int d = 0; d <= 3; ++d) CHECK(cut.stats.rays_per_depth[d] == pixels);
  for (int d = 4; d <= 11; ++d) CHECK(cut.stats.rays_per_depth[d] == 0);
  CHECK(std::fabs(pixel(cut, 3, 7).x - 0.2 * (1 - std::pow(0.5, 4)) / 0.5) < 1e-5);
}

TEST_CASE("every hit sends one feeler per light in front of it, counted at every depth", "[render][depth]") {
  // The two mirrors again, camera between them, so a primary ray hits the far
  // mirror A (z = -1, depths 0, 2, ..., 10) and the near one B (z = 1, depths
  // 1, ..., 9) in turn: 6 + 5 hits down to max_depth 10. Point lights P1, P2 at
  // z = 0 face both mirrors; P3 at z = -2 is behind A and faces B only (A hides
  // it, but its feeler is still sent). A quad light far to the side at z = 0,
  // 3 samples, faces both: shade traces the point lights' feelers itself and
  // spawn_shadows the quad's, and the statistics must count both kinds,
  // including at the last depth, whose children are never traced.
  Scene scene = parseScene(litMirrors(R"({"position": [0.2, 0.3, 0]}, {"position": [-0.4, 0.1, 0]},
      {"position": [0, 0, -2]}, {"type": "quad", "corner": [20, -1, 0], "edge1": [1, 0, 0], "edge2": [0, 2, 0],
      "samples": 3})"),
                           "lit_mirrors.json");
  RenderOptions opt = RenderOptions::fromScene(scene);
  const std::uint64_t pixels = static_cast<std::uint64_t>(opt.width) * opt.height;
  for (FirstHitMode first_hit : {FirstHitMode::Trace, FirstHitMode::ZBuffer}) {
    opt.first_hit = first_hit;
    opt.min_weight = 0;
    RenderResult full = renderScene(scene, opt);
    CHECK(full.stats.rays_by_kind[RAY_KIND_REFLECTED] == 10 * pixels);
    // Point lights: 2 x 11 hits + 5 hits on B; the quad: 3 x 11 hits.
    CHECK(full.stats.rays_by_kind[RAY_KIND_SHADOW] == (2 * 11 + 5 + 3 * 11) * pixels);

    opt.min_weight = 0.1;  // hits at depths 0 to 3 only: A twice, B twice
    RenderResult cut = renderScene(scene, opt);
    CHECK(cut.stats.rays_by_kind[RAY_KIND_SHADOW] == (2 * 4 + 2 + 3 * 4) * pixels);
  }
}

TEST_CASE("hundreds of lights of both kinds: every feeler sent and counted, every pixel finite", "[render][depth]") {
  // The two mirrors with 600 point lights and 300 two-sample quads, all at
  // z = 0 and so in front of both mirrors (the quads far to the side, out of
  // the rays' way): each of a pixel's 11 hits sends 600 + 2 x 300 feelers.
  // Point lights once met a 512-light buffer limit; area feelers go in runs of
  // Renderer::kShadowSlots, here several per slice.
  std::string lights;
  for (int i = 0; i < 600; ++i)
    lights += std::string(lights.empty() ? "" : ", ") + R"({"position": [)" + std::to_string(-0.6 + 0.002 * i) +
              R"(, 0.3, 0], "intensity": 0.001})";
  for (int i = 0; i < 300; ++i)
    lights += R"(, {"type": "quad", "corner": [)" + std::to_string(20 + 0.01 * i) +
              R"(, -1, 0], "edge1": [0.005, 0, 0], "edge2": [0, 2, 0], "samples": 2, "intensity": 0.01})";
  Scene scene = parseScene(litMirrors(lights), "many_lights.json");
  RenderOptions opt = RenderOptions::fromScene(scene);
  const std::uint64_t pixels = static_cast<std::uint64_t>(opt.width) * opt.height;
  RenderResult r = renderScene(scene, opt);
  CHECK(r.stats.rays_by_kind[RAY_KIND_SHADOW] == (600 + 2 * 300) * 11 * pixels);
  std::size_t bad = 0;
  for (float x : r.rgba) bad += !std::isfinite(x);
  CHECK(bad == 0);
}

TEST_CASE("auto traces a handful of primitives by brute force, more through the BVH, to the same image",
          "[render][accel]") {
  auto scene_with = [](int spheres) {
    std::string objects = R"({"type": "plane", "point": [0, -1, 0], "normal": [0, 1, 0], "material": "m"})";
    for (int i = 0; i < spheres; ++i)
      objects += R"(, {"type": "sphere", "center": [)" + std::to_string(i - 1.5) + R"(, 0, 0], "radius": 0.4,
                     "material": "m"})";
    return parseScene(R"({"camera": {"position": [0, 1, 6], "look_at": [0, 0, 0], "fov": 40},
                          "film": {"width": 32, "height": 24}, "render": {"max_depth": 3},
                          "materials": {"m": {"diffuse": [0.5, 0.6, 0.7], "reflect": 0.3}},
                          "lights": [{"position": [3, 5, 4]}], "objects": [)" + objects + "]}",
                      "auto.json");
  };
  for (int spheres : {3, 4}) {
    Scene scene = scene_with(spheres);
    RenderOptions opt = RenderOptions::fromScene(scene);
    CHECK(opt.accel == AccelKind::Auto);  // the scene format's default
    RenderResult chosen = renderScene(scene, opt);
    const std::size_t primitives = static_cast<std::size_t>(spheres) + 1;
    const AccelKind expected = primitives <= kAutoBruteForcePrimitives ? AccelKind::None : AccelKind::Bvh;
    CHECK(chosen.stats.accel == expected);
    opt.accel = expected == AccelKind::None ? AccelKind::Bvh : AccelKind::None;
    RenderResult other = renderScene(scene, opt);
    CHECK(other.stats.accel == opt.accel);
    CHECK(std::memcmp(chosen.rgba.data(), other.rgba.data(), chosen.rgba.size() * sizeof(float)) == 0);
  }
}

TEST_CASE("the wavefront image matches the recursive double-precision tracer", "[render][reference]") {
  // Mirror and glass spheres in a box: reflection, refraction with total internal
  // reflection, shadows through glass, several bounces.
  const char* json = R"({
    "camera": {"position": [0, 1, 5.5], "look_at": [0, 0.6, 0], "fov": 50},
    "film": {"width": 48, "height": 36},
    "render": {"max_depth": 6, "min_weight": 0.01, "ambient": [0.1, 0.1, 0.1], "background": [0.2, 0.3, 0.5]},
    "materials": {
      "white": {"diffuse": [0.7, 0.7, 0.7], "specular": [0.2, 0.2, 0.2], "shininess": 10},
      "red": {"diffuse": [0.7, 0.1, 0.1]},
      "mirror": {"diffuse": [0.05, 0.05, 0.05], "reflect": 0.85, "specular": [0.5, 0.5, 0.5], "shininess": 60},
      "glass": {"diffuse": [0, 0, 0], "reflect": 0.08, "transmit": 0.9, "ior": 1.5,
                "specular": [0.6, 0.6, 0.6], "shininess": 100, "model": "blinn"}
    },
    "lights": [{"position": [1, 3.5, 2], "intensity": 0.8}, {"position": [-2, 3, 3], "intensity": 0.4}],
    "objects": [
      {"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "white"},
      {"type": "box", "min": [-2.5, 0, -2.2], "max": [2.5, 3, -2], "material": "red"},
      {"type": "sphere", "center": [-0.9, 0.8, -0.5], "radius": 0.8, "material": "mirror"},
      {"type": "sphere", "center": [0.9, 0.7, 0.6], "radius": 0.7, "material": "glass"},
      {"type": "box", "min": [-0.3, 0, 1.2], "max": [0.3, 0.5, 1.8], "material": "red",
       "transform": {"rotate": {"axis": [0, 1, 0], "angle": 30}}}
    ]
  })";
  Scene scene = parseScene(json, "reference.json");
  RenderOptions opt = RenderOptions::fromScene(scene);
  RenderResult r = renderScene(scene, opt);
  int agree = 0, total = 0;
  for (int j = 0; j < opt.height; ++j)
    for (int i = 0; i < opt.width; ++i) {
      Vec3 expected = referenceRadiance(scene, opt, referencePrimaryRay(scene, opt, i, j), 1.0, 0);
      ++total;
      if (maxDiff(pixel(r, i, j), expected) < 1e-3) ++agree;
    }
  INFO(agree << " of " << total << " pixels agree within 1e-3");
  // Pixels whose rays graze a silhouette may branch differently in float and double.
  CHECK(agree >= total * 97 / 100);
}

TEST_CASE("camera conventions: pixel centres with i to the right and j down and depth along the unit ray", "[render][camera]") {
  // A wall at z = -4 facing the camera; a small sphere up and to the left.
  const char* json = R"({
    "camera": {"position": [0, 0, 0], "look_at": [0, 0, -1], "fov": 60},
    "film": {"width": 40, "height": 30},
    "objects": [{"type": "plane", "point": [0, 0, -4], "normal": [0, 0, 1]},
                {"type": "sphere", "center": [-1.2, 0.9, -3], "radius": 0.3}]
  })";
  Scene scene = parseScene(json, "camera.json");
  RenderOptions opt = RenderOptions::fromScene(scene);
  RenderResult r = renderScene(scene, opt);
  const double tan_half = std::tan(30.0 * M_PI / 180);
  for (int j = 0; j < opt.height; ++j)
    for (int i = 0; i < opt.width; ++i) {
      size_t k = static_cast<size_t>(j) * opt.width + i;
      if (r.primid[k] != 0) continue;
      // Ray through (i + 0.5, j + 0.5): direction (x, y, -1) with x, y on the film.
      double x = (2 * (i + 0.5) / opt.width - 1) * tan_half * opt.width / opt.height;
      double y = (1 - 2 * (j + 0.5) / opt.height) * tan_half;
      double expected = 4 * std::sqrt(x * x + y * y + 1);
      CHECK(std::fabs(r.depth[k] - expected) < 1e-5 * expected);
    }
  // The sphere (up and left) shows in the top-left quadrant only.
  int sphere_pixels = 0;
  for (int j = 0; j < opt.height; ++j)
    for (int i = 0; i < opt.width; ++i)
      if (r.primid[static_cast<size_t>(j) * opt.width + i] == 1) {
        ++sphere_pixels;
        CHECK(i < opt.width / 2);
        CHECK(j < opt.height / 2);
      }
  CHECK(sphere_pixels > 4);
}

TEST_CASE("the same scene and seed give the same image bit for bit", "[render][determinism]") {
  Scene scene = loadSceneFile(PRISM_SOURCE_DIR "/scenes/whitted.json");
  RenderOptions opt = RenderOptions::fromScene(scene);
  opt.width = 80;
  opt.height = 45;
  opt.spp = 3;
  opt.seed = 7;
  RenderResult a = renderScene(scene, opt);
  RenderResult b = renderScene(scene, opt);
  REQUIRE(a.rgba.size() == b.rgba.size());
  CHECK(std::memcmp(a.rgba.data(), b.rgba.data(), a.rgba.size() * sizeof(float)) == 0);
  CHECK(a.stats.totalRays() == b.stats.totalRays());
  opt.seed = 8;
  RenderResult c = renderScene(scene, opt);
  CHECK(std::memcmp(a.rgba.data(), c.rgba.data(), a.rgba.size() * sizeof(float)) != 0);
}

// The first launches' wait (a driver compiling a kernel for its launch) is
// counted once per kernel: a render whose kernels have all run before reports
// none, and what a render reports lies within its tracing time.
TEST_CASE("first launches are counted once per kernel, inside the tracing time", "[render][stats]") {
  const Scene scene = parseScene(R"({"camera": {"position": [0, 0, 5], "look_at": [0, 0, 0]},
    "film": {"width": 16, "height": 12}, "lights": [{"position": [3, 3, 3]}],
    "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "m"}],
    "materials": {"m": {"diffuse": 0.5, "reflect": 0.3}}})",
                                 "stats.json");
  const RenderOptions options = RenderOptions::fromScene(scene);
  const RenderStats first = sharedRenderer().render(scene, options).stats;
  CHECK(first.first_launch_seconds >= 0.0);
  CHECK(first.first_launch_seconds <= first.seconds - first.setup_seconds);
  const RenderStats again = sharedRenderer().render(scene, options).stats;
  CHECK(again.first_launch_seconds == 0.0);
}
