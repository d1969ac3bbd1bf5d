// Meshes inside scenes: the same mesh through every format renders the same
// primid and depth AOVs; objects naming one file share it; smooth normals;
// the quick-render camera frames the mesh; which primitives of a flattened
// scene are plain triangles, read from its mesh headers.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>

#include <unistd.h>

#include "mesh/mesh_cache.h"
#include "render/gpu_scene.h"
#include "render/renderer.h"
#include "scene/animation.h"
#include "scene/camera_check.h"
#include "scene/light_check.h"
#include "scene/mesh_objects.h"
#include "scene_format/scene_loader.h"
#include "support/shared_context.h"

using namespace prism;
namespace fs = std::filesystem;

namespace {

// A unit icosahedron subdivided once and pushed onto the sphere: 80 triangles.
struct SmallMesh {
  std::vector<Vec3> v;
  std::vector<std::array<int, 3>> f;
};

SmallMesh icosphere() {
  const double t = (1 + std::sqrt(5.0)) / 2;
  SmallMesh m;
  m.v = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
         {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  m.f = {{0, 11, 5}, {0, 5, 1}, {0, 1, 7}, {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
         {11, 10, 2}, {10, 7, 6}, {7, 1, 8}, {3, 9, 4}, {3, 4, 2}, {3, 2, 6}, {3, 6, 8},
         {3, 8, 9}, {4, 9, 5}, {2, 4, 11}, {6, 2, 10}, {8, 6, 7}, {9, 8, 1}};
  for (Vec3& p : m.v) p = normalize(p);
  SmallMesh out;
  out.v = m.v;
  auto mid = [&](int a, int b) {
    out.v.push_back(normalize((m.v[a] + m.v[b]) * 0.5));
    return static_cast<int>(out.v.size()) - 1;
  };
  for (auto& tri : m.f) {
    int ab = mid(tri[0], tri[1]), bc = mid(tri[1], tri[2]), ca = mid(tri[2], tri[0]);
    out.f.push_back({tri[0], ab, ca});
    out.f.push_back({tri[1], bc, ab});
    out.f.push_back({tri[2], ca, bc});
    out.f.push_back({ab, bc, ca});
  }
  return out;
}

fs::path scratch() {
  fs::path dir = fs::temp_directory_path() / ("prism-mesh-scene-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  return dir;
}

void writeObj(const SmallMesh& m, const fs::path& p) {
  std::ofstream o(p);
  o.precision(9);
  for (auto& v : m.v) o << "v " << v.x << " " << v.y << " " << v.z << "\n";
  for (auto& f : m.f) o << "f " << f[0] + 1 << " " << f[1] + 1 << " " << f[2] + 1 << "\n";
}

// The scene of `json`, whose meshes may name "ico.obj" (the icosphere) beside
// it; a loaded scene holds its meshes, so the files go at once.
Scene icosphereScene(const std::string& json) {
  fs::path dir = scratch();
  writeObj(icosphere(), dir / "ico.obj");
  std::ofstream(dir / "scene.json") << json;
  Scene scene = loadSceneFile((dir / "scene.json").string());
  fs::remove_all(dir);
  return scene;
}

void writeOff(const SmallMesh& m, const fs::path& p) {
  std::ofstream o(p);
  o.precision(9);
  o << "OFF\n" << m.v.size() << " " << m.f.size() << " 0\n";
  for (auto& v : m.v) o << v.x << " " << v.y << " " << v.z << "\n";
  for (auto& f : m.f) o << "3 " << f[0] << " " << f[1] << " " << f[2] << "\n";
}

void writePly(const SmallMesh& m, const fs::path& p, bool binary) {
  std::ofstream o(p, std::ios::binary);
  o << "ply\nformat " << (binary ? "binary_little_endian" : "ascii") << " 1.0\n"
    << "element vertex " << m.v.size() << "\nproperty float x\nproperty float y\nproperty float z\n"
    << "element face " << m.f.size() << "\nproperty list uchar int vertex_indices\nend_header\n";
  o.precision(9);
  for (auto& v : m.v) {
    float xyz[3] = {float(v.x), float(v.y), float(v.z)};
    if (binary)
      o.write(reinterpret_cast<const char*>(xyz), sizeof xyz);
    else
      o << xyz[0] << " " << xyz[1] << " " << xyz[2] << "\n";
  }
  for (auto& f : m.f) {
    if (binary) {
      unsigned char n = 3;
      o.write(reinterpret_cast<const char*>(&n), 1);
      o.write(reinterpret_cast<const char*>(f.data()), 3 * sizeof(int));
    } else {
      o << "3 " << f[0] << " " << f[1] << " " << f[2] << "\n";
    }
  }
}

RenderResult renderMesh(const fs::path& file) {
  Scene scene = sceneForMesh(MeshCache::global().load(file.string()));
  RenderOptions opt = RenderOptions::fromScene(scene);
  opt.width = 64;
  opt.height = 48;
  return test::sharedRenderer().render(scene, opt);
}

}  // namespace

TEST_CASE("the same mesh as OBJ, PLY (ascii and binary) and OFF renders identical primid and depth AOVs",
          "[render][mesh]") {
  SmallMesh m = icosphere();
  fs::path dir = scratch();
  writeObj(m, dir / "ico.obj");
  writeOff(m, dir / "ico.off");
  writePly(m, dir / "ico_ascii.ply", false);
  writePly(m, dir / "ico_binary.ply", true);
  RenderResult reference = renderMesh(dir / "ico_binary.ply");
  int hits = 0;
  for (int32_t id : reference.primid) hits += id >= 0;
  CHECK(hits > 300);  // the sphere fills a good part of the 64x48 frame
  for (const char* name : {"ico.obj", "ico.off", "ico_ascii.ply"}) {
    INFO(name);
    RenderResult r = renderMesh(dir / name);
    CHECK(r.primid == reference.primid);
    CHECK(std::memcmp(r.depth.data(), reference.depth.data(), r.depth.size() * sizeof(float)) == 0);
  }
  fs::remove_all(dir);
}

TEST_CASE("objects naming one mesh file share it, analytic objects number first, then each mesh's triangles",
          "[render][mesh]") {
  SmallMesh m = icosphere();
  Scene scene = icosphereScene(R"({
    "camera": {"position": [0, 0, 9], "look_at": [0, 0, 0], "fov": 40},
    "film": {"width": 48, "height": 32},
    "materials": {"red": {"diffuse": [0.8, 0.1, 0.1]}},
    "lights": [{"position": [0, 5, 9]}],
    "objects": [
      {"type": "mesh", "file": "ico.obj", "transform": {"translate": [-2.5, 0, 0]}},
      {"type": "mesh", "file": "ico.obj", "material": "red", "transform": {"translate": [2.5, 0, 0]}, "smooth": true},
      {"type": "sphere", "center": [0, 0, 0], "radius": 0.5}
    ]
  })");
  REQUIRE(scene.objects.size() == 3);
  CHECK(scene.objects[0].mesh == scene.objects[1].mesh);
  CHECK(scene.objects[1].material_override);
  GpuScene gpu = flattenScene(scene, RenderOptions::fromScene(scene));
  const size_t n = m.f.size();
  // The sphere, the two copies' triangles (compact on the device), their two headers.
  REQUIRE(gpu.primitive_count == 2 * n + 1);
  REQUIRE(gpu.triangle_base == 1);
  REQUIRE(gpu.mesh_count == 2);
  REQUIRE(gpu.objects.size() == 2 * n + 3);
  CHECK(gpu.triangles.size() == 6 * n);
  CHECK(gpu.objects[0].type == OBJECT_SPHERE);
  CHECK(gpu.objects[1 + n].material == 1);  // "red", for every triangle of the second copy
  CHECK(gpu.objects[1].material == 0);
  CHECK(gpu.objects[1 + 2 * n].type == OBJECT_MESH);
  // The device keeps no record per triangle: the sphere and the headers only.
  CHECK(deviceRecords(gpu).size() == 3);

  RenderResult r = test::sharedRenderer().render(scene, RenderOptions::fromScene(scene));
  // Left third: the first copy (ids 1..n); right third: the second (n+1..2n); centre: the sphere.
  auto id = [&](int i, int j) { return r.primid[static_cast<size_t>(j) * r.width + i]; };
  CHECK((id(10, 16) >= 1 && id(10, 16) <= int(n)));
  CHECK((id(37, 16) > int(n) && id(37, 16) <= int(2 * n)));
  CHECK(id(24, 16) == 0);
}

TEST_CASE("the primitives that are not plain triangles are the records a walk over every primitive finds",
          "[render][mesh]") {
  // notPlainTriangles reads a static mesh's header, not its triangles'
  // records: a moving mesh between two static ones, a moving one last, and
  // analytic primitives (a moving sphere among them) must come out as the
  // walk over every record finds them, in order.
  const size_t n = icosphere().f.size();
  Scene scene = icosphereScene(R"({
    "camera": {"position": [0, 0, 9], "look_at": [0, 0, 0], "fov": 40, "shutter": [0, 1]},
    "film": {"width": 16, "height": 16},
    "lights": [{"position": [0, 5, 9]}],
    "objects": [
      {"type": "mesh", "file": "ico.obj", "transform": {"translate": [-2.5, 0, 0]}},
      {"type": "mesh", "file": "ico.obj", "transform": {"translate": [2, 0, 0]}, "transform_end": {"translate": [2, 0.5, 0]}},
      {"type": "sphere", "center": [0, 0, 0], "radius": 0.5, "transform_end": {"translate": [0, 0.2, 0]}},
      {"type": "mesh", "file": "ico.obj", "transform": {"rotate": {"axis": [0, 1, 0], "angle": 30}}},
      {"type": "plane", "point": [0, -2, 0], "normal": [0, 1, 0]},
      {"type": "mesh", "file": "ico.obj", "transform_end": {"translate": [0, 0, 1]}}
    ]
  })");
  GpuScene gpu = flattenScene(scene, RenderOptions::fromScene(scene));
  REQUIRE(gpu.mesh_count == 4);
  REQUIRE(gpu.triangle_base == 2);
  std::vector<size_t> walked;
  for (size_t k = 0; k < gpu.primitive_count; ++k)
    if (gpu.objects[k].type != OBJECT_TRIANGLE || gpu.objects[k].has_transform != 0) walked.push_back(k);
  // The sphere, the plane and the two moving meshes' triangles.
  CHECK(walked.size() == 2 + 2 * n);
  CHECK(notPlainTriangles(gpu) == walked);
  // Compact triangles with no header to say whether they move are refused.
  SceneGeometry headless = gpu;
  headless.mesh_count = 0;
  CHECK_THROWS_AS(notPlainTriangles(headless), std::logic_error);
}

TEST_CASE("k-DOP bounds render the boxes' image bit for bit, moving objects included, and bad names are refused",
          "[render][mesh][kdop]") {
  Scene scene = icosphereScene(R"({
    "camera": {"position": [0.3, 1, 9], "look_at": [0, 0, 0], "fov": 40, "shutter": [0, 1]},
    "film": {"width": 48, "height": 32, "spp": 2},
    "materials": {"glass": {"diffuse": [0.1, 0.1, 0.1], "transmit": 0.8, "ior": 1.5},
                  "mirror": {"diffuse": [0.2, 0.2, 0.2], "reflect": 0.7}},
    "lights": [{"position": [0, 5, 9]}],
    "render": {"accel": "bvh", "bounds": "kdop"},
    "objects": [
      {"type": "mesh", "file": "ico.obj", "material": "glass", "transform": {"translate": [-2, 0, 0], "rotate": {"axis": [1, 1, 0], "angle": 40}}},
      {"type": "mesh", "file": "ico.obj", "transform": {"translate": [2, 0, 0]}, "transform_end": {"translate": [2, 0.5, 0]}},
      {"type": "sphere", "center": [0, 0, -1], "radius": 0.8, "material": "mirror"},
      {"type": "box", "min": [-3, -2, -2], "max": [3, -1.5, 1]},
      {"type": "cylinder", "radius": 0.3, "height": 1, "transform": {"translate": [0, 1.2, 0]}}
    ]
  })");
  RenderOptions kdop = RenderOptions::fromScene(scene);
  REQUIRE(kdop.bounds == BoundsKind::Kdop);
  RenderOptions boxes = kdop;
  boxes.bounds = BoundsKind::Aabb;
  RenderResult a = test::sharedRenderer().render(scene, boxes);
  RenderResult b = test::sharedRenderer().render(scene, kdop);
  REQUIRE(a.rgba.size() == b.rgba.size());
  CHECK(std::memcmp(a.rgba.data(), b.rgba.data(), a.rgba.size() * sizeof(float)) == 0);
  CHECK(a.primid == b.primid);
  CHECK(std::count_if(a.primid.begin(), a.primid.end(), [](auto id) { return id >= 0; }) > long(a.primid.size() / 5));

