// Anti-aliasing and the first-hit pass inside the renderer: ray counts per mode
// (quincunx's (W+1)(H+1) + W*H, adaptive's corners on a flat image), constant
// images resolving to themselves under every filter, edge coverage measured
// through alpha against the exact area, bit-for-bit repeatability of every mode,
// Z-buffer against traced primary rays on real meshes, the settings' route
// from the scene file and the C API, and the film's memory check.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "kernels/shared/ray_gpu.h"
#include "prism.h"
#include "render/renderer.h"
#include "scene_format/scene_loader.h"
#include "support/square_coverage.h"
#include "support/shared_context.h"
#include "support/test_data.h"

using namespace prism;
using namespace prism::test;

namespace {

RenderOptions withMode(RenderOptions o, AaMode mode, int spp = 1, FilterKind filter = FilterKind::Box) {
  o.aa = mode;
  o.spp = spp;
  o.filter = filter;
  return o;
}

// A plane filling the view, lit by the ambient term alone: every sample has the
// same colour, so every mode and filter must give that colour back.
const char* kFlat = R"({
  "camera": {"position": [0, 0, 5], "look_at": [0, 0, 0], "fov": 30},
  "film": {"width": 19, "height": 13},
  "render": {"max_depth": 0, "ambient": [0.25, 0.5, 0.75]},
  "materials": {"m": {"ambient": [0.8, 0.6, 0.4], "diffuse": 0}},
  "objects": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 0, 1], "material": "m"}]
})";

