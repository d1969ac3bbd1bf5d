// `prism info [--json] FILE`: what a mesh file holds, as read by the plugins.
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "args.h"
#include "commands.h"
#include "help_text.h"
#include "prism.h"

namespace prism_cli {
namespace {

const std::vector<OptionSpec> kInfoOptions = {{"--json", "", false}, {"--help", "-h", false}};

struct ReportDeleter {
  void operator()(PrismMeshReportImpl* r) const { prismReleaseMeshReport(r); }
};

void printText(const std::string& path, PrismMeshReport report, const PrismMeshCounts& c) {
  std::printf("%s (read by plugin '%s')\n", path.c_str(), prismGetMeshPlugin(report));
  std::printf("  vertices:   %llu\n", static_cast<unsigned long long>(c.vertices));
  std::printf("  faces:      %llu\n", static_cast<unsigned long long>(c.faces));
  std::printf("  triangles:  %llu", static_cast<unsigned long long>(c.triangles));
  if (c.degenerate_triangles)
    std::printf(" (%llu degenerate, never hit)", static_cast<unsigned long long>(c.degenerate_triangles));
  std::printf("\n  attributes: %s%s%s%s\n", c.has_normals ? "normals " : "", c.has_texcoords ? "texcoords " : "",
              c.has_colors ? "colours " : "", c.has_normals || c.has_texcoords || c.has_colors ? "" : "positions only");
  if (c.vertices)
    std::printf("  bounds:     [%g, %g, %g] .. [%g, %g, %g]\n", c.bounds_min[0], c.bounds_min[1], c.bounds_min[2],
                c.bounds_max[0], c.bounds_max[1], c.bounds_max[2]);
  std::printf("  materials:  %u\n", c.materials);
  for (uint32_t i = 0; i < c.materials; ++i) std::printf("    %s\n", prismGetMeshMaterialName(report, i));
  for (uint32_t i = 0; i < prismGetMeshWarningCount(report); ++i)
    std::printf("  warning: %s\n", prismGetMeshWarning(report, i));
}

void printJson(const std::string& path, PrismMeshReport report, const PrismMeshCounts& c) {
  nlohmann::ordered_json j;
  j["file"] = path;
  j["plugin"] = prismGetMeshPlugin(report);
  j["vertices"] = c.vertices;
  j["faces"] = c.faces;
  j["triangles"] = c.triangles;
  j["degenerate_triangles"] = c.degenerate_triangles;
  j["has_normals"] = c.has_normals != 0;
  j["has_texcoords"] = c.has_texcoords != 0;
  j["has_colors"] = c.has_colors != 0;
  if (c.vertices) {
    j["bounds"] = {{"min", {c.bounds_min[0], c.bounds_min[1], c.bounds_min[2]}},
                   {"max", {c.bounds_max[0], c.bounds_max[1], c.bounds_max[2]}}};
  } else {
    j["bounds"] = nullptr;
  }
  j["materials"] = nlohmann::json::array();
  for (uint32_t i = 0; i < c.materials; ++i) j["materials"].push_back(prismGetMeshMaterialName(report, i));
  j["warnings"] = nlohmann::json::array();
  for (uint32_t i = 0; i < prismGetMeshWarningCount(report); ++i) j["warnings"].push_back(prismGetMeshWarning(report, i));
  std::printf("%s\n", j.dump(2).c_str());
}

}  // namespace

int runInfo(const std::vector<std::string>& args) {
  const ParsedArgs parsed = parseArgs(args, kInfoOptions, "prism info");
  if (parsed.has("--help")) {
    std::fputs(kInfoHelp, stdout);
    return kExitOk;
  }
  if (parsed.positionals().size() != 1) throw UsageError("expected one mesh file (prism info [--json] FILE)");
  const std::string& path = parsed.positionals()[0];
  PrismMeshReport raw = nullptr;
  if (prismInspectMeshFile(path.c_str(), &raw) != PRISM_OK) return failWithLastError();
  std::unique_ptr<PrismMeshReportImpl, ReportDeleter> report(raw);
  PrismMeshCounts counts{};
  counts.struct_size = sizeof counts;
  if (prismGetMeshCounts(report.get(), &counts) != PRISM_OK) return failWithLastError();
  if (parsed.has("--json"))
    printJson(path, report.get(), counts);
  else
    printText(path, report.get(), counts);
  return kExitOk;
}

int runPlugins(const std::vector<std::string>& args) {
  const ParsedArgs parsed = parseArgs(args, {{"--help", "-h", false}}, "prism plugins");
  if (parsed.has("--help")) {
    std::fputs(kPluginsHelp, stdout);
    return kExitOk;
  }
  uint32_t count = 0;
  if (prismGetPluginCount(&count) != PRISM_OK) return failWithLastError();
  if (count == 0) {
    std::printf("no plugins found (searched $PRISM_PLUGIN_PATH and plugins/ next to libprism)\n");
    return kExitOk;
  }
  for (uint32_t i = 0; i < count; ++i) {
    PrismPluginCandidateInfo info{};
    info.struct_size = sizeof info;
    if (prismGetPluginInfo(i, &info) != PRISM_OK) return failWithLastError();
    if (info.accepted)
      std::printf("%-8s reads %-16s %s\n", info.name, info.extensions, info.path);
    else
      std::printf("rejected %s: %s\n", info.path, info.reason);
  }
  return kExitOk;
}

}  // namespace prism_cli
