#include "loop_subdivision.h"

#include <OpenMesh/Core/IO/MeshIO.hh>  // before the mesh type: registers the readers and writers
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Tools/Subdivider/Uniform/LoopT.hh>

#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <unistd.h>

namespace prism::bench {

using SubdivisionMesh = OpenMesh::TriMesh_ArrayKernelT<>;

void writeLoopSubdivided(const std::string& in, const std::string& out, int steps) {
  SubdivisionMesh mesh;
  if (!OpenMesh::IO::read_mesh(mesh, in) || mesh.n_faces() == 0)
    throw std::runtime_error(in + ": OpenMesh could not read a triangle mesh from it");
  OpenMesh::Subdivider::Uniform::LoopT<SubdivisionMesh> loop;
  if (!loop.attach(mesh) || !loop(static_cast<size_t>(steps)))
    throw std::runtime_error(in + ": Loop subdivision failed");
  loop.detach();
  const std::filesystem::path target(out);
  std::filesystem::create_directories(target.parent_path());
  // Written beside the target and renamed, so an interrupted run leaves no half
  // file; the name keeps its extension, by which OpenMesh picks the writer.
  const std::string partial =
      (target.parent_path() / (".partial-" + std::to_string(getpid()) + "-" + target.filename().string())).string();
  OpenMesh::IO::Options binary(OpenMesh::IO::Options::Binary | OpenMesh::IO::Options::LSB);
  if (!OpenMesh::IO::write_mesh(mesh, partial, binary)) {
    std::remove(partial.c_str());
    throw std::runtime_error(out + ": could not be written");
  }
  std::filesystem::rename(partial, out);
}

}  // namespace prism::bench