// Camera at the origin looking down -z with a 90-degree field of view on a square
// film: film point (fx, fy) sees (2 fx / W - 1, 1 - 2 fy / H, -1). A triangle in
// the plane z = -1 whose edge is the line through film point q with normal n (it
// covers n.(p - q) >= 0) and reaches far beyond the film on that side.
std::string edgeScene(int size, double qx, double qy, double angle) {
  const double nx = std::cos(angle), ny = std::sin(angle);
  const double tx = -ny, ty = nx, far = 40.0 * size;
  const double film[3][2] = {{qx + far * tx, qy + far * ty}, {qx - far * tx, qy - far * ty},
                             {qx + far * nx, qy + far * ny}};
  std::string v[3];
  for (int k = 0; k < 3; ++k) {
    const double X = 2 * film[k][0] / size - 1, Y = 1 - 2 * film[k][1] / size;
    v[k] = "[" + std::to_string(X) + ", " + std::to_string(Y) + ", -1]";
  }
  const std::string s = std::to_string(size);
  return R"({"camera": {"position": [0, 0, 0], "look_at": [0, 0, -1], "fov": 90},
             "film": {"width": )" +
         s + R"(, "height": )" + s + R"(},
             "render": {"max_depth": 0, "background": [0, 0, 0]},
             "objects": [{"type": "triangle", "vertices": [)" +
         v[0] + ", " + v[1] + ", " + v[2] + "]}]}";
}

// Area of the pixel [i, i+1] x [j, j+1] on the side n.(p - q) >= 0, by clipping.
double pixelCoverage(int i, int j, double qx, double qy, double nx, double ny) {
  return prism::test::squareCoverage(i, j, qx, qy, nx, ny);
}

bool sameBits(const std::vector<float>& a, const std::vector<float>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

}  // namespace

TEST_CASE("quincunx costs (W+1)(H+1) + W*H primary rays and its AOVs are the pixel centres'", "[render][aa]") {
  Scene scene = loadSceneFile(PRISM_SOURCE_DIR "/scenes/whitted.json");
  RenderOptions opt = RenderOptions::fromScene(scene);
  opt.width = 37;
  opt.height = 21;
  const std::uint64_t w = opt.width, h = opt.height;
  RenderResult none = sharedRenderer().render(scene, withMode(opt, AaMode::None));
  RenderResult q = sharedRenderer().render(scene, withMode(opt, AaMode::Quincunx));
  CHECK(none.stats.rays_by_kind[RAY_KIND_PRIMARY] == w * h);
  CHECK(none.stats.rays_per_pixel == 1.0);
  CHECK(q.stats.rays_by_kind[RAY_KIND_PRIMARY] == (w + 1) * (h + 1) + w * h);
  CHECK(q.stats.rays_per_depth[0] == (w + 1) * (h + 1) + w * h);
  CHECK(q.stats.rays_per_pixel == Approx(static_cast<double>((w + 1) * (h + 1) + w * h) / (w * h)));
  CHECK(q.stats.aa == AaMode::Quincunx);
  CHECK(q.stats.filter == FilterKind::Tent);
  // The centres are the same rays as --aa none's, so their AOVs are identical.
  CHECK(q.primid == none.primid);
  CHECK(sameBits(q.depth, none.depth));
  CHECK(sameBits(q.normal, none.normal));
  CHECK(sameBits(q.albedo, none.albedo));
}

TEST_CASE("a constant image comes back unchanged from every mode and filter", "[render][aa]") {
  Scene scene = parseScene(kFlat, "flat.json");
  RenderOptions opt = RenderOptions::fromScene(scene);
  const float expected[3] = {0.25f * 0.8f, 0.5f * 0.6f, 0.75f * 0.4f};
  struct Case {
    AaMode mode;
    int spp;
    FilterKind filter;
  };
  const Case cases[] = {{AaMode::None, 1, FilterKind::Box},         {AaMode::Grid, 4, FilterKind::Tent},
                        {AaMode::Quincunx, 1, FilterKind::Box},     {AaMode::Adaptive, 1, FilterKind::Box},
                        {AaMode::Jitter, 3, FilterKind::Gaussian},  {AaMode::Poisson, 5, FilterKind::Mitchell},
                        {AaMode::Random, 2, FilterKind::Box}};
  for (const Case& c : cases) {
    INFO(aaModeName(c.mode) << " spp " << c.spp << " " << filterName(c.filter));
    RenderResult r = sharedRenderer().render(scene, withMode(opt, c.mode, c.spp, c.filter));
    REQUIRE(r.rgba.size() == 4u * opt.width * opt.height);
    double worst = 0;
    for (size_t p = 0; p < r.rgba.size() / 4; ++p) {
      for (int ch = 0; ch < 3; ++ch) worst = std::max(worst, std::fabs(double(r.rgba[4 * p + ch]) - expected[ch]));
      worst = std::max(worst, std::fabs(double(r.rgba[4 * p + 3]) - 1.0));
    }
    CHECK(worst < 1e-6);
    for (std::int32_t id : r.primid) CHECK(id == 0);
    if (c.mode == AaMode::Adaptive) {
      // Flat: the corners alone, each traced once.
      CHECK(r.stats.rays_by_kind[RAY_KIND_PRIMARY] == std::uint64_t(opt.width + 1) * (opt.height + 1));
    } else {
      CHECK(r.stats.rays_by_kind[RAY_KIND_PRIMARY] == sampleCount(c.mode, opt.width, opt.height, c.spp));
    }
  }
}

TEST_CASE("edge coverage: alpha approaches the exact pixel area, jitter faster than one sample", "[render][aa]") {
  const int size = 24;
  const double qx = 11.3, qy = 12.6, angle = 0.37;
  Scene scene = parseScene(edgeScene(size, qx, qy, angle), "edge.json");
  RenderOptions opt = RenderOptions::fromScene(scene);
  auto rmsError = [&](const RenderOptions& o) {
    RenderResult r = sharedRenderer().render(scene, o);
    double sum2 = 0;
    int n = 0;
    for (int j = 0; j < size; ++j)
      for (int i = 0; i < size; ++i) {
        double exact = pixelCoverage(i, j, qx, qy, std::cos(angle), std::sin(angle));
        if (exact <= 0 || exact >= 1) continue;  // only pixels the edge crosses
        double d = r.rgba[4 * (static_cast<size_t>(j) * size + i) + 3] - exact;
        sum2 += d * d;
        ++n;
      }
    REQUIRE(n >= size);
    return std::sqrt(sum2 / n);
  };
  const double none = rmsError(withMode(opt, AaMode::None));
  const double grid = rmsError(withMode(opt, AaMode::Grid, 16));
  const double jitter4 = rmsError(withMode(opt, AaMode::Jitter, 4));
  const double jitter64 = rmsError(withMode(opt, AaMode::Jitter, 64));
  const double poisson16 = rmsError(withMode(opt, AaMode::Poisson, 16));
  RenderOptions adaptive = withMode(opt, AaMode::Adaptive);
  adaptive.aa_max_level = 3;
  const double adaptive3 = rmsError(adaptive);
  INFO("rms: none " << none << ", grid16 " << grid << ", jitter4 " << jitter4 << ", jitter64 " << jitter64
                    << ", poisson16 " << poisson16 << ", adaptive3 " << adaptive3);
  CHECK(none > 0.2);  // one sample: coverage is 0 or 1
  CHECK(jitter4 < none);
  CHECK(jitter64 < jitter4);
  CHECK(jitter64 < 0.05);
  CHECK(grid < 0.1);
  CHECK(poisson16 < 0.1);
  CHECK(adaptive3 < 0.1);
}

TEST_CASE("every anti-aliasing mode repeats bit for bit, and the default is none at 1 spp and jitter above",
          "[render][aa][determinism]") {
  Scene scene = loadSceneFile(PRISM_SOURCE_DIR "/scenes/whitted.json");
  RenderOptions opt = RenderOptions::fromScene(scene);
  opt.width = 32;
  opt.height = 18;
  opt.seed = 11;
  const std::pair<AaMode, int> modes[] = {{AaMode::Grid, 4},   {AaMode::Quincunx, 1}, {AaMode::Adaptive, 1},
                                          {AaMode::Jitter, 5}, {AaMode::Poisson, 4},  {AaMode::Random, 3}};
  for (auto [mode, spp] : modes) {
    INFO(aaModeName(mode));
    RenderOptions o = withMode(opt, mode, spp, FilterKind::Mitchell);
    RenderResult a = sharedRenderer().render(scene, o);
    RenderResult b = sharedRenderer().render(scene, o);
    CHECK(sameBits(a.rgba, b.rgba));
    CHECK(a.primid == b.primid);
    CHECK(a.stats.totalRays() == b.stats.totalRays());
  }
  opt.aa.reset();
  opt.spp = 1;
  CHECK(sharedRenderer().render(scene, opt).stats.aa == AaMode::None);
  opt.spp = 4;
  RenderResult jitter = sharedRenderer().render(scene, opt);
  CHECK(jitter.stats.aa == AaMode::Jitter);
  CHECK(jitter.stats.rays_per_pixel == 4.0);
  CHECK(sameBits(jitter.rgba, sharedRenderer().render(scene, withMode(opt, AaMode::Jitter, 4)).rgba));
}

TEST_CASE("adaptive sampling gives the same image whether its film is traced in one batch or several",
          "[render][aa][adaptive]") {
  // 301 x 241 corners alone are more than one slice (65,536 positions), so with
  // a film of one slice the positions go through the device in several batches.
  Scene scene = loadSceneFile(PRISM_SOURCE_DIR "/scenes/whitted.json");
  RenderOptions opt = withMode(RenderOptions::fromScene(scene), AaMode::Adaptive);
  opt.width = 300;
  opt.height = 240;
  opt.aa_max_level = 2;
  RenderResult one = sharedRenderer().render(scene, opt);
  struct RestoreBatch {
    size_t slices = sharedRenderer().filmBatchSlices();
    ~RestoreBatch() { sharedRenderer().setFilmBatchSlices(slices); }
  } restore;
  sharedRenderer().setFilmBatchSlices(1);
  RenderResult several = sharedRenderer().render(scene, opt);
  const double positions = one.stats.rays_per_pixel * opt.width * opt.height;
  INFO(positions << " positions traced");
  REQUIRE(positions > 2.0 * Renderer::kSliceRays);
  // Each adaptive pass traces its new positions in batches of the film's size.
  CHECK(several.stats.film_batches > one.stats.film_batches);
  CHECK(one.stats.film_batches <= 1 + opt.aa_max_level);
  CHECK(sameBits(one.rgba, several.rgba));
  CHECK(one.primid == several.primid);
  CHECK(sameBits(one.depth, several.depth));
  CHECK(one.stats.totalRays() == several.stats.totalRays());
}

TEST_CASE("Z-buffer and traced primary rays render real meshes and analytic objects alike",
          "[render][firsthit][mesh]") {
  const std::string bunny = prism_test::testMeshDir() + "/bunny/bun_zipper_res2.ply";
  const std::string spot = prism_test::testMeshDir() + "/spot/spot.obj";
  const std::string json = R"({
    "camera": {"position": [0.3, 1.4, 4.2], "look_at": [0, 0.7, 0], "fov": 38},
    "film": {"width": 128, "height": 96},
    "render": {"max_depth": 3, "background": [0.2, 0.3, 0.45]},
    "materials": {
      "clay": {"diffuse": [0.8, 0.7, 0.6], "specular": 0.3, "shininess": 40},
      "mirror": {"diffuse": 0.05, "reflect": 0.8, "specular": 0.6, "shininess": 120},
      "glass": {"diffuse": 0, "transmit": 0.9, "reflect": 0.05, "ior": 1.5},
      "floor": {"texture": {"type": "checker", "color1": 0.9, "color2": 0.2, "scale": 0.5}}
    },
    "lights": [{"position": [3, 6, 5], "intensity": 0.8}, {"position": [-4, 3, 2], "intensity": 0.4}],
    "objects": [
      {"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "floor"},
      {"type": "mesh", "file": ")" + bunny + R"(", "material": "clay",
       "transform": {"scale": [9, 9, 9], "translate": [-0.6, -0.3, 0]}},
      {"type": "mesh", "file": ")" + spot + R"(", "material": "clay", "smooth": true,
       "transform": {"scale": [0.6, 0.6, 0.6], "translate": [0.9, 0.65, -0.4]}},
      {"type": "sphere", "center": [0.1, 0.35, 1.0], "radius": 0.35, "material": "glass"},
      {"type": "sphere", "center": [-1.4, 0.5, -0.8], "radius": 0.5, "material": "mirror"},
      {"type": "box", "min": [1.2, 0, 0.6], "max": [1.6, 0.4, 1.0], "material": "clay",
       "transform": {"rotate": {"axis": [0, 1, 0], "angle": 25}}}
    ]
  })";
  Scene scene = parseScene(json, "meshes.json");
  RenderOptions opt = RenderOptions::fromScene(scene);
  RenderOptions zopt = opt, topt = opt;
  zopt.first_hit = FirstHitMode::ZBuffer;
  topt.first_hit = FirstHitMode::Trace;
  RenderResult z = sharedRenderer().render(scene, zopt);
  RenderResult t = sharedRenderer().render(scene, topt);
  CHECK(z.stats.first_hit == FirstHitMode::ZBuffer);
  CHECK(t.stats.first_hit == FirstHitMode::Trace);
  CHECK(z.stats.rays_by_kind[RAY_KIND_PRIMARY] == t.stats.rays_by_kind[RAY_KIND_PRIMARY]);

  const size_t pixels = static_cast<size_t>(opt.width) * opt.height;
  // Primids: the plane, then the two meshes' triangles, then the analytic objects.
  const auto mesh_end =
      static_cast<std::int32_t>(1 + scene.objects[1].primitiveCount() + scene.objects[2].primitiveCount());
  size_t same_prim = 0, close_depth = 0, close_colour = 0, hits = 0, meshes = 0, analytic = 0;
  double worst_colour = 0;
  for (size_t p = 0; p < pixels; ++p) {
    if (z.primid[p] == t.primid[p]) ++same_prim;
    if (z.primid[p] >= 0) {
      ++hits;
      (z.primid[p] >= 1 && z.primid[p] < mesh_end ? meshes : analytic)++;
    }
    const double dz = z.depth[p], dt = t.depth[p];
    if (dz == dt || std::fabs(dz - dt) <= 1e-5 * std::fabs(dt)) ++close_depth;
    double diff = 0;
    for (int c = 0; c < 4; ++c) diff = std::max(diff, std::fabs(double(z.rgba[4 * p + c]) - t.rgba[4 * p + c]));
    worst_colour = std::max(worst_colour, diff);
    if (diff < 1e-3) ++close_colour;
  }
  INFO(same_prim << " of " << pixels << " primids agree, " << close_depth << " depths, " << close_colour
                 << " colours within 1e-3 (worst " << worst_colour << "); " << meshes << " mesh and " << analytic
                 << " other hits");
  CHECK(hits > pixels / 2);
  CHECK(meshes > pixels / 20);
  CHECK(same_prim >= pixels * 9999 / 10000);
  CHECK(close_depth >= pixels * 9999 / 10000);
  CHECK(close_colour >= pixels * 999 / 1000);

  // The same with 4 jittered samples a pixel: the Z-buffer answers every sample.
  zopt.spp = topt.spp = 4;
  zopt.width = topt.width = 64;
  zopt.height = topt.height = 48;
  RenderResult zj = sharedRenderer().render(scene, zopt);
  RenderResult tj = sharedRenderer().render(scene, topt);
  size_t close = 0;
  for (size_t p = 0; p < zj.rgba.size() / 4; ++p) {
    double diff = 0;
    for (int c = 0; c < 4; ++c) diff = std::max(diff, std::fabs(double(zj.rgba[4 * p + c]) - tj.rgba[4 * p + c]));
    if (diff < 1e-3) ++close;
  }
  CHECK(close >= zj.rgba.size() / 4 * 999 / 1000);
}

TEST_CASE("the film's anti-aliasing keys and render.first_hit reach the render options", "[render][aa][scene]") {
  Scene scene = parseScene(R"({"film": {"width": 8, "height": 6, "spp": 16, "aa": "poisson", "filter": "mitchell",
                                        "aa_threshold": 0.25, "aa_max_level": 3},
                               "render": {"first_hit": "trace"}})",
                           "keys.json");
  CHECK(scene.warnings.empty());
  RenderOptions o = RenderOptions::fromScene(scene);
  REQUIRE(o.aa.has_value());
  CHECK(*o.aa == AaMode::Poisson);
  CHECK(o.filter == FilterKind::Mitchell);
  CHECK(o.aa_threshold == 0.25);
  CHECK(o.aa_max_level == 3);
  CHECK(o.first_hit == FirstHitMode::Trace);

  RenderOptions d = RenderOptions::fromScene(parseScene("{}", "empty.json"));
  CHECK(!d.aa.has_value());
  CHECK(d.aaMode() == AaMode::None);
  CHECK(d.filter == FilterKind::Box);
  CHECK(d.aa_threshold == 0.1);
  CHECK(d.aa_max_level == 2);
  CHECK(d.first_hit == FirstHitMode::Auto);
  CHECK(RenderOptions::fromScene(parseScene(R"({"film": {"spp": 4}})", "spp.json")).aaMode() == AaMode::Jitter);
  CHECK(RenderOptions::fromScene(parseScene(R"({"film": {"spp": 4, "aa": "auto"}})", "auto.json")).aaMode() ==
        AaMode::Jitter);

  CHECK_THROWS_WITH(parseScene(R"({"film": {"aa": "supersample"}})", "bad.json"),
                    Catch::Contains("bad.json: film.aa: unknown anti-aliasing mode 'supersample'") &&
                        Catch::Contains("quincunx"));
  CHECK_THROWS_WITH(parseScene(R"({"film": {"filter": "lanczos"}})", "bad.json"),
                    Catch::Contains("film.filter: unknown filter 'lanczos'") && Catch::Contains("mitchell"));
  CHECK_THROWS_WITH(parseScene(R"({"film": {"aa": "grid", "spp": 5}})", "bad.json"),
                    Catch::Contains("film.spp") && Catch::Contains("square") && Catch::Contains("4 or 9"));
  CHECK_THROWS_WITH(parseScene(R"({"film": {"aa": "quincunx", "spp": 4}})", "bad.json"),
                    Catch::Contains("film.spp") && Catch::Contains("spp must be 1"));
  CHECK_THROWS_WITH(parseScene(R"({"film": {"aa_threshold": -1}})", "bad.json"),
                    Catch::Contains("film.aa_threshold"));
  CHECK_THROWS_WITH(parseScene(R"({"film": {"aa_max_level": 9}})", "bad.json"),
                    Catch::Contains("film.aa_max_level") && Catch::Contains("[0, 8]"));
  CHECK_THROWS_WITH(parseScene(R"({"render": {"first_hit": "raster"}})", "bad.json"),
                    Catch::Contains("render.first_hit: unknown first-hit mode 'raster'") &&
                        Catch::Contains("zbuffer"));
  CHECK_THROWS_WITH(withMode(RenderOptions(), AaMode::None, 4).validate(), Catch::Contains("spp must be 1"));
}

