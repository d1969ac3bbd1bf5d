#include "accel_bench.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <iostream>
#include <map>
#include <memory>

#include "accel/prim_ref.h"
#include "accel_workloads.h"
#include "bench_data.h"
#include "device/context.h"
#include "device/device_list.h"
#include "mesh/mesh_loader.h"
#include "mesh/plugin_registry.h"
#include "bench_plugins.h"
#include "plot_png.h"
#include "render/gpu_scene.h"
#include "render/ray_queries.h"
#include "scene_format/scene_loader.h"

#ifdef PRISM_BENCH_EMBREE
#include "embree_reference.h"
#endif

namespace prism::bench {
namespace {

struct BenchScene {
  std::string name;
  SceneGeometry geometry;
  // Triangle soup for Embree (shared vertices kept for meshes); empty when the
  // scene has other primitives, which Embree's triangle geometry cannot take.
  std::vector<float> positions;
  std::vector<std::uint32_t> indices;
};

BenchScene fromMesh(const std::string& name, const TriangleMesh& mesh) {
  BenchScene s;
  s.name = name;
  s.geometry = geometryFromMesh(mesh);
  s.positions = mesh.positions;
  s.indices = mesh.indices;
  return s;
}

BenchScene loadInput(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  const std::string name = std::filesystem::path(path).filename().string();
  if (ext != ".json") return fromMesh(name, *loadMeshFile(path, benchPlugins()));
  Scene scene = loadSceneFile(path);
  BenchScene s;
  s.name = name;
  s.geometry = flattenScene(scene, RenderOptions::fromScene(scene));
  const std::vector<ObjectGpu> primitives(s.geometry.objects.begin(),
                                          s.geometry.objects.begin() + static_cast<std::ptrdiff_t>(s.geometry.primitive_count));
  bool triangles_only = true;
  for (const ObjectGpu& o : primitives) triangles_only &= o.type == OBJECT_TRIANGLE && !o.has_transform;
  if (triangles_only)
    for (const ObjectGpu& o : primitives)
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

// Times every run in turn, one call each per round for `repeats` rounds, and
// returns each one's median. Interleaved, a change of load on the shared
// machine touches every contender alike, so the ratios taken in one run stay
// steadier than when each contender's repeats run back to back. Each round
// starts one contender later, so none always follows the same one.
std::vector<double> interleavedMedians(int repeats, const std::vector<std::function<double()>>& runs) {
  std::vector<std::vector<double>> times(runs.size());
  for (int r = 0; r < std::max(1, repeats); ++r)
    for (std::size_t k = 0; k < runs.size(); ++k) {
      const std::size_t i = (k + static_cast<std::size_t>(r)) % runs.size();
      times[i].push_back(runs[i]());
    }
  std::vector<double> out;
  for (auto& t : times) out.push_back(median(t));
  return out;
}

// Embree or one of prism's structures, answering the same rays.
struct Contender {
  BenchRow row;
  const DeviceAccel* accel = nullptr;  // prism's structure (null for Embree)
  std::function<double()> rebuild;  // builds the structure again, returns the build's seconds
  bool reference_build = false;      // walks the reference's structure (embree-8): its build is that one
  // (Embree's one-ray reference takes every ray alone, coherent or not; embree-8
  // takes the coherent ones eight at a time.)
  std::function<std::vector<HitGpu>(const std::vector<QueryRay>&, const std::vector<RayGpu>&, double*, RayCoherence)>
      intersect;
  // (view_rays: for RayQueryEngine's density rule, the camera rays whose hits the feelers start from)
  std::function<void(const std::vector<QueryRay>&, const std::vector<RayGpu>&, double*, RayCoherence,
                     std::uint64_t view_rays)>
      occluded;
};

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
  if (s == "bvh-kdop") return 0x56B4E9;
  if (s == "bvh-kobj") return 0xE69F00;
  if (s == "bvh-1ray") return 0x999999;
  if (s == "octree-1ray") return 0xF0A070;
  if (s == "bsp-1ray") return 0x80CFB0;
  if (s == "embree-8") return 0x5D3A9B;
  return 0x000000;
}

// Generated tori form a size sweep (a line); other scenes are markers. The
// tori are named by this prefix and their triangle count.
const std::string kTorusPrefix = "torus-";
bool isTorus(const std::string& scene) { return scene.rfind(kTorusPrefix, 0) == 0; }

void writePlots(const std::string& dir, const std::vector<BenchRow>& rows) {
  std::vector<std::string> order;
  for (const BenchRow& r : rows)
    if (std::find(order.begin(), order.end(), r.structure) == order.end()) order.push_back(r.structure);
  // Embree's rows last (embree-8, then the one-ray reference), as in the files.
  std::stable_partition(order.begin(), order.end(), [](const std::string& s) { return s.rfind("embree", 0) != 0; });
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
  // The legend names only the kinds of scene the run had.
  const bool tori = std::any_of(rows.begin(), rows.end(), [](const BenchRow& r) { return isTorus(r.scene); });
  const bool meshes = std::any_of(rows.begin(), rows.end(), [](const BenchRow& r) { return !isTorus(r.scene); });
  std::vector<std::string> notes;
  if (tori) notes.push_back("lines: tori");
  if (meshes) notes.push_back("squares: meshes");
  for (const Figure& f : figures) {
    std::vector<PlotSeries> series;
    for (const std::string& s : order) {
      PlotSeries ps;
      ps.name = s;
      ps.color = structureColour(s);
      for (const BenchRow& r : rows)
        if (r.structure == s)
          (isTorus(r.scene) ? ps.line : ps.markers)
              .emplace_back(static_cast<double>(r.triangles), r.*f.field);
      series.push_back(ps);
    }
    writeLogLogPlot(dir + "/" + f.file, f.title, "triangles", f.y, series, notes);
  }
}

}  // namespace

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
  if (options.embree)
    std::cout << "reference: Embree 3, rtcIntersect1 on " << threads << " threads"
              << (options.embree_packets ? " (embree-8: rtcIntersect8 / rtcOccluded8 on camera and shadow rays)" : "")
              << "\n";
#else
  if (options.embree) std::cout << "reference: none (prism-bench was built without Embree)\n";
#endif
  std::cout << "rays: " << options.camera << "x" << options.camera << " primary, shadow rays from their hits, "
            << options.random_rays << " random; median of " << options.repeats
            << " runs, the contenders taking turns\n\n";
  printTableHeader(std::cout);

