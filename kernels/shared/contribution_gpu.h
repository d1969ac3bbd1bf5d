/* Light brought to one film entry by one ray; shared by host and kernels. In a
 * render the film holds one entry per primary sample and `pixel` is the sample's
 * index (RayGpu.pixel). Queues of contributions are sorted by it, so accumulation
 * needs no atomics. */
#ifndef PRISM_CONTRIBUTION_GPU_H
#define PRISM_CONTRIBUTION_GPU_H

typedef struct ContributionGpu {
  float r, g, b;
  float a; /* coverage: 1 for a primary ray that hit something */
  int pixel; /* the film key: a sample index in a render */
  int pad[3]; /* keeps the struct at 32 bytes */
} ContributionGpu;

#endif
