/* The camera as the generate kernel sees it; shared by host and kernels. The
 * first block is the pinhole at shutter open, which is all the first-hit pass
 * needs; the rest describes a thin lens and a camera moving during the shutter
 * (kernels/sampling/camera_ray.h). */
#ifndef PRISM_CAMERA_GPU_H
#define PRISM_CAMERA_GPU_H

typedef struct CameraGpu {
  float origin[4];
  float forward[4]; /* unit view direction */
  float right[4];   /* unit right vector scaled by tan(fov/2) * aspect */
  float up[4];      /* unit up vector scaled by tan(fov/2) */
  int width, height, spp;
  int seed; /* low 32 bits of the user seed, mixed into the sample positions */
  float lens_radius;    /* 0: a pinhole */
  float focus_distance; /* of the plane in focus, along the view direction */
  float shutter_open, shutter_close;
  /* A moving camera: position and look-at at open and at close, the up vector
   * they share; moving == 0: the basis above holds for the whole shutter. */
  float look_at[4];
  float origin_end[4];
  float look_at_end[4];
  float world_up[4]; /* w: tan(fov/2) */
  int moving;
  int pad[3];
} CameraGpu;

#endif
