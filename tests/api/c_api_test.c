/* The C API used from C: list devices, create a context, load and render a
 * scene, read AOVs, and get clear errors for bad input. argv[1] is the scenes
 * folder. Exits non-zero on the first failed check. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "c_check.h"
#include "prism.h"

static int failures = 0;

/* Cancels the render the first time it is called. */
static int cancel_at_once(void* user, double fraction_done) {
  int* calls = (int*)user;
  (void)fraction_done;
  ++*calls;
  return 1;
}

int main(int argc, char** argv) {
  char path[4096];
  uint32_t count = 0, channels = 0;
  PrismDeviceInfo info;
  PrismContext ctx = NULL;
  PrismScene scene = NULL;
  PrismRenderOptions opts;
  PrismRenderStats stats;
  float *rgba, *depth, *primid;
  size_t pixels, i, hits = 0;
  float dummy = 0;

  if (argc < 2) {
    fprintf(stderr, "usage: c_api_test SCENES_DIR\n");
    return 2;
  }
  CHECK(prismGetVersion() == ((PRISM_VERSION_MAJOR << 16) | (PRISM_VERSION_MINOR << 8) | PRISM_VERSION_PATCH));
  CHECK(strcmp(prismGetVersionString(), PRISM_VERSION_STRING) == 0);

  CHECK_OK(prismGetDeviceCount(&count));
  CHECK(count > 0);
  CHECK_OK(prismGetDeviceInfo(0, &info));
  CHECK(info.name[0] != '\0' && info.compute_units > 0);
  CHECK(prismGetDeviceInfo(count, &info) == PRISM_ERROR_INVALID_ARGUMENT);
  CHECK(strstr(prismGetLastError(), "no device") != NULL);

  /* Errors: NULL out-pointers, unknown device, missing file, malformed JSON. */
  CHECK(prismCreateContext(NULL, NULL, NULL) == PRISM_ERROR_INVALID_ARGUMENT);
  CHECK(prismCreateContext("no-such-device-name", NULL, &ctx) == PRISM_ERROR_DEVICE && ctx == NULL);
  CHECK(strstr(prismGetLastError(), "no-such-device-name") != NULL);
  CHECK(prismLoadScene("/nonexistent/scene.json", &scene) == PRISM_ERROR_IO && scene == NULL);
  CHECK(strstr(prismGetLastError(), "/nonexistent/scene.json") != NULL);
  CHECK(prismLoadSceneFromString("{\"objects\": [ {\"type\": \"sphere\"} ]}", "inline.json", &scene) ==
        PRISM_ERROR_PARSE);
  CHECK(strstr(prismGetLastError(), "inline.json") != NULL && strstr(prismGetLastError(), "objects[0]") != NULL);
  CHECK(prismRender(NULL, NULL, NULL, NULL, NULL) == PRISM_ERROR_INVALID_ARGUMENT);

  CHECK_OK(prismCreateContext("cpu", NULL, &ctx));
  CHECK(prismGetAov(ctx, PRISM_AOV_DEPTH, &dummy, 1) == PRISM_ERROR_INVALID_OPERATION);
  snprintf(path, sizeof path, "%s/whitted.json", argv[1]);
  CHECK_OK(prismLoadScene(path, &scene));
  CHECK_OK(prismGetRenderOptions(scene, &opts));
  opts.width = 48;
  opts.height = 27;
  pixels = (size_t)opts.width * opts.height;
  rgba = (float*)malloc(pixels * 4 * sizeof(float));
  depth = (float*)malloc(pixels * sizeof(float));
  primid = (float*)malloc(pixels * sizeof(float));
  memset(&stats, 0, sizeof stats);
  stats.struct_size = sizeof stats;
  CHECK_OK(prismRender(ctx, scene, &opts, rgba, &stats));
  CHECK(stats.primary_rays == pixels);
  CHECK(stats.rays_per_depth[0] == pixels);

  CHECK_OK(prismGetAovChannels(PRISM_AOV_DEPTH, &channels));
  CHECK(channels == 1);
  CHECK(prismGetAov(ctx, PRISM_AOV_DEPTH, depth, pixels - 1) == PRISM_ERROR_INVALID_ARGUMENT);
  CHECK_OK(prismGetAov(ctx, PRISM_AOV_DEPTH, depth, pixels));
  CHECK_OK(prismGetAov(ctx, PRISM_AOV_PRIMID, primid, pixels));
  /* Where the primary ray hit, depth is finite and positive and alpha is 1; where
   * it missed, depth is +inf, primid -1 and alpha 0. */
  for (i = 0; i < pixels; ++i) {
    if (primid[i] >= 0) {
      ++hits;
      CHECK(isfinite(depth[i]) && depth[i] > 0);
      CHECK(rgba[4 * i + 3] == 1.0f);
    } else {
      CHECK(primid[i] == -1.0f && isinf(depth[i]) && rgba[4 * i + 3] == 0.0f);
    }
  }
  CHECK(hits > 0 && hits < pixels); /* the default scene shows sky and objects */

  /* Ray queries agree with the render: camera rays through the pixel centres hit
   * the primitive the primid AOV names, at the depth AOV's distance. */
  {
    PrismCamera cam;
    PrismRay* rays = (PrismRay*)malloc(pixels * sizeof(PrismRay));
    PrismHit* qhits = (PrismHit*)malloc(pixels * sizeof(PrismHit));
    uint8_t* blocked = (uint8_t*)malloc(pixels);
    double f[3], r[3], u[3], len, tan_half, aspect, seconds = -1;
    size_t same = 0, j, k;
    CHECK_OK(prismGetCamera(scene, &cam));
    for (k = 0; k < 3; ++k) f[k] = cam.look_at[k] - cam.position[k];
    len = sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
    for (k = 0; k < 3; ++k) f[k] /= len;
    r[0] = f[1] * cam.up[2] - f[2] * cam.up[1];
    r[1] = f[2] * cam.up[0] - f[0] * cam.up[2];
    r[2] = f[0] * cam.up[1] - f[1] * cam.up[0];
    len = sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
    for (k = 0; k < 3; ++k) r[k] /= len;
    u[0] = r[1] * f[2] - r[2] * f[1];
    u[1] = r[2] * f[0] - r[0] * f[2];
    u[2] = r[0] * f[1] - r[1] * f[0];
    tan_half = tan(cam.fov_degrees * 3.14159265358979323846 / 360.0);
    aspect = (double)opts.width / opts.height;
    for (j = 0; j < opts.height; ++j)
      for (i = 0; i < opts.width; ++i) {
        double x = (2.0 * (i + 0.5) / opts.width - 1) * tan_half * aspect;
        double y = (1 - 2.0 * (j + 0.5) / opts.height) * tan_half;
        double d[3];
        PrismRay* ray = &rays[j * opts.width + i];
        for (k = 0; k < 3; ++k) d[k] = f[k] + x * r[k] + y * u[k];
        len = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        for (k = 0; k < 3; ++k) {
          ray->org[k] = cam.position[k];
          ray->dir[k] = (float)(d[k] / len);
        }
        ray->tmin = 0;
        ray->tmax = INFINITY;
      }
    CHECK_OK(prismIntersect(ctx, scene, PRISM_ACCEL_BVH, rays, qhits, pixels, &seconds));
    CHECK(seconds >= 0);
    for (i = 0; i < pixels; ++i)
      if (qhits[i].prim == (int32_t)primid[i] &&
          (qhits[i].prim < 0 ? isinf(qhits[i].t) : fabs(qhits[i].t - depth[i]) <= 1e-4 * depth[i]))
        ++same;
    CHECK(same >= pixels - pixels / 100); /* a few silhouette pixels may round differently */
    CHECK_OK(prismOccluded(ctx, scene, PRISM_ACCEL_OCTREE, rays, blocked, pixels, NULL));
    for (i = 0; i < pixels; ++i) CHECK(blocked[i] == (qhits[i].prim >= 0) || qhits[i].prim != (int32_t)primid[i]);
    CHECK(prismIntersect(ctx, scene, (PrismAccel)99, rays, qhits, 1, NULL) == PRISM_ERROR_INVALID_ARGUMENT);
    free(rays);
    free(qhits);
    free(blocked);
  }

  /* The camera: read, refused when degenerate, changed when valid. */
  {
    PrismCamera cam, bad;
    PrismAccel accel;
    CHECK_OK(prismGetCamera(scene, &cam));
    CHECK(cam.fov_degrees > 0 && cam.fov_degrees < 180);
    bad = cam;
    bad.look_at[0] = bad.position[0];
    bad.look_at[1] = bad.position[1];
    bad.look_at[2] = bad.position[2];
    CHECK(prismSetCamera(scene, &bad) == PRISM_ERROR_INVALID_ARGUMENT);
    CHECK(strstr(prismGetLastError(), "look_at") != NULL);
    cam.fov_degrees = 20.0f;
    CHECK_OK(prismSetCamera(scene, &cam));
    CHECK_OK(prismGetCamera(scene, &bad));
    CHECK(bad.fov_degrees == 20.0f);
    /* Depth of field and motion blur fields go through the same checks as the
     * scene format's camera. */
    bad = cam;
    bad.shutter_open = 1.0f;
    bad.shutter_close = 0.5f;
    CHECK(prismSetCamera(scene, &bad) == PRISM_ERROR_INVALID_ARGUMENT);
    CHECK(strstr(prismGetLastError(), "shutter") != NULL);
    bad = cam;
    bad.aperture = -1.0f;
    CHECK(prismSetCamera(scene, &bad) == PRISM_ERROR_INVALID_ARGUMENT);
    CHECK(strstr(prismGetLastError(), "aperture") != NULL);
    cam.aperture = 0.05f;
    cam.focus_distance = 4.0f;
    cam.shutter_close = 1.0f;
    CHECK_OK(prismSetCamera(scene, &cam));
    CHECK_OK(prismGetCamera(scene, &bad));
    CHECK(bad.aperture == 0.05f && bad.focus_distance == 4.0f && bad.shutter_close == 1.0f && !bad.moving);
    cam.aperture = 0.0f;
    cam.shutter_close = 0.0f;
    CHECK_OK(prismSetCamera(scene, &cam));
    CHECK_OK(prismParseAccel("octree", &accel));
    CHECK(accel == PRISM_ACCEL_OCTREE && strcmp(prismAccelName(accel), "octree") == 0);
    CHECK(prismParseAccel("kdtree", &accel) == PRISM_ERROR_INVALID_ARGUMENT);
    CHECK_OK(prismParseAccel("auto", &accel));
    CHECK(accel == PRISM_ACCEL_AUTO && strcmp(prismAccelName(accel), "auto") == 0);
  }

  /* Options are checked before anything is allocated. */
  {
    PrismRenderOptions huge = opts;
    CHECK_OK(prismCheckRenderOptions(&opts));
    huge.width = huge.height = 32768;
    CHECK(prismCheckRenderOptions(&huge) == PRISM_ERROR_INVALID_ARGUMENT);
    CHECK(strstr(prismGetLastError(), "2^28") != NULL);
    CHECK(prismCheckRenderOptions(NULL) == PRISM_ERROR_INVALID_ARGUMENT);
  }

  /* The scene format's rules hold for values the C API is given: no NaN or
   * infinite light, no transform with entries or an inverse beyond floats. */
  {
    const float pos[3] = {0.0f, 5.0f, 5.0f}, white[3] = {1.0f, 1.0f, 1.0f};
    float bad_pos[3] = {0.0f, 5.0f, 5.0f};
    const float tri[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    const uint32_t idx[3] = {0, 1, 2};
    float m[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    bad_pos[1] = NAN;
    CHECK(prismAddPointLight(scene, bad_pos, white, 1.0f) == PRISM_ERROR_INVALID_ARGUMENT);
    CHECK(strstr(prismGetLastError(), "prismAddPointLight") != NULL && strstr(prismGetLastError(), "position") != NULL);
    bad_pos[1] = INFINITY;
    CHECK(prismAddPointLight(scene, bad_pos, white, 1.0f) == PRISM_ERROR_INVALID_ARGUMENT);
    CHECK(prismAddPointLight(scene, pos, white, NAN) == PRISM_ERROR_INVALID_ARGUMENT);
    CHECK(prismAddPointLight(scene, pos, white, INFINITY) == PRISM_ERROR_INVALID_ARGUMENT);
    CHECK(strstr(prismGetLastError(), "intensity") != NULL);
    /* Each within 1e30 alone, but not together (in a scene of their own). */
    {
      PrismScene bright = NULL;
      CHECK_OK(prismNewScene(&bright));
      CHECK_OK(prismAddPointLight(bright, pos, white, 6e29f));
      CHECK(prismAddPointLight(bright, pos, white, 6e29f) == PRISM_ERROR_INVALID_ARGUMENT);
      CHECK(strstr(prismGetLastError(), "summed over the scene's 2 lights") != NULL);
      prismReleaseScene(bright);
    }
    m[3] = NAN;
    CHECK(prismAddMeshArrays(scene, tri, 3, idx, 1, NULL, m, NULL) == PRISM_ERROR_INVALID_ARGUMENT);
    CHECK(strstr(prismGetLastError(), "object_to_world") != NULL && strstr(prismGetLastError(), "finite") != NULL);
    m[3] = 0.0f;
    m[0] = 1e30f; /* a float, but not when the kernels multiply by it */
    CHECK(prismAddMeshArrays(scene, tri, 3, idx, 1, NULL, m, NULL) == PRISM_ERROR_INVALID_ARGUMENT);
    m[0] = m[5] = m[10] = 1e-20f; /* invertible, but its inverse is not a float */
    CHECK(prismAddMeshArrays(scene, tri, 3, idx, 1, NULL, m, NULL) == PRISM_ERROR_INVALID_ARGUMENT);
    CHECK(strstr(prismGetLastError(), "inverse") != NULL);
    /* A mesh whose vertices the transform places past 1e15, and one already
     * there, as the scene format refuses them. */
    m[0] = m[5] = m[10] = 1e8f;
    {
      const float far_tri[9] = {1e8f, 0, 0, 1e8f, 1, 0, 1e8f, 0, 1};
      const float huge_tri[9] = {-1e30f, 0, 0, 1e30f, 0, 0, 0, 1e30f, 0};
      CHECK(prismAddMeshArrays(scene, far_tri, 3, idx, 1, NULL, m, NULL) == PRISM_ERROR_INVALID_ARGUMENT);
      CHECK(strstr(prismGetLastError(), "prismAddMeshArrays") != NULL &&
            strstr(prismGetLastError(), "at most 1e15") != NULL && strstr(prismGetLastError(), "vertex 0") != NULL);
      CHECK(prismAddMeshArrays(scene, huge_tri, 3, idx, 1, NULL, NULL, NULL) == PRISM_ERROR_INVALID_ARGUMENT);
      CHECK(strstr(prismGetLastError(), "at most 1e15") != NULL);
    }
    /* The camera's points too. */
    {
      PrismCamera cam, bad;
      CHECK_OK(prismGetCamera(scene, &cam));
      bad = cam;
      bad.position[2] = 1e20f;
      CHECK(prismSetCamera(scene, &bad) == PRISM_ERROR_INVALID_ARGUMENT);
      CHECK(strstr(prismGetLastError(), "position") != NULL && strstr(prismGetLastError(), "1e15") != NULL);
      bad = cam;
      bad.look_at[0] = -1e20f;
      CHECK(prismSetCamera(scene, &bad) == PRISM_ERROR_INVALID_ARGUMENT);
      CHECK(strstr(prismGetLastError(), "look_at") != NULL);
    }
  }

  /* Area lights: the scene loader's checks and messages; a valid one renders. */
  {
    PrismAreaLight light;
    float* before = (float*)malloc(sizeof(float) * 4 * pixels);
    float* lit = (float*)malloc(sizeof(float) * 4 * pixels);
    size_t k, brighter = 0, darker = 0;
    memset(&light, 0, sizeof light);
    light.struct_size = sizeof light;
    light.type = PRISM_LIGHT_QUAD;
    light.corner[1] = 6.0f;
    light.edge1[0] = 1.0f;
    light.edge2[0] = 2.0f; /* parallel to edge1: no area */
    light.color[0] = light.color[1] = light.color[2] = 1.0f;
    light.intensity = 1.0f;
    light.samples = 4;
    CHECK(prismAddAreaLight(scene, &light) == PRISM_ERROR_INVALID_ARGUMENT);
    CHECK(strstr(prismGetLastError(), "parallel") != NULL);
    light.edge2[0] = 0.0f;
    light.edge2[2] = 1.0f;
    light.samples = 0;
    CHECK(prismAddAreaLight(scene, &light) == PRISM_ERROR_INVALID_ARGUMENT);
    CHECK(strstr(prismGetLastError(), "samples") != NULL);
    light.samples = 4;
    light.intensity = 50.0f;
    CHECK_OK(prismRender(ctx, scene, &opts, before, NULL));
    CHECK_OK(prismAddAreaLight(scene, &light));
    CHECK_OK(prismRender(ctx, scene, &opts, lit, NULL));
    for (k = 0; k < pixels; ++k) {
      brighter += lit[4 * k] > before[4 * k];
      darker += lit[4 * k] < before[4 * k];
    }
    CHECK(brighter > 0 && darker == 0); /* a light only adds to what it reaches */
    free(before);
    free(lit);
  }

  /* Profiling: each kernel's device time, and set-up plus tracing make the render. */
  {
    PrismRenderOptions profiled = opts;
    uint32_t count = 0, k;
    double device = 0;
    PrismRenderStats st;
    memset(&st, 0, sizeof st);
    st.struct_size = sizeof st;
    profiled.profile = 0;
    CHECK_OK(prismRender(ctx, scene, &profiled, rgba, &st));
    CHECK(prismGetKernelTimeCount(ctx, &count) == PRISM_ERROR_INVALID_OPERATION);
    profiled.profile = 1;
    CHECK_OK(prismRender(ctx, scene, &profiled, rgba, &st));
    CHECK(fabs(st.setup_seconds + st.trace_seconds - st.seconds) < 1e-9 && st.trace_seconds > 0);
    CHECK_OK(prismGetKernelTimeCount(ctx, &count));
    CHECK(count >= 3); /* at least shade, accumulate and resolve ran */
    for (k = 0; k < count; ++k) {
      const char* name = NULL;
      double seconds = -1;
      uint64_t launches = 0;
      CHECK_OK(prismGetKernelTime(ctx, k, &name, &seconds, &launches));
      CHECK(name && name[0] && seconds >= 0 && launches > 0);
      device += seconds;
    }
    CHECK(device <= st.seconds); /* the device's share cannot exceed the wall time */
    {
      const char* name = NULL;
      double seconds = 0;
      uint64_t launches = 0;
      CHECK(prismGetKernelTime(ctx, count, &name, &seconds, &launches) == PRISM_ERROR_INVALID_ARGUMENT);
    }
  }

  /* A progress callback that returns nonzero cancels the render. */
  {
    int calls = 0;
    CHECK_OK(prismSetProgressCallback(ctx, cancel_at_once, &calls));
    CHECK(prismRender(ctx, scene, &opts, rgba, NULL) == PRISM_ERROR_INVALID_OPERATION);
    CHECK(calls == 1);
    CHECK(strstr(prismGetLastError(), "cancel") != NULL);
    CHECK_OK(prismSetProgressCallback(ctx, NULL, NULL));
  }

  free(rgba);
  free(depth);
  free(primid);
  prismReleaseScene(scene);
  prismReleaseContext(ctx);
  prismReleaseScene(NULL);
  prismReleaseContext(NULL);
  if (failures) {
    fprintf(stderr, "%d check(s) failed\n", failures);
    return 1;
  }
  printf("c_api_test: all checks passed\n");
  return 0;
}
