// Images for texturing, read by OpenImageIO into linear RGB: the texels the
// kernels sample bilinearly (kernels/shading/texture.h). 8- and 16-bit images
// are sRGB-encoded unless the file says otherwise (or the scene does), and are
// decoded here with the exact sRGB curve, so the kernels work in linear light.
#pragma once

#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace prism {

// Texels of every image of a scene together, at most (float4 each on the device).
constexpr std::size_t kMaxTextureTexels = std::size_t(1) << 26;

struct ImageTexture {
  std::string file;
  int width = 0, height = 0;
  bool srgb = true;        // whether the file's values were decoded from sRGB
  std::vector<float> rgb;  // linear, 3 per texel, rows top to bottom
};
using SharedImage = std::shared_ptr<const ImageTexture>;

struct ImageTextureError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The sRGB transfer function's inverse (IEC 61966-2-1): an encoded value in
// [0, 1] to linear light.
double srgbToLinear(double encoded);

// Reads a regular file's first subimage: grey or RGB, with or without alpha
// (more colour channels keep the first three). Alpha is left out, and the
// colour is the file's own, not multiplied by alpha. `srgb`: decode from sRGB;
// empty: as the file says (its colour space), else sRGB for integer pixels and
// linear for floats. `texels_held`: the texels of the scene's images read
// before it; the image is refused, before its pixels are read, when it would
// take them past kMaxTextureTexels. Throws ImageTextureError naming the file
// and what is wrong.
SharedImage readImageTexture(const std::string& path, std::optional<bool> srgb, std::size_t texels_held);

}  // namespace prism
