// A primitive kind — sphere, box, plane, triangle, quadric, polygon,
// polyhedron, patch — in one place: how
// the scene format spells it and what makes it valid, its device record, its
// bounds, its exact (or conservative) test against a cell of a spatial
// subdivision, and a double-precision reference intersection. The kernel half
// is kernels/geometry/<kind>.h. Adding a kind: its file here and its kernel
// header, one entry in primitive_kinds.cpp, one case in kernels/geometry/object.h.
//
// Meshes are not a kind: a mesh object expands into triangles.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "kernels/shared/object_gpu.h"
#include "scene/json_reader.h"
#include "scene/primitives/bounds.h"
#include "scene/scene.h"

namespace prism {

// Render-wide settings some kinds' device records depend on.
struct FlattenSettings {
  int inside_test = POLYGON_CROSSING;  // for polygons that name none
};

struct PrimitiveKind {
  ObjectType type;
  int gpu_type;  // OBJECT_* (kernels/shared/object_gpu.h)
  // The scene format's "type" values that make one (presets of one kind share it).
  std::vector<std::string> names;
  // Whether its records carry side data (p[OBJECT_DATA_WORD] holds the offset).
  bool has_side_data;

  // Reads the object's own keys (the loader reads type, material and the
  // transforms) and lists every key it knows through r.checkObject.
  void (*parse)(const JsonReader& r, const Json& v, const std::string& path, const std::string& name, Object& o);
  // After baking: "" when the object can be rendered, else what is wrong with
  // it, naming the field. Shared by the loader and the C API (which goes
  // through the loader).
  std::string (*problem)(const Object& o);
  // Applies a static transform to the geometry, for kinds the kernels keep in
  // world space; null: the kind is intersected in object space.
  void (*bake)(Object& o);

  // The device record of primitive `part` of the object (0 for a kind of one
  // primitive per object; a patch set has Object::primitiveCount() of them):
  // p[] (and flags), with parameters that do not fit p[] appended to `side`
  // (placed in a data record, kernels/shared/object_gpu.h). Throws
  // std::invalid_argument when the settings do not suit the object.
  void (*flatten)(const Object& o, std::size_t part, const FlattenSettings& settings, ObjectGpu& g,
                  std::vector<float>& side);
  // Object-space box of the record's shape, in double; false: unbounded (a
  // plane) or not finite. `side` is the record's side data (or null).
  bool (*local_bounds)(const ObjectGpu& g, const float* side, double lo[3], double hi[3]);
  // Whether the untransformed shape meets the closed cell, exactly (CGAL) or
  // conservatively; counts into *exact_tests the tests CGAL decided. Null: the
  // box from local_bounds decides.
  bool (*meets_cell)(const ObjectGpu& g, const float* side, const CellBox& cell, std::size_t* exact_tests);
  // The box of the part inside `cell` for split heuristics; null: the
  // object's box cut by the cell.
  bool (*clipped_bounds)(const ObjectGpu& g, const CellBox& cell, Aabb* out);

  // Nearest t in (tmin, tmax) where the object-space ray o + t d meets the
  // shape, computed in double from the scene model (not the device record),
  // by a textbook method independent of the kernel's.
  std::optional<double> (*reference)(const Object& o, const Vec3& origin, const Vec3& dir, double tmin, double tmax);
};

// Every kind, in ObjectType order.
const std::vector<const PrimitiveKind*>& primitiveKinds();
// The kind of an analytic object (not a mesh).
const PrimitiveKind& primitiveKind(ObjectType type);
// The kind of a device record, or null for a record that is not a primitive.
const PrimitiveKind* primitiveKindOfGpu(int gpu_type);
// The kind the scene format's `type` names, or null.
const PrimitiveKind* primitiveKindNamed(const std::string& name);
// "sphere, box, plane, ..." for messages.
std::string primitiveKindNames();

// The side data of a record that sits in its object array (null when its kind has none).
const float* objectSideData(const ObjectGpu& g);
// Appends `side` to an object array as a data record (and the records its
// floats run on into), after every primitive; returns the first record's index.
std::size_t appendSideData(const std::vector<float>& side, std::vector<ObjectGpu>& out);
// The offset of a record's data record, for flattening (written as int bits).
void setSideDataOffset(ObjectGpu& g, int records);

// The object keys every kind accepts, plus the kind's own.
std::vector<std::string> objectKeys(std::initializer_list<const char*> own);

// The kinds, each defined in its own file.
extern const PrimitiveKind kSphereKind, kBoxKind, kPlaneKind, kTriangleKind, kQuadricKind, kPolygonKind,
    kPolyhedronKind, kPatchKind;

}  // namespace prism
