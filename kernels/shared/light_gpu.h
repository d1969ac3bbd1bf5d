/* A light; shared by host and kernels. A point light is a position and an
 * intensity; an area light (quad, disk, sphere) is a shape of uniform emitted
 * radiance that shadow feelers sample (kernels/shading/light.h). */
#ifndef PRISM_LIGHT_GPU_H
#define PRISM_LIGHT_GPU_H

#define LIGHT_POINT 0
#define LIGHT_QUAD 1
#define LIGHT_DISK 2
#define LIGHT_SPHERE 3

typedef struct LightGpu {
  float position[4]; /* point: position; quad: corner; disk, sphere: centre; w: radius */
  float color[4];    /* rgb x intensity: a point light's intensity, an area light's radiance; w: area */
  float edge1[4];    /* quad: the two edges from the corner; disk: two orthogonal radii */
  float edge2[4];
  float normal[4];   /* quad, disk: unit normal (both faces emit) */
  int type;          /* LIGHT_* */
  int samples;       /* feelers spawn_shadows sends per hit (the host already divided by spp);
                        0 for a point light, whose one feeler shade traces */
  int pad[2];
} LightGpu;

#endif
