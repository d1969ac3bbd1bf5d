// Image textures: sRGB decoding against the standard's closed form, the
// texels read back from a PNG and an EXR written here, and renders of a
// textured floor seen straight down whose every pixel is the bilinear
// sample, computed here in double, at the point the pixel sees — for each
// wrap mode; and the refusals.
#include <catch2/catch.hpp>

#include <OpenImageIO/imageio.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include <unistd.h>

#include "render/gpu_scene.h"
#include "render/renderer.h"
#include "scene/image_texture.h"
#include "scene_format/scene_loader.h"
#include "support/scene_errors.h"
#include "support/shared_context.h"

using namespace prism;
using namespace prism::test;

namespace {

constexpr int kW = 5, kH = 3;

std::string tempDir() {
  const auto dir = std::filesystem::temp_directory_path() / ("prism-texture-test-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  return dir.string();
}

// A 5 x 3 8-bit RGB image of distinct values; returns its path.
std::string writePng(std::vector<std::uint8_t>* bytes) {
  std::mt19937 rng(3);
  bytes->resize(kW * kH * 3);
  for (auto& b : *bytes) b = static_cast<std::uint8_t>(rng() % 256);
  const std::string path = tempDir() + "/tex.png";
  auto out = OIIO::ImageOutput::create(path);
  REQUIRE(out);
  REQUIRE(out->open(path, OIIO::ImageSpec(kW, kH, 3, OIIO::TypeDesc::UINT8)));
  REQUIRE(out->write_image(OIIO::TypeDesc::UINT8, bytes->data()));
  out->close();
  return path;
}

// NAME.obj with its NAME.mtl, written in dir and loaded as a scene's one object.
Scene meshScene(const std::string& dir, const std::string& name, const std::string& mtl, const std::string& obj) {
  std::ofstream(dir + "/" + name + ".mtl") << mtl;
  std::ofstream(dir + "/" + name + ".obj") << "mtllib " + name + ".mtl\n" + obj;
  return parseScene(R"({"objects": [{"type": "mesh", "file": ")" + dir + "/" + name + R"(.obj"}]})", name);
}

std::string warningLines(const Scene& scene) {
  std::string lines;
  for (const std::string& w : scene.warnings) lines += w + "\n";
  return lines;
}

// Bilinear filtering in double, written from the definition: texel centres at
// ((i + 0.5) / w, 1 - (j + 0.5) / h), the wrap applied to texel indices.
Vec3 bilinear(const ImageTexture& img, int wrap, double s, double t) {
  auto wrapped = [wrap](long long i, long long n) {
    if (wrap == 1) return std::clamp<long long>(i, 0, n - 1);
    if (wrap == 2) {
      long long k = ((i % (2 * n)) + 2 * n) % (2 * n);
      return k < n ? k : 2 * n - 1 - k;
    }
    return ((i % n) + n) % n;
  };
  const double x = s * img.width - 0.5, y = (1 - t) * img.height - 0.5;
  const double x0 = std::floor(x), y0 = std::floor(y), fx = x - x0, fy = y - y0;
  auto at = [&](long long i, long long j) {
    const std::size_t k = 3 * (wrapped(j, img.height) * img.width + wrapped(i, img.width));
    return Vec3{img.rgb[k], img.rgb[k + 1], img.rgb[k + 2]};
  };
  const auto i = static_cast<long long>(x0), j = static_cast<long long>(y0);
  return (at(i, j) * (1 - fx) + at(i + 1, j) * fx) * (1 - fy) + (at(i, j + 1) * (1 - fx) + at(i + 1, j + 1) * fx) * fy;
}

}  // namespace

TEST_CASE("sRGB decoding follows IEC 61966-2-1", "[render][texture]") {
  CHECK(srgbToLinear(0) == 0);
  CHECK(srgbToLinear(1) == Approx(1).epsilon(1e-15));
  CHECK(srgbToLinear(0.5) == Approx(0.21404114048223255).epsilon(1e-12));
  // The two pieces meet at 0.04045 (to the standard's rounding of its constants).
  CHECK(std::fabs(0.04045 / 12.92 - std::pow((0.04045 + 0.055) / 1.055, 2.4)) < 1e-7);
}

TEST_CASE("an 8-bit PNG reads as its sRGB values decoded, a float EXR as linear", "[render][texture]") {
  std::vector<std::uint8_t> bytes;
  const std::string png = writePng(&bytes);
  const SharedImage img = readImageTexture(png, std::nullopt, 0);
  REQUIRE(img->width == kW);
  REQUIRE(img->height == kH);
  CHECK(img->srgb);
  for (std::size_t k = 0; k < bytes.size(); ++k) CHECK(img->rgb[k] == Approx(srgbToLinear(bytes[k] / 255.0)).margin(1e-6));
  // Told it is linear, the same file keeps its values.
  const SharedImage raw = readImageTexture(png, false, 0);
  for (std::size_t k = 0; k < bytes.size(); ++k) CHECK(raw->rgb[k] == Approx(bytes[k] / 255.0).margin(1e-6));
  const std::string exr = tempDir() + "/tex.exr";
  std::vector<float> values(kW * kH * 3);
  for (std::size_t k = 0; k < values.size(); ++k) values[k] = 0.1f * k;
  auto out = OIIO::ImageOutput::create(exr);
  REQUIRE(out);
  REQUIRE(out->open(exr, OIIO::ImageSpec(kW, kH, 3, OIIO::TypeDesc::FLOAT)));
  REQUIRE(out->write_image(OIIO::TypeDesc::FLOAT, values.data()));
  out->close();
  const SharedImage e = readImageTexture(exr, std::nullopt, 0);
  CHECK_FALSE(e->srgb);
  for (std::size_t k = 0; k < values.size(); ++k) CHECK(e->rgb[k] == Approx(values[k]).margin(1e-6));
}

TEST_CASE("a textured floor seen straight down shows the bilinear sample at every pixel, for each wrap mode",
          "[render][texture]") {
  std::vector<std::uint8_t> bytes;
  const std::string png = writePng(&bytes);
  const int width = 64, height = 48;
  for (const char* wrap : {"repeat", "clamp", "mirror"}) {
    // The floor y = 0 (its (u, v) = (z, x)), the image 0.7 units across, seen
    // from above through a wide lens: several periods, and the edges between.
    const std::string json = std::string(R"({
      "camera": {"position": [0.3, 4, 0.2], "look_at": [0.3, 0, 0.2], "up": [0, 0, -1], "fov": 60},
      "film": {"width": )") + std::to_string(width) + R"(, "height": )" + std::to_string(height) + R"(},
      "render": {"max_depth": 0, "ambient": [1, 1, 1]},
      "materials": {"tex": {"ambient": 1, "diffuse": 0, "specular": 0,
                            "texture": {"type": "image", "file": ")" + png + R"(", "wrap": ")" + wrap + R"(", "scale": 0.7}}},
      "objects": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "tex"}]})";
    const Scene scene = parseScene(json, "floor");
    RenderOptions options = RenderOptions::fromScene(scene);
    options.first_hit = FirstHitMode::Trace;
    const RenderResult r = sharedRenderer().render(scene, options);
    const CameraBasis cam = cameraBasis(scene.camera, width, height);
    const ImageTexture& img = *scene.materials[1].texture.image;
    const int mode = std::string(wrap) == "repeat" ? 0 : std::string(wrap) == "clamp" ? 1 : 2;
    double worst = 0;
    for (int py = 0; py < height; ++py)
      for (int px = 0; px < width; ++px) {
        // The pixel centre's ray (the camera's own convention) meets y = 0 at p.
        const double fx = 2 * (px + 0.5) / width - 1, fy = 1 - 2 * (py + 0.5) / height;
        const Vec3 d = cam.forward + cam.right * fx + cam.up * fy;
        const Vec3 p = cam.origin + d * (-cam.origin.y / d.y);
        const Vec3 want = bilinear(img, mode, p.z / 0.7, p.x / 0.7);
        const float* got = &r.rgba[4 * (py * width + px)];
        worst = std::max({worst, std::fabs(got[0] - want.x), std::fabs(got[1] - want.y), std::fabs(got[2] - want.z)});
      }
    INFO(wrap << ": worst channel difference " << worst);
    CHECK(worst < 2e-4);
  }
}

