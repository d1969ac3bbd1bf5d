/* The C API's promise, call by call: a NULL pointer, an index past the end, an
 * unknown enum value, a NaN, a size of zero or a call out of order gives an
 * error status (never a crash, never PRISM_OK) and a message that names the
 * function at fault. argv[1] is the scenes folder. Exits non-zero on the first
 * failed check's count. */
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "c_check.h"
#include "prism.h"

static int failures = 0;
static int calls = 0;

/* `status` must be the error `want` with a message containing `name`. */
static void expect(PrismStatus status, PrismStatus want, const char* name, const char* what, int line) {
  const char* message = prismGetLastError();
  ++calls;
  if (status != want) {
    fprintf(stderr, "line %d: %s: %s returned %s, expected %s (%s)\n", line, name, what, prismStatusName(status),
            prismStatusName(want), message);
    ++failures;
  } else if (!message || !strstr(message, name)) {
    fprintf(stderr, "line %d: %s: %s: the message does not name the function: '%s'\n", line, name, what,
            message ? message : "(null)");
    ++failures;
  }
}

#define EXPECT(call, want, name) expect((call), (want), (name), #call, __LINE__)
#define BAD(call, name) EXPECT(call, PRISM_ERROR_INVALID_ARGUMENT, name)

/* A transport that fails at once (prismSetFrameParts). */
static int failingExchange(void* user, int to_all, const void* data, uint64_t size, PrismReceiveFn receive,
                           void* receiver) {
  (void)user, (void)to_all, (void)data, (void)size, (void)receive, (void)receiver;
  return 5;
}

/* Part 1 of 2 alone: every part's bytes are its own, so the parts agree on the frame. */
static int echoExchange(void* user, int to_all, const void* data, uint64_t size, PrismReceiveFn receive,
                        void* receiver) {
  (void)user;
  receive(receiver, 0, data, size);
  if (to_all) receive(receiver, 1, data, size);
  return 0;
}

static int failingCompareSwap(void* user, uint32_t word, uint64_t expected, uint64_t desired, uint64_t* found) {
  (void)user, (void)word, (void)expected, (void)desired, (void)found;
  return 7;
}

