#include "render/light_buffer.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

#include "accel/prim_ref.h"

namespace prism {
namespace {

// Relative widening of each face's (u, v) range: far above float's rounding of
// the kernel's w_b / |w_a|, far below a cell.
constexpr double kMargin = 1e-4;

struct Face {
  int axis, sign, b, c;  // its axis, the side it faces, and its (u, v) axes
};
constexpr Face kFaces[6] = {{0, 1, 1, 2}, {0, -1, 1, 2}, {1, 1, 0, 2}, {1, -1, 0, 2}, {2, 1, 0, 1}, {2, -1, 0, 1}};

// The (u, v) range, on `face` (u = x_b / |x_a| from the light), of the
// directions from `light` to the box, clipped to the face and widened by
// kMargin; false when none of them is on this face.
bool faceRange(const Face& f, const double lo[3], const double hi[3], const double light[3], double* u0, double* u1,
               double* v0, double* v1) {
  // The part of the box on the face's side of the light: distances along the axis.
  double dmin, dmax;
  if (f.sign > 0) {
    dmin = lo[f.axis] - light[f.axis];
    dmax = hi[f.axis] - light[f.axis];
  } else {
    dmin = light[f.axis] - hi[f.axis];
    dmax = light[f.axis] - lo[f.axis];
  }
  if (dmax < 0) return false;
  *u0 = *v0 = -1, *u1 = *v1 = 1;
  if (dmin > 0) {
    // u = (x_b - L_b) / d is monotone in each over the part: its corners bound it.
    const double ub[2] = {lo[f.b] - light[f.b], hi[f.b] - light[f.b]}, vb[2] = {lo[f.c] - light[f.c], hi[f.c] - light[f.c]};
    *u0 = *v0 = INFINITY;
    *u1 = *v1 = -INFINITY;
    for (double d : {dmin, dmax})
      for (int k = 0; k < 2; ++k) {
        *u0 = std::min(*u0, ub[k] / d), *u1 = std::max(*u1, ub[k] / d);
        *v0 = std::min(*v0, vb[k] / d), *v1 = std::max(*v1, vb[k] / d);
      }
  }  // else the part reaches the light's plane: every direction of the face, conservatively
  const double m = 1 + kMargin;
  if (*u0 > m || *u1 < -m || *v0 > m || *v1 < -m) return false;
  *u0 = std::max(*u0, -1.0) - kMargin, *u1 = std::min(*u1, 1.0) + kMargin;
  *v0 = std::max(*v0, -1.0) - kMargin, *v1 = std::min(*v1, 1.0) + kMargin;
  return true;
}

// A face's window as the kernel maps it: cell = floor((x - origin) * scale),
// clamped, from the float values it is given.
struct Window {
  float u0 = 0, su = 0, v0 = 0, sv = 0;
  int cell(double x, float origin, float scale, int res) const {
    return std::clamp(static_cast<int>(std::floor((x - origin) * double(scale))), 0, res - 1);
  }
};

}  // namespace

int lightBufferResolution(std::size_t bounded, std::size_t point_lights) {
  // About one primitive per cell of the faces' windows, within the cell budget.
  const int budget = static_cast<int>(std::sqrt(double(kLightBufferCellBudget) / (6.0 * std::max<std::size_t>(1, point_lights))));
  const int r = static_cast<int>(std::ceil(std::sqrt(double(bounded))));
  return std::clamp(std::min(r, budget), 1, kMaxLightBufferResolution);
}

LightBuffer buildLightBuffer(const std::vector<ObjectGpu>& objects, const std::vector<LightGpu>& lights,
                             int resolution) {
  LightBuffer lb;
  lb.resolution = resolution;
  const std::size_t per_light = 6 * static_cast<std::size_t>(resolution) * resolution;
  const std::size_t n = primitiveCount(objects);
  std::vector<std::array<double, 6>> boxes;
  std::vector<std::int32_t> bounded;
  for (std::size_t i = 0; i < n; ++i) {
    Aabb b;
    if (!objectBounds(objects[i], &b)) {
      lb.ids.push_back(static_cast<std::int32_t>(i));  // unbounded: tested by every feeler
      continue;
    }
    boxes.push_back({b.lo[0], b.lo[1], b.lo[2], b.hi[0], b.hi[1], b.hi[2]});
    bounded.push_back(static_cast<std::int32_t>(i));
  }
  lb.cells.assign(2 * (1 + per_light * lights.size()), 0);
  lb.windows.assign(4 * 6 * lights.size(), 0.0f);
  double scene_lo[3] = {INFINITY, INFINITY, INFINITY}, scene_hi[3] = {-INFINITY, -INFINITY, -INFINITY};
  for (const auto& b : boxes)
    for (int a = 0; a < 3; ++a) scene_lo[a] = std::min(scene_lo[a], b[a]), scene_hi[a] = std::max(scene_hi[a], b[3 + a]);
  lb.cells[1] = static_cast<std::int32_t>(lb.ids.size());  // entry 0: the unbounded, from ids[0]
  std::vector<std::int32_t> counts(per_light);
  double weighted = 0, weights = 0;
  for (std::size_t l = 0; l < lights.size(); ++l) {
    if (lights[l].type != LIGHT_POINT) continue;
    const double light[3] = {lights[l].position[0], lights[l].position[1], lights[l].position[2]};
    // Each face's cells cover only where the bounded primitives' box is seen
    // from the light: every cell then has its share of them.
    Window windows[6];
    for (int f = 0; f < 6; ++f) {
      double u0, u1, v0, v1;
      if (boxes.empty() || !faceRange(kFaces[f], scene_lo, scene_hi, light, &u0, &u1, &v0, &v1)) continue;
      Window& w = windows[f];
      w.u0 = static_cast<float>(u0), w.v0 = static_cast<float>(v0);
      w.su = static_cast<float>(resolution / std::max(u1 - u0, 1e-6));
      w.sv = static_cast<float>(resolution / std::max(v1 - v0, 1e-6));
      float* out = &lb.windows[4 * (6 * l + f)];
      out[0] = w.u0, out[1] = w.su, out[2] = w.v0, out[3] = w.sv;
    }
    // Two passes: count, then fill, so each light's lists are contiguous.
    for (int pass = 0; pass < 2; ++pass) {
      std::vector<std::int32_t> cursor;
      if (pass == 1) {
        cursor.resize(per_light);
        for (std::size_t c = 0; c < per_light; ++c) {
          cursor[c] = static_cast<std::int32_t>(lb.ids.size());
          lb.cells[2 * (1 + l * per_light + c)] = cursor[c];
          lb.cells[2 * (1 + l * per_light + c) + 1] = counts[c];
          lb.ids.resize(lb.ids.size() + counts[c]);
        }
      } else {
        std::fill(counts.begin(), counts.end(), 0);
      }
      for (std::size_t k = 0; k < bounded.size(); ++k)
        for (int f = 0; f < 6; ++f) {
          double u0, u1, v0, v1;
          const Window& w = windows[f];
          if (w.su == 0 || !faceRange(kFaces[f], boxes[k].data(), boxes[k].data() + 3, light, &u0, &u1, &v0, &v1))
            continue;
          const int i0 = w.cell(u0, w.u0, w.su, resolution), i1 = w.cell(u1, w.u0, w.su, resolution);
          const int j0 = w.cell(v0, w.v0, w.sv, resolution), j1 = w.cell(v1, w.v0, w.sv, resolution);
          for (int j = j0; j <= j1; ++j)
            for (int i = i0; i <= i1; ++i) {
              const std::size_t c = (static_cast<std::size_t>(f) * resolution + j) * resolution + i;
              if (pass == 0)
                ++counts[c];
              else
                lb.ids[cursor[c]++] = bounded[k];
            }
        }
    }
    // Feelers leave from surfaces, so a cell is met about as often as it
    // holds primitives: weight each list's length by its own length.
    for (std::int32_t n : counts) {
      weighted += double(n) * n;
      weights += n;
    }
  }
  lb.mean_candidates = weights > 0 ? weighted / weights : 0;
  if (lb.ids.empty()) lb.ids.push_back(0);  // (a buffer cannot be empty; count 0 reads none)
  return lb;
}

ShadowMode planShadows(ShadowMode asked, AccelKind structure, const std::vector<ObjectGpu>& objects,
                       const std::vector<LightGpu>& lights, LightBuffer* out) {
  std::size_t points = 0;
  for (const LightGpu& l : lights) points += l.type == LIGHT_POINT;
  if (asked == ShadowMode::Accel || points == 0) return ShadowMode::Accel;  // (no point light: nothing to choose)
  if (points > kMaxLightBufferLights) {
    if (asked == ShadowMode::Auto) return ShadowMode::Accel;
    throw std::invalid_argument("shadows lightbuffer: at most " + std::to_string(kMaxLightBufferLights) +
                                " point lights have a light buffer, and the scene has " + std::to_string(points) +
                                "; use shadows accel or auto");
  }
  const std::size_t primitives = primitiveCount(objects);
  if (asked == ShadowMode::Auto && (structure == AccelKind::None || primitives > kAutoLightBufferMaxPrimitives))
    return ShadowMode::Accel;
  *out = buildLightBuffer(objects, lights, lightBufferResolution(primitives, points));
  if (asked == ShadowMode::Auto && out->mean_candidates > kAutoLightBufferCandidates) return ShadowMode::Accel;
  return ShadowMode::LightBuffer;
}

}  // namespace prism