TEST_CASE("a mesh's map_Kd is sampled at the texture coordinates its vertices carry", "[render][texture]") {
  std::vector<std::uint8_t> bytes;
  const std::string png = writePng(&bytes);
  // A square in the plane z = 0, its corners at uv (0.1, 0.2) .. (1.7, 1.4): a
  // texture repeated across it, through the file's own material.
  const std::string dir = tempDir();
  {
    std::ofstream mtl(dir + "/quad.mtl");
    mtl << "newmtl painted\nKa 1 1 1\nKd 0 0 0\nKs 0 0 0\nmap_Kd tex.png\n";
    std::ofstream obj(dir + "/quad.obj");
    obj << "mtllib quad.mtl\nv -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\n"
           "vt 0.1 0.2\nvt 1.7 0.2\nvt 1.7 1.4\nvt 0.1 1.4\nusemtl painted\nf 1/1 2/2 3/3 4/4\n";
  }
  const int width = 48, height = 48;
  const std::string json = R"({
    "camera": {"position": [0, 0, 3], "look_at": [0, 0, 0], "fov": 30},
    "film": {"width": 48, "height": 48},
    "render": {"max_depth": 0, "ambient": [1, 1, 1]},
    "objects": [{"type": "mesh", "file": ")" + dir + R"(/quad.obj"}]})";
  const Scene scene = parseScene(json, "quad");
  REQUIRE(scene.warnings.empty());
  const Material& m = scene.materials.back();
  REQUIRE(m.texture.kind == Texture::Kind::Image);
  RenderOptions options = RenderOptions::fromScene(scene);
  options.first_hit = FirstHitMode::Trace;
  const RenderResult r = sharedRenderer().render(scene, options);
  const CameraBasis cam = cameraBasis(scene.camera, width, height);
  double worst = 0;
  int inside = 0;
  for (int py = 0; py < height; ++py)
    for (int px = 0; px < width; ++px) {
      const double fx = 2 * (px + 0.5) / width - 1, fy = 1 - 2 * (py + 0.5) / height;
      const Vec3 d = cam.forward + cam.right * fx + cam.up * fy;
      const Vec3 p = cam.origin + d * (-cam.origin.z / d.z);
      if (std::fabs(p.x) > 0.98 || std::fabs(p.y) > 0.98) continue;  // off the square, or on its edge
      ++inside;
      // uv is linear over the square (both triangles of it agree).
      const double u = 0.1 + 1.6 * (p.x + 1) / 2, v = 0.2 + 1.2 * (p.y + 1) / 2;
      const Vec3 want = bilinear(*m.texture.image, 0, u, v);
      const float* got = &r.rgba[4 * (py * width + px)];
      worst = std::max({worst, std::fabs(got[0] - want.x), std::fabs(got[1] - want.y), std::fabs(got[2] - want.z)});
    }
  INFO(inside << " pixels on the square, worst channel difference " << worst);
  CHECK(inside > width * height / 4);
  CHECK(worst < 2e-4);
  // A map_Kd that cannot be read is a warning, and the material stays plain.
  const Scene lost = meshScene(dir, "lost", "newmtl lost\nKd 0.5 0.5 0.5\nmap_Kd missing.png\n",
                               "v 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl lost\nf 1 2 3\n");
  const std::string warnings = warningLines(lost);
  INFO(warnings);
  std::size_t map_warnings = 0;
  for (const std::string& w : lost.warnings) map_warnings += w.find("map_Kd not used") != std::string::npos;
  CHECK(map_warnings == 1);
  CHECK_THAT(warnings, Catch::Contains("missing.png: cannot open: no such file"));
  CHECK(lost.materials.back().texture.kind == Texture::Kind::None);
}