int main(int argc, char** argv) {
  char path[4096];
  uint32_t count = 0, u32 = 0;
  PrismDeviceInfo info;
  PrismContextOptions context_options;
  PrismContext ctx = NULL, none_ctx = NULL;
  PrismScene scene = NULL, none_scene = NULL;
  PrismCamera camera;
  PrismAreaLight area;
  PrismMaterial material;
  PrismObject object;
  PrismMeshReport report = NULL;
  PrismResult result = NULL;
  const float* pixels = NULL;
  PrismMeshCounts mesh_counts;
  PrismPluginCandidateInfo plugin;
  PrismRenderOptions opts, small;
  PrismRenderStats stats;
  PrismNanReport nan_report;
  PrismDeviceShare share;
  PrismFrameParts parts;
  PrismDeviceInfo first_info;
  uint32_t devices = 0;
  PrismAccel accel;
  PrismAa aa;
  PrismFilter filter;
  PrismFirstHit first_hit;
  PrismShadows shadows;
  PrismBounds bounds;
  PrismAov aov;
  PrismRay ray;
  PrismHit hit;
  uint8_t occluded = 0;
  const char* text = NULL;
  double seconds = 0;
  uint64_t launches = 0;
  float rgba[4 * 8 * 6], out[8 * 6 * 3];
  const float pos[3] = {0, 5, 5}, white[3] = {1, 1, 1}, negative[3] = {-1, 0, 0};
  const float tri[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  const uint32_t idx[3] = {0, 1, 2}, bad_idx[3] = {0, 1, 7};

  if (argc < 2) {
    fprintf(stderr, "usage: c_api_arguments_test SCENES_DIR\n");
    return 2;
  }
  snprintf(path, sizeof path, "%s/whitted.json", argv[1]);

  /* Devices and contexts. */
  BAD(prismGetDeviceCount(NULL), "prismGetDeviceCount");
  CHECK_OK(prismGetDeviceCount(&count));
  BAD(prismGetDeviceInfo(0, NULL), "prismGetDeviceInfo");
  EXPECT(prismGetDeviceInfo(count, &info), PRISM_ERROR_INVALID_ARGUMENT, "prismGetDeviceInfo");
  prismDefaultContextOptions(NULL); /* a no-op, not a crash */
  prismDefaultContextOptions(&context_options);
  BAD(prismCreateContext(NULL, NULL, NULL), "prismCreateContext");
  EXPECT(prismCreateContext("no-such-device", NULL, &none_ctx), PRISM_ERROR_DEVICE, "prismCreateContext");
  if (none_ctx) {
    fprintf(stderr, "a failed prismCreateContext left a context\n");
    ++failures;
  }
  CHECK_OK(prismCreateContext(NULL, &context_options, &ctx));
  BAD(prismGetContextDevice(NULL, &info), "prismGetContextDevice");
  BAD(prismGetContextDevice(ctx, NULL), "prismGetContextDevice");
  BAD(prismGetContextDeviceCount(NULL, &devices), "prismGetContextDeviceCount");
  BAD(prismGetContextDeviceCount(ctx, NULL), "prismGetContextDeviceCount");
  CHECK_OK(prismGetContextDeviceCount(ctx, &devices));
  CHECK(devices == 1); /* one selector, one device */
  BAD(prismGetContextDeviceAt(NULL, 0, &info), "prismGetContextDeviceAt");
  BAD(prismGetContextDeviceAt(ctx, 0, NULL), "prismGetContextDeviceAt");
  BAD(prismGetContextDeviceAt(ctx, 1, &info), "prismGetContextDeviceAt");
  CHECK_OK(prismGetContextDeviceAt(ctx, 0, &info));
  CHECK_OK(prismGetContextDevice(ctx, &first_info));
  CHECK(strcmp(info.name, first_info.name) == 0 && info.index == first_info.index);
  /* Several devices: no device twice, no empty part, 'all' alone. */
  EXPECT(prismCreateContext("0,0", NULL, &none_ctx), PRISM_ERROR_DEVICE, "prismCreateContext");
  EXPECT(prismCreateContext("0,", NULL, &none_ctx), PRISM_ERROR_DEVICE, "prismCreateContext");
  EXPECT(prismCreateContext("all,0", NULL, &none_ctx), PRISM_ERROR_DEVICE, "prismCreateContext");
  CHECK(none_ctx == NULL);
  BAD(prismSetProgressCallback(NULL, NULL, NULL), "prismSetProgressCallback");
  prismReleaseContext(NULL);

  /* Scenes. */
  BAD(prismLoadScene(NULL, &scene), "prismLoadScene");
  BAD(prismLoadScene(path, NULL), "prismLoadScene");
  BAD(prismLoadSceneFromString(NULL, "x.json", &scene), "prismLoadSceneFromString");
  BAD(prismLoadSceneFromString("{}", "x.json", NULL), "prismLoadSceneFromString");
  BAD(prismNewScene(NULL), "prismNewScene");
  BAD(prismLoadMeshAsScene(NULL, &scene), "prismLoadMeshAsScene");
  BAD(prismLoadMeshAsScene(path, NULL), "prismLoadMeshAsScene");
  CHECK_OK(prismLoadScene(path, &scene));
  BAD(prismGetSceneDevice(NULL, &text), "prismGetSceneDevice");
  BAD(prismGetSceneDevice(scene, NULL), "prismGetSceneDevice");
  CHECK_OK(prismGetSceneDevice(scene, &text));
  CHECK(text && text[0] == 0); /* the example scene names no device */
  /* Animations: a still has one frame, its own. */
  BAD(prismGetFrameCount(NULL, &count), "prismGetFrameCount");
  BAD(prismGetFrameCount(scene, NULL), "prismGetFrameCount");
  CHECK_OK(prismGetFrameCount(scene, &count));
  CHECK(count == 1);
  {
    PrismScene frame = (PrismScene)1, animated = NULL;
    PrismCamera camera;
    BAD(prismGetFrameScene(NULL, 0, &frame), "prismGetFrameScene");
    CHECK(frame == NULL);
    BAD(prismGetFrameScene(scene, 0, NULL), "prismGetFrameScene");
    BAD(prismGetFrameScene(scene, 1, &frame), "prismGetFrameScene");
    CHECK(frame == NULL && strstr(prismGetLastError(), "frame 1 is not in the animation (frames 0 to 0)"));
    CHECK_OK(prismGetFrameScene(scene, 0, &frame));
    prismReleaseScene(frame);
    /* Three frames 2 apart: frame 2's shutter is the first moved by 4. */
    CHECK_OK(prismNewScene(&animated));
    CHECK_OK(prismAddSceneJson(animated, "{\"camera\": {\"shutter\": [0, 1]}, "
                                         "\"animation\": {\"frames\": 3, \"step\": 2}}"));
    CHECK_OK(prismGetFrameCount(animated, &count));
    CHECK(count == 3);
    CHECK_OK(prismGetFrameScene(animated, 2, &frame));
    memset(&camera, 0, sizeof camera);
    camera.struct_size = sizeof camera;
    CHECK_OK(prismGetCamera(frame, &camera));
    CHECK(camera.shutter_open == 4.0f && camera.shutter_close == 5.0f);
    CHECK_OK(prismGetFrameCount(frame, &count));
    CHECK(count == 1);
    prismReleaseScene(frame);
    frame = NULL;
    /* The same check as the format's, when a camera set later moves the last
       frame's shutter out of range. */
    CHECK_OK(prismAddSceneJson(animated, "{\"animation\": {\"frames\": 3, \"step\": 4e14}}"));
    camera.shutter_open = 3e14f;
    camera.shutter_close = 3e14f;
    CHECK_OK(prismSetCamera(animated, &camera));
    BAD(prismGetFrameScene(animated, 0, &frame), "prismGetFrameScene");
    CHECK(frame == NULL && strstr(prismGetLastError(), "the last frame's shutter"));
    EXPECT(prismAddSceneJson(animated, "{\"animation\": {\"frames\": 0}}"), PRISM_ERROR_PARSE, "prismAddSceneJson");
    prismReleaseScene(animated);
  }
  BAD(prismGetSceneWarningCount(NULL, &count), "prismGetSceneWarningCount");
  BAD(prismGetSceneWarningCount(scene, NULL), "prismGetSceneWarningCount");
  CHECK_OK(prismGetSceneWarningCount(scene, &count));
  BAD(prismGetSceneObjectCount(NULL, &count), "prismGetSceneObjectCount");
  BAD(prismGetSceneObjectCount(scene, NULL), "prismGetSceneObjectCount");
  BAD(prismGetSceneWarning(NULL, 0, &text), "prismGetSceneWarning");
  BAD(prismGetSceneWarning(scene, 0, NULL), "prismGetSceneWarning");
  EXPECT(prismGetSceneWarning(scene, count, &text), PRISM_ERROR_INVALID_ARGUMENT, "prismGetSceneWarning");
  BAD(prismGetCamera(NULL, &camera), "prismGetCamera");
  BAD(prismGetCamera(scene, NULL), "prismGetCamera");
  BAD(prismSetCamera(NULL, &camera), "prismSetCamera");
  BAD(prismSetCamera(scene, NULL), "prismSetCamera");
  memset(&camera, 0, sizeof camera); /* struct_size 0 */
  BAD(prismSetCamera(scene, &camera), "prismSetCamera");
  camera.struct_size = sizeof camera;
  CHECK_OK(prismGetCamera(scene, &camera));
  camera.fov_degrees = NAN;
  BAD(prismSetCamera(scene, &camera), "prismSetCamera");

  /* Building a scene in code. */
  prismDefaultMaterial(NULL); /* no-ops, not crashes */
  prismDefaultObject(NULL, PRISM_OBJECT_SPHERE);
  prismDefaultMaterial(&material);
  prismDefaultObject(&object, PRISM_OBJECT_SPHERE);
  BAD(prismAddSceneJson(NULL, "{}"), "prismAddSceneJson");
  BAD(prismAddSceneJson(scene, NULL), "prismAddSceneJson");
  EXPECT(prismAddSceneJson(scene, "{\"objects\": [1"), PRISM_ERROR_PARSE, "prismAddSceneJson");
  BAD(prismAddMaterial(NULL, "m", &material, NULL), "prismAddMaterial");
  BAD(prismAddMaterial(scene, NULL, &material, NULL), "prismAddMaterial");
  BAD(prismAddMaterial(scene, "m", NULL, NULL), "prismAddMaterial");
  BAD(prismAddMaterial(scene, "", &material, NULL), "prismAddMaterial");
  material.struct_size = 8;
  BAD(prismAddMaterial(scene, "m", &material, NULL), "prismAddMaterial");
  prismDefaultMaterial(&material);
  material.model = 7;
  BAD(prismAddMaterial(scene, "m", &material, NULL), "prismAddMaterial");
  prismDefaultMaterial(&material);
  material.ior = NAN;
  BAD(prismAddMaterial(scene, "m", &material, NULL), "prismAddMaterial");
  BAD(prismAddObject(NULL, &object, NULL), "prismAddObject");
  BAD(prismAddObject(scene, NULL, NULL), "prismAddObject");
  object.struct_size = 8;
  BAD(prismAddObject(scene, &object, NULL), "prismAddObject");
  prismDefaultObject(&object, (PrismObjectType)9);
  BAD(prismAddObject(scene, &object, NULL), "prismAddObject");
  prismDefaultObject(&object, PRISM_OBJECT_SPHERE);
  object.radius = INFINITY;
  BAD(prismAddObject(scene, &object, NULL), "prismAddObject");
  prismDefaultObject(&object, PRISM_OBJECT_TRIANGLE); /* all three vertices at the origin */
  BAD(prismAddObject(scene, &object, NULL), "prismAddObject");
  prismDefaultObject(&object, PRISM_OBJECT_QUADRIC); /* all coefficients 0: no surface */
  BAD(prismAddObject(scene, &object, NULL), "prismAddObject");
  object.coefficients[0] = NAN;
  BAD(prismAddObject(scene, &object, NULL), "prismAddObject");
  prismDefaultObject(&object, PRISM_OBJECT_SPHERE);
  object.material = "no-such-material";
  BAD(prismAddObject(scene, &object, NULL), "prismAddObject");
  BAD(prismSetBackground(NULL, white), "prismSetBackground");
  BAD(prismSetBackground(scene, NULL), "prismSetBackground");
  BAD(prismSetAmbient(NULL, white), "prismSetAmbient");
  BAD(prismSetAmbient(scene, NULL), "prismSetAmbient");
  BAD(prismSetAmbient(scene, negative), "prismSetAmbient");
  BAD(prismSetBackground(scene, negative), "prismSetBackground");

  /* Lights and meshes. */
  BAD(prismAddPointLight(NULL, pos, white, 1.0f), "prismAddPointLight");
  BAD(prismAddPointLight(scene, NULL, white, 1.0f), "prismAddPointLight");
  BAD(prismAddPointLight(scene, pos, NULL, 1.0f), "prismAddPointLight");
  BAD(prismAddPointLight(scene, pos, white, -1.0f), "prismAddPointLight");
  BAD(prismAddAreaLight(NULL, &area), "prismAddAreaLight");
  BAD(prismAddAreaLight(scene, NULL), "prismAddAreaLight");
  memset(&area, 0, sizeof area); /* struct_size 0 */
  BAD(prismAddAreaLight(scene, &area), "prismAddAreaLight");
  area.struct_size = sizeof area;
  area.type = 99;
  BAD(prismAddAreaLight(scene, &area), "prismAddAreaLight");
  BAD(prismAddMeshFile(NULL, path, NULL, NULL, 0, NULL), "prismAddMeshFile");
  BAD(prismAddMeshFile(scene, NULL, NULL, NULL, 0, NULL), "prismAddMeshFile");
  BAD(prismAddMeshArrays(NULL, tri, 3, idx, 1, NULL, NULL, NULL), "prismAddMeshArrays");
  BAD(prismAddMeshArrays(scene, NULL, 3, idx, 1, NULL, NULL, NULL), "prismAddMeshArrays");
  BAD(prismAddMeshArrays(scene, tri, 3, NULL, 1, NULL, NULL, NULL), "prismAddMeshArrays");
  BAD(prismAddMeshArrays(scene, tri, 0, idx, 1, NULL, NULL, NULL), "prismAddMeshArrays");
  BAD(prismAddMeshArrays(scene, tri, 3, idx, 0, NULL, NULL, NULL), "prismAddMeshArrays");
  BAD(prismAddMeshArrays(scene, tri, 3, bad_idx, 1, NULL, NULL, NULL), "prismAddMeshArrays");
  BAD(prismAddMeshArrays(scene, tri, 3, idx, 1, "no-such-material", NULL, NULL), "prismAddMeshArrays");
  BAD(prismInspectMeshFile(NULL, &report), "prismInspectMeshFile");
  BAD(prismInspectMeshFile(path, NULL), "prismInspectMeshFile");
  BAD(prismGetMeshCounts(NULL, &mesh_counts), "prismGetMeshCounts");
  if (prismGetMeshPlugin(NULL) == NULL || prismGetMeshMaterialName(NULL, 0) != NULL ||
      prismGetMeshWarningCount(NULL) != 0 || prismGetMeshWarning(NULL, 0) != NULL) {
    fprintf(stderr, "mesh report getters must answer \"\", NULL or 0 for a NULL report\n");
    ++failures;
  }
  prismReleaseMeshReport(NULL);
  BAD(prismGetPluginCount(NULL), "prismGetPluginCount");
  CHECK_OK(prismGetPluginCount(&count));
  BAD(prismGetPluginInfo(0, NULL), "prismGetPluginInfo");
  EXPECT(prismGetPluginInfo(count, &plugin), PRISM_ERROR_INVALID_ARGUMENT, "prismGetPluginInfo");

  /* Names and enums. */
  BAD(prismParseAccel(NULL, &accel), "prismParseAccel");
  BAD(prismParseAccel("bvh", NULL), "prismParseAccel");
  BAD(prismParseAa(NULL, &aa), "prismParseAa");
  BAD(prismParseAa("jitter", NULL), "prismParseAa");
  BAD(prismParseFilter(NULL, &filter), "prismParseFilter");
  BAD(prismParseFilter("box", NULL), "prismParseFilter");
  BAD(prismParseFirstHit(NULL, &first_hit), "prismParseFirstHit");
  BAD(prismParseFirstHit("auto", NULL), "prismParseFirstHit");
  BAD(prismParseShadows(NULL, &shadows), "prismParseShadows");
  BAD(prismParseShadows("auto", NULL), "prismParseShadows");
  BAD(prismParseShadows("shadowmap", &shadows), "unknown shadow mode 'shadowmap' (expected auto, accel, lightbuffer)");
  BAD(prismParseBounds(NULL, &bounds), "prismParseBounds");
  BAD(prismParseBounds("kdop", NULL), "prismParseBounds");
  BAD(prismParseBounds("obb", &bounds), "unknown bounds 'obb' (expected aabb, kdop)");
  BAD(prismParseAov(NULL, &aov), "prismParseAov");
  BAD(prismParseAov("depth", NULL), "prismParseAov");
  BAD(prismGetAovChannels((PrismAov)99, &u32), "prismGetAovChannels");
  BAD(prismGetAovChannels(PRISM_AOV_DEPTH, NULL), "prismGetAovChannels");
  if (prismAccelName((PrismAccel)99) != NULL || prismAaName((PrismAa)99) != NULL ||
      prismFilterName((PrismFilter)99) != NULL || prismFirstHitName((PrismFirstHit)99) != NULL ||
      prismShadowsName((PrismShadows)99) != NULL || prismBoundsName((PrismBounds)99) != NULL ||
      prismStatusName((PrismStatus)999) == NULL) {
    fprintf(stderr, "names of unknown values: NULL (a status: a text that says unknown)\n");
    ++failures;
  }

  /* Rendering, in and out of order. */
  EXPECT(prismGetAov(ctx, PRISM_AOV_DEPTH, out, 8 * 6), PRISM_ERROR_INVALID_OPERATION, "prismGetAov");
  EXPECT(prismGetKernelTimeCount(ctx, &u32), PRISM_ERROR_INVALID_OPERATION, "prismGetKernelTimeCount");
  memset(&share, 0, sizeof share);
  share.struct_size = sizeof share;
  EXPECT(prismGetRenderDeviceShare(ctx, 0, &share), PRISM_ERROR_INVALID_OPERATION, "prismGetRenderDeviceShare");
  EXPECT(prismGetRenderDeviceShareCount(ctx, &u32), PRISM_ERROR_INVALID_OPERATION, "prismGetRenderDeviceShareCount");
  EXPECT(prismGetRenderWarningCount(ctx, &u32), PRISM_ERROR_INVALID_OPERATION, "prismGetRenderWarningCount");
  EXPECT(prismGetRenderWarning(ctx, 0, &text), PRISM_ERROR_INVALID_OPERATION, "prismGetRenderWarning");
  memset(&nan_report, 0, sizeof nan_report);
  nan_report.struct_size = sizeof nan_report;
  EXPECT(prismGetNanReport(ctx, &nan_report), PRISM_ERROR_INVALID_OPERATION, "prismGetNanReport");
  BAD(prismGetRenderOptions(NULL, &opts), "prismGetRenderOptions");
  BAD(prismGetRenderOptions(scene, NULL), "prismGetRenderOptions");
  memset(&opts, 0, sizeof opts);
  opts.struct_size = sizeof opts;
  CHECK_OK(prismGetRenderOptions(scene, &opts));
  small = opts;
  small.width = 8;
  small.height = 6;
  small.accel = 99;
  BAD(prismCheckRenderOptions(&small), "prismCheckRenderOptions");
  BAD(prismRender(ctx, scene, &small, rgba, NULL), "prismRender");
  small.accel = PRISM_ACCEL_AUTO;
  small.width = 0;
  BAD(prismRender(ctx, scene, &small, rgba, NULL), "prismRender");
  /* Counts past int are refused naming the value given, not one clamped to int. */
  small.width = 4294967295u;
  BAD(prismCheckRenderOptions(&small), "prismCheckRenderOptions");
  CHECK(strstr(prismGetLastError(), "width must be in 1..32768, got 4294967295") != NULL);
  small.width = 8;
  small.aa_max_level = 2147483648u;
  BAD(prismRender(ctx, scene, &small, rgba, NULL), "prismRender");
  CHECK(strstr(prismGetLastError(), "got 2147483648") != NULL);
  small.aa_max_level = opts.aa_max_level;
  small.min_weight = NAN;
  BAD(prismRender(ctx, scene, &small, rgba, NULL), "prismRender");
  small.min_weight = opts.min_weight;
  BAD(prismRender(NULL, scene, &small, rgba, NULL), "prismRender");
  BAD(prismRender(ctx, NULL, &small, rgba, NULL), "prismRender");
  BAD(prismRender(ctx, scene, &small, NULL, NULL), "prismRender");
  small.struct_size = 0;
  BAD(prismRender(ctx, scene, &small, rgba, NULL), "prismRender");
  small.struct_size = sizeof small;
  stats.struct_size = 0;
  BAD(prismRender(ctx, scene, &small, rgba, &stats), "prismRender");
  CHECK_OK(prismRender(ctx, scene, &small, rgba, NULL));
  EXPECT(prismGetNanReport(ctx, &nan_report), PRISM_ERROR_INVALID_OPERATION,
         "prismGetNanReport"); /* the render did not check */
  small.check_nan = 1;
  CHECK_OK(prismRender(ctx, scene, &small, rgba, NULL));
  small.check_nan = 0;
  BAD(prismGetNanReport(NULL, &nan_report), "prismGetNanReport");
  BAD(prismGetNanReport(ctx, NULL), "prismGetNanReport");
  nan_report.struct_size = 0;
  BAD(prismGetNanReport(ctx, &nan_report), "prismGetNanReport");
  nan_report.struct_size = sizeof nan_report;
  nan_report.found = 7;
  CHECK_OK(prismGetNanReport(ctx, &nan_report));
  CHECK(nan_report.found == 0 && nan_report.primitive == -1); /* a plain scene: every value finite */
  BAD(prismGetRenderDeviceShare(NULL, 0, &share), "prismGetRenderDeviceShare");
  BAD(prismGetRenderDeviceShare(ctx, 0, NULL), "prismGetRenderDeviceShare");
  BAD(prismGetRenderDeviceShare(ctx, 1, &share), "prismGetRenderDeviceShare");
  share.struct_size = 0;
  BAD(prismGetRenderDeviceShare(ctx, 0, &share), "prismGetRenderDeviceShare");
  share.struct_size = sizeof share;
  CHECK_OK(prismGetRenderDeviceShare(ctx, 0, &share));
  /* one device traced every sample of the 8x6 render, one per pixel */
  CHECK(share.units == 1 && share.samples == 8 * 6 && share.failed == 0 && share.failure && share.failure[0] == 0);
  CHECK(share.device && strcmp(share.device, first_info.name) == 0);
  /* it resolved the frame: the whole film, rgba and (x, y) a sample */
  CHECK(share.film_bytes == 8 * 6 * 6 * sizeof(float));
  /* a caller built before film_bytes: its shorter struct is filled up to there */
  share.film_bytes = 7;
  share.struct_size = offsetof(PrismDeviceShare, film_bytes);
  CHECK_OK(prismGetRenderDeviceShare(ctx, 0, &share));
  CHECK(share.film_bytes == 7 && share.units == 1);
  share.struct_size = offsetof(PrismDeviceShare, film_bytes) - 1;
  BAD(prismGetRenderDeviceShare(ctx, 0, &share), "prismGetRenderDeviceShare");
  share.struct_size = sizeof share;
  BAD(prismGetRenderDeviceShareCount(NULL, &u32), "prismGetRenderDeviceShareCount");
  BAD(prismGetRenderDeviceShareCount(ctx, NULL), "prismGetRenderDeviceShareCount");
  CHECK_OK(prismGetRenderDeviceShareCount(ctx, &u32));
  CHECK(u32 == 1);

  /* A frame shared by processes: the parts are checked; a transport that fails
   * fails the render; NULL renders alone again. */
  memset(&parts, 0, sizeof parts);
  BAD(prismSetFrameParts(ctx, &parts), "prismSetFrameParts"); /* struct_size */
  parts.struct_size = sizeof parts;
  BAD(prismSetFrameParts(NULL, &parts), "prismSetFrameParts");
  BAD(prismSetFrameParts(ctx, &parts), "prismSetFrameParts"); /* parts 0 */
  parts.parts = 2;
  parts.part = 2;
  parts.exchange = failingExchange;
  BAD(prismSetFrameParts(ctx, &parts), "prismSetFrameParts");
  parts.part = 1;
  parts.exchange = NULL;
  BAD(prismSetFrameParts(ctx, &parts), "prismSetFrameParts");
  parts.exchange = failingExchange;
  CHECK_OK(prismSetFrameParts(ctx, &parts));
  EXPECT(prismRender(ctx, scene, &small, rgba, NULL), PRISM_ERROR_UNKNOWN, "prismRender");
  CHECK(strstr(prismGetLastError(), "returned 5") != NULL);
  /* Dealing as devices come free: a compare-and-swap that fails fails the render. */
  parts.exchange = echoExchange;
  parts.compare_swap = failingCompareSwap;
  CHECK_OK(prismSetFrameParts(ctx, &parts));
  EXPECT(prismRender(ctx, scene, &small, rgba, NULL), PRISM_ERROR_UNKNOWN, "prismRender");
  CHECK(strstr(prismGetLastError(), "compare-and-swap") != NULL && strstr(prismGetLastError(), "returned 7") != NULL);
  /* A caller built before compare_swap: its shorter struct deals fixed stretches,
   * compare_swap unread. Part 1's stretch is the render's one unit, which the
   * echo says part 0 traced too: a claim made twice is an error. */
  parts.struct_size = offsetof(PrismFrameParts, compare_swap);
  CHECK_OK(prismSetFrameParts(ctx, &parts));
  EXPECT(prismRender(ctx, scene, &small, rgba, NULL), PRISM_ERROR_UNKNOWN, "prismRender");
  CHECK(strstr(prismGetLastError(), "parts 0 and 1 both traced unit 0") != NULL);
  parts.struct_size = offsetof(PrismFrameParts, compare_swap) - 1;
  BAD(prismSetFrameParts(ctx, &parts), "prismSetFrameParts");
  parts.struct_size = sizeof parts;
  parts.compare_swap = NULL;
  CHECK_OK(prismSetFrameParts(ctx, NULL));
  CHECK_OK(prismRender(ctx, scene, &small, rgba, NULL));
  parts.parts = 1;
  parts.part = 0;
  parts.exchange = NULL;
  CHECK_OK(prismSetFrameParts(ctx, &parts)); /* one part: alone */
  CHECK_OK(prismRender(ctx, scene, &small, rgba, NULL));
  BAD(prismGetRenderWarningCount(NULL, &u32), "prismGetRenderWarningCount");
  BAD(prismGetRenderWarningCount(ctx, NULL), "prismGetRenderWarningCount");
  CHECK_OK(prismGetRenderWarningCount(ctx, &u32));
  CHECK(u32 == 0);
  BAD(prismGetRenderWarning(NULL, 0, &text), "prismGetRenderWarning");
  BAD(prismGetRenderWarning(ctx, 0, NULL), "prismGetRenderWarning");
  BAD(prismGetRenderWarning(ctx, 0, &text), "prismGetRenderWarning"); /* there is none */
  BAD(prismGetAov(NULL, PRISM_AOV_DEPTH, out, 8 * 6), "prismGetAov");
  BAD(prismGetAov(ctx, PRISM_AOV_DEPTH, NULL, 8 * 6), "prismGetAov");
  BAD(prismGetAov(ctx, PRISM_AOV_NORMAL, out, 8 * 6), "prismGetAov"); /* needs 3 floats a pixel */
  BAD(prismGetAov(ctx, (PrismAov)99, out, 8 * 6 * 3), "prismGetAov");

  /* Results. */
  BAD(prismRenderToResult(ctx, scene, &small, NULL), "prismRenderToResult");
  BAD(prismRenderToResult(NULL, scene, &small, &result), "prismRenderToResult");
  CHECK(result == NULL); /* a failed call leaves no result */
  BAD(prismRenderToResult(ctx, NULL, &small, &result), "prismRenderToResult");
  small.struct_size = 0;
  BAD(prismRenderToResult(ctx, scene, &small, &result), "prismRenderToResult");
  small.struct_size = sizeof small;
  small.width = 0;
  BAD(prismRenderToResult(ctx, scene, &small, &result), "prismRenderToResult");
  small.width = 8;
  CHECK_OK(prismRenderToResult(ctx, scene, &small, &result));
  BAD(prismGetResultSize(NULL, &u32, &u32), "prismGetResultSize");
  BAD(prismGetResultSize(result, NULL, &u32), "prismGetResultSize");
  BAD(prismGetResultSize(result, &u32, NULL), "prismGetResultSize");
  BAD(prismGetResultImage(NULL, &pixels), "prismGetResultImage");
  BAD(prismGetResultImage(result, NULL), "prismGetResultImage");
  BAD(prismGetResultAov(NULL, PRISM_AOV_DEPTH, &pixels, &u32), "prismGetResultAov");
  BAD(prismGetResultAov(result, PRISM_AOV_DEPTH, NULL, &u32), "prismGetResultAov");
  BAD(prismGetResultAov(result, PRISM_AOV_DEPTH, &pixels, NULL), "prismGetResultAov");
  BAD(prismGetResultAov(result, (PrismAov)99, &pixels, &u32), "prismGetResultAov");
  BAD(prismGetResultStats(NULL, &stats), "prismGetResultStats");
  BAD(prismGetResultStats(result, NULL), "prismGetResultStats");
  stats.struct_size = 0;
  BAD(prismGetResultStats(result, &stats), "prismGetResultStats");
  BAD(prismGetResultWarningCount(NULL, &u32), "prismGetResultWarningCount");
  BAD(prismGetResultWarningCount(result, NULL), "prismGetResultWarningCount");
  CHECK_OK(prismGetResultWarningCount(result, &u32));
  CHECK(u32 == 0); /* a plain scene */
  BAD(prismGetResultWarning(result, 0, &text), "prismGetResultWarning");
  BAD(prismGetResultWarning(NULL, 0, &text), "prismGetResultWarning");
  prismReleaseResult(result);
  {
    /* Each value within its bound, 1e42 together: the result keeps the
     * render's warning, as the context does after prismRender. */
    PrismScene bright = NULL;
    CHECK_OK(prismLoadSceneFromString(
        "{\"camera\": {\"position\": [0, 0, 5], \"look_at\": [0, 0, 0]},"
        " \"materials\": {\"hot\": {\"diffuse\": 1e6, \"texture\": {\"type\": \"checker\", \"color1\": 1e6,"
        " \"color2\": 1e6}}}, \"lights\": [{\"position\": [0, 0, 5], \"intensity\": 1e30}],"
        " \"objects\": [{\"type\": \"sphere\", \"center\": [0, 0, 0], \"radius\": 1, \"material\": \"hot\"}]}",
        "bright.json", &bright));
    CHECK_OK(prismRenderToResult(ctx, bright, &small, &result));
    CHECK_OK(prismGetResultWarningCount(result, &u32));
    CHECK(u32 == 1);
    CHECK_OK(prismGetResultWarning(result, 0, &text));
    CHECK(text && strstr(text, "of the colour image's 48 pixels are not finite") != NULL);
    BAD(prismGetResultWarning(result, 1, &text), "prismGetResultWarning");
    prismReleaseResult(result);
    prismReleaseScene(bright);
  }
  prismReleaseResult(NULL);
  EXPECT(prismGetKernelTime(ctx, 0, &text, &seconds, &launches), PRISM_ERROR_INVALID_OPERATION,
         "prismGetKernelTime"); /* the render was not profiled */

  /* Ray queries. */
  memset(&ray, 0, sizeof ray);
  ray.dir[2] = -1;
  ray.tmax = INFINITY;
  BAD(prismIntersect(NULL, scene, PRISM_ACCEL_BVH, &ray, &hit, 1, NULL), "prismIntersect");
  BAD(prismIntersect(ctx, NULL, PRISM_ACCEL_BVH, &ray, &hit, 1, NULL), "prismIntersect");
  BAD(prismIntersect(ctx, scene, PRISM_ACCEL_BVH, NULL, &hit, 1, NULL), "prismIntersect");
  BAD(prismIntersect(ctx, scene, PRISM_ACCEL_BVH, &ray, NULL, 1, NULL), "prismIntersect");
  BAD(prismIntersect(ctx, scene, (PrismAccel)99, &ray, &hit, 1, NULL), "prismIntersect");
  BAD(prismOccluded(NULL, scene, PRISM_ACCEL_BVH, &ray, &occluded, 1, NULL), "prismOccluded");
  BAD(prismOccluded(ctx, scene, PRISM_ACCEL_BVH, NULL, &occluded, 1, NULL), "prismOccluded");
  BAD(prismOccluded(ctx, scene, PRISM_ACCEL_BVH, &ray, NULL, 1, NULL), "prismOccluded");
  BAD(prismOccluded(ctx, scene, (PrismAccel)99, &ray, &occluded, 1, NULL), "prismOccluded");
  CHECK_OK(prismIntersect(ctx, scene, PRISM_ACCEL_BVH, &ray, &hit, 0, NULL)); /* nothing to do is fine */

  /* Images. */
  BAD(prismWriteImage(NULL, rgba, 8, 6, 4), "prismWriteImage");
  BAD(prismWriteImage("out.png", NULL, 8, 6, 4), "prismWriteImage");
  BAD(prismWriteImage("out.png", rgba, 0, 6, 4), "prismWriteImage");
  BAD(prismWriteImage("out.png", rgba, 8, 6, 2), "prismWriteImage");
  EXPECT(prismWriteImage("out.xyz", rgba, 8, 6, 4), PRISM_ERROR_IO, "prismWriteImage"); /* as prism_api.cpp maps ImageError */

  prismReleaseScene(scene);
  prismReleaseScene(NULL);
  prismReleaseContext(ctx);
  (void)none_scene;
  printf("%d calls checked, %d failed\n", calls, failures);
  return failures == 0 ? 0 : 1;
}
