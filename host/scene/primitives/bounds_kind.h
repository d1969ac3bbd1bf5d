// Bounding volumes (render.bounds, --bounds, PrismRenderOptions.bounds):
// axis-aligned boxes, or "set of normals" slabs along four diagonals as well
// (Kay and Kajiya) around the analytic objects in the leaves and the BVH's
// children (host/accel/kdop_bounds.h, AccelBuildOptions::kdop_*).
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