TEST_CASE("patches carry their (u, v) as texture coordinates, by either method", "[render][texture][patches]") {
  // A curved patch seen from the front: the triangles of subdivision carry
  // (u, v) at their vertices, Newton's root is (u, v) itself; the same image
  // within the tolerance's worth of texture.
  std::vector<std::uint8_t> bytes;
  const std::string png = writePng(&bytes);
  std::string points = "[";
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      points += std::string(i || j ? ", " : "") + "[" + std::to_string(i / 1.5 - 1) + ", " + std::to_string(j / 1.5 - 1) +
                ", " + std::to_string(0.3 * ((i == 1 || i == 2) + (j == 1 || j == 2))) + "]";
  points += "]";
  auto scene = [&](const char* method) {
    return parseScene(R"({"camera": {"position": [0, 0, 4], "look_at": [0, 0, 0], "fov": 40},
      "film": {"width": 40, "height": 40}, "render": {"max_depth": 0, "ambient": [1, 1, 1]},
      "materials": {"t": {"ambient": 1, "diffuse": 0, "specular": 0, "texture": {"type": "image", "file": ")" + png +
                          R"("}}},
      "objects": [{"type": "patches", "patches": [)" + points + R"(], "method": ")" + method +
                          R"(", "tolerance": 0.0005, "material": "t"}]})",
                      method);
  };
  RenderOptions options = RenderOptions::fromScene(scene("analytic"));
  const RenderResult a = sharedRenderer().render(scene("analytic"), options);
  const RenderResult s = sharedRenderer().render(scene("subdivision"), options);
  std::size_t both = 0, far = 0;
  for (std::size_t p = 0; p < a.primid.size(); ++p) {
    if (a.primid[p] < 0 || s.primid[p] < 0) continue;
    ++both;
    double d = 0;
    for (int c = 0; c < 3; ++c) d = std::max(d, std::fabs(double(a.rgba[4 * p + c]) - s.rgba[4 * p + c]));
    far += d > 0.02;
  }
  INFO(both << " pixels on the patch, " << far << " differ by more than 0.02");
  CHECK(both > a.primid.size() / 4);
  CHECK(far <= both / 100);
}

