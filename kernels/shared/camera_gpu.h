/* The pinhole camera as the generate kernel sees it; shared by host and kernels. */
#ifndef PRISM_CAMERA_GPU_H
#define PRISM_CAMERA_GPU_H

typedef struct CameraGpu {
  float origin[4];
  float forward[4]; /* unit view direction */
  float right[4];   /* unit right vector scaled by tan(fov/2) * aspect */
  float up[4];      /* unit up vector scaled by tan(fov/2) */
  int width, height, spp;
  int seed; /* low 32 bits of the user seed, mixed into the sample positions */
} CameraGpu;

#endif
