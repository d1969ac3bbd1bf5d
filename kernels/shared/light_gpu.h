/* A point light; shared by host and kernels. */
#ifndef PRISM_LIGHT_GPU_H
#define PRISM_LIGHT_GPU_H

typedef struct LightGpu {
  float position[4]; /* xyz + unused lane */
  float color[4];    /* rgb already multiplied by intensity */
} LightGpu;

#endif
