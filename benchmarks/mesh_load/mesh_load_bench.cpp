// Loads one mesh file once and prints how long it took and the process's
// peak resident memory, so that run.sh can compare prism's plugins with
// OpenMesh's read_mesh format by format. Also converts a mesh to OBJ, OFF or
// ASCII PLY (the inputs run.sh compares), writing with round-trip precision.
//
//   mesh_load_bench prism FILE                load with loadMeshFile
//   mesh_load_bench openmesh FILE             load with OpenMesh::IO::read_mesh
//   mesh_load_bench convert IN OUT            write IN as OUT (.obj .off .ply)
//
// Output (one line): "<reader> <file> <vertices> v <triangles> tris <seconds> s <peak MiB> MiB <base MiB> MiB"
// where base is the peak RSS before the load began (the program itself).
// Plugins are looked for in $PRISM_PLUGIN_PATH, then in the build tree.
#ifdef PRISM_BENCH_OPENMESH
#include <OpenMesh/Core/IO/MeshIO.hh>  // before the mesh type: registers the readers
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#endif

#include <sys/resource.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "mesh/mesh_loader.h"

namespace {

double peakMiB() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_maxrss / 1024.0;  // ru_maxrss is in KiB on Linux
}

// $PRISM_PLUGIN_PATH first, then build/plugins (this program is
// build/benchmarks/mesh_load/mesh_load_bench).
std::vector<std::string> pluginDirs() {
  std::vector<std::string> dirs = prism::PluginRegistry::defaultSearchPath();
  auto exe = std::filesystem::canonical("/proc/self/exe");
  dirs.push_back((exe.parent_path().parent_path().parent_path() / "plugins").string());
  return dirs;
}

int convert(const std::string& in, const std::string& out, const prism::PluginRegistry& registry) {
  prism::SharedMesh m = prism::loadMeshFile(in, registry);
  std::FILE* f = std::fopen(out.c_str(), "w");
  if (f == nullptr) return std::perror(out.c_str()), 1;
  const std::string ext = std::filesystem::path(out).extension().string();
  const std::size_t nv = m->vertexCount(), nt = m->triangleCount();
  if (ext == ".ply")
    std::fprintf(f, "ply\nformat ascii 1.0\nelement vertex %zu\nproperty float x\nproperty float y\nproperty float z\n"
                    "element face %zu\nproperty list uchar int vertex_indices\nend_header\n", nv, nt);
  else if (ext == ".off")
    std::fprintf(f, "OFF\n%zu %zu 0\n", nv, nt);
  for (std::size_t v = 0; v < nv; ++v)
    std::fprintf(f, ext == ".obj" ? "v %.9g %.9g %.9g\n" : "%.9g %.9g %.9g\n", m->positions[3 * v],
                 m->positions[3 * v + 1], m->positions[3 * v + 2]);
  for (std::size_t t = 0; t < nt; ++t) {
    const std::uint32_t* i = &m->indices[3 * t];
    if (ext == ".obj") std::fprintf(f, "f %u %u %u\n", i[0] + 1, i[1] + 1, i[2] + 1);
    else std::fprintf(f, "3 %u %u %u\n", i[0], i[1], i[2]);
  }
  return std::fclose(f) == 0 ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: %s prism|openmesh FILE | convert IN OUT\n", argv[0]);
    return 2;
  }
  const std::string mode = argv[1], file = argv[2];
  try {
    prism::PluginRegistry registry(pluginDirs());  // scanned before timing starts
    if (mode == "convert") return argc > 3 ? convert(file, argv[3], registry) : 2;
    const double base = peakMiB();
    std::size_t vertices = 0, triangles = 0;
    auto start = std::chrono::steady_clock::now();
    if (mode == "prism") {
      prism::SharedMesh m = prism::loadMeshFile(file, registry);
      vertices = m->vertexCount();
      triangles = m->triangleCount();
#ifdef PRISM_BENCH_OPENMESH
    } else if (mode == "openmesh") {
      OpenMesh::PolyMesh_ArrayKernelT<> mesh;
      if (!OpenMesh::IO::read_mesh(mesh, file)) {
        std::fprintf(stderr, "openmesh: read_mesh failed on %s\n", file.c_str());
        return 1;
      }
      vertices = mesh.n_vertices();
      for (auto f : mesh.faces()) triangles += mesh.valence(f) - 2;
#endif
    } else {
      std::fprintf(stderr, "unknown reader '%s'\n", mode.c_str());
      return 2;
    }
    double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("%s %s %zu v %zu tris %.3f s %.1f MiB %.1f MiB\n", mode.c_str(), file.c_str(), vertices, triangles,
                seconds, peakMiB(), base);
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 1;
  }
}
