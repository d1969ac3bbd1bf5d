#include "render_args.h"

#include <algorithm>
#include <cctype>

#include "args.h"

namespace prism_cli {
namespace {

const std::vector<OptionSpec> kRenderOptions = {
    {"--output", "-o", true},  {"--width", "", true},     {"--height", "", true},
    {"--spp", "", true},       {"--max-depth", "", true}, {"--min-weight", "", true},
    {"--device", "", true},    {"--aov", "", true},       {"--seed", "", true},
    {"--no-cache", "", false}, {"--quiet", "", false},    {"--help", "-h", false},
    {"--accel", "", true},     {"--camera-pos", "", true}, {"--camera-look", "", true},
    {"--camera-up", "", true}, {"--fov", "", true},    {"--aperture", "", true},
    {"--focus-distance", "", true}, {"--stats", "", false},
    {"--aa", "", true},        {"--filter", "", true},    {"--aa-threshold", "", true},
    {"--aa-max-level", "", true}, {"--first-hit", "", true}, {"--inside-test", "", true},
    {"--shadows", "", true},   {"--bounds", "", true},    {"--check-nan", "", false},
    {"--frames", "", true},
};

// "K" or "A-B" with A <= B, frame numbers from 0.
std::pair<uint32_t, uint32_t> parseFrames(const std::string& text) {
  auto number = [&](const std::string& part) {
    if (part.empty() || part.size() > 9 || !std::all_of(part.begin(), part.end(), [](unsigned char c) {
          return std::isdigit(c) != 0;
        }))
      throw UsageError("--frames: expected a frame number K or a range A-B (from 0), got '" + text + "'");
    return static_cast<uint32_t>(std::stoul(part));
  };
  const size_t dash = text.find('-');
  if (dash == std::string::npos) {
    const uint32_t k = number(text);
    return {k, k};
  }
  const uint32_t first = number(text.substr(0, dash)), last = number(text.substr(dash + 1));
  if (last < first) throw UsageError("--frames: the range " + text + " ends before it starts");
  return {first, last};
}

// The same list as the library's image writer, checked here so that a typo in -o
// does not cost a whole render.
bool isKnownImageFormat(const std::string& ext) {
  return ext == ".png" || ext == ".exr" || ext == ".hdr" || ext == ".pfm" || ext == ".tif" || ext == ".tiff";
}

void checkOutput(const RenderRequest& request) {
  const std::string ext = lowerExtension(request.output_path);
  if (!isKnownImageFormat(ext)) {
    throw UsageError("--output: unknown image format '" + ext + "' in '" + request.output_path +
                     "' (expected .png, .exr, .hdr, .pfm, .tif)");
  }
  if (request.aov && (*request.aov == PRISM_AOV_DEPTH || *request.aov == PRISM_AOV_PRIMID) && ext == ".png") {
    const char* name = *request.aov == PRISM_AOV_DEPTH ? "depth" : "primid";
    throw UsageError(std::string("--aov ") + name + " cannot be written to '" + request.output_path +
                     "': 8-bit PNG cannot hold its values (+inf, -1, distances over 1); "
                     "use a float format: .exr, .pfm, .tif or .hdr");
  }
}

}  // namespace

std::string frameOutputPath(const std::string& path, uint32_t frame, uint32_t frames) {
  if (frames <= 1) return path;
  const size_t slash = path.find_last_of('/');
  const size_t name_start = slash == std::string::npos ? 0 : slash + 1;
  const size_t hash_end = path.find_last_of('#');
  if (hash_end != std::string::npos && hash_end >= name_start) {
    size_t hash_start = hash_end;
    while (hash_start > name_start && path[hash_start - 1] == '#') --hash_start;
    std::string number = std::to_string(frame);
    const size_t width = hash_end + 1 - hash_start;
    if (number.size() < width) number.insert(0, width - number.size(), '0');
    return path.substr(0, hash_start) + number + path.substr(hash_end + 1);
  }
  const size_t width = std::max<size_t>(4, std::to_string(frames - 1).size());
  std::string number = std::to_string(frame);
  number.insert(0, width - number.size(), '0');
  const size_t extension = path.size() - lowerExtension(path).size();
  return path.substr(0, extension) + "_" + number + path.substr(extension);
}

std::string lowerExtension(const std::string& path) {
  const size_t slash = path.find_last_of('/');
  const size_t dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash) || dot == slash + 1) return "";
  std::string ext = path.substr(dot);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

