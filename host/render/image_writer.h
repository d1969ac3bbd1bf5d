// Writes linear float pixels to an image file (OpenImageIO; PFM by hand). The format follows
// the extension: .png is 8-bit sRGB (encoded here, not by OIIO); .exr, .hdr, .pfm and
// .tif/.tiff keep linear floats. Colour management beyond the sRGB curve is left out.
#pragma once

#include <stdexcept>
#include <string>

namespace prism {

// A file that could not be written, or an unknown format; the message names the path.
class ImageError : public std::runtime_error {
 public:
  explicit ImageError(const std::string& message) : std::runtime_error(message) {}
};

// `pixels` holds width*height*channels floats, rows top to bottom, channels 1 (grey),
// 3 (RGB) or 4 (RGBA; alpha is written linear). The file appears only once complete:
// it is written under a temporary name in the same folder and renamed.
// Throws std::invalid_argument for a bad size or channel count, ImageError otherwise.
void writeImage(const std::string& path, const float* pixels, int width, int height, int channels);

}  // namespace prism
