/* Light brought to one pixel by one ray; shared by host and kernels. Queues of
 * contributions are sorted by pixel, so accumulation needs no atomics. */
#ifndef PRISM_CONTRIBUTION_GPU_H
#define PRISM_CONTRIBUTION_GPU_H

typedef struct ContributionGpu {
  float r, g, b;
  float a; /* coverage: 1 for a primary ray that hit something */
  int pixel;
  int pad[3]; /* keeps the struct at 32 bytes */
} ContributionGpu;

#endif
