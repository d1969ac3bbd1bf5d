// Compile-time checks that the host compiler lays out the structs shared with
// the kernels as OpenCL C does: 4-byte scalars, no padding, sizes in multiples
// of 16 bytes so arrays of them keep float4 alignment.
#include <cstddef>

#include "kernels/shared/camera_gpu.h"
#include "kernels/shared/contribution_gpu.h"
#include "kernels/shared/hit_gpu.h"
#include "kernels/shared/light_gpu.h"
#include "kernels/shared/material_gpu.h"
#include "kernels/shared/motion_gpu.h"
#include "kernels/shared/object_gpu.h"
#include "kernels/shared/ray_gpu.h"
#include "kernels/shared/surface_gpu.h"

static_assert(sizeof(RayGpu) == 80, "RayGpu must be 80 bytes");
static_assert(offsetof(RayGpu, dx) == 16 && offsetof(RayGpu, wr) == 32 && offsetof(RayGpu, pixel) == 44 &&
                  offsetof(RayGpu, kind) == 52 && offsetof(RayGpu, sample) == 56 &&
                  offsetof(RayGpu, time) == 64 && offsetof(RayGpu, strata_id) == 72,
              "RayGpu field offsets");
static_assert(sizeof(HitGpu) == 16 && offsetof(HitGpu, prim) == 4 && offsetof(HitGpu, v) == 12, "HitGpu layout");
static_assert(sizeof(ObjectGpu) == 112 && offsetof(ObjectGpu, p) == 16 && offsetof(ObjectGpu, world_to_object) == 64,
              "ObjectGpu layout");
static_assert(sizeof(MaterialGpu) == 144 && offsetof(MaterialGpu, image_offset) == 124 && offsetof(MaterialGpu, gloss) == 108 && offsetof(MaterialGpu, roughness) == 116 && offsetof(MaterialGpu, checker2) == 64 &&
                  offsetof(MaterialGpu, shininess) == 80 && offsetof(MaterialGpu, model) == 96,
              "MaterialGpu layout");
static_assert(sizeof(LightGpu) == 96 && offsetof(LightGpu, color) == 16 && offsetof(LightGpu, normal) == 64 &&
                  offsetof(LightGpu, type) == 80,
              "LightGpu layout");
static_assert(sizeof(CameraGpu) == 176 && offsetof(CameraGpu, width) == 64 && offsetof(CameraGpu, seed) == 76 &&
                  offsetof(CameraGpu, look_at) == 96 && offsetof(CameraGpu, moving) == 160,
              "CameraGpu layout");
static_assert(sizeof(ContributionGpu) == 32 && offsetof(ContributionGpu, pixel) == 16, "ContributionGpu layout");
static_assert(sizeof(SurfaceGpu) == 112 && offsetof(SurfaceGpu, material) == 80, "SurfaceGpu layout");
static_assert(sizeof(ObjectDataGpu) == sizeof(ObjectGpu) &&
                  offsetof(ObjectDataGpu, words) == OBJECT_DATA_HEADER_FLOATS * sizeof(float),
              "ObjectDataGpu layout");
static_assert(sizeof(MotionGpu) == sizeof(ObjectGpu) && offsetof(MotionGpu, translate1) == 60,
              "a MotionGpu takes one ObjectGpu slot");
