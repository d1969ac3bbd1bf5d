#!/usr/bin/env python3
"""Rewrites a checkout of prism (argument: its folder) to build without OpenImageIO,
for a lent GPU machine that has none of prism's Debian packages: OpenImageIO
brings 268 libraries (353 MB) that cannot travel there. The build writes PFM only,
reads PNG textures through libpng, draws no benchmark plots and leaves out the two
test files that call OpenImageIO directly. Everything else, every kernel among it,
is as in the real build. For docs/devices.md's runs only: never commit the result."""
import pathlib
import sys

src = pathlib.Path(sys.argv[1])


def edit(path, old, new):
    p = src / path
    text = p.read_text()
    if old not in text:
        sys.exit(f"oiio_free.py: {path} has changed; update this script")
    p.write_text(text.replace(old, new, 1))


def cut(path, start, end, new):
    """Replaces the text from `start` up to (not including) `end`."""
    p = src / path
    text = p.read_text()
    i = text.find(start)
    j = text.find(end, i) if i >= 0 else -1
    if j < 0:
        sys.exit(f"oiio_free.py: {path} has changed; update this script")
    p.write_text(text[:i] + new + text[j:])


edit("CMakeLists.txt", "pkg_check_modules(OIIO REQUIRED IMPORTED_TARGET OpenImageIO)",
     "add_library(PkgConfig::OIIO INTERFACE IMPORTED)\n"
     "set_target_properties(PkgConfig::OIIO PROPERTIES INTERFACE_LINK_LIBRARIES png16)")

edit("host/render/image_writer.cpp", "#include <OpenImageIO/imageio.h>\n", "")
cut("host/render/image_writer.cpp", "void writeWithOiio(", "}  // namespace\n",
    "void writeWithOiio(const std::string&, const fs::path&, Format, const float*, int, int, int) {\n"
    '  throw std::runtime_error("this device build of prism writes PFM only");\n}\n\n')

edit("host/scene/image_texture.cpp", "#include <OpenImageIO/imageio.h>\n", "#include <png.h>\n")
cut("host/scene/image_texture.cpp", "  auto in = OIIO::ImageInput::open(path);", "  return image;\n}", """\
  png_image img{};
  img.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&img, path.c_str()))
    throw ImageTextureError(path + ": this device build of prism reads PNG only: " + img.message);
  img.format = PNG_FORMAT_RGB;
  std::vector<unsigned char> bytes(PNG_IMAGE_SIZE(img));
  if (!png_image_finish_read(&img, nullptr, bytes.data(), 0, nullptr)) throw ImageTextureError(path + ": " + img.message);
  const std::size_t texels = static_cast<std::size_t>(img.width) * img.height;
  auto image = std::make_shared<ImageTexture>();
  image->file = path;
  image->width = static_cast<int>(img.width);
  image->height = static_cast<int>(img.height);
  image->srgb = srgb ? *srgb : true;
  image->rgb.resize(texels * 3);
  for (std::size_t i = 0; i < texels * 3; ++i) {
    const double x = bytes[i] / 255.0;
    image->rgb[i] = static_cast<float>(image->srgb ? srgbToLinear(x) : x);
  }
""")

edit("benchmarks/plot_png.cpp", "#include <OpenImageIO/imageio.h>\n", "")
cut("benchmarks/plot_png.cpp", "  std::unique_ptr<OIIO::ImageOutput> out", "}\n\n}  // namespace prism::bench",
    "  (void)px;\n  (void)path;\n")

edit("benchmarks/povray_bench.cpp", "#include <OpenImageIO/imagebuf.h>\n#include <OpenImageIO/imagebufalgo.h>\n", "")
cut("benchmarks/povray_bench.cpp", "    OIIO::ImageBuf a(pov_png)", "    const double pov_s",
    "    struct { double meanerror = 0, maxerror = 0; long nwarn = 0, nfail = 0; } cmp;\n")

for test in ("tests/render/texture_test.cpp", "tests/host/image_writer_test.cpp"):
    (src / test).unlink()
