#include "render/gpu_scene.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>

#include "kernels/shared/mesh_gpu.h"
#include "kernels/shared/motion_gpu.h"
#include "scene/mesh_objects.h"
#include "scene/motion.h"
#include "scene/primitives/polygon_shape.h"
#include "scene/primitives/primitive_kind.h"

namespace prism {
namespace {

constexpr double pi = 3.14159265358979323846;

void put3(float* dst, const Vec3& v) {
  dst[0] = static_cast<float>(v.x);
  dst[1] = static_cast<float>(v.y);
  dst[2] = static_cast<float>(v.z);
}

void put4(float* dst, const Vec3& v, double w = 0) {
  put3(dst, v);
  dst[3] = static_cast<float>(w);
}

// The record of primitive `part` of an analytic object, by its kind;
// parameters that do not fit the record go to `side`.
ObjectGpu flattenObject(const Object& ob, std::size_t part, const FlattenSettings& settings,
                        std::vector<float>& side) {
  const PrimitiveKind& kind = primitiveKind(ob.type);
  ObjectGpu g{};
  g.type = kind.gpu_type;
  g.material = ob.material;
  kind.flatten(ob, part, settings, g, side);
  g.has_transform = ob.transform.isIdentity() ? 0 : 1;
  Transform inv = g.has_transform ? ob.transform.inverse() : Transform::identity();
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 4; ++c) g.world_to_object[4 * r + c] = static_cast<float>(inv.m[r][c]);
  return g;
}

Vec3 vertexAt(const std::vector<float>& xyz, std::uint32_t i) { return {xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]}; }

// The meshes' compact triangles (kernels/shared/mesh_gpu.h), gathered while
// the scene is flattened and placed after the analytic primitives at the end.
struct MeshBlock {
  std::vector<ObjectGpu> records;  // the triangles' host records (the builders' input)
  std::vector<MeshGpu> headers;    // first_triangle counts from the block's start until placed
  std::vector<std::uint32_t> triangles;
  std::vector<float> positions;  // xyz per vertex
  std::vector<float> extras;     // normals, texcoords, materials; offsets count from here until placed
};

float intBits(std::int32_t i) {
  float f;
  std::memcpy(&f, &i, sizeof f);
  return f;
}

