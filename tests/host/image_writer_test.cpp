// Round trips through OpenImageIO's reader: float formats must come back bit for bit
// (the depth AOV relies on +inf surviving), PNG must hold the sRGB encoding computed
// here independently, and failures must leave no file behind.
#include <OpenImageIO/imageio.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "render/image_writer.h"

namespace fs = std::filesystem;

namespace {

const float kInf = std::numeric_limits<float>::infinity();

// A fresh, empty folder per test case.
struct ScratchDir {
  fs::path path;
  ScratchDir() {
    static int counter = 0;
    path = fs::temp_directory_path() /
           ("prism-image-writer-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~ScratchDir() {
    std::error_code ignored;
    fs::remove_all(path, ignored);
  }
  std::string file(const std::string& name) const { return (path / name).string(); }
  std::vector<std::string> entries() const {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(path)) names.push_back(entry.path().filename().string());
    return names;
  }
};

struct ReadImage {
  int width = 0, height = 0, channels = 0;
  std::vector<float> floats;
  std::vector<unsigned char> bytes;
};

ReadImage readBack(const std::string& path, OIIO::TypeDesc type) {
  OIIO::ImageSpec config;
  // Return PNG bytes as stored rather than premultiplied by alpha.
  config.attribute("oiio:UnassociatedAlpha", 1);
  auto in = OIIO::ImageInput::open(path, &config);
  INFO(OIIO::geterror());
  REQUIRE(in);
  const OIIO::ImageSpec& spec = in->spec();
  ReadImage image;
  image.width = spec.width;
  image.height = spec.height;
  image.channels = spec.nchannels;
  const size_t n = static_cast<size_t>(spec.width) * spec.height * spec.nchannels;
  bool ok;
  if (type == OIIO::TypeDesc::UINT8) {
    image.bytes.resize(n);
    ok = in->read_image(0, 0, 0, spec.nchannels, type, image.bytes.data());
  } else {
    image.floats.resize(n);
    ok = in->read_image(0, 0, 0, spec.nchannels, type, image.floats.data());
  }
  INFO(in->geterror());
  REQUIRE(ok);
  in->close();
  return image;
}

uint32_t bitsOf(float f) {
  uint32_t u;
  std::memcpy(&u, &f, sizeof u);
  return u;
}

// Random finite floats over many magnitudes and both signs, with +inf sprinkled in.
std::vector<float> randomPixels(size_t count, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> mantissa(-1.0f, 1.0f);
  std::uniform_int_distribution<int> exponent(-20, 20);
  std::vector<float> values(count);
  for (size_t i = 0; i < count; ++i) values[i] = std::ldexp(mantissa(rng), exponent(rng));
  for (size_t i = 0; i < count; i += 7) values[i] = kInf;
  return values;
}

void requireBitExact(const std::vector<float>& expected, const std::vector<float>& actual) {
  REQUIRE(expected.size() == actual.size());
  for (size_t i = 0; i < expected.size(); ++i) {
    INFO("value " << i << ": wrote " << expected[i] << ", read " << actual[i]);
    REQUIRE(bitsOf(expected[i]) == bitsOf(actual[i]));
  }
}

// The reference: IEC 61966-2-1 in double, written out independently of the writer.
int expectedSrgb8(float linear) {
  double v = std::isnan(linear) ? 0.0 : static_cast<double>(linear);
  v = v < 0.0 ? 0.0 : (v > 1.0 ? 1.0 : v);
  const double s = v <= 0.0031308 ? v * 12.92 : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055;
  return static_cast<int>(std::floor(s * 255.0 + 0.5));
}

int expectedLinear8(float linear) {
  double v = std::isnan(linear) ? 0.0 : static_cast<double>(linear);
  v = v < 0.0 ? 0.0 : (v > 1.0 ? 1.0 : v);
  return static_cast<int>(std::floor(v * 255.0 + 0.5));
}

}  // namespace

TEST_CASE("EXR keeps float pixels bit for bit, +inf included", "[image_writer]") {
  ScratchDir dir;
  for (int channels : {1, 3, 4}) {
    SECTION(std::to_string(channels) + " channels") {
      const int w = 13, h = 7;
      const auto pixels = randomPixels(static_cast<size_t>(w) * h * channels, 1u + channels);
      const auto path = dir.file("out.exr");
      prism::writeImage(path, pixels.data(), w, h, channels);
      const auto image = readBack(path, OIIO::TypeDesc::FLOAT);
      REQUIRE(image.width == w);
      REQUIRE(image.height == h);
      REQUIRE(image.channels == channels);
      requireBitExact(pixels, image.floats);
    }
  }
}