TEST_CASE("image textures that cannot be read are refused with the reason", "[render][texture]") {
  auto material = [](const std::string& texture) {
    return R"({"materials": {"m": {"texture": )" + texture + "}}}";
  };
  CHECK_THAT(errorOf(material(R"({"type": "image", "file": "/nonexistent.png"})")),
             Catch::Contains("materials.m.texture.file: /nonexistent.png: cannot open: no such file"));
  CHECK_THAT(errorOf(material(R"({"type": "image", "file": "/dev/zero"})")), Catch::Contains("not a regular file"));
  CHECK_THAT(errorOf(material(R"({"type": "image", "file": ")" PRISM_SOURCE_DIR R"(/scenes/whitted.json"})")),
             Catch::Contains("cannot read as an image"));
  std::vector<std::uint8_t> bytes;
  const std::string png = writePng(&bytes);
  CHECK_THAT(errorOf(material(R"({"type": "image", "file": ")" + png + R"(", "wrap": "tile"})")),
             Catch::Contains("unknown wrap mode 'tile' (expected repeat, clamp, mirror)"));
  CHECK_THAT(errorOf(material(R"({"type": "photo"})")), Catch::Contains("expected checker, image"));
  // The scale divides coordinates in float: 1e-50 would be 0 there.
  for (const char* scale : {"1e-50", "0", "2e15"})
    CHECK_THAT(errorOf(material(R"({"type": "checker", "scale": )" + std::string(scale) + "}")),
               Catch::Contains("materials.m.texture.scale: expected a number in [1e-15, 1e15]"));
  for (const char* scale : {"1e-15", "1e15"}) CHECK(errorOf(material(R"({"type": "checker", "scale": )" + std::string(scale) + "}")) == "");
  // A file that ends before its pixels do.
  const std::string cut = tempDir() + "/cut.pgm";
  std::ofstream(cut) << "P5\n4 4\n255\nAB";
  const std::string cut_error = errorOf(material(R"({"type": "image", "file": ")" + cut + R"("})"));
  CHECK_THAT(cut_error, Catch::Contains("cut.pgm: cannot read its pixels: "));
  CHECK_THAT(cut_error, !Catch::EndsWith(": "));  // a reason follows, OpenImageIO's or prism's
  // Two colour channels and no alpha: neither grey nor RGB.
  const std::string uv = tempDir() + "/uv.exr";
  OIIO::ImageSpec spec(2, 2, 2, OIIO::TypeDesc::FLOAT);
  spec.channelnames = {"U", "V"};
  spec.alpha_channel = -1;
  const std::vector<float> values(8, 0.5f);
  auto out = OIIO::ImageOutput::create(uv);
  REQUIRE(out);
  REQUIRE(out->open(uv, spec));
  REQUIRE(out->write_image(OIIO::TypeDesc::FLOAT, values.data()));
  out->close();
  CHECK_THAT(errorOf(material(R"({"type": "image", "file": ")" + uv + R"("})")),
             Catch::Contains("uv.exr: 2 colour channels (U, V); expected grey or RGB, with or without alpha"));
}