// A mesh object's primitives: its triangles into `block`, in file order, in
// world space (object space when the mesh moves: the kernels transform rays at
// their time instead); with polygon faces, one POLYGON record (its vertices
// into `sides`) in `analytic` for each of them instead of its triangles.
void appendMesh(const Object& ob, const FlattenSettings& settings, std::vector<ObjectGpu>& analytic,
                std::vector<std::pair<std::size_t, std::vector<float>>>& sides, MeshBlock& block, bool moving) {
  const TriangleMesh& mesh = *ob.mesh;
  const bool identity = ob.transform.isIdentity() || moving;
  std::vector<Vec3> world(mesh.vertexCount());
  for (std::size_t v = 0; v < world.size(); ++v) {
    Vec3 p = vertexAt(mesh.positions, static_cast<std::uint32_t>(v));
    world[v] = identity ? p : ob.transform.applyPoint(p);
  }
  auto material = [&](std::size_t t) {
    const int file_material = mesh.triangle_materials.empty() ? -1 : mesh.triangle_materials[t];
    return ob.material_override || file_material < 0 ? ob.material : ob.mesh_material_offset + file_material;
  };
  std::vector<std::size_t> kept;  // the triangles that stay triangles
  if (ob.polygon_faces.empty()) {
    kept.resize(mesh.triangleCount());
    for (std::size_t t = 0; t < kept.size(); ++t) kept[t] = t;
  } else {
    // Faces kept as polygons (flat: vertex normals are for triangles), the rest
    // as their fan of triangles.
    std::size_t t = 0;
    for (std::size_t f = 0; f < ob.polygon_faces.size(); ++f) {
      const std::uint32_t corners = mesh.face_corners[f];
      if (ob.polygon_faces[f]) {
        std::vector<Vec3> verts;
        for (std::uint32_t v : faceVertexIndices(mesh, t, corners)) verts.push_back(world[v]);
        ObjectGpu g{};
        std::vector<float> side;
        flattenPolygon(verts, static_cast<InsideTest>(settings.inside_test), g, side);
        g.material = material(t);
        sides.emplace_back(analytic.size(), std::move(side));
        analytic.push_back(g);
      } else {
        for (std::uint32_t k = 0; k + 2 < corners; ++k) kept.push_back(t + k);
      }
      t += corners - 2;
    }
  }
  if (kept.empty()) return;

  constexpr std::size_t kMaxIndex = static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max());
  const std::size_t first_vertex = block.positions.size() / 3;
  if (first_vertex + world.size() > kMaxIndex / 3 || block.extras.size() + 6 * world.size() + kept.size() > kMaxIndex)
    throw std::invalid_argument("scene too large: the meshes hold more than 2^31 / 3 vertices together");
  MeshGpu header{};
  header.type = OBJECT_MESH;
  header.first_triangle = static_cast<int>(block.records.size());
  header.first_vertex = static_cast<int>(first_vertex);
  header.normal_offset = header.texcoord_offset = header.material_offset = -1;
  for (const Vec3& p : world) block.positions.insert(block.positions.end(), {float(p.x), float(p.y), float(p.z)});

  if (ob.smooth && mesh.normals.size() == mesh.positions.size()) {
    // Normals map by the inverse transpose of the object-to-world transform.
    Transform inv = identity ? Transform::identity() : ob.transform.inverse();
    header.flags |= OBJECT_FLAG_VERTEX_NORMALS;
    header.normal_offset = static_cast<int>(block.extras.size());
    for (std::size_t v = 0; v < world.size(); ++v) {
      Vec3 n = vertexAt(mesh.normals, static_cast<std::uint32_t>(v));
      Vec3 w{inv.m[0][0] * n.x + inv.m[1][0] * n.y + inv.m[2][0] * n.z,
             inv.m[0][1] * n.x + inv.m[1][1] * n.y + inv.m[2][1] * n.z,
             inv.m[0][2] * n.x + inv.m[1][2] * n.y + inv.m[2][2] * n.z};
      double len = length(w);
      if (len > 0) w = w / len;
      block.extras.insert(block.extras.end(), {float(w.x), float(w.y), float(w.z)});
    }
  }
  if (mesh.texcoords.size() == 2 * mesh.vertexCount()) {
    header.flags |= OBJECT_FLAG_TEXCOORDS;
    header.texcoord_offset = static_cast<int>(block.extras.size());
    block.extras.insert(block.extras.end(), mesh.texcoords.begin(), mesh.texcoords.end());
  }
  header.material = material(kept.front());
  for (std::size_t t : kept)
    if (material(t) != header.material) header.material = -1;
  if (header.material < 0) {
    header.material_offset = static_cast<int>(block.extras.size());
    for (std::size_t t : kept) block.extras.push_back(intBits(material(t)));
  }
  block.headers.push_back(header);

  for (std::size_t t : kept) {
    ObjectGpu g{};
    g.type = OBJECT_TRIANGLE;
    g.material = material(t);
    for (int k = 0; k < 3; ++k) {
      std::uint32_t v = mesh.indices[3 * t + k];
      put3(g.p + 3 * k, world[v]);
      block.triangles.push_back(static_cast<std::uint32_t>(first_vertex + v));
    }
    block.records.push_back(g);
  }
}