TEST_CASE("a film too large for the device is refused with what would fit", "[render][aa][memory]") {
  Scene scene = parseScene(kFlat, "flat.json");
  RenderOptions opt = RenderOptions::fromScene(scene);
  opt.width = 8192;
  opt.height = 8192;
  opt.aa = AaMode::Jitter;
  opt.spp = 65536;  // 2^42 samples: no device holds their film
  try {
    sharedRenderer().render(scene, opt);
    FAIL("the render should have been refused");
  } catch (const FilmTooLarge& e) {
    const std::string message = e.what();
    CHECK(message.find("4398046511104 samples") != std::string::npos);
    CHECK(message.find("fewer samples per pixel") != std::string::npos);
    CHECK(message.find(sharedContext().device().name) != std::string::npos);
  }
  // The renderer is still usable afterwards.
  opt.width = 4;
  opt.height = 4;
  opt.spp = 1;
  opt.aa.reset();
  CHECK(sharedRenderer().render(scene, opt).rgba.size() == 64);
}

TEST_CASE("the C API carries the anti-aliasing and first-hit settings and reports rays per pixel", "[render][aa][api]") {
  PrismScene scene = nullptr;
  REQUIRE(prismLoadSceneFromString(kFlat, "flat.json", &scene) == PRISM_OK);
  PrismRenderOptions options{};
  REQUIRE(prismGetRenderOptions(scene, &options) == PRISM_OK);
  CHECK(options.aa == PRISM_AA_AUTO);
  CHECK(options.filter == PRISM_FILTER_BOX);
  CHECK(options.first_hit == PRISM_FIRST_HIT_AUTO);
  CHECK(options.aa_threshold == Approx(0.1));
  CHECK(options.aa_max_level == 2);
  PrismAa aa;
  REQUIRE(prismParseAa("quincunx", &aa) == PRISM_OK);
  CHECK(aa == PRISM_AA_QUINCUNX);
  CHECK(std::string(prismAaName(PRISM_AA_POISSON)) == "poisson");
  CHECK(prismParseAa("bogus", &aa) == PRISM_ERROR_INVALID_ARGUMENT);
  CHECK(std::string(prismGetLastError()).find("jitter") != std::string::npos);
  PrismFilter filter;
  CHECK(prismParseFilter("gaussian", &filter) == PRISM_OK);
  CHECK(filter == PRISM_FILTER_GAUSSIAN);
  PrismFirstHit first_hit;
  CHECK(prismParseFirstHit("trace", &first_hit) == PRISM_OK);
  CHECK(first_hit == PRISM_FIRST_HIT_TRACE);
  CHECK(prismFirstHitName(static_cast<PrismFirstHit>(9)) == nullptr);

  PrismContextOptions context_options;
  prismDefaultContextOptions(&context_options);
  PrismContext context = nullptr;
  REQUIRE(prismCreateContext(nullptr, &context_options, &context) == PRISM_OK);
  options.width = 10;
  options.height = 6;
  options.aa = PRISM_AA_QUINCUNX;
  options.first_hit = PRISM_FIRST_HIT_TRACE;
  std::vector<float> rgba(4 * 10 * 6);
  PrismRenderStats stats{};
  stats.struct_size = sizeof stats;
  REQUIRE(prismRender(context, scene, &options, rgba.data(), &stats) == PRISM_OK);
  CHECK(stats.primary_rays == 11u * 7 + 10 * 6);
  CHECK(stats.rays_per_pixel == Approx((11.0 * 7 + 10 * 6) / 60));
  CHECK(stats.first_hit_used == PRISM_FIRST_HIT_TRACE);
  options.aa = PRISM_AA_AUTO;
  options.first_hit = PRISM_FIRST_HIT_AUTO;
  REQUIRE(prismRender(context, scene, &options, rgba.data(), &stats) == PRISM_OK);
  CHECK(stats.first_hit_used == PRISM_FIRST_HIT_TRACE);  // a lone plane: the Z-buffer would test it everywhere
  CHECK(stats.rays_per_pixel == 1.0);
  options.aa = 42;
  CHECK(prismRender(context, scene, &options, rgba.data(), &stats) == PRISM_ERROR_INVALID_ARGUMENT);
  options.aa = PRISM_AA_GRID;
  options.spp = 8;
  CHECK(prismRender(context, scene, &options, rgba.data(), &stats) == PRISM_ERROR_INVALID_ARGUMENT);
  CHECK(std::string(prismGetLastError()).find("square") != std::string::npos);
  options.aa = PRISM_AA_JITTER;
  options.spp = 65536;
  options.width = 8192;
  options.height = 8192;
  // rgba is far too small for this size, but the render is refused before anything is written.
  CHECK(prismRender(context, scene, &options, rgba.data(), &stats) == PRISM_ERROR_OUT_OF_MEMORY);
  CHECK(std::string(prismGetLastError()).find("fewer samples per pixel") != std::string::npos);
  prismReleaseContext(context);
  prismReleaseScene(scene);
}
