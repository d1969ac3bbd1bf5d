// The registration of every primitive kind.
#include <array>
#include <cstring>
#include <stdexcept>

#include "scene/primitives/primitive_kind.h"

namespace prism {

const std::vector<const PrimitiveKind*>& primitiveKinds() {
  static const std::vector<const PrimitiveKind*> kinds = {&kSphereKind, &kBoxKind, &kPlaneKind, &kTriangleKind,
                                                             &kQuadricKind, &kPolygonKind, &kPolyhedronKind,
                                                             &kPatchKind};
  return kinds;
}

const PrimitiveKind& primitiveKind(ObjectType type) {
  for (const PrimitiveKind* k : primitiveKinds())
    if (k->type == type) return *k;
  throw std::logic_error("no primitive kind for object type " + std::to_string(static_cast<int>(type)));
}

const PrimitiveKind* primitiveKindOfGpu(int gpu_type) {
  // Asked twice for every primitive a builder bounds: a table by type.
  static const std::array<const PrimitiveKind*, 32> table = [] {
    std::array<const PrimitiveKind*, 32> t{};
    for (const PrimitiveKind* k : primitiveKinds())
      if (k->gpu_type >= 0 && k->gpu_type < 32 && !t[k->gpu_type]) t[k->gpu_type] = k;
    return t;
  }();
  return gpu_type >= 0 && gpu_type < 32 ? table[gpu_type] : nullptr;
}

const PrimitiveKind* primitiveKindNamed(const std::string& name) {
  for (const PrimitiveKind* k : primitiveKinds())
    for (const std::string& n : k->names)
      if (n == name) return k;
  return nullptr;
}

std::string primitiveKindNames() {
  std::vector<std::string> names;
  for (const PrimitiveKind* k : primitiveKinds()) names.insert(names.end(), k->names.begin(), k->names.end());
  return join(names);
}

const float* objectSideData(const ObjectGpu& g) {
  const PrimitiveKind* kind = primitiveKindOfGpu(g.type);
  if (!kind || !kind->has_side_data) return nullptr;
  int records;
  std::memcpy(&records, &g.p[OBJECT_DATA_WORD], sizeof records);
  // The floats run on past the record's `words` into the records after it:
  // address them from the record's bytes, not through that array.
  return reinterpret_cast<const float*>(reinterpret_cast<const unsigned char*>(&g + records) +
                                        OBJECT_DATA_HEADER_FLOATS * sizeof(float));
}

std::size_t appendSideData(const std::vector<float>& side, std::vector<ObjectGpu>& out) {
  const std::size_t first = out.size();
  constexpr std::size_t kSlot = sizeof(ObjectGpu) / sizeof(float);
  const std::size_t records = (OBJECT_DATA_HEADER_FLOATS + side.size() + kSlot - 1) / kSlot;
  out.resize(first + records, ObjectGpu{});
  ObjectDataGpu header{};
  header.type = OBJECT_DATA;
  header.size = static_cast<int>(side.size());
  unsigned char* bytes = reinterpret_cast<unsigned char*>(&out[first]);
  std::memcpy(bytes, &header, OBJECT_DATA_HEADER_FLOATS * sizeof(float));
  std::memcpy(bytes + OBJECT_DATA_HEADER_FLOATS * sizeof(float), side.data(), side.size() * sizeof(float));
  return first;
}

void setSideDataOffset(ObjectGpu& g, int records) { std::memcpy(&g.p[OBJECT_DATA_WORD], &records, sizeof records); }

std::vector<std::string> objectKeys(std::initializer_list<const char*> own) {
  std::vector<std::string> keys = {"type", "material", "transform", "transform_end"};
  keys.insert(keys.end(), own.begin(), own.end());
  return keys;
}

}  // namespace prism