// The motion record of an object moving from `open` to `close` (object to
// world) over the camera's shutter.
MotionGpu flattenMotion(const Transform& open, const Transform& close, const Camera& camera) {
  MotionGpu g{};
  g.type = OBJECT_MOTION;
  // Times on the device count from the shutter's open, as the camera's do.
  g.shutter_open = 0.0f;
  g.shutter_close = static_cast<float>(camera.shutter_close - camera.shutter_open);
  const DecomposedTransform ends[2] = {decompose(open), decompose(close)};
  float* translate[2] = {g.translate0, g.translate1};
  float* rotate[2] = {g.shape0 + MOTION_ROTATION, g.shape1 + MOTION_ROTATION};
  float* stretch[2] = {g.shape0 + MOTION_STRETCH, g.shape1 + MOTION_STRETCH};
  for (int e = 0; e < 2; ++e) {
    put3(translate[e], ends[e].translate);
    for (int i = 0; i < 3; ++i) rotate[e][i] = static_cast<float>(ends[e].rotate[i]);
    const auto& st = ends[e].stretch;
    const double packed[6] = {st[0][0], st[0][1], st[0][2], st[1][1], st[1][2], st[2][2]};
    for (int i = 0; i < 6; ++i) stretch[e][i] = static_cast<float>(packed[i]);
  }
  // Translation alone: keep the constant world-to-object linear part instead.
  if (std::memcmp(g.shape0, g.shape1, sizeof g.shape0) == 0) {
    g.kind = MOTION_TRANSLATE;
    const Transform inv = open.inverse();
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) g.shape0[3 * i + j] = static_cast<float>(inv.m[i][j]);
  }
  return g;
}

MaterialGpu flattenMaterial(const Material& m) {
  MaterialGpu g{};
  put4(g.ambient, m.ambient);
  put4(g.diffuse, m.diffuse);
  put4(g.specular, m.specular);
  put4(g.checker1, m.texture.color1);
  put4(g.checker2, m.texture.color2);
  g.shininess = static_cast<float>(m.shininess);
  g.reflect = static_cast<float>(m.reflect);
  g.transmit = static_cast<float>(m.transmit);
  g.ior = static_cast<float>(m.ior);
  g.model = static_cast<int>(m.model);
  g.texture = static_cast<int>(m.texture.kind);
  g.texture_scale = static_cast<float>(m.texture.scale);
  g.gloss = static_cast<float>(m.gloss);
  g.translucency = static_cast<float>(m.translucency);
  g.roughness = static_cast<float>(m.roughness);
  g.distribution = static_cast<int>(m.distribution);
  return g;
}

// Two orthogonal vectors of length `radius` spanning the plane of unit normal n.
void diskAxes(const Vec3& n, double radius, Vec3& a, Vec3& b) {
  Vec3 helper = std::fabs(n.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
  a = normalize(cross(n, helper));
  b = cross(n, a);
  a = a * radius;
  b = b * radius;
}

LightGpu flattenLight(const Light& l, int spp) {
  LightGpu g{};
  g.type = static_cast<int>(l.type);
  double area = 0;
  switch (l.type) {
    case LightType::Point:
      put4(g.position, l.position);
      break;
    case LightType::Quad:
      put4(g.position, l.corner);
      put4(g.edge1, l.edge1);
      put4(g.edge2, l.edge2);
      put4(g.normal, normalize(cross(l.edge1, l.edge2)));
      area = length(cross(l.edge1, l.edge2));
      break;
    case LightType::Disk: {
      put4(g.position, l.center, l.radius);
      Vec3 n = normalize(l.normal), a, b;
      diskAxes(n, l.radius, a, b);
      put4(g.edge1, a);
      put4(g.edge2, b);
      put4(g.normal, n);
      area = pi * l.radius * l.radius;
      break;
    }
    case LightType::Sphere:
      put4(g.position, l.center, l.radius);
      area = 4 * pi * l.radius * l.radius;
      break;
  }
  put4(g.color, l.color * l.intensity, area);
  // The feelers spawn_shadows sends per hit: an area light's `samples` are per
  // pixel; a point light's one feeler is traced by shade, so it spawns none.
  g.samples = l.type == LightType::Point ? 0 : std::max(1, (l.samples + spp - 1) / spp);
  return g;
}

}  // namespace

CameraBasis cameraBasis(const Camera& camera, int width, int height) {
  CameraBasis b;
  b.origin = camera.position;
  b.forward = normalize(camera.look_at - camera.position);
  Vec3 right = normalize(cross(b.forward, camera.up));
  Vec3 up = cross(right, b.forward);
  double tan_half = std::tan(camera.fov * pi / 360.0);
  double aspect = static_cast<double>(width) / height;
  b.right = right * (tan_half * aspect);
  b.up = up * tan_half;
  return b;
}