RenderRequest parseRenderArgs(const std::vector<std::string>& args) {
  const ParsedArgs parsed = parseArgs(args, kRenderOptions, "prism render");
  RenderRequest request;
  if (parsed.has("--help")) {
    request.help = true;
    return request;
  }

  const auto& positionals = parsed.positionals();
  if (positionals.empty()) throw UsageError("missing the scene file (prism render SCENE.json -o OUT)");
  if (positionals.size() > 1) {
    throw UsageError("one scene file at a time (got '" + positionals[0] + "' and '" + positionals[1] + "')");
  }
  request.scene_path = positionals[0];

  const auto output = parsed.text("--output");
  if (!output) throw UsageError("missing -o OUT, the image file to write (e.g. -o out.png)");
  if (output->empty()) throw UsageError("--output: empty file name");
  request.output_path = *output;

  request.width = parsed.uint32("--width", 0);
  request.height = parsed.uint32("--height", 0);
  request.spp = parsed.uint32("--spp", 0);
  request.max_depth = parsed.uint32("--max-depth", 0);
  request.min_weight = parsed.nonNegativeFloat("--min-weight");
  request.seed = parsed.uint64("--seed");
  request.device = parsed.text("--device").value_or("");
  request.use_kernel_cache = !parsed.has("--no-cache");
  request.quiet = parsed.has("--quiet");
  request.stats = parsed.has("--stats");
  request.check_nan = parsed.has("--check-nan");
  if (const auto text = parsed.text("--frames")) request.frames = parseFrames(*text);

  if (const auto aov_name = parsed.text("--aov")) {
    PrismAov aov;
    if (prismParseAov(aov_name->c_str(), &aov) != PRISM_OK) {
      throw UsageError("--aov: unknown AOV '" + *aov_name + "' (expected depth, normal, primid or albedo)");
    }
    request.aov = aov;
  }
  if (const auto accel_name = parsed.text("--accel")) {
    PrismAccel accel;
    if (prismParseAccel(accel_name->c_str(), &accel) != PRISM_OK)
      throw UsageError("--accel: unknown structure '" + *accel_name + "' (expected auto, bvh, octree, bsp or none)");
    request.accel = accel;
  }
  if (const auto name = parsed.text("--aa")) {
    PrismAa aa;
    if (prismParseAa(name->c_str(), &aa) != PRISM_OK)
      throw UsageError("--aa: unknown mode '" + *name +
                       "' (expected none, grid, quincunx, adaptive, jitter, poisson, random or auto)");
    request.aa = aa;
  }
  if (const auto name = parsed.text("--filter")) {
    PrismFilter filter;
    if (prismParseFilter(name->c_str(), &filter) != PRISM_OK)
      throw UsageError("--filter: unknown filter '" + *name + "' (expected box, tent, gaussian or mitchell)");
    request.filter = filter;
  }
  request.aa_threshold = parsed.nonNegativeFloat("--aa-threshold");
  // Ranges and combinations (--aa grid with a square --spp, ...) are the
  // library's to check, once the scene's options are known (render_command.cpp).
  request.aa_max_level = parsed.uint32("--aa-max-level", 0);
  if (const auto name = parsed.text("--first-hit")) {
    PrismFirstHit first_hit;
    if (prismParseFirstHit(name->c_str(), &first_hit) != PRISM_OK)
      throw UsageError("--first-hit: unknown mode '" + *name + "' (expected zbuffer, trace or auto)");
    request.first_hit = first_hit;
  }
  if (const auto name = parsed.text("--inside-test")) {
    PrismInsideTest inside_test;
    if (prismParseInsideTest(name->c_str(), &inside_test) != PRISM_OK)
      throw UsageError("--inside-test: unknown test '" + *name + "' (expected crossing, radial or left-right)");
    request.inside_test = inside_test;
  }
  if (const auto name = parsed.text("--shadows")) {
    PrismShadows shadows;
    if (prismParseShadows(name->c_str(), &shadows) != PRISM_OK)
      throw UsageError("--shadows: unknown mode '" + *name + "' (expected auto, accel or lightbuffer)");
    request.shadows = shadows;
  }
  if (const auto name = parsed.text("--bounds")) {
    PrismBounds bounds;
    if (prismParseBounds(name->c_str(), &bounds) != PRISM_OK)
      throw UsageError("--bounds: unknown bounds '" + *name + "' (expected aabb or kdop)");
    request.bounds = bounds;
  }
  request.camera_pos = parsed.triple("--camera-pos");
  request.camera_look = parsed.triple("--camera-look");
  request.camera_up = parsed.triple("--camera-up");
  request.fov = parsed.floatBetween("--fov", 0, 180);
  request.aperture = parsed.nonNegativeFloat("--aperture");
  request.focus_distance = parsed.nonNegativeFloat("--focus-distance");
  if (request.focus_distance && !(*request.focus_distance > 0))
    throw UsageError("--focus-distance: expected a positive distance, got '" + *parsed.text("--focus-distance") + "'");
  checkOutput(request);
  return request;
}

}  // namespace prism_cli
