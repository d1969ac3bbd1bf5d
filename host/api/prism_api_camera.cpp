// C API: the scene's camera and the choice of acceleration structure.
#include <cstring>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "api/api_boundary.h"
#include "api/api_enums.h"
#include "api/api_fragments.h"
#include "api/api_handles.h"
#include "scene_format/scene_loader.h"

using namespace prism;

namespace {

struct AccelName {
  const char* name;
  PrismAccel accel;
};
const AccelName kAccelNames[] = {
    {"bvh", PRISM_ACCEL_BVH},   {"octree", PRISM_ACCEL_OCTREE}, {"bsp", PRISM_ACCEL_BSP},
    {"none", PRISM_ACCEL_NONE}, {"auto", PRISM_ACCEL_AUTO}};


}  // namespace

const char* accelNameOf(std::int64_t value) {
  for (const AccelName& entry : kAccelNames)
    if (static_cast<std::int64_t>(entry.accel) == value) return entry.name;
  return nullptr;
}

extern "C" {

PRISM_API PrismStatus prismGetCamera(PrismScene scene, PrismCamera* camera) {
  if (!scene || !camera) return fail(PRISM_ERROR_INVALID_ARGUMENT, "prismGetCamera: NULL argument");
  const Camera& c = scene->scene.camera;
  camera->struct_size = sizeof(PrismCamera);
  putVec3(camera->position, c.position);
  putVec3(camera->look_at, c.look_at);
  putVec3(camera->up, c.up);
  camera->fov_degrees = static_cast<float>(c.fov);
  camera->aperture = static_cast<float>(c.aperture);
  camera->focus_distance = static_cast<float>(c.focus_distance);
  camera->shutter_open = static_cast<float>(c.shutter_open);
  camera->shutter_close = static_cast<float>(c.shutter_close);
  camera->moving = c.moving ? 1 : 0;
  putVec3(camera->position_end, c.moving ? c.position_end : c.position);
  putVec3(camera->look_at_end, c.moving ? c.look_at_end : c.look_at);
  return PRISM_OK;
}

PRISM_API PrismStatus prismSetCamera(PrismScene scene, const PrismCamera* camera) {
  if (!scene || !camera) return fail(PRISM_ERROR_INVALID_ARGUMENT, "prismSetCamera: NULL argument");
  if (camera->struct_size < sizeof(PrismCamera))
    return fail(PRISM_ERROR_INVALID_ARGUMENT, "prismSetCamera: struct_size is too small (fill it with prismGetCamera)");
  return guarded(__func__, [&] {
    // The scene loader reads the camera, as it would from a file, into a scratch
    // scene whose camera starts from the defaults: every field is replaced, and
    // the rules and messages are the file's. A focus distance of 0 (to look_at)
    // and a camera that does not move are what a file says by leaving keys out.
    nlohmann::json c{{"position", jsonTriple(camera->position)},
                     {"look_at", jsonTriple(camera->look_at)},
                     {"up", jsonTriple(camera->up)},
                     {"fov", camera->fov_degrees},
                     {"aperture", camera->aperture},
                     {"shutter", nlohmann::json::array({camera->shutter_open, camera->shutter_close})}};
    if (camera->focus_distance != 0) c["focus_distance"] = camera->focus_distance;
    if (camera->moving) {
      c["position_end"] = jsonTriple(camera->position_end);
      c["look_at_end"] = jsonTriple(camera->look_at_end);
    }
    Scene scratch;
    addCallFragment(scratch, nlohmann::json{{"camera", c}});
    scene->scene.camera = scratch.camera;
    return PRISM_OK;
  });
}

PRISM_API PrismStatus prismParseAccel(const char* name, PrismAccel* accel) {
  if (!name || !accel) return fail(PRISM_ERROR_INVALID_ARGUMENT, "prismParseAccel: NULL argument");
  for (const AccelName& entry : kAccelNames)
    if (std::strcmp(name, entry.name) == 0) {
      *accel = entry.accel;
      return PRISM_OK;
    }
  return fail(PRISM_ERROR_INVALID_ARGUMENT,
              std::string("unknown acceleration structure '") + name + "' (expected auto, bvh, octree, bsp or none)");
}

PRISM_API const char* prismAccelName(PrismAccel accel) { return accelNameOf(enumValue(accel)); }

}  // extern "C"
