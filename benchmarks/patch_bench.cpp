#include "patch_bench.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <sstream>

#include "accel_workloads.h"
#include "bench_options.h"
#include "device/context.h"
#include "device/device_list.h"
#include "render/gpu_scene.h"
#include "render/ray_queries.h"
#include "scene/patches/bpt_file.h"
#include "scene/patches/patch_subdivision.h"
#include "scene/primitives/primitive_kind.h"
#include "scene_format/scene_loader.h"

namespace prism::bench {
namespace {

const char* kUsage =
    "usage: prism-bench patches [--device D] [--file F.bpt] [--tolerances X,...] [--camera N]\n"
    "                           [--random N] [--check N] [--repeat N]\n"
    "\n"
    "Ray traces the Bezier patches of --file (default: the teapot in tests/data/patches)\n"
    "by Newton iteration on patch pieces (\"analytic\") and by successive subdivision\n"
    "into triangles at each tolerance of --tolerances, given as fractions of the\n"
    "patches' size (default 0.004,0.001,0.00025), through the same BVH:\n"
    "  prims      pieces or triangles          set-up  subdivision or cutting, seconds\n"
    "  build      BVH build, seconds           camera  N x N primary rays (default 512)\n"
    "  random     incoherent rays (default 262144), both in Mrays/s and as a ratio to\n"
    "             the analytic method, the median of --repeat runs (default 3)\n"
    "  accuracy   on --check camera rays (default 2000), against successive subdivision\n"
    "             along each ray in double: hit/miss disagreements, and the distance\n"
    "             between the hits times the cosine of incidence (the distance of the\n"
    "             hit from the surface), median, 99.9th percentile and largest, in units\n"
    "             of the size.\n";

struct Variant {
  std::string name;
  Scene scene;
  double setup_seconds = 0;
};

Variant loadVariant(const std::string& file, const std::string& method, double tolerance) {
  std::ostringstream json;
  json.precision(17);
  json << R"({"objects": [{"type": "patches", "file": ")" << file << R"(", "method": ")" << method << '"';
  if (tolerance > 0) json << R"(, "tolerance": )" << tolerance;
  json << "}]}";
  const auto start = std::chrono::steady_clock::now();
  Variant v{method == "analytic" ? "analytic" : "subdivision", parseScene(json.str(), "patches"), 0};
  v.setup_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return v;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0 : v[v.size() / 2];
}

}  // namespace

