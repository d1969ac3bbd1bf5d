#include "bench_report.h"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <fstream>
#include <stdexcept>

namespace prism::bench {
namespace {

std::string num(double v, const char* format) {
  if (!std::isfinite(v)) return "-";
  char buf[64];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

std::string csvField(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

nlohmann::json jsonNumber(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

std::ofstream openOut(const std::string& path) {
  std::ofstream f(path);
  if (!f) throw std::runtime_error(path + ": cannot open for writing");
  return f;
}

}  // namespace

void printTableHeader(std::ostream& out) {
  char line[512];
  std::snprintf(line, sizeof line,
                "%-26s %9s %-8s %9s %7s %9s %9s %6s %7s %5s %6s %6s %6s %8s %8s %8s %6s %6s %6s %6s %7s\n", "scene",
                "tris", "accel", "build s", "B/tri", "nodes", "leaves", "p/leaf", "SAH", "dup", "vis/p", "vis/r", "obj/p",
                "prim Mr/s", "shad Mr/s", "rand Mr/s", "xEprim", "xEshad", "xErand", "xEbld", "agree%");
  out << line;
}

void printTableRow(std::ostream& out, const BenchRow& r) {
  std::string scene = r.scene.size() > 26 ? "..." + r.scene.substr(r.scene.size() - 23) : r.scene;
  char line[512];
  std::snprintf(line, sizeof line,
                "%-26s %9zu %-8s %9s %7s %9s %9s %6s %7s %5s %6s %6s %6s %8s %8s %8s %6s %6s %6s %6s %7s\n",
                scene.c_str(), r.triangles, r.structure.c_str(), num(r.build_seconds, "%.4f").c_str(),
                num(r.bytes_per_triangle, "%.1f").c_str(), num(r.nodes, "%.0f").c_str(), num(r.leaves, "%.0f").c_str(),
                num(r.prims_per_leaf, "%.2f").c_str(), num(r.sah, "%.1f").c_str(), num(r.duplication, "%.2f").c_str(),
                num(r.visits_primary, "%.1f").c_str(), num(r.visits_random, "%.1f").c_str(),
                num(r.objects_primary, "%.2f").c_str(),
                num(r.primary_mrays, "%.2f").c_str(), num(r.shadow_mrays, "%.2f").c_str(),
                num(r.random_mrays, "%.2f").c_str(), num(r.primary_ratio, "%.2f").c_str(),
                num(r.shadow_ratio, "%.2f").c_str(), num(r.random_ratio, "%.2f").c_str(),
                num(r.build_ratio, "%.2f").c_str(), num(r.agreement, "%.3f").c_str());
  out << line << std::flush;
}

void writeCsv(const std::string& path, const std::vector<BenchRow>& rows) {
  std::ofstream f = openOut(path);
  f << "scene,triangles,structure,build_seconds,bytes_per_triangle,nodes,leaves,prims_per_leaf,sah_cost,"
       "duplication,primary_mrays,shadow_mrays,random_mrays,primary_vs_embree,shadow_vs_embree,random_vs_embree,"
       "build_time_vs_embree,agreement_percent,visits_per_primary_ray,visits_per_random_ray,objects_per_primary_ray\n";
  for (const BenchRow& r : rows) {
    auto v = [](double x) { return std::isfinite(x) ? num(x, "%.6g") : std::string(); };
    f << csvField(r.scene) << ',' << r.triangles << ',' << r.structure << ',' << v(r.build_seconds) << ','
      << v(r.bytes_per_triangle) << ',' << v(r.nodes) << ',' << v(r.leaves) << ',' << v(r.prims_per_leaf) << ','
      << v(r.sah) << ',' << v(r.duplication) << ',' << v(r.primary_mrays) << ',' << v(r.shadow_mrays) << ','
      << v(r.random_mrays) << ',' << v(r.primary_ratio) << ',' << v(r.shadow_ratio) << ',' << v(r.random_ratio)
      << ',' << v(r.build_ratio) << ',' << v(r.agreement) << ',' << v(r.visits_primary) << ','
      << v(r.visits_random) << ',' << v(r.objects_primary) << '\n';
  }
  if (!f) throw std::runtime_error(path + ": write failed");
}

void writeJson(const std::string& path, const BenchMeta& meta, const std::vector<BenchRow>& rows) {
  nlohmann::json j;
  j["command"] = meta.command;
  j["device"] = meta.device;
  j["embree_threads"] = meta.embree_threads;
  j["camera"] = {meta.camera_width, meta.camera_height};
  j["random_rays"] = meta.random_rays;
  j["repeats"] = meta.repeats;
  j["rows"] = nlohmann::json::array();
  for (const BenchRow& r : rows) {
    j["rows"].push_back({{"scene", r.scene},
                         {"triangles", r.triangles},
                         {"structure", r.structure},
                         {"build_seconds", jsonNumber(r.build_seconds)},
                         {"bytes_per_triangle", jsonNumber(r.bytes_per_triangle)},
                         {"nodes", jsonNumber(r.nodes)},
                         {"leaves", jsonNumber(r.leaves)},
                         {"prims_per_leaf", jsonNumber(r.prims_per_leaf)},
                         {"sah_cost", jsonNumber(r.sah)},
                         {"duplication", jsonNumber(r.duplication)},
                         {"visits_per_primary_ray", jsonNumber(r.visits_primary)},
                         {"visits_per_random_ray", jsonNumber(r.visits_random)},
                         {"objects_per_primary_ray", jsonNumber(r.objects_primary)},
                         {"primary_mrays", jsonNumber(r.primary_mrays)},
                         {"shadow_mrays", jsonNumber(r.shadow_mrays)},
                         {"random_mrays", jsonNumber(r.random_mrays)},
                         {"primary_vs_embree", jsonNumber(r.primary_ratio)},
                         {"shadow_vs_embree", jsonNumber(r.shadow_ratio)},
                         {"random_vs_embree", jsonNumber(r.random_ratio)},
                         {"build_time_vs_embree", jsonNumber(r.build_ratio)},
                         {"agreement_percent", jsonNumber(r.agreement)}});
  }
  std::ofstream f = openOut(path);
  f << j.dump(2) << '\n';
  if (!f) throw std::runtime_error(path + ": write failed");
}

}  // namespace prism::bench
