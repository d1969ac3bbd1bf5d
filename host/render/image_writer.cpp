// Image output for films and AOVs: format by extension, sRGB encoding for PNG, channel
// adaptation for formats with fixed layouts (HDR: RGB, PFM: grey or RGB), and
// write-to-temporary-then-rename so a failed write leaves nothing behind. OpenImageIO
// writes every format except PFM, which OIIO 2.4 can read but not write.
#include "render/image_writer.h"

#include <OpenImageIO/imageio.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <system_error>
#include <vector>

namespace prism {
namespace {

namespace fs = std::filesystem;

enum class Format { Png, Exr, Hdr, Pfm, Tiff };

const char* const kExpectedFormats = "(expected .png, .exr, .hdr, .pfm, .tif)";

Format formatFromPath(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  if (ext == ".png") return Format::Png;
  if (ext == ".exr") return Format::Exr;
  if (ext == ".hdr") return Format::Hdr;
  if (ext == ".pfm") return Format::Pfm;
  if (ext == ".tif" || ext == ".tiff") return Format::Tiff;
  if (ext.empty()) throw ImageError(path + ": no extension to choose an image format " + kExpectedFormats);
  throw ImageError(path + ": unknown image format '" + fs::path(path).extension().string() + "' " +
                   kExpectedFormats);
}

// HDR (RGBE) holds exactly RGB; PFM holds grey or RGB. Others take 1, 3 or 4 as given.
int channelsOnDisk(Format format, int channels) {
  if (format == Format::Hdr) return 3;
  if (format == Format::Pfm) return channels == 4 ? 3 : channels;
  return channels;
}

std::vector<float> adaptChannels(const float* pixels, size_t count, int from, int to) {
  std::vector<float> out(count * static_cast<size_t>(to));
  for (size_t i = 0; i < count; ++i) {
    for (int c = 0; c < to; ++c) {
      // 1 -> 3 repeats grey; 4 -> 3 drops alpha.
      out[i * to + c] = pixels[i * from + (from == 1 ? 0 : c)];
    }
  }
  return out;
}

// The sRGB OETF (IEC 61966-2-1) to 8 bits, in double so that values on a rounding
// boundary land the same way on every compiler; NaN gives 0, +inf gives 255.
unsigned char encodeSrgb8(float linear) {
  if (std::isnan(linear)) return 0;
  const double v = std::clamp(static_cast<double>(linear), 0.0, 1.0);
  const double encoded = v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055;
  return static_cast<unsigned char>(std::lround(std::clamp(encoded, 0.0, 1.0) * 255.0));
}

std::vector<unsigned char> encodePng(const float* pixels, size_t count, int channels) {
  std::vector<unsigned char> out(count * static_cast<size_t>(channels));
  for (size_t i = 0; i < out.size(); ++i) {
    const bool alpha = channels == 4 && i % 4 == 3;
    if (alpha) {
      const float a = pixels[i];
      const double clamped = std::isnan(a) ? 0.0 : std::clamp(static_cast<double>(a), 0.0, 1.0);
      out[i] = static_cast<unsigned char>(std::lround(clamped * 255.0));
    } else {
      out[i] = encodeSrgb8(pixels[i]);
    }
  }
  return out;
}

// A hidden sibling with a name unique to this process and call, keeping the folder
// (so rename stays on one file system) and the extension.
fs::path temporaryPathFor(const fs::path& target) {
  static std::atomic<unsigned> counter{0};
  std::string name = "." + target.stem().string() + ".tmp-" + std::to_string(::getpid()) + "-" +
                     std::to_string(counter++) + target.extension().string();
  return target.parent_path() / name;
}

void removeQuietly(const fs::path& path) {
  std::error_code ignored;
  fs::remove(path, ignored);
}

// PFM by hand: OIIO 2.4 reads PFM but has no PFM writer. The format is a text header,
// then float rows from the bottom up in the byte order the scale's sign announces.
void writePfm(const fs::path& file, const float* pixels, int width, int height, int channels) {
  std::ofstream out(file, std::ios::binary);
  if (!out) throw std::runtime_error("could not open \"" + file.string() + "\": " + std::strerror(errno));
  const uint16_t probe = 1;
  const bool little_endian = *reinterpret_cast<const unsigned char*>(&probe) == 1;
  out << (channels == 1 ? "Pf" : "PF") << '\n' << width << ' ' << height << '\n'
      << (little_endian ? "-1.0" : "1.0") << '\n';
  const size_t row_floats = static_cast<size_t>(width) * channels;
  for (int row = height - 1; row >= 0; --row) {
    out.write(reinterpret_cast<const char*>(pixels + row * row_floats),
              static_cast<std::streamsize>(row_floats * sizeof(float)));
  }
  out.close();
  if (!out) throw std::runtime_error("could not write \"" + file.string() + "\": " + std::strerror(errno));
}

void writeWithOiio(const std::string& path, const fs::path& file, Format format, const float* pixels,
                   int width, int height, int channels) {
  const size_t count = static_cast<size_t>(width) * static_cast<size_t>(height);
  OIIO::ImageSpec spec(width, height, channels,
                       format == Format::Png ? OIIO::TypeDesc::UINT8 : OIIO::TypeDesc::FLOAT);
  std::vector<unsigned char> bytes;
  const void* data = pixels;
  OIIO::TypeDesc data_type = OIIO::TypeDesc::FLOAT;
  if (format == Format::Png) {
    bytes = encodePng(pixels, count, channels);
    data = bytes.data();
    data_type = OIIO::TypeDesc::UINT8;
    spec.attribute("oiio:ColorSpace", "sRGB");
    // Our colour is not premultiplied; without this OIIO would divide it by alpha.
    spec.attribute("oiio:UnassociatedAlpha", 1);
  } else {
    spec.attribute("oiio:ColorSpace", "linear");
  }

  // The writer is chosen by the real name; the data goes to the temporary one.
  auto out = OIIO::ImageOutput::create(path);
  if (!out) throw std::runtime_error(OIIO::geterror());
  if (!out->open(file.string(), spec)) throw std::runtime_error(out->geterror());
  const bool written = out->write_image(data_type, data);
  std::string reason = written ? std::string() : out->geterror();
  // close() flushes (PNG writes on close), so its failure is a failed write too.
  if (!out->close() && reason.empty()) reason = out->geterror();
  if (!written || !reason.empty()) {
    throw std::runtime_error(reason.empty() ? "unknown OpenImageIO error" : reason);
  }
}

}  // namespace

void writeImage(const std::string& path, const float* pixels, int width, int height, int channels) {
  if (pixels == nullptr) throw std::invalid_argument(path + ": no pixel data");
  if (width <= 0 || height <= 0) {
    throw std::invalid_argument(path + ": bad image size " + std::to_string(width) + "x" + std::to_string(height));
  }
  if (channels != 1 && channels != 3 && channels != 4) {
    throw std::invalid_argument(path + ": " + std::to_string(channels) + " channels (expected 1, 3 or 4)");
  }
  const Format format = formatFromPath(path);
  const size_t count = static_cast<size_t>(width) * static_cast<size_t>(height);
  const int disk_channels = channelsOnDisk(format, channels);
  std::vector<float> adapted;
  if (disk_channels != channels) {
    adapted = adaptChannels(pixels, count, channels, disk_channels);
    pixels = adapted.data();
  }

  const fs::path target(path);
  // Said plainly here, since the writers would only name the temporary file.
  const fs::path folder = target.parent_path().empty() ? fs::path(".") : target.parent_path();
  std::error_code error;
  if (!fs::is_directory(folder, error)) {
    throw ImageError(path + ": cannot write image: folder '" + folder.string() + "' does not exist");
  }
  const fs::path temporary = temporaryPathFor(target);
  try {
    if (format == Format::Pfm) {
      writePfm(temporary, pixels, width, height, disk_channels);
    } else {
      writeWithOiio(path, temporary, format, pixels, width, height, disk_channels);
    }
    fs::rename(temporary, target);
  } catch (const fs::filesystem_error& e) {
    removeQuietly(temporary);
    throw ImageError(path + ": cannot write image: " + e.code().message());
  } catch (const std::exception& e) {
    removeQuietly(temporary);
    throw ImageError(path + ": cannot write image: " + e.what());
  }
}

}  // namespace prism