int patchMain(const std::vector<std::string>& args) {
  std::string device_name, file = PRISM_SOURCE_DIR "/tests/data/patches/teapot.bpt";
  std::vector<double> tolerances = {0.004, 0.001, 0.00025};
  int camera = 512, repeats = 3;
  std::size_t random_count = 262144, check = 2000;
  const int status = parseBenchOptions(args, "patches", kUsage, [&](const std::string& a, const OptionValue& value) {
    if (a == "--device") {
      device_name = value();
    } else if (a == "--file") {
      file = value();
    } else if (a == "--tolerances") {
      tolerances.clear();
      std::stringstream ss(value());
      for (std::string s; std::getline(ss, s, ',');) tolerances.push_back(std::stod(s));
      for (double t : tolerances)
        if (!(t >= 1e-6 && t < 1)) throw std::invalid_argument("--tolerances: each must be in [1e-6, 1)");
    } else if (a == "--camera") {
      camera = std::max(1, std::stoi(value()));
    } else if (a == "--random") {
      random_count = std::stoul(value());
    } else if (a == "--check") {
      check = std::stoul(value());
    } else if (a == "--repeat") {
      repeats = std::max(1, std::stoi(value()));
    } else {
      throw std::invalid_argument("unknown option '" + a + "'");
    }
  });
  if (status >= 0) return status;
  try {
    const double size = patchSetSize(readBptFile(file));
    std::vector<Variant> variants;
    variants.push_back(loadVariant(file, "analytic", 0));
    for (double t : tolerances) variants.push_back(loadVariant(file, "subdivision", t * size));
    Context context(selectDevice(device_name), true);
    std::vector<std::unique_ptr<RayQueryEngine>> engines;
    std::vector<double> build_seconds;
    std::vector<std::size_t> prims;
    Aabb box;  // of the analytic variant, the first: the rays frame it
    for (const Variant& v : variants) {
      SceneGeometry geometry = flattenScene(v.scene, RenderOptions::fromScene(v.scene));
      if (&v == &variants.front()) box = boundsOf(geometry.objects);
      prims.push_back(v.scene.objects[0].primitiveCount());
      const auto start = std::chrono::steady_clock::now();
      engines.push_back(std::make_unique<RayQueryEngine>(context, std::move(geometry), AccelKind::Bvh));
      build_seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() -
                              engines.back()->compileSeconds());
    }
    // Framed closer than cameraRays frames a box (its margin suits scenes of
    // many objects): the teapot fills about half of the image.
    Aabb framed = box;
    for (int a = 0; a < 3; ++a) {
      const float c = 0.5f * (box.lo[a] + box.hi[a]), h = 0.5f * (box.hi[a] - box.lo[a]);
      framed.lo[a] = c - 0.45f * h;
      framed.hi[a] = c + 0.45f * h;
    }
    const std::vector<QueryRay> camera_rays = cameraRays(framed, camera, camera);
    const std::vector<QueryRay> random_rays = randomRays(box, random_count, 7);
    std::printf("device: %s\nfile: %s (%zu patches, size %.4g)\nrays: %d x %d camera, %zu random; median of %d runs, "
                "the methods taking turns\n\n",
                context.device().name.c_str(), file.c_str(), readBptFile(file).size(), size, camera, camera,
                random_count, repeats);
    for (auto& e : engines) e->intersect(camera_rays);  // compiles and warms up, untimed
    std::vector<std::vector<double>> cam_t(variants.size()), rnd_t(variants.size());
    std::vector<std::vector<HitGpu>> cam_hits(variants.size());
    for (int rep = 0; rep < repeats; ++rep)
      for (std::size_t k = 0; k < variants.size(); ++k) {
        double s = 0;
        cam_hits[k] = engines[k]->intersect(camera_rays, &s);
        cam_t[k].push_back(s);
        engines[k]->intersect(random_rays, &s);
        rnd_t[k].push_back(s);
      }
    // Accuracy against the analytic object's double-precision reference.
    const Object& exact = variants[0].scene.objects[0];
    const PrimitiveKind& kind = primitiveKind(exact.type);
    const std::size_t stride = std::max<std::size_t>(1, camera_rays.size() / std::max<std::size_t>(1, check));
    std::printf("%-12s %10s %9s %8s %8s %6s %9s %7s %9s %7s %9s %11s %11s %11s\n", "method", "tolerance", "prims", "set-up",
                "build", "hit%", "camera", "x anl", "random", "x anl", "disagree", "median err", "99.9% err", "max err");
    const double cam0 = camera_rays.size() / median(cam_t[0]) * 1e-6, rnd0 = random_rays.size() / median(rnd_t[0]) * 1e-6;
    for (std::size_t k = 0; k < variants.size(); ++k) {
      std::size_t disagree = 0, compared = 0, hits = 0;
      for (const HitGpu& h : cam_hits[k]) hits += h.prim >= 0;
      std::vector<double> errors;
      for (std::size_t r = 0; r < camera_rays.size(); r += stride) {
        const QueryRay& q = camera_rays[r];
        const Vec3 o{q.ox, q.oy, q.oz}, d{q.dx, q.dy, q.dz};
        const std::optional<double> ref = kind.reference(exact, o, d, q.tmin, 1e30);
        const HitGpu& h = cam_hits[k][r];
        ++compared;
        if (ref.has_value() != (h.prim >= 0)) {
          ++disagree;
          continue;
        }
        if (!ref) continue;
        // Distance from the surface: along the ray times the cosine of
        // incidence at the exact hit (from the analytic method's piece).
        const HitGpu& a = cam_hits[0][r];
        double cosine = 1;
        if (a.prim >= 0) {
          const PatchPiece& piece = exact.pieces->at(static_cast<std::size_t>(a.prim));
          cosine = std::fabs(dot(patchNormal(piece.patch, a.u, a.v), normalize(d)));
        }
        errors.push_back(std::fabs(h.t - *ref) * length(d) * cosine / size);
      }
      const double cam = camera_rays.size() / median(cam_t[k]) * 1e-6, rnd = random_rays.size() / median(rnd_t[k]) * 1e-6;
      std::sort(errors.begin(), errors.end());
      const double max_err = errors.empty() ? 0 : errors.back();
      const double p999 = errors.empty() ? 0 : errors[std::min(errors.size() - 1, errors.size() * 999 / 1000)];
      char tol[32];
      std::snprintf(tol, sizeof tol, "%.3g", k == 0 ? 1e-6 : tolerances[k - 1]);
      std::printf("%-12s %10s %9zu %8.3f %8.3f %6.1f %9.2f %7.2f %9.2f %7.2f %8.2f%% %11.2e %11.2e %11.2e\n",
                  variants[k].name.c_str(), tol, prims[k], variants[k].setup_seconds, build_seconds[k],
                  100.0 * hits / camera_rays.size(), cam, cam / cam0,
                  rnd, rnd / rnd0, 100.0 * disagree / std::max<std::size_t>(1, compared), median(errors), p999, max_err);
    }
    std::printf("\n(tolerance and errors in units of the size; camera and random in Mrays/s; x anl: ratio to the\n"
                "analytic method; disagree: camera rays where hit or miss differs from the double reference;\n"
                "the largest errors are rays within the tolerance of a silhouette or of where two parts of the\n"
                "surface cross, which meet one part on the triangles and the other on the surface)\n");
  } catch (const std::exception& e) {
    std::cerr << "prism-bench patches: " << e.what() << "\n";
    return 1;
  }
  return 0;
}

}  // namespace prism::bench
