/* The motion of a moving object during the shutter; shared by host and kernels.
 * Its object-to-world transform at shutter open and at close, each decomposed
 * as translation x rotation (a unit quaternion, kept as x, y, z with w >= 0) x
 * stretch (symmetric 3x3, from the polar decomposition), so time interpolates
 * translation and stretch linearly and rotation by slerp
 * (kernels/geometry/motion.h). A record has an ObjectGpu's size and sits in the
 * object array after every primitive, at the moving object's index plus the
 * offset its flags carry (OBJECT_MOTION_SHIFT); its type tells it from a
 * primitive. */
#ifndef PRISM_MOTION_GPU_H
#define PRISM_MOTION_GPU_H

#define OBJECT_MOTION 100 /* the type of a motion record: not a primitive */

/* A motion whose rotation and stretch are the same at both ends translates
 * only: its record keeps, in place of shape0, the constant world-to-object
 * linear part (its 3 rows), so a ray needs no slerp and no inverse. */
#define MOTION_ROTATION 0 /* offsets in shape0, shape1 */
#define MOTION_STRETCH 3
#define MOTION_GENERAL 0
#define MOTION_TRANSLATE 1

typedef struct MotionGpu {
  int type; /* OBJECT_MOTION */
  float shutter_open, shutter_close; /* the interval time runs over */
  /* shape: the rotation's x, y, z (MOTION_ROTATION), then the stretch's xx, xy,
   * xz, yy, yz, zz (MOTION_STRETCH): one array, so a translation's 9-float
   * linear part stays inside it. */
  float translate0[3], shape0[9];
  float translate1[3], shape1[9];
  int kind; /* MOTION_* */
} MotionGpu;

#endif
