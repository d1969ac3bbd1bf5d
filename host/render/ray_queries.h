// Closest-hit and any-hit queries for caller-supplied rays, through the same
// extend / occlude kernels the renderer uses. The tests check the kernels'
// intersection routines through this path.
#pragma once

#include <vector>

#include "device/context.h"
#include "kernels/shared/hit_gpu.h"
#include "kernels/shared/ray_gpu.h"
#include "scene/scene.h"

namespace prism {

// Closest hit of each ray (only origin, direction, tmin and tmax are read).
std::vector<HitGpu> traceClosest(Context& context, const Scene& scene, const std::vector<RayGpu>& rays);

// Fraction of light each ray carries from tmin to tmax (1 unblocked, 0 blocked by
// an opaque object, the product of k_trans over semitransparent ones).
std::vector<float> traceTransmittance(Context& context, const Scene& scene, const std::vector<RayGpu>& rays);

}  // namespace prism
