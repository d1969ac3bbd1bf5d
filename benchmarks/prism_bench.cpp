// prism-bench: measurements of prism against a reference, for people who want
// to know which acceleration structure wins on their scenes and devices.
//   prism-bench accel [--device D] [--sizes N,...] [--out DIR] [--structures LIST (see --help)]
//                     [--camera N] [--random N] [--repeat N] [--no-embree] [--data DIR] [FILES...]
#include <cstdlib>
#include <exception>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "accel_bench.h"
#include "bench_data.h"
#include "distributed_bench.h"  // prism-bench distributed: parses its own options
#include "firsthit_bench.h"  // prism-bench firsthit: parses its own options
#include "patch_bench.h"     // prism-bench patches: parses its own options
#include "polygon_bench.h"   // prism-bench polygons: parses its own options
#include "shadows_bench.h"   // prism-bench shadows: parses its own options
#include "devices_bench.h"   // prism-bench devices: parses its own options
#include "povray_bench.h"    // prism-bench povray: parses its own options
#include "mpi_bench.h"       // prism-bench mpi: parses its own options

namespace {

const char* kUsage =
    "usage: prism-bench accel [options] [FILES...]\n"
    "       prism-bench firsthit [options] [FILES...]   (see prism-bench firsthit --help)\n"
    "       prism-bench distributed [options]          (see prism-bench distributed --help)\n"
    "       prism-bench povray [options]               (see prism-bench povray --help)\n"
    "       prism-bench polygons [options]             (see prism-bench polygons --help)\n"
    "       prism-bench patches [options]              (see prism-bench patches --help)\n"
    "       prism-bench shadows [options]              (see prism-bench shadows --help)\n"
    "       prism-bench devices [options]              (see prism-bench devices --help)\n"
    "       prism-bench mpi [options]                  (see prism-bench mpi --help)\n"
    "       prism-bench mesh [--data DIR] NAME         the path of one ladder mesh, e.g.\n"
    "                                                  bunny/bunny_loop2_1.1M.ply (made if needed)\n"
    "\n"
    "Builds each acceleration structure over each scene and traces the same rays\n"
    "through it and through Intel Embree (rtcIntersect1, as many threads as the\n"
    "device has compute units). FILES are mesh files (any format a plugin reads)\n"
    "or JSON scenes; without FILES, the benchmark ladder of real meshes and generated\n"
    "bumpy tori of 1k, 10k, 100k and 1M triangles.\n"
    "\n"
    "options:\n"
    "  --device D          OpenCL device: index, cpu, gpu or a name substring\n"
    "  --sizes N,...       generated tori of about N triangles each (k and M suffixes allowed)\n"
    "  --structures LIST   comma-separated among bvh, octree, bsp, none (default\n"
    "                      bvh,octree,bsp); bvh-1ray, octree-1ray and bsp-1ray (the structure\n"
    "                      walked one ray a work-item on every column, as on a GPU; bvh,\n"
    "                      octree and bsp take the camera and shadow rays eight at a time on\n"
    "                      a CPU where that pays);\n"
    "                      bvh-kdop (the BVH with \"set of normals\" bounds on its nodes and\n"
    "                      its objects), bvh-kobj (on its objects only); embree-8 (Embree's\n"
    "                      packets beside its one-ray reference: rtcIntersect8 and\n"
    "                      rtcOccluded8 on the camera and shadow rays, eight neighbours a\n"
    "                      packet, rtcIntersect1 on random rays; needs a prism-bench built\n"
    "                      with Embree, and not --no-embree)\n"
    "  --out DIR           where accel.csv, accel.json and the PNG plots go (default bench-out)\n"
    "  --camera N          N x N primary rays (default 1024)\n"
    "  --random N          incoherent random rays (default 1048576)\n"
    "  --repeat N          timings are the median of N runs (default 3)\n"
    "  --data DIR          folder searched first for the ladder's meshes (default:\n"
    "                      $PRISM_BENCH_DATA); then ../shared/data/meshes beside the\n"
    "                      source tree, then tests/data/meshes. The 1.1M-triangle bunny,\n"
    "                      if none has it, is made from the 69k one by Loop subdivision\n"
    "                      and cached in the build tree; missing meshes are skipped\n"
    "  --no-embree         leave out the Embree reference\n"
    "  --packets always    camera and shadow rays in packets wherever a walk allows, the\n"
    "                      density limits lifted (to measure where packets pay; default:\n"
    "                      where they pay, as a render takes them)\n";

[[noreturn]] void usageError(const std::string& message) {
  std::cerr << "prism-bench: " << message << "\n\n" << kUsage;
  std::exit(2);
}

std::vector<std::string> splitList(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream ss(s);
  std::string item;
  while (std::getline(ss, item, ','))
    if (!item.empty()) out.push_back(item);
  return out;
}

std::size_t parseCount(const std::string& option, const std::string& text) {
  std::size_t scale = 1;
  std::string digits = text;
  if (!digits.empty() && (digits.back() == 'k' || digits.back() == 'K')) scale = 1000, digits.pop_back();
  if (!digits.empty() && (digits.back() == 'm' || digits.back() == 'M')) scale = 1000000, digits.pop_back();
  std::size_t used = 0;
  unsigned long long v = 0;
  try {
    v = std::stoull(digits, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != digits.size() || v == 0) usageError(option + ": expected a positive count, got '" + text + "'");
  return static_cast<std::size_t>(v) * scale;
}

// prism-bench mesh [--data DIR] NAME: for scripts that need one ladder mesh
// (benchmarks/mesh_load/run.sh), found or made the way the ladder is.
int meshPathMain(const std::vector<std::string>& args) {
  std::string data_dir, name;
  for (std::size_t i = 1; i < args.size(); ++i) {
    if (args[i] == "--data" && i + 1 < args.size())
      data_dir = args[++i];
    else if (!args[i].empty() && args[i][0] != '-' && name.empty())
      name = args[i];
    else
      usageError("mesh: unexpected argument '" + args[i] + "'");
  }
  if (name.empty()) usageError("mesh: needs a NAME such as bunny/bunny_loop2_1.1M.ply");
  try {
    std::cout << prism::bench::findBenchMesh(name, data_dir) << "\n";
  } catch (const std::exception& e) {
    std::cerr << "prism-bench: " << e.what() << "\n";
    return 1;
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  if (args.empty() || args[0] == "--help" || args[0] == "-h") {
    std::cout << kUsage;
    return args.empty() ? 2 : 0;
  }
  if (args[0] == "firsthit") return prism::bench::firstHitMain(args);
  if (args[0] == "distributed") return prism::bench::distributedMain(args);
  if (args[0] == "povray") return prism::bench::povrayMain(args);
  if (args[0] == "polygons") return prism::bench::polygonMain(args);
  if (args[0] == "patches") return prism::bench::patchMain(args);
  if (args[0] == "shadows") return prism::bench::shadowsMain(args);
  if (args[0] == "devices") return prism::bench::devicesMain(args);
  if (args[0] == "mpi") return prism::bench::mpiMain(args);
  if (args[0] == "mesh") return meshPathMain(args);
  if (args[0] != "accel")
    usageError("unknown command '" + args[0] + "' (expected accel, firsthit, distributed, povray, polygons, patches, shadows, devices, mpi or mesh)");
  prism::bench::AccelBenchOptions options;
  options.command = "prism-bench";
  for (const std::string& a : args) options.command += " " + a;
  for (std::size_t i = 1; i < args.size(); ++i) {
    const std::string& a = args[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= args.size()) usageError(a + " needs a value");
      return args[++i];
    };
    if (a == "--help" || a == "-h") {
      std::cout << kUsage;
      return 0;
    } else if (a == "--device") {
      options.device = value();
    } else if (a == "--sizes") {
      options.sizes.clear();
      for (const std::string& s : splitList(value())) options.sizes.push_back(parseCount("--sizes", s));
      options.sizes_given = true;
    } else if (a == "--structures") {
      options.structures.clear();
      for (const std::string& s : splitList(value())) {
        prism::AccelKind kind;
        if (s == "bvh-kdop")
          options.bvh_kdop = true;
        else if (s == "bvh-kobj")
          options.bvh_kdop_objects = true;
        else if (s == "bvh-1ray")
          options.one_ray.push_back(prism::AccelKind::Bvh);
        else if (s == "octree-1ray")
          options.one_ray.push_back(prism::AccelKind::Octree);
        else if (s == "bsp-1ray")
          options.one_ray.push_back(prism::AccelKind::Bsp);
        else if (s == "embree-8")
          options.embree_packets = true;
        else if (!prism::tryParseAccelKind(s, &kind))
          usageError("--structures: unknown structure '" + s +
                     "' (expected bvh, bvh-1ray, bvh-kdop, bvh-kobj, octree, octree-1ray, bsp, bsp-1ray, none or embree-8)");
        else
          options.structures.push_back(kind);
      }
    } else if (a == "--out") {
      options.out_dir = value();
    } else if (a == "--camera") {
      options.camera = static_cast<int>(parseCount("--camera", value()));
    } else if (a == "--random") {
      options.random_rays = parseCount("--random", value());
    } else if (a == "--repeat") {
      options.repeats = static_cast<int>(parseCount("--repeat", value()));
    } else if (a == "--data") {
      options.data_dir = value();
    } else if (a == "--packets") {
      const std::string use = value();
      if (use != "always" && use != "where-pays")
        usageError("--packets: expected always or where-pays, not '" + use + "'");
      options.packets_always = use == "always";
    } else if (a == "--no-embree") {
      options.embree = false;
    } else if (!a.empty() && a[0] == '-') {
      usageError("unknown option '" + a + "'");
    } else {
      options.files.push_back(a);
    }
  }
  if (options.embree_packets && !options.embree)
    usageError("--structures embree-8 walks the Embree reference's BVH; it cannot go with --no-embree");
#ifndef PRISM_BENCH_EMBREE
  if (options.embree_packets) usageError("--structures embree-8: this prism-bench was built without Embree");
#endif
  try {
    prism::bench::runAccelBench(options);
  } catch (const std::exception& e) {
    std::cerr << "prism-bench: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