  fs::path dir = scratch();
  std::ofstream(dir / "bad.json") << R"({"render": {"bounds": "obb"}})";
  CHECK_THROWS_WITH(loadSceneFile((dir / "bad.json").string()),
                    Catch::Contains("render.bounds") && Catch::Contains("unknown bounds 'obb'") &&
                        Catch::Contains("aabb, kdop"));
  fs::remove_all(dir);
}

TEST_CASE("a point cloud is refused for rendering with the reason", "[render][mesh]") {
  fs::path dir = scratch();
  std::ofstream(dir / "points.off") << "OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n";
  std::ofstream(dir / "scene.json") << R"({"objects": [{"type": "mesh", "file": "points.off"}]})";
  CHECK_THROWS_WITH(loadSceneFile((dir / "scene.json").string()),
                    Catch::Contains("objects[0].file") && Catch::Contains("no faces"));
  CHECK_THROWS_WITH(sceneForMesh(MeshCache::global().load((dir / "points.off").string())),
                    Catch::Contains("no faces"));
  fs::remove_all(dir);
}

TEST_CASE("a mesh's vertices stay within 1e15 where its object places them, as a triangle's do",
          "[render][mesh]") {
  fs::path dir = scratch();
  // x = 1e10 is a float, and 1e10 * 1e5 is 1e15 exactly: the limit itself.
  std::ofstream(dir / "far.obj") << "v 1e10 0 0\nv 1e10 1 0\nv 1e10 0 1\nf 1 2 3\n";
  std::ofstream(dir / "huge.obj") << "v 0 0 0\nv 1 0 0\nv 0 1e20 0\nf 1 2 3\n";
  auto load = [&](const std::string& objects) {
    std::ofstream(dir / "scene.json") << R"({"objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1}, )" +
                                             objects + "]}";
    return loadSceneFile((dir / "scene.json").string());
  };
  const std::string far = R"({"type": "mesh", "file": "far.obj")";
  CHECK(load(far + "}").objects.size() == 2);
  CHECK(load(far + R"(, "transform": {"scale": 1e5}})").objects.size() == 2);
  CHECK_THROWS_WITH(load(far + R"(, "transform": {"scale": 1.000001e5}})"),
                    Catch::Contains("objects[1]: vertices must have coordinates of at most 1e15") &&
                        Catch::Contains("once placed by the object's transform") && Catch::Contains("vertex 0") &&
                        Catch::Contains("far.obj"));
  // A moving mesh is placed at both ends (where the flattening puts it when the
  // shutter is closed), and taken as the file has it when the shutter is open
  // (the kernels move the rays into its object space).
  CHECK(load(far + R"(, "transform": {"scale": 1e5}, "transform_end": {"scale": 1e5}})").objects.size() == 2);
  CHECK_THROWS_WITH(load(far + R"(, "transform": {"scale": 1e5}, "transform_end": {"scale": 1.000001e5}})"),
                    Catch::Contains("once placed by the object's transform_end") && Catch::Contains("vertex 0"));
  CHECK_THROWS_WITH(load(far + R"(, "transform": {"scale": 1.000001e5}, "transform_end": {"scale": 1e5}})"),
                    Catch::Contains("once placed by the object's transform:"));
  CHECK_THROWS_WITH(load(R"({"type": "mesh", "file": "huge.obj"})"),
                    Catch::Contains("objects[1]: vertices must have coordinates of at most 1e15") &&
                        Catch::Contains("vertex 2"));
  CHECK_THROWS_WITH(load(R"({"type": "mesh", "file": "huge.obj", "transform": {"scale": 1e-10},
                            "transform_end": {"scale": 1e-10}})"),
                    Catch::Contains("as the mesh has them") && Catch::Contains("vertex 2"));
  // A vertex no face uses is never placed.
  std::ofstream(dir / "stray.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1e30 0 0\nf 1 2 3\n";
  CHECK(load(R"({"type": "mesh", "file": "stray.obj"})").objects.size() == 2);
  // The same rule for a triangle, for comparison: the same words.
  CHECK_THROWS_WITH(load(R"({"type": "triangle", "vertices": [[1e10, 0, 0], [1e10, 1, 0], [1e10, 0, 1]],
                            "transform": {"scale": 1.000001e5}})"),
                    Catch::Contains("objects[1]: vertices must have coordinates of at most 1e15"));
  // A mesh rendered on its own is refused before its camera is placed. One within
  // the limit whose framing camera would stand past it (about 3.25 bounding radii
  // out: z near 1.28e15 here) is shown from a camera at the limit instead, with a
  // warning, as the camera check asks.
  CHECK_THROWS_WITH(sceneForMesh(MeshCache::global().load((dir / "huge.obj").string())),
                    Catch::Contains("vertices must have coordinates of at most 1e15") && Catch::Contains("huge.obj"));
  std::ofstream(dir / "wide.obj") << "v -4e14 0 0\nv 4e14 0 0\nv 0 4e14 0\nf 1 2 3\n";
  const Scene wide = sceneForMesh(MeshCache::global().load((dir / "wide.obj").string()));
  CHECK(cameraProblem(wide.camera).empty());
  CHECK(wide.camera.position.z > 9.99e14);
  REQUIRE(wide.warnings.size() == 1);
  CHECK_THAT(wide.warnings[0], Catch::Contains("wide.obj") && Catch::Contains("too large to show whole"));
  REQUIRE(wide.lights.size() == 1);
  CHECK(wide.lights[0].position == wide.camera.position);  // the headlight
  CHECK(lightProblem(wide.lights[0]).empty());
  // An animation's frame held still places a moving mesh where its path is then:
  // a quarter turn takes (9.9e14, 9.9e14, 0) to (-9.9e14, 9.9e14, 0), and halfway,
  // to (0, 1.4e15, 0).
  std::ofstream(dir / "corner.obj") << "v 9.9e14 9.9e14 0\nv 9.9e14 9e14 0\nv 9e14 9.9e14 0\nf 1 2 3\n";
  std::ofstream(dir / "turning.json") << R"({"animation": {"frames": 3},
      "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1},
                  {"type": "mesh", "file": "corner.obj", "transform_end": {"rotate": {"axis": [0, 0, 1], "angle": 90}}}]})";
  const Scene turning = loadSceneFile((dir / "turning.json").string());
  CHECK_NOTHROW(sceneAtFrame(turning, 0));
  CHECK_NOTHROW(sceneAtFrame(turning, 2));
  CHECK_THROWS_WITH(sceneAtFrame(turning, 1), Catch::Contains("frame 1 of the animation: objects[1]: vertices must have "
                                                              "coordinates of at most 1e15") &&
                                                  Catch::Contains("the object's transform at this frame: vertex 0"));
  fs::remove_all(dir);
}

TEST_CASE("the quick-render camera frames the whole mesh", "[render][mesh]") {
  SmallMesh m = icosphere();
  fs::path dir = scratch();
  writeOff(m, dir / "ico.off");
  Scene scene = sceneForMesh(MeshCache::global().load((dir / "ico.off").string()));
  RenderOptions opt = RenderOptions::fromScene(scene);
  CameraBasis b = cameraBasis(scene.camera, opt.width, opt.height);
  // Every vertex projects inside the film, and the silhouette fills a good part of it.
  double widest = 0;
  for (const Vec3& v : m.v) {
    Vec3 d = v - b.origin;
    double z = dot(d, b.forward);
    REQUIRE(z > 0);
    double x = dot(d, normalize(b.right)) / z / length(b.right);
    double y = dot(d, normalize(b.up)) / z / length(b.up);
    CHECK(std::fabs(x) < 1);
    CHECK(std::fabs(y) < 1);
    widest = std::max(widest, std::fabs(y));
  }
  CHECK(widest > 0.35);  // the bounding sphere of the box is wider than the mesh itself
  CHECK(scene.lights.size() == 1);
  CHECK(scene.lights[0].position == scene.camera.position);
  fs::remove_all(dir);
}
