/* A scene built in code and rendered: a checkered floor, a glass sphere and a
 * pyramid from arrays, two materials, a point light, a camera, then the image
 * written with prismWriteImage.
 *
 *   render_scene OUT.png [DEVICE]
 */
#include <stdio.h>
#include <stdlib.h>

#include <prism.h>

static void check(PrismStatus status, const char* what) {
  if (status != PRISM_OK) {
    fprintf(stderr, "render_scene: %s failed: %s (%s)\n", what, prismGetLastError(), prismStatusName(status));
    exit(1);
  }
}

int main(int argc, char** argv) {
  static const float pyramid[5 * 3] = {-1, 0, -1, 1, 0, -1, 1, 0, 1, -1, 0, 1, 0, 1.5f, 0};
  static const uint32_t pyramid_triangles[4 * 3] = {0, 4, 1, 1, 4, 2, 2, 4, 3, 3, 4, 0};
  const float light_position[3] = {3, 5, 4}, white[3] = {1, 1, 1}, sky[3] = {0.5f, 0.7f, 1.0f};
  PrismContext context = NULL;
  PrismScene scene = NULL;
  PrismCamera camera;
  PrismMaterial material;
  PrismObject object;
  PrismRenderOptions options;
  PrismRenderStats stats;
  float* rgba;
  size_t i, covered = 0;

  if (argc < 2) {
    fprintf(stderr, "usage: render_scene OUT.png [DEVICE]\n");
    return 2;
  }
  check(prismCreateContext(argc > 2 ? argv[2] : NULL, NULL, &context), "prismCreateContext");
  check(prismNewScene(&scene), "prismNewScene");
  check(prismSetBackground(scene, sky), "prismSetBackground");

  prismDefaultMaterial(&material); /* the defaults a scene file's material starts from */
  material.checker = 1;
  material.checker_scale = 0.5f;
  check(prismAddMaterial(scene, "floor", &material, NULL), "prismAddMaterial");
  prismDefaultMaterial(&material);
  material.diffuse[0] = material.diffuse[1] = material.diffuse[2] = 0.02f;
  material.specular[0] = material.specular[1] = material.specular[2] = 0.9f;
  material.shininess = 200;
  material.reflect = 0.1f, material.transmit = 0.9f, material.ior = 1.5f;
  check(prismAddMaterial(scene, "glass", &material, NULL), "prismAddMaterial");

  prismDefaultObject(&object, PRISM_OBJECT_PLANE); /* through the origin, normal +y */
  object.material = "floor";
  check(prismAddObject(scene, &object, NULL), "prismAddObject");
  prismDefaultObject(&object, PRISM_OBJECT_SPHERE);
  object.center[0] = 1.2f, object.center[1] = 0.6f, object.center[2] = 1.2f;
  object.radius = 0.6f;
  object.material = "glass";
  check(prismAddObject(scene, &object, NULL), "prismAddObject");
  check(prismAddMeshArrays(scene, pyramid, 5, pyramid_triangles, 4, NULL, NULL, NULL), "prismAddMeshArrays");
  check(prismAddPointLight(scene, light_position, white, 1.0f), "prismAddPointLight");

  camera.struct_size = sizeof camera;
  check(prismGetCamera(scene, &camera), "prismGetCamera");
  camera.position[0] = 2.5f, camera.position[1] = 2.5f, camera.position[2] = 5.0f;
  camera.look_at[0] = 0.0f, camera.look_at[1] = 0.5f, camera.look_at[2] = 0.0f;
  check(prismSetCamera(scene, &camera), "prismSetCamera");

  options.struct_size = sizeof options;
  check(prismGetRenderOptions(scene, &options), "prismGetRenderOptions");
  options.width = 160, options.height = 120;
  check(prismCheckRenderOptions(&options), "prismCheckRenderOptions");
  rgba = malloc((size_t)options.width * options.height * 4 * sizeof(float));
  if (!rgba) return 1;
  stats.struct_size = sizeof stats;
  check(prismRender(context, scene, &options, rgba, &stats), "prismRender");
  check(prismWriteImage(argv[1], rgba, options.width, options.height, 4), "prismWriteImage");

  for (i = 0; i < (size_t)options.width * options.height; ++i) covered += rgba[4 * i + 3] > 0;
  printf("%s: %ux%u, %zu of %zu pixels covered, %llu rays in %.3f s\n", argv[1], options.width, options.height,
         covered, (size_t)options.width * options.height,
         (unsigned long long)(stats.primary_rays + stats.reflected_rays + stats.refracted_rays + stats.shadow_rays),
         stats.seconds);
  free(rgba);
  prismReleaseScene(scene);
  prismReleaseContext(context);
  return covered > 0 ? 0 : 1;  /* the floor covers the lower part of the picture */
}