  std::vector<std::string> inputs = options.files;
  std::vector<std::size_t> sizes = options.sizes;
  if (inputs.empty()) {
    BenchLadder ladder = benchLadder(options.data_dir);
    for (const std::string& note : ladder.notes) std::cout << "ladder: " << note << "\n";
    inputs = ladder.files;
    if (!options.sizes_given) sizes = {1000, 10000, 100000, 1000000};
  }
  std::vector<BenchRow> rows;
  auto runScene = [&](const BenchScene& scene) {
    const Aabb box = boundsOf(scene.geometry.objects);
    const std::vector<QueryRay> primary = cameraRays(box, options.camera, options.camera);
    const std::vector<QueryRay> random = randomRays(box, options.random_rays, 1234);
    const std::vector<RayGpu> primary_gpu = toRayGpu(primary), random_gpu = toRayGpu(random);
    const float light[3] = {box.hi[0] + (box.hi[0] - box.lo[0]), box.hi[1] + 2 * (box.hi[1] - box.lo[1]),
                            box.hi[2] + (box.hi[2] - box.lo[2])};

    // Everything is built first, so that the rays can be timed in turns.
    std::vector<Contender> contenders;
    bool have_embree = false;
#ifdef PRISM_BENCH_EMBREE
    std::unique_ptr<EmbreeReference> ref;
    if (options.embree && !scene.indices.empty()) {
      ref = std::make_unique<EmbreeReference>(scene.positions, scene.indices, threads);
      Contender c;
      c.row.structure = "embree";
      c.row.build_seconds = ref->buildSeconds();
      c.row.bytes_per_triangle = double(ref->bytes()) / std::max<std::size_t>(1, scene.indices.size() / 3);
      c.rebuild = [&scene, threads] { return EmbreeReference(scene.positions, scene.indices, threads).buildSeconds(); };
      c.intersect = [&ref](const std::vector<QueryRay>& q, const std::vector<RayGpu>&, double* s, RayCoherence) {
        return ref->intersect(q, s);
      };
      c.occluded = [&ref](const std::vector<QueryRay>& q, const std::vector<RayGpu>&, double* s, RayCoherence,
                          std::uint64_t) { ref->occluded(q, s); };
      contenders.push_back(std::move(c));
      have_embree = true;
      if (options.embree_packets) {
        // The same BVH, so the same build; camera and shadow rays go eight at
        // a time, random rays alone (prism's "bvh" takes the first two in
        // packets where its density rule says they pay, random rays alone).
        Contender p;
        p.row = contenders.front().row;
        p.row.structure = "embree-8";
        p.reference_build = true;
        p.intersect = [&ref](const std::vector<QueryRay>& q, const std::vector<RayGpu>&, double* s,
                             RayCoherence coherence) {
          return coherence == RayCoherence::Coherent ? ref->intersect8(q, s) : ref->intersect(q, s);
        };
        p.occluded = [&ref](const std::vector<QueryRay>& q, const std::vector<RayGpu>&, double* s,
                            RayCoherence coherence, std::uint64_t) {
          if (coherence == RayCoherence::Coherent)
            ref->occluded8(q, s);
          else
            ref->occluded(q, s);
        };
        contenders.push_back(std::move(p));
      }
    }
#endif
    std::vector<std::unique_ptr<RayQueryEngine>> engines;
    struct Variant {
      AccelKind kind;
      std::string name;
      bool kdop_objects, kdop_bvh;
      PacketUse packets;
    };
    std::vector<Variant> variants;
    const PacketUse packets = options.packets_always ? PacketUse::Always : PacketUse::WherePays;
    for (AccelKind kind : options.structures) variants.push_back({kind, accelName(kind), false, false, packets});
    for (AccelKind kind : options.one_ray)
      variants.push_back({kind, std::string(accelName(kind)) + "-1ray", false, false, PacketUse::Never});
    if (options.bvh_kdop) variants.push_back({AccelKind::Bvh, "bvh-kdop", true, true, PacketUse::WherePays});
    if (options.bvh_kdop_objects) variants.push_back({AccelKind::Bvh, "bvh-kobj", true, false, PacketUse::WherePays});
    for (const Variant& v : variants) {
      const AccelKind kind = v.kind;
      AccelBuildOptions build;
      build.kdop_objects = v.kdop_objects;
      build.kdop_bvh = v.kdop_bvh;
      engines.push_back(std::make_unique<RayQueryEngine>(context, scene.geometry, kind, std::vector<MaterialGpu>{},
                                                         build, v.packets));
      RayQueryEngine* engine = engines.back().get();
      const AccelStats& st = engine->accel().stats;
      Contender c;
      c.accel = &engine->accel();
      c.row.structure = v.name;
      c.row.build_seconds = st.build_seconds;
      c.rebuild = [&scene, kind, build] { return buildAccel(kind, scene.geometry.objects, build)->stats.build_seconds; };
      c.row.bytes_per_triangle =
          scene.geometry.primitive_count == 0 ? kNaN : double(engine->deviceBytes()) / scene.geometry.primitive_count;
      c.row.nodes = static_cast<double>(st.node_count);
      c.row.leaves = static_cast<double>(st.leaf_count);
      c.row.prims_per_leaf = st.mean_prims_per_leaf;
      c.row.sah = st.sah_cost;
      c.row.duplication = st.duplication;
      c.intersect = [engine](const std::vector<QueryRay>&, const std::vector<RayGpu>& g, double* s,
                             RayCoherence coherence) { return engine->intersect(g, s, coherence);
      };
      c.occluded = [engine](const std::vector<QueryRay>&, const std::vector<RayGpu>& g, double* s,
                            RayCoherence coherence, std::uint64_t view_rays) {
        engine->occluded(g, s, coherence, view_rays);
      };
      contenders.push_back(std::move(c));
    }
    if (contenders.empty()) return;

    // Build times: the median of up to three builds, the contenders taking
    // turns as for the rays (a build takes both cores, so a busy moment on the
    // shared machine can double a single one).
    const int builds = std::min(3, std::max(1, options.repeats));
    std::vector<std::vector<double>> build_seconds(contenders.size());
    for (std::size_t i = 0; i < contenders.size(); ++i) build_seconds[i].push_back(contenders[i].row.build_seconds);
    for (int b = 1; b < builds; ++b)
      for (std::size_t i = 0; i < contenders.size(); ++i)
        if (!contenders[i].reference_build) build_seconds[i].push_back(contenders[i].rebuild());
    for (std::size_t i = 0; i < contenders.size(); ++i)  // the reference, where there is one, is contender 0
      contenders[i].row.build_seconds =
          contenders[i].reference_build ? median(build_seconds[0]) : median(build_seconds[i]);

    // One untimed round gives the hits (the reference is Embree's when it
    // runs, else the first structure's) and warms every contender up.
    std::vector<HitGpu> reference_hits;
    for (Contender& c : contenders) {
      double s;
      std::vector<HitGpu> hits = c.intersect(primary, primary_gpu, &s, RayCoherence::Coherent);
      if (reference_hits.empty()) reference_hits = hits;
      if (c.row.structure != "embree") c.row.agreement = agreementPercent(reference_hits, hits);
    }
    const std::vector<QueryRay> shadows = shadowRays(primary, reference_hits, light);
    {
      double s;
      const std::vector<HitGpu> random_hits =
          contenders.front().intersect(random, random_gpu, &s, RayCoherence::Scattered);
      for (Contender& c : contenders) {
        if (!c.accel) continue;
        const BvhVisits p = bvhNodeVisits(*c.accel, primary, reference_hits);
        const BvhVisits r = bvhNodeVisits(*c.accel, random, random_hits);
        c.row.visits_primary = p.inner + p.leaves;
        c.row.visits_random = r.inner + r.leaves;
        c.row.objects_primary = p.objects;
      }
    }
    const std::vector<RayGpu> shadows_gpu = toRayGpu(shadows);

    auto timeAll = [&](const std::vector<QueryRay>& rays, const std::vector<RayGpu>& rays_gpu, bool occlusion,
                       RayCoherence coherence, std::uint64_t view_rays) {
      std::vector<std::function<double()>> runs;
      for (Contender& c : contenders)
        runs.push_back([&c, &rays, &rays_gpu, occlusion, coherence, view_rays] {
          double s;
          if (occlusion)
            c.occluded(rays, rays_gpu, &s, coherence, view_rays);
          else
            c.intersect(rays, rays_gpu, &s, coherence);
          return s;
        });
      std::vector<double> seconds = interleavedMedians(options.repeats, runs);
      std::vector<double> out;
      for (double t : seconds) out.push_back(mrays(rays.size(), t));
      return out;
    };
    // Camera rays in pixel order travel alike, as a render's do, and so do
    // the shadow rays from their hits to one light: both go in packets where
    // the structure and device take them (render/ray_kernel.h). The shadow
    // rays' view is the camera's, as for a render's feelers: the density rule
    // counts the frame's samples, not the hits among them.
    const std::vector<double> primary_mrays = timeAll(primary, primary_gpu, false, RayCoherence::Coherent, 0);
    const std::vector<double> shadow_mrays =
        timeAll(shadows, shadows_gpu, true, RayCoherence::Coherent, primary.size());
    const std::vector<double> random_mrays = timeAll(random, random_gpu, false, RayCoherence::Scattered, 0);

    for (std::size_t i = 0; i < contenders.size(); ++i) {
      BenchRow& row = contenders[i].row;
      row.scene = scene.name;
      row.triangles = scene.geometry.primitive_count;
      row.primary_mrays = primary_mrays[i];
      row.shadow_mrays = shadow_mrays[i];
      row.random_mrays = random_mrays[i];
      if (have_embree) {
        const BenchRow& e = contenders[0].row;
        row.primary_ratio = row.primary_mrays / e.primary_mrays;
        row.shadow_ratio = row.shadow_mrays / e.shadow_mrays;
        row.random_ratio = row.random_mrays / e.random_mrays;
        row.build_ratio = row.build_seconds / e.build_seconds;
      }
      printTableRow(std::cout, row);
    }
    // Embree's rows last in the files, its one-ray reference at the very end, as before.
    for (const Contender& c : contenders)
      if (c.accel) rows.push_back(c.row);
    for (auto c = contenders.rbegin(); c != contenders.rend(); ++c)
      if (!c->accel) rows.push_back(c->row);
  };

  for (const std::string& path : inputs) runScene(loadInput(path));
  for (std::size_t n : sizes) {
    TriangleMesh torus = bumpyTorus(n);
    runScene(fromMesh(kTorusPrefix + std::to_string(torus.triangleCount()), torus));
  }

  writeCsv(options.out_dir + "/accel.csv", rows);
  writeJson(options.out_dir + "/accel.json", meta, rows);
  writePlots(options.out_dir, rows);
  std::cout << "\nwrote " << options.out_dir << "/accel.csv, accel.json, build_time.png, primary_mrays.png, "
            << "shadow_mrays.png, random_mrays.png\n";
  return rows;
}

}  // namespace prism::bench
