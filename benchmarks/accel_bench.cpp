#include "accel_bench.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>

#include "accel/accel_workloads.h"
#include "device/context.h"
#include "device/device_list.h"
#include "mesh/mesh_loader.h"
#include "mesh/plugin_registry.h"
#include "plot_png.h"
#include "render/gpu_scene.h"
#include "render/ray_queries.h"
#include "scene/scene_loader.h"

#ifdef PRISM_BENCH_EMBREE
#include "embree_reference.h"
#endif

namespace prism::bench {
namespace {

struct BenchScene {
  std::string name;
  std::vector<ObjectGpu> objects;
  // Triangle soup for Embree (shared vertices kept for meshes); empty when the
  // scene has other primitives, which Embree's triangle geometry cannot take.
  std::vector<float> positions;
  std::vector<std::uint32_t> indices;
};

const PluginRegistry& registry() {
  static PluginRegistry r = [] {
    std::vector<std::string> dirs = PluginRegistry::defaultSearchPath();
    dirs.push_back(PRISM_BINARY_DIR "/plugins");
    return PluginRegistry(dirs);
  }();
  return r;
}

BenchScene fromMesh(const std::string& name, const TriangleMesh& mesh) {
  BenchScene s;
  s.name = name;
  s.objects = trianglesFromMesh(mesh);
  s.positions = mesh.positions;
  s.indices = mesh.indices;
  return s;
}

BenchScene loadInput(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  const std::string name = std::filesystem::path(path).filename().string();
  if (ext != ".json") return fromMesh(name, *loadMeshFile(path, registry()));
  Scene scene = loadSceneFile(path);
  BenchScene s;
  s.name = name;
  s.objects = flattenScene(scene, RenderOptions::fromScene(scene)).objects;
  bool triangles_only = true;
  for (const ObjectGpu& o : s.objects) triangles_only &= o.type == OBJECT_TRIANGLE && !o.has_transform;
  if (triangles_only)
    for (const ObjectGpu& o : s.objects)
      for (int k = 0; k < 3; ++k) {
        for (int a = 0; a < 3; ++a) s.positions.push_back(o.p[3 * k + a]);
        s.indices.push_back(static_cast<std::uint32_t>(s.indices.size()));
      }
  return s;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? kNaN : v[v.size() / 2];
}

template <typename F>
double medianSeconds(int repeats, F run) {
  std::vector<double> t;
  for (int i = 0; i < std::max(1, repeats); ++i) t.push_back(run());
  return median(t);
}

double mrays(std::size_t rays, double seconds) { return seconds > 0 ? rays / seconds / 1e6 : kNaN; }

double agreementPercent(const std::vector<HitGpu>& a, const std::vector<HitGpu>& b) {
  if (a.empty()) return kNaN;
  std::size_t same = 0;
  for (std::size_t i = 0; i < a.size(); ++i) same += a[i].prim == b[i].prim;
  return 100.0 * same / a.size();
}

// The same colour for a structure in every figure; Embree in black.
long structureColour(const std::string& s) {
  if (s == "bvh") return 0x0072B2;
  if (s == "octree") return 0xD55E00;
  if (s == "bsp") return 0x009E73;
  if (s == "none") return 0xCC79A7;
  return 0x000000;
}

void writePlots(const std::string& dir, const std::vector<BenchRow>& rows) {
  std::vector<std::string> order;
  for (const BenchRow& r : rows)
    if (std::find(order.begin(), order.end(), r.structure) == order.end()) order.push_back(r.structure);
  std::stable_partition(order.begin(), order.end(), [](const std::string& s) { return s != "embree"; });
  struct Figure {
    const char* file;
    const char* title;
    const char* y;
    double BenchRow::*field;
  };
  const Figure figures[] = {
      {"build_time.png", "Build time", "seconds", &BenchRow::build_seconds},
      {"primary_mrays.png", "Primary rays (camera)", "Mrays/s", &BenchRow::primary_mrays},
      {"shadow_mrays.png", "Shadow rays (any hit)", "Mrays/s", &BenchRow::shadow_mrays},
      {"random_mrays.png", "Incoherent random rays", "Mrays/s", &BenchRow::random_mrays},
  };
  for (const Figure& f : figures) {
    std::vector<PlotSeries> series;
    for (const std::string& s : order) {
      PlotSeries ps;
      ps.name = s;
      ps.color = structureColour(s);
      // Generated tori form a size sweep (a line); other scenes are markers.
      for (const BenchRow& r : rows)
        if (r.structure == s)
          (r.scene.rfind("torus-", 0) == 0 ? ps.line : ps.markers)
              .emplace_back(static_cast<double>(r.triangles), r.*f.field);
      series.push_back(ps);
    }
    writeLogLogPlot(dir + "/" + f.file, f.title, "triangles", f.y, series);
  }
}

}  // namespace

std::vector<std::string> defaultLadder(const std::string& data_dir) {
  static const char* files[] = {"bunny/bun_zipper_res4.ply",  "bunny/bun_zipper_res3.ply",
                                "spot/spot.obj",              "teapot/teapot.obj",
                                "mori_knob/testObj.obj",      "bunny/bun_zipper_res2.ply",
                                "dragon/dragon_vcg_43k.ply",  "bunny/bun_zipper.ply",
                                "armadillo/armadillo.obj",    "dragon/dragon_100k_vcgflags.ply",
                                "bunny/bunny_loop2_1.1M.ply"};
  std::vector<std::string> out;
  for (const char* f : files) {
    std::string p = data_dir + "/" + f;
    if (std::filesystem::exists(p)) out.push_back(p);
  }
  return out;
}

std::vector<BenchRow> runAccelBench(const AccelBenchOptions& options) {
  DeviceDescription device = selectDevice(options.device);
  Context context(device, true);
  const int threads = static_cast<int>(std::max(1u, device.compute_units));
  std::filesystem::create_directories(options.out_dir);

  BenchMeta meta;
  meta.command = options.command;
  meta.device = device.name + " (" + device.platform_name + ", driver " + device.driver_version + ", " +
                std::to_string(device.compute_units) + " compute units)";
  meta.embree_threads = threads;
  meta.camera_width = meta.camera_height = options.camera;
  meta.random_rays = options.random_rays;
  meta.repeats = options.repeats;
  std::cout << "device: " << meta.device << "\n";
#ifdef PRISM_BENCH_EMBREE
  if (options.embree) std::cout << "reference: Embree " << "3, rtcIntersect1 on " << threads << " threads\n";
#else
  if (options.embree) std::cout << "reference: none (prism-bench was built without Embree)\n";
#endif
  std::cout << "rays: " << options.camera << "x" << options.camera << " primary, shadow rays from their hits, "
            << options.random_rays << " random; median of " << options.repeats << " runs\n\n";
  printTableHeader(std::cout);

  std::vector<std::string> inputs = options.files;
  std::vector<std::size_t> sizes = options.sizes;
  if (inputs.empty()) {
    inputs = defaultLadder(options.data_dir);
    if (!options.sizes_given) sizes = {1000, 10000, 100000, 1000000};
  }
  std::vector<BenchRow> rows;
  auto runScene = [&](const BenchScene& scene) {
    const Aabb box = boundsOf(scene.objects);
    const std::vector<QueryRay> primary = cameraRays(box, options.camera, options.camera);
    const std::vector<QueryRay> random = randomRays(box, options.random_rays, 1234);
    const std::vector<RayGpu> primary_gpu = toRayGpu(primary), random_gpu = toRayGpu(random);
    const float light[3] = {box.hi[0] + (box.hi[0] - box.lo[0]), box.hi[1] + 2 * (box.hi[1] - box.lo[1]),
                            box.hi[2] + (box.hi[2] - box.lo[2])};
    std::vector<QueryRay> shadows;
    std::vector<RayGpu> shadows_gpu;
    std::vector<HitGpu> reference_hits;
    BenchRow embree_row;
    bool have_embree = false;
#ifdef PRISM_BENCH_EMBREE
    if (options.embree && !scene.indices.empty()) {
      EmbreeReference ref(scene.positions, scene.indices, threads);
      embree_row.scene = scene.name;
      embree_row.triangles = scene.objects.size();
      embree_row.structure = "embree";
      embree_row.build_seconds = ref.buildSeconds();
      embree_row.primary_mrays = mrays(primary.size(), medianSeconds(options.repeats, [&] {
                                         double s;
                                         reference_hits = ref.intersect(primary, &s);
                                         return s;
                                       }));
      shadows = shadowRays(primary, reference_hits, light);
      embree_row.shadow_mrays = mrays(shadows.size(), medianSeconds(options.repeats, [&] {
                                        double s;
                                        ref.occluded(shadows, &s);
                                        return s;
                                      }));
      embree_row.random_mrays = mrays(random.size(), medianSeconds(options.repeats, [&] {
                                        double s;
                                        ref.intersect(random, &s);
                                        return s;
                                      }));
      embree_row.primary_ratio = embree_row.shadow_ratio = embree_row.random_ratio = embree_row.build_ratio = 1;
      have_embree = true;
      printTableRow(std::cout, embree_row);
    }
#endif
    for (AccelKind kind : options.structures) {
      RayQueryEngine engine(context, scene.objects, kind);
      const AccelStats& st = engine.accel().stats;
      BenchRow row;
      row.scene = scene.name;
      row.triangles = scene.objects.size();
      row.structure = accelName(kind);
      row.build_seconds = st.build_seconds;
      row.bytes_per_triangle = scene.objects.empty() ? kNaN : double(st.bytes) / scene.objects.size();
      row.nodes = static_cast<double>(st.node_count);
      row.leaves = static_cast<double>(st.leaf_count);
      row.prims_per_leaf = st.mean_prims_per_leaf;
      row.sah = st.sah_cost;
      row.duplication = st.duplication;
      std::vector<HitGpu> hits;
      row.primary_mrays = mrays(primary.size(), medianSeconds(options.repeats, [&] {
                                  double s;
                                  hits = engine.intersect(primary_gpu, &s);
                                  return s;
                                }));
      if (reference_hits.empty()) reference_hits = hits;  // no Embree: agreement with the first structure
      row.agreement = agreementPercent(reference_hits, hits);
      if (shadows.empty()) shadows = shadowRays(primary, reference_hits, light);
      if (shadows_gpu.empty()) shadows_gpu = toRayGpu(shadows);
      row.shadow_mrays = mrays(shadows.size(), medianSeconds(options.repeats, [&] {
                                 double s;
                                 engine.occluded(shadows_gpu, &s);
                                 return s;
                               }));
      row.random_mrays = mrays(random.size(), medianSeconds(options.repeats, [&] {
                                 double s;
                                 engine.intersect(random_gpu, &s);
                                 return s;
                               }));
      if (have_embree) {
        row.primary_ratio = row.primary_mrays / embree_row.primary_mrays;
        row.shadow_ratio = row.shadow_mrays / embree_row.shadow_mrays;
        row.random_ratio = row.random_mrays / embree_row.random_mrays;
        row.build_ratio = row.build_seconds / embree_row.build_seconds;
      }
      printTableRow(std::cout, row);
      rows.push_back(row);
    }
    if (have_embree) rows.push_back(embree_row);
  };

  for (const std::string& path : inputs) runScene(loadInput(path));
  for (std::size_t n : sizes) {
    TriangleMesh torus = bumpyTorus(n);
    runScene(fromMesh("torus-" + std::to_string(torus.triangleCount()), torus));
  }

  writeCsv(options.out_dir + "/accel.csv", rows);
  writeJson(options.out_dir + "/accel.json", meta, rows);
  writePlots(options.out_dir, rows);
  std::cout << "\nwrote " << options.out_dir << "/accel.csv, accel.json, build_time.png, primary_mrays.png, "
            << "shadow_mrays.png, random_mrays.png\n";
  return rows;
}

}  // namespace prism::bench
