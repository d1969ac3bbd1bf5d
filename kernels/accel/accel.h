/* The interface every acceleration structure implements for the extend and
 * occlude kernels. A structure's header defines ACCEL_PARAMS (the kernel
 * parameters it needs), ACCEL_ARGS (passing them on) and:
 *   bool accel_closest(ACCEL_PARAMS, float3 o, float3 d, float tmin, float tmax, HitGpu* hit);
 *   float accel_transmittance(ACCEL_PARAMS, __global const MaterialGpu* materials,
 *                             float3 o, float3 d, float tmin, float tmax);
 * The program is built with -DPRISM_ACCEL_<NAME> to pick one. */
#ifndef PRISM_ACCEL_ACCEL_H
#define PRISM_ACCEL_ACCEL_H

#include "accel/none.h"

#endif
