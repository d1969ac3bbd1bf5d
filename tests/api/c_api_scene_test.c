/* A scene built in code through the typed C API calls renders bit for bit as
 * the same scene written in the scene format, and a value either route refuses
 * is refused by both with the same message. The JSON text is printed from the
 * very floats the typed calls receive (%.17g of each, exact as a double), so
 * the two scenes hold the same numbers. */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "c_check.h"
#include "prism.h"

static int failures = 0;

/* The Whitted scene of scenes/whitted.json, as floats. */
static const float kEye[3] = {0, 2.0f, 6.5f}, kLookAt[3] = {0, 0.8f, 0}, kFov = 40;
static const float kAmbient[3] = {0.15f, 0.15f, 0.15f}, kBackground[3] = {0.45f, 0.65f, 0.95f};
static const float kLight1[3] = {-4, 7, 6}, kLight1Color[3] = {1, 1, 1}, kLight1Power = 0.7f;
static const float kLight2[3] = {6, 9, 2}, kLight2Color[3] = {1, 0.95f, 0.9f}, kLight2Power = 0.5f;
static const float kMirrorCenter[3] = {1.1f, 1.1f, -1.5f}, kMirrorRadius = 1.1f;
static const float kGlassCenter[3] = {-0.7f, 0.9f, 0.8f}, kGlassRadius = 0.9f;
static const float kTriangle[9] = {-2.5f, 0.01f, 1.5f, -1.2f, 0.01f, 2.2f, -2.0f, 1.4f, 1.8f};
static const float kBoxMin[3] = {1.8f, 0, 0.6f}, kBoxMax[3] = {2.6f, 0.7f, 1.4f};
/* A capped cylinder (x + 2)^2 + (z + 1)^2 = 0.4^2 as a general quadric. */
static const float kQuadric[10] = {1, 0, 1, 0, 0, 0, 4, 0, 2, 4.84f};
static const float kClipMin[3] = {-2.4f, 0, -1.4f}, kClipMax[3] = {-1.6f, 1.2f, -0.6f};

static PrismMaterial checker(void) {
  PrismMaterial m;
  prismDefaultMaterial(&m);
  m.diffuse[0] = m.diffuse[1] = m.diffuse[2] = 0.9f;
  m.specular[0] = m.specular[1] = m.specular[2] = 0.1f;
  m.shininess = 16;
  m.checker = 1;
  m.checker_color1[0] = 1.0f, m.checker_color1[1] = 0.1f, m.checker_color1[2] = 0.05f;
  m.checker_color2[0] = 1.0f, m.checker_color2[1] = 0.9f, m.checker_color2[2] = 0.1f;
  m.checker_scale = 1;
  return m;
}

static PrismMaterial glass(void) {
  PrismMaterial m;
  prismDefaultMaterial(&m);
  m.model = PRISM_SHADING_BLINN;
  m.ambient[0] = m.ambient[1] = m.ambient[2] = 0;
  m.diffuse[0] = m.diffuse[1] = m.diffuse[2] = 0.02f;
  m.specular[0] = m.specular[1] = m.specular[2] = 0.9f;
  m.shininess = 300;
  m.reflect = 0.1f;
  m.transmit = 0.9f;
  m.ior = 1.5f;
  return m;
}

static PrismMaterial brushed(void) {
  PrismMaterial m;
  prismDefaultMaterial(&m);
  m.model = PRISM_SHADING_COOK_TORRANCE;
  m.diffuse[0] = 0.3f, m.diffuse[1] = 0.2f, m.diffuse[2] = 0.1f;
  m.specular[0] = m.specular[1] = m.specular[2] = 0.8f;
  m.roughness = 0.25f;
  m.distribution = PRISM_MICROFACET_GGX;
  m.ior = 1.5f;
  return m;
}

static PrismMaterial mirror(void) {
  PrismMaterial m;
  prismDefaultMaterial(&m);
  m.ambient[0] = m.ambient[1] = m.ambient[2] = 0.1f;
  m.diffuse[0] = 0.1f, m.diffuse[1] = 0.1f, m.diffuse[2] = 0.12f;
  m.specular[0] = m.specular[1] = m.specular[2] = 0.9f;
  m.shininess = 200;
  m.reflect = 0.8f;
  return m;
}

/* Appends printf-style text to the buffer. */
static void put(char* buf, size_t size, const char* fmt, ...) {
  size_t used = strlen(buf);
  va_list args;
  va_start(args, fmt);
  vsnprintf(buf + used, size - used, fmt, args);
  va_end(args);
}