GpuScene flattenScene(const Scene& scene, const RenderOptions& options) {
  GpuScene g;
  // Objects move only when the shutter is open for a while; each moving one's
  // primitives (a moving mesh: its header and its triangles' host records)
  // point to its motion record, appended after every primitive and header.
  const bool shutter = scene.camera.hasShutterInterval();
  std::vector<MotionGpu> motions;
  // (index, motion record): analytic primitives, triangle records of the block, headers.
  std::vector<std::pair<std::size_t, std::size_t>> moving_analytic, moving_triangles, moving_headers;
  std::vector<ObjectGpu> analytic;
  MeshBlock block;
  std::vector<std::pair<std::size_t, std::vector<float>>> sides;  // (primitive, its side data)
  FlattenSettings settings;
  settings.inside_test = static_cast<int>(options.inside_test);
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    const Object& ob = scene.objects[i];
    const bool moves = shutter && ob.moving;
    const std::size_t first = analytic.size(), first_triangle = block.records.size(),
                      first_header = block.headers.size();
    if (ob.type == ObjectType::Mesh) {
      try {
        appendMesh(ob, settings, analytic, sides, block, moves);
      } catch (const std::invalid_argument& e) {
        throw std::invalid_argument("objects[" + std::to_string(i) + "]: " + e.what());
      }
    } else {
      for (std::size_t part = 0; part < ob.primitiveCount(); ++part) {
        std::vector<float> side;
        try {
          analytic.push_back(flattenObject(ob, part, settings, side));
        } catch (const std::invalid_argument& e) {
          throw std::invalid_argument("objects[" + std::to_string(i) + "]: " + e.what());
        }
        if (!side.empty()) sides.emplace_back(analytic.size() - 1, std::move(side));
      }
    }
    if (!moves) continue;
    for (std::size_t k = first; k < analytic.size(); ++k) moving_analytic.emplace_back(k, motions.size());
    for (std::size_t k = first_triangle; k < block.records.size(); ++k) moving_triangles.emplace_back(k, motions.size());
    for (std::size_t k = first_header; k < block.headers.size(); ++k) moving_headers.emplace_back(k, motions.size());
    motions.push_back(flattenMotion(ob.transform, ob.transform_end, scene.camera));
  }

  // Host records: analytic primitives, triangle records, headers, motion, data.
  const std::size_t base = analytic.size(), triangles = block.records.size(), meshes = block.headers.size();
  g.triangle_base = base;
  g.primitive_count = base + triangles;
  g.mesh_count = meshes;
  g.objects = std::move(analytic);
  g.objects.reserve(base + triangles + meshes + motions.size());
  g.objects.insert(g.objects.end(), block.records.begin(), block.records.end());
  block.records = {};
  const std::size_t extras_at = block.positions.size();
  if (extras_at + block.extras.size() > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max()))
    throw std::invalid_argument("scene too large: the meshes hold more than 2^31 values together");
  for (MeshGpu& h : block.headers) {
    h.first_triangle += static_cast<int>(base);
    for (int* offset : {&h.normal_offset, &h.texcoord_offset, &h.material_offset})
      if (*offset >= 0) *offset += static_cast<int>(extras_at);
    ObjectGpu slot;
    std::memcpy(&slot, &h, sizeof slot);
    g.objects.push_back(slot);
  }
  const std::size_t motion_base = g.objects.size();
  auto setMotion = [&](std::size_t index, std::size_t k) {
    const std::size_t offset = motion_base + k - index;
    if (offset >= (std::size_t(1) << (31 - OBJECT_MOTION_SHIFT)))
      throw std::invalid_argument("motion blur: a moving object's primitives must be among the first " +
                                  std::to_string(1u << (31 - OBJECT_MOTION_SHIFT)) + " of the scene");
    ObjectGpu& o = g.objects[index];
    o.has_transform = OBJECT_MOVING;
    o.flags |= static_cast<int>(offset << OBJECT_MOTION_SHIFT);
  };
  for (const auto& [i, k] : moving_analytic) setMotion(i, k);
  for (const auto& [i, k] : moving_triangles) setMotion(base + i, k);
  for (const auto& [i, k] : moving_headers) setMotion(base + triangles + i, k);
  for (const MotionGpu& m : motions) {
    ObjectGpu slot;
    std::memcpy(&slot, &m, sizeof slot);
    g.objects.push_back(slot);
  }
  for (const auto& [i, side] : sides) {
    const std::size_t record = appendSideData(side, g.objects);
    if (record - i > static_cast<std::size_t>(std::numeric_limits<int>::max()))
      throw std::invalid_argument("scene too large: side data beyond 2^31 records of its primitive");
    setSideDataOffset(g.objects[i], static_cast<int>(record - i));
  }
  g.triangles = std::move(block.triangles);
  g.mesh_data = std::move(block.positions);
  g.mesh_data.insert(g.mesh_data.end(), block.extras.begin(), block.extras.end());
  // The readers refuse images past the limit before reading them; this
  // guards scenes assembled in code.
  if (const std::size_t held = imageTexelsHeld(scene); held > kMaxTextureTexels)
    throw std::invalid_argument("textures: the scene's images hold " + std::to_string(held) + " texels together, more than " +
                                std::to_string(kMaxTextureTexels));
  std::map<const ImageTexture*, int> image_offsets;  // each image's texels once, however many materials use it
  for (const Material& m : scene.materials) {
    MaterialGpu mg = flattenMaterial(m);
    if (const ImageTexture* image = m.texture.kind == Texture::Kind::Image ? m.texture.image.get() : nullptr) {
      auto [it, fresh] = image_offsets.emplace(image, static_cast<int>(g.texels.size() / 4));
      if (fresh) {
        const std::size_t texels = static_cast<std::size_t>(image->width) * image->height;
        for (std::size_t t = 0; t < texels; ++t)
          g.texels.insert(g.texels.end(), {image->rgb[3 * t], image->rgb[3 * t + 1], image->rgb[3 * t + 2], 1.0f});
      }
      mg.image_offset = it->second;
      mg.image_width = image->width;
      mg.image_height = image->height;
      mg.wrap = static_cast<int>(m.texture.wrap);
    }
    g.materials.push_back(mg);
  }
  if (g.texels.empty()) g.texels.assign(4, 0.0f);  // (a buffer cannot be empty)
  for (const Light& l : scene.lights) g.lights.push_back(flattenLight(l, std::max(1, options.spp)));
  put4(g.ambient, scene.render.ambient);
  put4(g.background, scene.render.background);
  CameraBasis b = cameraBasis(scene.camera, options.width, options.height);
  put4(g.camera.origin, b.origin);
  put4(g.camera.forward, b.forward);
  put4(g.camera.right, b.right);
  put4(g.camera.up, b.up);
  g.camera.width = options.width;
  g.camera.height = options.height;
  g.camera.spp = options.spp;
  g.camera.seed = static_cast<int>(static_cast<std::uint32_t>(options.seed ^ (options.seed >> 32)));
  const Camera& c = scene.camera;
  g.camera.lens_radius = static_cast<float>(c.aperture);
  g.camera.focus_distance = static_cast<float>(c.focus_distance > 0 ? c.focus_distance : length(c.look_at - c.position));
  // Time on the device counts from the shutter's open: a late frame of an
  // animation (open near 1e6) would otherwise have instants 0.0625 apart.
  g.camera.shutter_open = 0.0f;
  g.camera.shutter_close = static_cast<float>(c.shutter_close - c.shutter_open);
  g.camera.moving = c.moving && c.hasShutterInterval() ? 1 : 0;
  put4(g.camera.look_at, c.look_at);
  put4(g.camera.origin_end, c.moving ? c.position_end : c.position);
  put4(g.camera.look_at_end, c.moving ? c.look_at_end : c.look_at);
  put4(g.camera.world_up, c.up, std::tan(c.fov * pi / 360.0));
  return g;
}

}  // namespace prism