TEST_CASE("an image's alpha is left out: grey and alpha reads as grey, RGBA as the colour the file stores",
          "[render][texture]") {
  // Alpha runs 0, 85, 170, 255 across the texels and colour stays put: the
  // file keeps them apart (PNG), and the texels must not darken with alpha.
  for (const int channels : {2, 4}) {
    INFO(channels << " channels");
    std::vector<std::uint8_t> bytes(4 * channels);
    for (int t = 0; t < 4; ++t) {
      for (int c = 0; c + 1 < channels; ++c) bytes[t * channels + c] = static_cast<std::uint8_t>(40 + 50 * c + 30 * t);
      bytes[t * channels + channels - 1] = static_cast<std::uint8_t>(85 * t);
    }
    const std::string png = tempDir() + "/alpha" + std::to_string(channels) + ".png";
    OIIO::ImageSpec spec(2, 2, channels, OIIO::TypeDesc::UINT8);
    spec.attribute("oiio:UnassociatedAlpha", 1);  // write the bytes as they are
    auto out = OIIO::ImageOutput::create(png);
    REQUIRE(out);
    REQUIRE(out->open(png, spec));
    REQUIRE(out->write_image(OIIO::TypeDesc::UINT8, bytes.data()));
    out->close();
    const SharedImage img = readImageTexture(png, std::nullopt, 0);
    for (int t = 0; t < 4; ++t)
      for (int c = 0; c < 3; ++c) {
        const int stored = bytes[t * channels + (channels == 2 ? 0 : c)];
        CHECK(img->rgb[3 * t + c] == Approx(srgbToLinear(stored / 255.0)).margin(1e-6));
      }
  }
}

TEST_CASE("the scene's images together hold at most 2^26 texels, refused before their pixels are read",
          "[render][texture]") {
  // A header of 8192 x 8192 (2^26 texels: within the limit alone) with no
  // pixels behind it: refused for the total, its pixels are never read;
  // read, it would fail for want of them.
  const std::string dir = tempDir();
  std::ofstream(dir + "/big.pgm") << "P5\n8192 8192\n255\n";
  std::ofstream(dir + "/one.pgm") << "P5\n1 1\n255\nA";
  auto scene = [&](const std::string& materials) {
    return R"({"materials": {)" + materials + "}}";
  };
  const std::string one = R"("a": {"texture": {"type": "image", "file": ")" + dir + R"(/one.pgm"}})";
  const std::string big = R"("b": {"texture": {"type": "image", "file": ")" + dir + R"(/big.pgm"}})";
  CHECK_THAT(errorOf(scene(big)), Catch::Contains("big.pgm: cannot read its pixels"));
  CHECK_THAT(errorOf(scene(one + ", " + big)),
             Catch::Contains("materials.b.texture.file: " + dir +
                             "/big.pgm: 8192 x 8192 texels, which with the 1 texels of the scene's images before it pass "
                             "the 67108864 texels textures may hold together"));
  // The same through a mesh's map_Kd: a warning, and the material stays plain.
  const Scene mesh = meshScene(dir, "big", "newmtl small\nmap_Kd one.pgm\nnewmtl large\nmap_Kd big.pgm\n",
                               "v 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl small\nf 1 2 3\nusemtl large\nf 3 2 1\n");
  CHECK_THAT(warningLines(mesh), Catch::Contains("material 'large': map_Kd not used: ") &&
                           Catch::Contains("big.pgm: 8192 x 8192 texels, which with the 1 texels"));
  REQUIRE(mesh.materials.size() >= 2);
  CHECK(mesh.materials[mesh.materials.size() - 2].texture.kind == Texture::Kind::Image);
  CHECK(mesh.materials.back().texture.kind == Texture::Kind::None);
}

TEST_CASE("an image shared by several materials counts once toward the texel limit", "[render][texture]") {
  std::vector<std::uint8_t> bytes;
  const std::string png = writePng(&bytes);
  const Scene scene = parseScene(R"({"materials": {
      "a": {"texture": {"type": "image", "file": ")" + png + R"("}},
      "b": {"texture": {"type": "checker"}},
      "c": {"texture": {"type": "image", "file": ")" + png + R"("}}}})", "shared");
  // The loader reads the file once for each material that names it: two images.
  CHECK(imageTexelsHeld(scene) == 2 * kW * kH);
  Scene shared = scene;
  shared.materials[3].texture.image = shared.materials[1].texture.image;  // one image, two materials
  CHECK(imageTexelsHeld(shared) == kW * kH);
  // The flattening stores it once too.
  RenderOptions options = RenderOptions::fromScene(shared);
  CHECK(flattenScene(shared, options).texels.size() == 4 * kW * kH);
}