static void putVec(char* buf, size_t size, const float* v) {
  put(buf, size, "[%.17g, %.17g, %.17g]", (double)v[0], (double)v[1], (double)v[2]);
}

static void putMaterial(char* buf, size_t size, const char* name, const PrismMaterial* m, int last) {
  static const char* const models[] = {"phong", "blinn", "cook-torrance"};
  put(buf, size, "\"%s\": {\"model\": \"%s\", \"ambient\": ", name, models[m->model]);
  putVec(buf, size, m->ambient);
  put(buf, size, ", \"diffuse\": ");
  putVec(buf, size, m->diffuse);
  put(buf, size, ", \"specular\": ");
  putVec(buf, size, m->specular);
  put(buf, size, ", \"shininess\": %.17g, \"reflect\": %.17g, \"transmit\": %.17g, \"ior\": %.17g",
      (double)m->shininess, (double)m->reflect, (double)m->transmit, (double)m->ior);
  if (m->model == PRISM_SHADING_COOK_TORRANCE)
    put(buf, size, ", \"roughness\": %.17g, \"distribution\": \"%s\"", (double)m->roughness,
        m->distribution == PRISM_MICROFACET_GGX ? "ggx" : "beckmann");
  if (m->checker) {
    put(buf, size, ", \"texture\": {\"type\": \"checker\", \"color1\": ");
    putVec(buf, size, m->checker_color1);
    put(buf, size, ", \"color2\": ");
    putVec(buf, size, m->checker_color2);
    put(buf, size, ", \"scale\": %.17g}", (double)m->checker_scale);
  }
  put(buf, size, "}%s", last ? "" : ", ");
}

/* The scene as scene-format text, from the same floats. */
static void sceneJson(char* buf, size_t size) {
  PrismMaterial c = checker(), g = glass(), m = mirror(), b = brushed();
  buf[0] = 0;
  put(buf, size, "{\"camera\": {\"position\": ");
  putVec(buf, size, kEye);
  put(buf, size, ", \"look_at\": ");
  putVec(buf, size, kLookAt);
  put(buf, size, ", \"fov\": %.17g},\n \"render\": {\"ambient\": ", (double)kFov);
  putVec(buf, size, kAmbient);
  put(buf, size, ", \"background\": ");
  putVec(buf, size, kBackground);
  put(buf, size, "},\n \"materials\": {");
  putMaterial(buf, size, "checker", &c, 0);
  putMaterial(buf, size, "mirror", &m, 0);
  putMaterial(buf, size, "glass", &g, 0);
  putMaterial(buf, size, "brushed", &b, 1);
  put(buf, size, "},\n \"lights\": [{\"position\": ");
  putVec(buf, size, kLight1);
  put(buf, size, ", \"color\": ");
  putVec(buf, size, kLight1Color);
  put(buf, size, ", \"intensity\": %.17g}, {\"position\": ", (double)kLight1Power);
  putVec(buf, size, kLight2);
  put(buf, size, ", \"color\": ");
  putVec(buf, size, kLight2Color);
  put(buf, size, ", \"intensity\": %.17g}],\n \"objects\": [", (double)kLight2Power);
  put(buf, size, "{\"type\": \"plane\", \"point\": [0, 0, 0], \"normal\": [0, 1, 0], \"material\": \"checker\"}, ");
  put(buf, size, "{\"type\": \"sphere\", \"center\": ");
  putVec(buf, size, kMirrorCenter);
  put(buf, size, ", \"radius\": %.17g, \"material\": \"mirror\"}, ", (double)kMirrorRadius);
  put(buf, size, "{\"type\": \"sphere\", \"center\": ");
  putVec(buf, size, kGlassCenter);
  put(buf, size, ", \"radius\": %.17g, \"material\": \"glass\", \"transform\": {\"matrix\": "
                 "[1, 0, 0, 0.25, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]}}, ",
      (double)kGlassRadius);
  put(buf, size, "{\"type\": \"triangle\", \"vertices\": [");
  putVec(buf, size, kTriangle);
  put(buf, size, ", ");
  putVec(buf, size, kTriangle + 3);
  put(buf, size, ", ");
  putVec(buf, size, kTriangle + 6);
  put(buf, size, "], \"material\": \"mirror\"}, {\"type\": \"box\", \"min\": ");
  putVec(buf, size, kBoxMin);
  put(buf, size, ", \"max\": ");
  putVec(buf, size, kBoxMax);
  put(buf, size, ", \"material\": \"brushed\"}, {\"type\": \"quadric\", \"coefficients\": [");
  for (int i = 0; i < 10; ++i) put(buf, size, "%s%.17g", i ? ", " : "", (double)kQuadric[i]);
  put(buf, size, "], \"clip\": {\"min\": ");
  putVec(buf, size, kClipMin);
  put(buf, size, ", \"max\": ");
  putVec(buf, size, kClipMax);
  put(buf, size, "}, \"capped\": true, \"material\": \"brushed\"}]}");
}

