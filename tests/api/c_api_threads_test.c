/* The C API's thread and ownership rules (docs/c-api.md, "Threads and
 * ownership"): two threads, each with its own context, render one shared scene
 * at the same time and get the single-threaded image bit for bit; each thread
 * sees its own last error; a result outlives the context and scene that made
 * it. argv[1] is the scenes folder. */
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "c_check.h"
#include "prism.h"

static int failures = 0;

enum { kWidth = 64, kHeight = 36, kRounds = 3 };

struct Job {
  PrismScene scene;        /* shared, read only */
  const float* reference;  /* the single-threaded image */
  const char* marker;      /* this thread's name in its error messages */
  int failures;
};

static void* renderInTurns(void* arg) {
  struct Job* job = (struct Job*)arg;
  PrismContext ctx = NULL;
  PrismRenderOptions options;
  PrismScene missing = NULL;
  char path[256];
  static float images[2][kWidth * kHeight * 4];
  float* mine = images[job->marker[0] == 'A' ? 0 : 1];
  int round;
  if (prismCreateContext("cpu", NULL, &ctx) != PRISM_OK) {
    ++job->failures;
    return NULL;
  }
  options.struct_size = sizeof options;
  prismGetRenderOptions(job->scene, &options);
  options.width = kWidth, options.height = kHeight;
  for (round = 0; round < kRounds; ++round) {
    PrismResult result = NULL;
    const float* pixels = NULL;
    if (prismRenderToResult(ctx, job->scene, &options, &result) != PRISM_OK ||
        prismGetResultImage(result, &pixels) != PRISM_OK ||
        memcmp(pixels, job->reference, sizeof(float) * kWidth * kHeight * 4) != 0) {
      fprintf(stderr, "thread %s, round %d: the result differs from the single-threaded image\n", job->marker, round);
      ++job->failures;
    }
    prismReleaseResult(result);
    if (prismRender(ctx, job->scene, &options, mine, NULL) != PRISM_OK ||
        memcmp(mine, job->reference, sizeof(float) * kWidth * kHeight * 4) != 0) {
      fprintf(stderr, "thread %s, round %d: prismRender differs from the single-threaded image\n", job->marker, round);
      ++job->failures;
    }
    /* An error of this thread's own, read back while the other thread works. */
    snprintf(path, sizeof path, "/nonexistent/%s-%d.json", job->marker, round);
    if (prismLoadScene(path, &missing) == PRISM_OK || !strstr(prismGetLastError(), path)) {
      fprintf(stderr, "thread %s: its last error is not its own: %s\n", job->marker, prismGetLastError());
      ++job->failures;
    }
  }
  prismReleaseContext(ctx);
  return NULL;
}

int main(int argc, char** argv) {
  char path[4096];
  PrismContext ctx = NULL;
  PrismScene scene = NULL;
  PrismResult kept = NULL;
  PrismRenderOptions options;
  PrismRenderStats stats;
  const float* pixels = NULL;
  const float* depth = NULL;
  uint32_t width = 0, height = 0, channels = 0;
  float* reference;
  pthread_t threads[2];
  struct Job jobs[2];
  size_t i, n = (size_t)kWidth * kHeight, hits = 0;

  if (argc < 2) {
    fprintf(stderr, "usage: c_api_threads_test SCENES_DIR\n");
    return 2;
  }
  snprintf(path, sizeof path, "%s/whitted.json", argv[1]);
  CHECK_OK(prismLoadScene(path, &scene));
  CHECK_OK(prismCreateContext("cpu", NULL, &ctx));
  options.struct_size = sizeof options;
  CHECK_OK(prismGetRenderOptions(scene, &options));
  options.width = kWidth, options.height = kHeight;
  CHECK_OK(prismRenderToResult(ctx, scene, &options, &kept));

  /* The result owns its data: it outlives its context and its scene. */
  prismReleaseContext(ctx);
  CHECK_OK(prismLoadScene(path, &jobs[0].scene)); /* a second copy of the scene for the threads */
  prismReleaseScene(scene);
  CHECK_OK(prismGetResultSize(kept, &width, &height));
  CHECK(width == kWidth && height == kHeight);
  CHECK_OK(prismGetResultImage(kept, &pixels));
  CHECK_OK(prismGetResultAov(kept, PRISM_AOV_DEPTH, &depth, &channels));
  CHECK(channels == 1);
  for (i = 0; i < n; ++i) hits += depth[i] < 1e30f && pixels[4 * i + 3] == 1.0f;
  CHECK(hits > n / 3 && hits < n); /* the floor is hit, the sky is not, and alpha agrees with depth */
  stats.struct_size = sizeof stats;
  CHECK_OK(prismGetResultStats(kept, &stats));
  CHECK(stats.primary_rays == n);
  reference = malloc(n * 4 * sizeof(float));
  if (!reference) return 1;
  memcpy(reference, pixels, n * 4 * sizeof(float));
  prismReleaseResult(kept);

  jobs[0].reference = reference, jobs[0].marker = "A", jobs[0].failures = 0;
  jobs[1] = jobs[0];
  jobs[1].marker = "B";
  for (i = 0; i < 2; ++i) CHECK(pthread_create(&threads[i], NULL, renderInTurns, &jobs[i]) == 0);
  for (i = 0; i < 2; ++i) pthread_join(threads[i], NULL);
  failures += jobs[0].failures + jobs[1].failures;
  printf("two threads, two contexts, one scene: %d rounds each, %d failure(s)\n", kRounds, failures);

  prismReleaseScene(jobs[0].scene);
  free(reference);
  return failures ? 1 : 0;
}
