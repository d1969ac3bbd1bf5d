/* prism as a ray-query engine: a cube built from arrays, a grid of rays shot at
 * it, and every answer checked against the closed form (a ray straight down
 * the -z axis towards the cube [-1,1]^3 from z = 5 hits its top face at t = 4
 * inside the square, and misses outside it). Exits 0 when every hit agrees.
 *
 *   query_mesh [DEVICE]     DEVICE: index, "cpu", "gpu" or a name substring
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include <prism.h>

/* Prints prism's message for a failed call and leaves. */
static void check(PrismStatus status, const char* what) {
  if (status != PRISM_OK) {
    fprintf(stderr, "query_mesh: %s failed: %s (%s)\n", what, prismGetLastError(), prismStatusName(status));
    exit(1);
  }
}

int main(int argc, char** argv) {
  static const float corners[8 * 3] = {-1, -1, -1, 1, -1, -1, 1, 1, -1, -1, 1, -1,
                                       -1, -1, 1,  1, -1, 1,  1, 1, 1,  -1, 1, 1};
  static const uint32_t triangles[12 * 3] = {0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4,
                                             2, 3, 7, 2, 7, 6, 1, 2, 6, 1, 6, 5, 0, 4, 7, 0, 7, 3};
  enum { N = 64 }; /* an N x N grid of rays over [-2, 2]^2 */
  PrismRay rays[N * N];
  PrismHit hits[N * N];
  PrismContext context = NULL;
  PrismScene scene = NULL;
  size_t i, wrong = 0, hit_count = 0;
  double seconds = 0;

  check(prismCreateContext(argc > 1 ? argv[1] : NULL, NULL, &context), "prismCreateContext");
  check(prismNewScene(&scene), "prismNewScene");
  check(prismAddMeshArrays(scene, corners, 8, triangles, 12, NULL, NULL, NULL), "prismAddMeshArrays");

  for (i = 0; i < N * N; ++i) {
    PrismRay r = {{0, 0, 5}, 0.0f, {0, 0, -1}, INFINITY};
    r.org[0] = -2.0f + 4.0f * ((float)(i % N) + 0.5f) / N;
    r.org[1] = -2.0f + 4.0f * ((float)(i / N) + 0.5f) / N;
    rays[i] = r;
  }
  check(prismIntersect(context, scene, PRISM_ACCEL_AUTO, rays, hits, N * N, &seconds), "prismIntersect");

  for (i = 0; i < N * N; ++i) {
    const int inside = fabsf(rays[i].org[0]) < 1 && fabsf(rays[i].org[1]) < 1;
    const int hit = hits[i].prim >= 0;
    hit_count += (size_t)hit;
    /* The top face is triangles 2 and 3 (z = +1). */
    if (hit != inside || (hit && (fabsf(hits[i].t - 4.0f) > 1e-5f || (hits[i].prim != 2 && hits[i].prim != 3))))
      ++wrong;
  }
  printf("%zu rays, %zu hits, %zu disagree with the closed form; traced in %.3f ms\n", (size_t)(N * N), hit_count,
         wrong, seconds * 1e3);
  prismReleaseScene(scene);
  prismReleaseContext(context);
  return wrong == 0 ? 0 : 1;
}