TEST_CASE("PFM keeps float pixels bit for bit with the top row first", "[image_writer]") {
  ScratchDir dir;
  const int w = 5, h = 4;
  for (int channels : {1, 3}) {
    SECTION(std::to_string(channels) + " channels") {
      auto pixels = randomPixels(static_cast<size_t>(w) * h * channels, 10u + channels);
      pixels[0] = 1234.5f;  // a marker in the top-left pixel
      const auto path = dir.file("out.pfm");
      prism::writeImage(path, pixels.data(), w, h, channels);
      const auto image = readBack(path, OIIO::TypeDesc::FLOAT);
      REQUIRE(image.channels == channels);
      REQUIRE(image.floats[0] == 1234.5f);
      requireBitExact(pixels, image.floats);
    }
  }
  SECTION("RGBA drops alpha") {
    const auto pixels = randomPixels(static_cast<size_t>(w) * h * 4, 20u);
    const auto path = dir.file("rgba.pfm");
    prism::writeImage(path, pixels.data(), w, h, 4);
    const auto image = readBack(path, OIIO::TypeDesc::FLOAT);
    REQUIRE(image.channels == 3);
    std::vector<float> rgb;
    for (size_t i = 0; i < pixels.size(); ++i) {
      if (i % 4 != 3) rgb.push_back(pixels[i]);
    }
    requireBitExact(rgb, image.floats);
  }
}

TEST_CASE("TIFF keeps float pixels bit for bit", "[image_writer]") {
  ScratchDir dir;
  const int w = 6, h = 3;
  const auto pixels = randomPixels(static_cast<size_t>(w) * h * 4, 30u);
  const auto path = dir.file("out.tif");
  prism::writeImage(path, pixels.data(), w, h, 4);
  const auto image = readBack(path, OIIO::TypeDesc::FLOAT);
  REQUIRE(image.channels == 4);
  requireBitExact(pixels, image.floats);
}

TEST_CASE("HDR is written as RGB", "[image_writer]") {
  ScratchDir dir;
  const int w = 4, h = 2;
  SECTION("grey is repeated into three channels") {
    std::vector<float> grey(w * h);
    for (size_t i = 0; i < grey.size(); ++i) grey[i] = 0.25f * static_cast<float>(i + 1);
    const auto path = dir.file("grey.hdr");
    prism::writeImage(path, grey.data(), w, h, 1);
    const auto image = readBack(path, OIIO::TypeDesc::FLOAT);
    REQUIRE(image.channels == 3);
    for (size_t i = 0; i < grey.size(); ++i) {
      for (int c = 0; c < 3; ++c) REQUIRE(image.floats[i * 3 + c] == Approx(grey[i]).epsilon(0.01));
    }
  }
  SECTION("alpha is dropped") {
    std::vector<float> rgba(w * h * 4);
    for (size_t i = 0; i < rgba.size(); ++i) rgba[i] = (i % 4 == 3) ? 0.0f : 0.5f + 0.125f * (i % 4);
    const auto path = dir.file("rgba.hdr");
    prism::writeImage(path, rgba.data(), w, h, 4);
    const auto image = readBack(path, OIIO::TypeDesc::FLOAT);
    REQUIRE(image.channels == 3);
    for (size_t i = 0; i < size_t(w * h); ++i) {
      for (int c = 0; c < 3; ++c) REQUIRE(image.floats[i * 3 + c] == Approx(rgba[i * 4 + c]).epsilon(0.01));
    }
  }
}

TEST_CASE("PNG holds 8-bit sRGB colour and linear alpha", "[image_writer]") {
  ScratchDir dir;
  const int w = 32, h = 16, channels = 4;
  std::mt19937 rng(42);
  std::uniform_real_distribution<float> value(-0.2f, 1.2f);
  std::vector<float> pixels(static_cast<size_t>(w) * h * channels);
  for (auto& v : pixels) v = value(rng);
  // Non-finite values and the curve's linear segment near 0.
  const float specials[] = {std::nanf(""), kInf, -kInf, 0.0f, 1.0f, 0.0031308f, 0.002f, 0.5f};
  for (size_t i = 0; i < sizeof specials / sizeof specials[0]; ++i) pixels[i] = specials[i];
  pixels[3] = 0.5f;  // first pixel's alpha, kept away from the top-row marker check below

  const auto path = dir.file("out.png");
  prism::writeImage(path, pixels.data(), w, h, channels);
  const auto image = readBack(path, OIIO::TypeDesc::UINT8);
  REQUIRE(image.width == w);
  REQUIRE(image.height == h);
  REQUIRE(image.channels == channels);
  for (size_t i = 0; i < pixels.size(); ++i) {
    const bool alpha = i % 4 == 3;
    const int expected = alpha ? expectedLinear8(pixels[i]) : expectedSrgb8(pixels[i]);
    INFO("value " << i << " = " << pixels[i] << (alpha ? " (alpha)" : ""));
    REQUIRE(static_cast<int>(image.bytes[i]) == expected);
  }
  REQUIRE(image.bytes[0] == 0);    // NaN
  REQUIRE(image.bytes[1] == 255);  // +inf
  REQUIRE(image.bytes[2] == 0);    // -inf
  REQUIRE(image.bytes[3] == 128);  // alpha 0.5 stays linear
}

