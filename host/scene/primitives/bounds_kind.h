// What bounds the BVH's children (render.bounds, --bounds,
// PrismRenderOptions.bounds): their axis-aligned boxes, or the boxes and
// "set of normals" slabs along four diagonals as well (Kay and Kajiya's
// bounding volumes; host/accel/kdop_bounds.h).
#pragma once

#include <string>

namespace prism {

enum class BoundsKind { Aabb, Kdop };

constexpr const char* kBoundsKindNames = "aabb, kdop";

// False for an unknown name.
inline bool tryParseBoundsKind(const std::string& name, BoundsKind* kind) {
  if (name == "aabb") *kind = BoundsKind::Aabb;
  else if (name == "kdop") *kind = BoundsKind::Kdop;
  else return false;
  return true;
}

inline const char* boundsKindName(BoundsKind kind) { return kind == BoundsKind::Kdop ? "kdop" : "aabb"; }

}  // namespace prism