/* The same scene through the typed calls. */
static int buildInCode(PrismScene* out) {
  static const float shift[16] = {1, 0, 0, 0.25f, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  PrismScene scene = NULL;
  PrismCamera camera;
  PrismMaterial m;
  PrismObject o;
  uint32_t index = 99;
  CHECK_OK(prismNewScene(&scene));
  camera.struct_size = sizeof camera;
  CHECK_OK(prismGetCamera(scene, &camera));
  memcpy(camera.position, kEye, sizeof kEye);
  memcpy(camera.look_at, kLookAt, sizeof kLookAt);
  camera.fov_degrees = kFov;
  CHECK_OK(prismSetCamera(scene, &camera));
  CHECK_OK(prismSetAmbient(scene, kAmbient));
  CHECK_OK(prismSetBackground(scene, kBackground));
  m = checker();
  CHECK_OK(prismAddMaterial(scene, "checker", &m, &index));
  CHECK(index == 1); /* after the default material */
  m = mirror();
  CHECK_OK(prismAddMaterial(scene, "mirror", &m, NULL));
  m = glass();
  CHECK_OK(prismAddMaterial(scene, "glass", &m, &index));
  CHECK(index == 3);
  m = brushed();
  CHECK_OK(prismAddMaterial(scene, "brushed", &m, NULL));
  CHECK_OK(prismAddPointLight(scene, kLight1, kLight1Color, kLight1Power));
  CHECK_OK(prismAddPointLight(scene, kLight2, kLight2Color, kLight2Power));
  prismDefaultObject(&o, PRISM_OBJECT_PLANE); /* the point (origin) and normal (+y) it starts with */
  o.material = "checker";
  CHECK_OK(prismAddObject(scene, &o, &index));
  CHECK(index == 0);
  prismDefaultObject(&o, PRISM_OBJECT_SPHERE);
  memcpy(o.center, kMirrorCenter, sizeof kMirrorCenter);
  o.radius = kMirrorRadius;
  o.material = "mirror";
  CHECK_OK(prismAddObject(scene, &o, NULL));
  memcpy(o.center, kGlassCenter, sizeof kGlassCenter);
  o.radius = kGlassRadius;
  o.material = "glass";
  o.object_to_world = shift;
  CHECK_OK(prismAddObject(scene, &o, NULL));
  prismDefaultObject(&o, PRISM_OBJECT_TRIANGLE);
  memcpy(o.vertices, kTriangle, sizeof kTriangle);
  o.material = "mirror";
  CHECK_OK(prismAddObject(scene, &o, NULL));
  prismDefaultObject(&o, PRISM_OBJECT_BOX);
  memcpy(o.box_min, kBoxMin, sizeof kBoxMin);
  memcpy(o.box_max, kBoxMax, sizeof kBoxMax);
  o.material = "brushed";
  CHECK_OK(prismAddObject(scene, &o, &index));
  CHECK(index == 4);
  prismDefaultObject(&o, PRISM_OBJECT_QUADRIC);
  memcpy(o.coefficients, kQuadric, sizeof kQuadric);
  memcpy(o.clip_min, kClipMin, sizeof kClipMin);
  memcpy(o.clip_max, kClipMax, sizeof kClipMax);
  o.capped = 1;
  o.material = "brushed";
  CHECK_OK(prismAddObject(scene, &o, &index));
  CHECK(index == 5);
  {
    uint32_t count = 0;
    CHECK_OK(prismGetSceneObjectCount(scene, &count));
    CHECK(count == 6);
  }
  *out = scene;
  return 0;
}

/* What follows the function's name in the last error: "prismX: <rest>". */
static const char* afterFunction(void) {
  const char* m = prismGetLastError();
  const char* colon = strstr(m, ": ");
  return colon ? colon + 2 : m;
}

/* Both routes refuse the value with the same message: the typed call's is
 * "prismAddObject: objects[5].radius: ...", the file's "prismLoadSceneFromString:
 * bad: objects[5].radius: ...". */
static void sameRefusal(PrismStatus typed, const char* json) {
  char typed_message[1024], file_message[1024];
  PrismScene scene = NULL;
  PrismStatus file;
  snprintf(typed_message, sizeof typed_message, "%s", afterFunction());
  file = prismLoadSceneFromString(json, "bad", &scene);
  snprintf(file_message, sizeof file_message, "%s", afterFunction());
  CHECK(typed == PRISM_ERROR_INVALID_ARGUMENT);
  CHECK(file == PRISM_ERROR_PARSE);
  CHECK(scene == NULL);
  if (strncmp(file_message, "bad: ", 5) != 0 || strcmp(file_message + 5, typed_message) != 0) {
    fprintf(stderr, "different messages:\n  typed: %s\n  file:  %s\n", typed_message, file_message);
    ++failures;
  }
}

int main(int argc, char** argv) {
  static char json[16384];
  PrismContext ctx = NULL;
  PrismScene typed = NULL, file = NULL;
  PrismRenderOptions options;
  PrismMaterial m;
  PrismObject o;
  float *a, *b, *da, *db;
  size_t n, i, differ = 0, hits = 0;
  uint32_t index = 0;
  const float bad_light[3] = {0, 1e30f, 0}, white[3] = {1, 1, 1};
  (void)argc, (void)argv;

  CHECK_OK(prismCreateContext(NULL, NULL, &ctx));
  if (buildInCode(&typed) != 0) return 1;
  sceneJson(json, sizeof json);
  CHECK_OK(prismLoadSceneFromString(json, "whitted-as-text", &file));

  options.struct_size = sizeof options;
  CHECK_OK(prismGetRenderOptions(file, &options));
  options.width = 96, options.height = 54, options.max_depth = 8;
  n = (size_t)options.width * options.height;
  a = malloc(n * 4 * sizeof(float)), b = malloc(n * 4 * sizeof(float));
  da = malloc(n * sizeof(float)), db = malloc(n * sizeof(float));
  if (!a || !b || !da || !db) return 1;
  CHECK_OK(prismRender(ctx, typed, &options, a, NULL));
  CHECK_OK(prismGetAov(ctx, PRISM_AOV_DEPTH, da, n));
  CHECK_OK(prismRender(ctx, file, &options, b, NULL));
  CHECK_OK(prismGetAov(ctx, PRISM_AOV_DEPTH, db, n));
  for (i = 0; i < 4 * n; ++i) differ += memcmp(&a[i], &b[i], sizeof(float)) != 0;
  for (i = 0; i < n; ++i) differ += memcmp(&da[i], &db[i], sizeof(float)) != 0, hits += isfinite(da[i]) != 0;
  printf("built in code and written as text: %zu of %zu values differ; %zu of %zu pixels hit\n", differ, 5 * n, hits, n);
  CHECK(differ == 0);
  CHECK(hits > n / 2 && hits < n); /* the plane fills the lower part, the sky the rest */

  /* The same refusals, the same words. Each typed call would add objects[6] or
   * lights[2]; each text puts the same value at that index. */
  prismDefaultObject(&o, PRISM_OBJECT_SPHERE);
  o.radius = -1;
  sameRefusal(prismAddObject(typed, &o, NULL),
              "{\"objects\": [{\"type\": \"plane\", \"point\": [0,0,0], \"normal\": [0,1,0]}, {\"type\": \"plane\", "
              "\"point\": [0,0,0], \"normal\": [0,1,0]}, {\"type\": \"plane\", \"point\": [0,0,0], \"normal\": "
              "[0,1,0]}, {\"type\": \"plane\", \"point\": [0,0,0], \"normal\": [0,1,0]}, {\"type\": \"plane\", "
              "\"point\": [0,0,0], \"normal\": [0,1,0]}, {\"type\": \"plane\", \"point\": [0,0,0], \"normal\": [0,1,0]}, {\"type\": \"sphere\", \"center\": [0,0,0], \"radius\": "
              "-1}]}");
  prismDefaultObject(&o, PRISM_OBJECT_BOX);
  o.box_max[1] = -2;
  sameRefusal(prismAddObject(typed, &o, NULL),
              "{\"objects\": [{\"type\": \"plane\", \"point\": [0,0,0], \"normal\": [0,1,0]}, {\"type\": \"plane\", "
              "\"point\": [0,0,0], \"normal\": [0,1,0]}, {\"type\": \"plane\", \"point\": [0,0,0], \"normal\": "
              "[0,1,0]}, {\"type\": \"plane\", \"point\": [0,0,0], \"normal\": [0,1,0]}, {\"type\": \"plane\", "
              "\"point\": [0,0,0], \"normal\": [0,1,0]}, {\"type\": \"plane\", \"point\": [0,0,0], \"normal\": [0,1,0]}, {\"type\": \"box\", \"min\": [-1,-1,-1], \"max\": "
              "[1,-2,1]}]}");
  prismDefaultMaterial(&m);
  m.ior = 0;
  sameRefusal(prismAddMaterial(typed, "thin", &m, NULL), "{\"materials\": {\"thin\": {\"ior\": 0}}}");
  {
    PrismCamera camera;
    camera.struct_size = sizeof camera;
    CHECK_OK(prismGetCamera(typed, &camera));
    camera.fov_degrees = 200;
    sameRefusal(prismSetCamera(typed, &camera), "{\"camera\": {\"fov\": 200}}");
    camera.fov_degrees = 40;
    camera.up[0] = 0, camera.up[1] = 0, camera.up[2] = 0;
    sameRefusal(prismSetCamera(typed, &camera),
                "{\"camera\": {\"position\": [0, 2, 6.5], \"look_at\": [0, 0.800000011920929, 0], \"up\": [0, 0, 0]}}");
  }
  /* A file cannot name a material twice (its keys are unique); a call can, and is refused. */
  prismDefaultMaterial(&m);
  CHECK(prismAddMaterial(typed, "glass", &m, NULL) == PRISM_ERROR_INVALID_ARGUMENT);
  CHECK(strcmp(prismGetLastError(), "prismAddMaterial: materials.glass: a material named 'glass' already exists") == 0);
  sameRefusal(prismAddPointLight(typed, bad_light, white, 1e30f),
              "{\"lights\": [{\"position\": [0,0,0]}, {\"position\": [0,0,0]}, {\"position\": [0, 1.0000000150474662e+30, "
              "0], \"intensity\": 1.0000000150474662e+30}]}");

  /* A refused call leaves the scene as it was: the next object is still objects[6]. */
  prismDefaultObject(&o, PRISM_OBJECT_SPHERE);
  CHECK_OK(prismAddObject(typed, &o, &index));
  CHECK(index == 6);
  /* A fragment adds what a file would; a bad one adds nothing. */
  CHECK(prismAddSceneJson(typed, "{\"objects\": [{\"type\": \"sphere\", \"center\": [0,0,0], \"radius\": 1}, "
                                 "{\"type\": \"sphere\", \"center\": [0,0,0], \"radius\": 0}]}") == PRISM_ERROR_PARSE);
  CHECK(strstr(prismGetLastError(), "prismAddSceneJson: json: objects[8].radius") != NULL);
  CHECK_OK(prismAddSceneJson(typed, "{\"materials\": {\"red\": {\"diffuse\": [1, 0, 0]}}, \"objects\": "
                                    "[{\"type\": \"sphere\", \"center\": [0,3,0], \"radius\": 1, \"material\": \"red\"}]}"));
  CHECK_OK(prismAddObject(typed, &o, &index));
  CHECK(index == 8);

  /* A context's cached query structure never outlives its scene: scenes made
   * after a release (often at the released one's address) get their own. */
  for (i = 0; i < 6; ++i) {
    PrismScene s = NULL;
    PrismRay ray = {{0, 0, 5}, 0, {0, 0, -1}, INFINITY};
    PrismHit hit;
    CHECK_OK(prismNewScene(&s));
    prismDefaultObject(&o, PRISM_OBJECT_SPHERE);
    o.radius = 0.5f + 0.5f * (float)i;
    CHECK_OK(prismAddObject(s, &o, NULL));
    CHECK_OK(prismIntersect(ctx, s, PRISM_ACCEL_BVH, &ray, &hit, 1, NULL));
    CHECK(hit.prim == 0 && fabsf(hit.t - (5.0f - o.radius)) < 1e-5f);
    prismReleaseScene(s);
  }

  free(a), free(b), free(da), free(db);
  prismReleaseScene(typed);
  prismReleaseScene(file);
  prismReleaseContext(ctx);
  if (failures) fprintf(stderr, "%d check(s) failed\n", failures);
  return failures ? 1 : 0;
}