TEST_CASE("PNG takes grey and RGB, and the extension's case does not matter", "[image_writer]") {
  ScratchDir dir;
  const float grey[] = {0.0f, 0.18f, 0.5f, 1.0f};
  prism::writeImage(dir.file("grey.PNG"), grey, 2, 2, 1);
  const auto image = readBack(dir.file("grey.PNG"), OIIO::TypeDesc::UINT8);
  REQUIRE(image.channels == 1);
  for (int i = 0; i < 4; ++i) REQUIRE(static_cast<int>(image.bytes[i]) == expectedSrgb8(grey[i]));

  const float rgb[] = {0.1f, 0.2f, 0.3f};
  prism::writeImage(dir.file("rgb.png"), rgb, 1, 1, 3);
  const auto pixel = readBack(dir.file("rgb.png"), OIIO::TypeDesc::UINT8);
  REQUIRE(pixel.channels == 3);
  for (int c = 0; c < 3; ++c) REQUIRE(static_cast<int>(pixel.bytes[c]) == expectedSrgb8(rgb[c]));
}

TEST_CASE("a successful write leaves only the output file", "[image_writer]") {
  ScratchDir dir;
  const float pixel[] = {0.5f, 0.5f, 0.5f, 1.0f};
  prism::writeImage(dir.file("a.exr"), pixel, 1, 1, 4);
  prism::writeImage(dir.file("a.exr"), pixel, 1, 1, 4);  // overwriting is fine
  REQUIRE(dir.entries() == std::vector<std::string>{"a.exr"});
}

TEST_CASE("an unknown or missing extension is refused with the formats listed", "[image_writer]") {
  ScratchDir dir;
  const float pixel[] = {1.0f, 1.0f, 1.0f};
  const auto path = dir.file("out.xyz");
  REQUIRE_THROWS_MATCHES(prism::writeImage(path, pixel, 1, 1, 3), prism::ImageError,
                         Catch::Message(path + ": unknown image format '.xyz' "
                                               "(expected .png, .exr, .hdr, .pfm, .tif)"));
  REQUIRE_THROWS_WITH(prism::writeImage(dir.file("noext"), pixel, 1, 1, 3),
                      Catch::Contains(dir.file("noext")) && Catch::Contains(".png, .exr"));
  REQUIRE(dir.entries().empty());
}

TEST_CASE("a write into a missing folder names the path and leaves no file", "[image_writer]") {
  ScratchDir dir;
  const float pixel[] = {1.0f, 1.0f, 1.0f, 1.0f};
  for (const char* name : {"out.png", "out.exr", "out.pfm", "out.hdr", "out.tif"}) {
    const auto path = dir.file(std::string("missing/") + name);
    REQUIRE_THROWS_AS(prism::writeImage(path, pixel, 1, 1, 4), prism::ImageError);
    REQUIRE_THROWS_WITH(prism::writeImage(path, pixel, 1, 1, 4), Catch::StartsWith(path + ": "));
    REQUIRE_FALSE(fs::exists(path));
  }
  REQUIRE(dir.entries().empty());
}

TEST_CASE("a write that fails at the last step removes its temporary file", "[image_writer]") {
  ScratchDir dir;
  // The target name is taken by a folder, so the final rename fails.
  fs::create_directory(dir.path / "taken.png");
  const float pixel[] = {1.0f, 1.0f, 1.0f};
  REQUIRE_THROWS_WITH(prism::writeImage(dir.file("taken.png"), pixel, 1, 1, 3),
                      Catch::StartsWith(dir.file("taken.png") + ": "));
  REQUIRE(dir.entries() == std::vector<std::string>{"taken.png"});
  REQUIRE(fs::is_directory(dir.path / "taken.png"));
}

TEST_CASE("bad sizes and channel counts are refused", "[image_writer]") {
  ScratchDir dir;
  const float pixel[] = {1.0f, 1.0f};
  REQUIRE_THROWS_AS(prism::writeImage(dir.file("a.exr"), pixel, 1, 1, 2), std::invalid_argument);
  REQUIRE_THROWS_AS(prism::writeImage(dir.file("a.exr"), pixel, 0, 1, 1), std::invalid_argument);
  REQUIRE_THROWS_AS(prism::writeImage(dir.file("a.exr"), nullptr, 1, 1, 1), std::invalid_argument);
  REQUIRE(dir.entries().empty());
}
