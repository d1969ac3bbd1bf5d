#include "scene/image_texture.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace prism {

double srgbToLinear(double encoded) {
  return encoded <= 0.04045 ? encoded / 12.92 : std::pow((encoded + 0.055) / 1.055, 2.4);
}

namespace {

// The channels holding colour: all but alpha. Grey (one) or RGB (the first three).
std::vector<int> colourChannels(const OIIO::ImageSpec& spec, const std::string& path) {
  std::vector<int> colour;
  for (int c = 0; c < spec.nchannels; ++c)
    if (c != spec.alpha_channel) colour.push_back(c);
  if (colour.size() == 1) return {colour[0], colour[0], colour[0]};
  if (colour.size() >= 3) return {colour[0], colour[1], colour[2]};
  std::string names;
  for (const std::string& n : spec.channelnames) names += (names.empty() ? "" : ", ") + n;
  throw ImageTextureError(path + ": " + std::to_string(colour.size()) + " colour channels (" + names +
                          "); expected grey or RGB, with or without alpha");
}

}  // namespace

SharedImage readImageTexture(const std::string& path, std::optional<bool> srgb, std::size_t texels_held) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);
  if (ec || !fs::exists(st)) throw ImageTextureError(path + ": cannot open: no such file");
  if (fs::is_directory(st)) throw ImageTextureError(path + ": is a folder, not an image");
  if (!fs::is_regular_file(st)) throw ImageTextureError(path + ": is not a regular file");
  // The colour as the file stores it: prism has no use for alpha, and
  // OpenImageIO would otherwise multiply by it the colour of formats that
  // keep the two apart (PNG, TGA), blackening transparent texels.
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  auto in = OIIO::ImageInput::open(path, &config);
  if (!in) throw ImageTextureError(path + ": cannot read as an image: " + OIIO::geterror());
  const OIIO::ImageSpec& spec = in->spec();
  if (spec.width < 1 || spec.height < 1 || spec.depth > 1 || spec.nchannels < 1)
    throw ImageTextureError(path + ": not a 2D image with pixels");
  const std::size_t texels = static_cast<std::size_t>(spec.width) * spec.height;
  const std::string size = std::to_string(spec.width) + " x " + std::to_string(spec.height) + " texels";
  if (texels > kMaxTextureTexels)
    throw ImageTextureError(path + ": " + size + ", more than the " + std::to_string(kMaxTextureTexels) +
                            " textures may hold");
  if (texels > kMaxTextureTexels - std::min(texels_held, kMaxTextureTexels))
    throw ImageTextureError(path + ": " + size + ", which with the " + std::to_string(texels_held) +
                            " texels of the scene's images before it pass the " + std::to_string(kMaxTextureTexels) +
                            " texels textures may hold together");
  const std::vector<int> channel = colourChannels(spec, path);
  std::vector<float> pixels(texels * spec.nchannels);
  if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, pixels.data())) {
    const std::string why = in->geterror();
    throw ImageTextureError(path + ": cannot read its pixels: " + (why.empty() ? "the file is damaged or ends early" : why));
  }
  in->close();
  auto image = std::make_shared<ImageTexture>();
  image->file = path;
  image->width = spec.width;
  image->height = spec.height;
  if (srgb) {
    image->srgb = *srgb;
  } else {
    const std::string space = spec.get_string_attribute("oiio:ColorSpace");
    const bool integer = spec.format.basetype != OIIO::TypeDesc::FLOAT && spec.format.basetype != OIIO::TypeDesc::HALF &&
                         spec.format.basetype != OIIO::TypeDesc::DOUBLE;
    image->srgb = space == "sRGB" || (space != "Linear" && space != "linear" && integer);
  }
  image->rgb.resize(texels * 3);
  for (std::size_t t = 0; t < texels; ++t)
    for (int c = 0; c < 3; ++c) {
      const float v = pixels[t * spec.nchannels + channel[c]];
      const double x = std::isfinite(v) ? std::clamp(double(v), 0.0, 1e6) : 0.0;
      image->rgb[3 * t + c] = static_cast<float>(image->srgb ? srgbToLinear(std::min(x, 1.0)) : x);
    }
  return image;
}

}  // namespace prism
