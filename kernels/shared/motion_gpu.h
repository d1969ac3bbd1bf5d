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
 * only: its record keeps, in place of rotate0 and stretch0, the constant
 * world-to-object linear part (its 3 rows), so a ray needs no slerp and no
 * inverse. */
#define MOTION_GENERAL 0
#define MOTION_TRANSLATE 1

typedef struct MotionGpu {
  int type; /* OBJECT_MOTION */
  float shutter_open, shutter_close; /* the interval time runs over */
  float translate0[3], rotate0[3], stretch0[6]; /* stretch: xx, xy, xz, yy, yz, zz */
  float translate1[3], rotate1[3], stretch1[6];
  int kind; /* MOTION_* */
} MotionGpu;

#endif
