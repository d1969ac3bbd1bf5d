// The light buffer (Haines and Greenberg, "The light buffer: a shadow-testing
// accelerator", 1986): for each point light, a direction cube around it whose
// cells list every primitive that some ray leaving the light through that cell
// could meet. A shadow feeler from a surface point to the light lies along one
// direction from the light, so it tests only the list of the cell that
// direction falls in (kernels/shading/light_buffer.h), instead of walking the
// acceleration structure. Unbounded primitives (planes) are in no list: the
// feeler tests them all, as every structure does.
//
// A face's cells cover only the window of directions in which the bounded
// primitives' box is seen from the light (directions outside it meet nothing
// bounded). A primitive is listed in a cell when its bounding box's directions
// from the light reach the cell, widened by a small margin so that float rounding in
// the kernel's choice of face and cell can never miss it: conservative, so the
// shadows are those of the acceleration structure (tests/render/light_buffer_test.cpp).
// Primitives without a box (planes) have their own list, which every feeler tests.
#pragma once

#include <cstdint>
#include <vector>

#include "kernels/shared/light_gpu.h"
#include "kernels/shared/object_gpu.h"
#include "accel/accel_structure.h"
#include "render/render_options.h"

namespace prism {

// More point lights than this: `--shadows lightbuffer` is refused (auto takes
// the structure), since every light holds its own cube.
constexpr std::size_t kMaxLightBufferLights = 64;
constexpr int kMaxLightBufferResolution = 256;
constexpr std::size_t kLightBufferCellBudget = std::size_t(1) << 22;  // cells of all lights together

struct LightBuffer {
  int resolution = 1;  // cells along a face's side
  // First the unbounded primitives' entry; then per light (all of them, in
  // order; lights other than points have empty cells), per face (+x, -x, +y,
  // -y, +z, -z), per cell (row j, column i): the first index into `ids` and
  // the count.
  std::vector<std::int32_t> cells;  // 2 ints per entry
  std::vector<std::int32_t> ids;
  // Per light and face, the window of directions its cells cover (where the
  // bounded primitives' box is seen from the light): u0, cells per unit of u,
  // v0, cells per unit of v; a face that sees none has 0 cells per unit.
  std::vector<float> windows;
  // The mean length of the list a feeler tests (before planes), taking each
  // cell as often as it holds primitives (feelers leave from surfaces):
  // sum of count^2 / sum of count.
  double mean_candidates = 0;
};

// Cells along a face window's side for a scene of `bounded` primitives: about
// one primitive per cell, from 1 to kMaxLightBufferResolution, within
// kLightBufferCellBudget cells over `point_lights` lights.
int lightBufferResolution(std::size_t bounded, std::size_t point_lights);

// The light buffer of every point light over the bounded primitives (the
// records before the first non-primitive record; planes go in their own list).
LightBuffer buildLightBuffer(const std::vector<ObjectGpu>& objects, const std::vector<LightGpu>& lights,
                             int resolution);

// How this scene's point-light feelers go: `asked`, or for auto the light
// buffer when its cells list few enough candidates (mean_candidates at most
// kAutoLightBufferCandidates; calibrated with prism-bench shadows, docs/accel.md)
// and the structure otherwise — always the structure when it is brute force
// (`structure`, the one in use, is none: a handful of primitives, which the
// light buffer would list whole). The light buffer, when it is the answer, is
// left in *out. Throws std::invalid_argument, in the user's terms, when the
// light buffer is asked for a scene it cannot serve (too many point lights).
constexpr double kAutoLightBufferCandidates = 8;
constexpr std::size_t kAutoLightBufferMaxPrimitives = 100000;
ShadowMode planShadows(ShadowMode asked, AccelKind structure, const std::vector<ObjectGpu>& objects,
                       const std::vector<LightGpu>& lights, LightBuffer* out);

}  // namespace prism
