#include "mpi_bench.h"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <regex>
#include <stdexcept>

#include "bench_options.h"
#include "bench_process.h"

namespace prism::bench {
namespace {

const char* kUsage =
    "usage: prism-bench mpi [--ranks LIST] [--scene FILE] [--size WxH] [--spp N] [--device SEL]\n"
    "                       [--repeat N] [--uneven] [--tcp] [--out DIR]\n"
    "\n"
    "Renders --scene (default scenes/whitted.json) at --size (default 640x480) with\n"
    "--spp jittered samples (default 16) by prism render alone and under mpirun\n"
    "--oversubscribe -np N for each N of --ranks (default 2,3), every rank on\n"
    "--device (default 0), the runs taking turns --repeat times (default 3; medians).\n"
    "Prints each run's wall time (process start to exit: MPI start-up, every rank's\n"
    "kernels and structure included) and prism's tracing time, the speed of N ranks\n"
    "against one process on each, and whether the images are the same bit for bit.\n"
    "On one machine the ranks share its cores, which one PoCL process already uses\n"
    "in full: there the best is 1.0x, and the figure measures the cost of sharing.\n"
    "--uneven: the last rank runs on one PoCL thread at the lowest priority (nice\n"
    "19), a slower node; the ranks deal the frame's units as their devices come\n"
    "free, and the table after the times shows how many each took and how long\n"
    "each was busy in the last run (equal busy times: none waited for another).\n"
    "--tcp: the ranks talk over Open MPI's TCP transport and its pt2pt one-sided\n"
    "component over the loopback interface (OMPI_MCA_pml=ob1 OMPI_MCA_btl=tcp,self\n"
    "OMPI_MCA_btl_tcp_if_include=lo OMPI_MCA_osc=pt2pt), as machines without RDMA\n"
    "hardware talk, instead of shared memory; the share table\n"
    "is printed too (a rank's compare-and-swap on rank 0's words then waits for\n"
    "rank 0 to progress MPI: docs/devices.md).\n"
    "Writes the images to --out (default bench-out).\n";

struct Run {
  std::vector<double> wall, tracing;
  std::string image;
  std::string shares;  // the last run's device table rows (--stats), one per rank's device
};

// The rows of --stats' device table: "  [i] part r: name   units samples busy".
std::string shareRows(const std::string& out) {
  std::string rows;
  const std::regex row(R"(  \[[0-9]+\] part [0-9]+: [^\n]*\n)");
  for (auto it = std::sregex_iterator(out.begin(), out.end(), row); it != std::sregex_iterator(); ++it)
    rows += it->str();
  return rows;
}

// prism's summary line: "... tracing 0.52 s; ...".
double tracingSeconds(const std::string& out) {
  std::smatch m;
  if (!std::regex_search(out, m, std::regex("tracing ([0-9.]+) s;"))) throw std::runtime_error("no summary in:\n" + out);
  return std::stod(m[1]);
}

std::string fileBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

}  // namespace

int mpiMain(const std::vector<std::string>& args) {
  std::string scene = PRISM_SOURCE_DIR "/scenes/whitted.json", device = "0", out_dir = "bench-out";
  std::vector<int> ranks{2, 3};
  int width = 640, height = 480, spp = 16, repeats = 3;
  bool uneven = false, tcp = false;
  const int status = parseBenchOptions(args, "mpi", kUsage, [&](const std::string& a, const OptionValue& value) {
    if (a == "--ranks") {
      ranks.clear();
      std::string list = value();
      for (size_t at = 0; at <= list.size();) {
        const size_t comma = std::min(list.find(',', at), list.size());
        const int n = std::stoi(list.substr(at, comma - at));
        if (n < 2) throw std::invalid_argument("--ranks: each count is at least 2 (1 is the reference)");
        ranks.push_back(n);
        at = comma + 1;
      }
    } else if (a == "--scene") {
      scene = value();
    } else if (a == "--size") {
      parseSize(a, value(), &width, &height);
    } else if (a == "--spp") {
      spp = std::max(1, std::stoi(value()));
    } else if (a == "--device") {
      device = value();
    } else if (a == "--repeat") {
      repeats = std::max(1, std::stoi(value()));
    } else if (a == "--uneven") {
      uneven = true;
    } else if (a == "--tcp") {
      tcp = true;
    } else if (a == "--out") {
      out_dir = value();
    } else {
      throw std::invalid_argument("unknown option '" + a + "'");
    }
  });
  if (status >= 0) return status;
#ifndef PRISM_BENCH_MPI
  (void)scene, (void)device, (void)out_dir, (void)width, (void)height, (void)spp, (void)repeats;
  std::cout << "prism-bench mpi: skipped: prism was built without MPI (install libopenmpi-dev and "
               "configure with -DPRISM_MPI=ON)\n";
  return 0;
#else
  try {
    std::filesystem::create_directories(out_dir);
    const std::string render = shellQuote(PRISM_CLI_PATH) + " render " + shellQuote(scene) + " --width " +
                               std::to_string(width) + " --height " + std::to_string(height) +
                               " --aa jitter --spp " + std::to_string(spp) + " --device " + shellQuote(device);
    // Root may start ranks here (benchmark machines often run as root).
    const std::string mpirun = "OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 "
                               "OMPI_MCA_btl_vader_single_copy_mechanism=none " +
                               std::string(tcp ? "OMPI_MCA_pml=ob1 OMPI_MCA_btl=tcp,self OMPI_MCA_btl_tcp_if_include=lo "
                                               "OMPI_MCA_osc=pt2pt "
                                             : "") +
                               shellQuote(PRISM_MPIEXEC) + " --oversubscribe -np ";
    std::vector<int> counts{1};
    counts.insert(counts.end(), ranks.begin(), ranks.end());
    std::vector<Run> runs(counts.size());
    auto once = [&](size_t i) {
      runs[i].image = out_dir + "/mpi-" + std::to_string(counts[i]) + ".pfm";
      const std::string own = render + " -o " + shellQuote(runs[i].image) + " --stats";
      std::string command = own;
      if (counts[i] > 1 && !uneven) command = mpirun + std::to_string(counts[i]) + " " + own;
      if (counts[i] > 1 && uneven)  // MPMD: the last rank slower
        command = mpirun + std::to_string(counts[i] - 1) + " " + own + " : -np 1 -x POCL_MAX_PTHREAD_COUNT=1 nice -n 19 " + own;
      int code = 0;
      const auto start = std::chrono::steady_clock::now();
      const std::string out = capture(command, &code);
      const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      if (code != 0) throw std::runtime_error("failed (" + command + "):\n" + out);
      runs[i].wall.push_back(wall);
      runs[i].tracing.push_back(tracingSeconds(out));
      runs[i].shares = shareRows(out);
    };
    for (size_t i = 0; i < counts.size(); ++i) once(i);  // untimed: kernels built, caches warm
    for (Run& r : runs) r.wall.clear(), r.tracing.clear();
    for (int k = 0; k < repeats; ++k)
      for (size_t i = 0; i < counts.size(); ++i) once(i);

    std::printf("scene: %s, %dx%d at %d spp (jitter), device %s on every rank%s; median of %d runs, taking turns\n\n",
                scene.c_str(), width, height, spp, device.c_str(), tcp ? ", ranks over TCP (osc pt2pt)" : "",
                repeats);
    std::printf("%-8s %10s %12s %12s %14s  %s\n", "ranks", "wall s", "speed (wall)", "tracing s", "speed (tracing)",
                "image");
    const std::string reference = fileBytes(runs[0].image);
    for (size_t i = 0; i < counts.size(); ++i) {
      const double wall = median(runs[i].wall), tracing = median(runs[i].tracing);
      std::printf("%-8d %10.3f %11.2fx %12.3f %13.2fx  %s\n", counts[i], wall, median(runs[0].wall) / wall, tracing,
                  median(runs[0].tracing) / tracing,
                  i == 0 ? "reference" : fileBytes(runs[i].image) == reference ? "same bits" : "DIFFERENT");
    }
    if (uneven || tcp) {
      std::printf("\n%seach rank's share of the last run:\n",
                  uneven ? "the last rank on one PoCL thread at nice 19; " : "");
      std::printf("       device                                      units      samples     busy s\n");
      for (size_t i = 1; i < counts.size(); ++i) std::printf("%d ranks:\n%s", counts[i], runs[i].shares.c_str());
    }
    std::printf("\nspeed: one process's time over N ranks' (above 1: faster). Reproduce: prism-bench mpi");
    for (size_t i = 1; i < args.size(); ++i) std::printf(" %s", args[i].c_str());
    std::printf("\n");
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "prism-bench mpi: " << e.what() << "\n";
    return 1;
  }
#endif
}

}  // namespace prism::bench
