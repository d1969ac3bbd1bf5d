#include "accel/prim_ref.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

#include "accel/leaf_packets.h"
#include "accel/task_group.h"
#include "kernels/shared/mesh_gpu.h"
#include "kernels/shared/motion_gpu.h"
#include "scene/motion.h"
#include "scene/primitives/primitive_kind.h"

namespace prism {
namespace {

// Object-space box of the shape (the stored parameters), in double, by its kind.
bool localBounds(const ObjectGpu& ob, double lo[3], double hi[3]) {
  const PrimitiveKind* kind = primitiveKindOfGpu(ob.type);
  return kind && kind->local_bounds(ob, objectSideData(ob), lo, hi);
}

// Inverse of the 3x4 world-to-object matrix in double: object-to-world.
bool invert(const float* m, double out[12]) {
  double a[3][3] = {{m[0], m[1], m[2]}, {m[4], m[5], m[6]}, {m[8], m[9], m[10]}};
  double t[3] = {m[3], m[7], m[11]};
  double det = a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
               a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
  if (!(det != 0) || !std::isfinite(det)) return false;
  double inv[3][3];
  inv[0][0] = (a[1][1] * a[2][2] - a[1][2] * a[2][1]) / det;
  inv[0][1] = (a[0][2] * a[2][1] - a[0][1] * a[2][2]) / det;
  inv[0][2] = (a[0][1] * a[1][2] - a[0][2] * a[1][1]) / det;
  inv[1][0] = (a[1][2] * a[2][0] - a[1][0] * a[2][2]) / det;
  inv[1][1] = (a[0][0] * a[2][2] - a[0][2] * a[2][0]) / det;
  inv[1][2] = (a[0][2] * a[1][0] - a[0][0] * a[1][2]) / det;
  inv[2][0] = (a[1][0] * a[2][1] - a[1][1] * a[2][0]) / det;
  inv[2][1] = (a[0][1] * a[2][0] - a[0][0] * a[2][1]) / det;
  inv[2][2] = (a[0][0] * a[1][1] - a[0][1] * a[1][0]) / det;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) out[4 * r + c] = inv[r][c];
    out[4 * r + 3] = -(inv[r][0] * t[0] + inv[r][1] * t[1] + inv[r][2] * t[2]);
  }
  return true;
}

DecomposedTransform decomposedEnd(const MotionGpu& m, int end) {
  const float* t = end ? m.translate1 : m.translate0;
  // A translation's record keeps its rotation and stretch in the close slots only.
  const bool second = end || m.kind == MOTION_TRANSLATE;
  const float* q = (second ? m.shape1 : m.shape0) + MOTION_ROTATION;
  const float* s = (second ? m.shape1 : m.shape0) + MOTION_STRETCH;
  DecomposedTransform d;
  d.translate = {t[0], t[1], t[2]};
  double w2 = 1.0 - (double(q[0]) * q[0] + double(q[1]) * q[1] + double(q[2]) * q[2]);
  d.rotate[0] = q[0];
  d.rotate[1] = q[1];
  d.rotate[2] = q[2];
  d.rotate[3] = std::sqrt(std::max(0.0, w2));
  const double st[3][3] = {{s[0], s[1], s[2]}, {s[1], s[3], s[4]}, {s[2], s[4], s[5]}};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) d.stretch[i][j] = st[i][j];
  return d;
}

struct Box3 {
  double lo[3], hi[3];
};

// The object-to-world transforms of a motion at s = i / kMotionSteps, kept for
// the last record asked (a moving mesh's primitives share one, and come in a row).
constexpr int kMotionSteps = 64;
const std::vector<Transform>& motionSteps(const MotionGpu& motion) {
  thread_local MotionGpu cached{};
  thread_local std::vector<Transform> steps;
  if (steps.empty() || std::memcmp(&cached, &motion, sizeof motion) != 0) {
    const DecomposedTransform a = decomposedEnd(motion, 0), b = decomposedEnd(motion, 1);
    steps.resize(kMotionSteps + 1);
    for (int i = 0; i <= kMotionSteps; ++i) steps[i] = interpolate(a, b, static_cast<double>(i) / kMotionSteps);
    cached = motion;
  }
  return steps;
}

Box3 cornerBox(const Transform& t, const double lo[3], const double hi[3], double grow) {
  Box3 box{{INFINITY, INFINITY, INFINITY}, {-INFINITY, -INFINITY, -INFINITY}};
  for (int corner = 0; corner < 8; ++corner) {
    const Vec3 w = t.applyPoint({(corner & 1) ? hi[0] : lo[0], (corner & 2) ? hi[1] : lo[1], (corner & 4) ? hi[2] : lo[2]});
    const double wv[3] = {w.x, w.y, w.z};
    for (int k = 0; k < 3; ++k) {
      box.lo[k] = std::min(box.lo[k], wv[k] - grow);
      box.hi[k] = std::max(box.hi[k], wv[k] + grow);
    }
  }
  return box;
}

// World boxes of object-space box [lo, hi] over a motion: `swept` holds it at
// every instant, and lerp(open, close, s) at instant s (linear bounds).
//   Translation alone: the box at open and at close, exactly (a translated box
//   moves linearly), and their union.
//   Otherwise: kMotionSteps step boxes, box i the corners' box at s = i/steps
//   grown by how far any point can move before the next step (translation,
//   stretch and rotation bounded separately: |dT| + |dS| |x| + dphi |S x|), so
//   box i holds the object over its step. Their union is `swept`; `open` and
//   `close` start as the first and last, each face then pushed out by the most
//   the straight line between them cuts into a step's box at either end of
//   its step.
void movingBoxes(const MotionGpu& motion, const double lo[3], const double hi[3], Box3* swept, Box3* open,
                 Box3* close) {
  const std::vector<Transform>& t = motionSteps(motion);
  if (motion.kind == MOTION_TRANSLATE) {
    *open = cornerBox(t.front(), lo, hi, 0);
    *close = cornerBox(t.back(), lo, hi, 0);
    for (int k = 0; k < 3; ++k) {
      swept->lo[k] = std::min(open->lo[k], close->lo[k]);
      swept->hi[k] = std::max(open->hi[k], close->hi[k]);
    }
    return;
  }
  const DecomposedTransform a = decomposedEnd(motion, 0), b = decomposedEnd(motion, 1);
  const double dphi = rotationAngle(a, b) / kMotionSteps;
  double radius = 0;  // of the object-space box around the origin
  for (int corner = 0; corner < 8; ++corner) {
    Vec3 c{(corner & 1) ? hi[0] : lo[0], (corner & 2) ? hi[1] : lo[1], (corner & 4) ? hi[2] : lo[2]};
    radius = std::max(radius, length(c));
  }
  double stretch_norm = 0, stretch_step = 0;  // Frobenius norms bound the operator norms
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const double da = a.stretch[i][j], db = b.stretch[i][j];
      stretch_norm = std::max(stretch_norm, std::max(std::fabs(da), std::fabs(db)));
      stretch_step += (db - da) * (db - da);
    }
  stretch_norm *= 3;  // max entry x 3 bounds the Frobenius norm of a 3x3 matrix
  stretch_step = std::sqrt(stretch_step) / kMotionSteps;
  const double move =
      length(b.translate - a.translate) / kMotionSteps + stretch_step * radius + dphi * stretch_norm * radius;
  Box3 steps[kMotionSteps];
  for (int i = 0; i < kMotionSteps; ++i) steps[i] = cornerBox(t[i], lo, hi, move);
  *open = steps[0];
  *close = steps[kMotionSteps - 1];
  *swept = steps[0];
  for (int axis = 0; axis < 3; ++axis) {
    double push_lo = 0, push_hi = 0;
    const double a_lo = open->lo[axis], b_lo = close->lo[axis], a_hi = open->hi[axis], b_hi = close->hi[axis];
    for (int i = 0; i < kMotionSteps; ++i) {
      for (int end = 0; end < 2; ++end) {
        const double s = static_cast<double>(i + end) / kMotionSteps;
        push_lo = std::max(push_lo, a_lo + s * (b_lo - a_lo) - steps[i].lo[axis]);
        push_hi = std::max(push_hi, steps[i].hi[axis] - (a_hi + s * (b_hi - a_hi)));
      }
      swept->lo[axis] = std::min(swept->lo[axis], steps[i].lo[axis]);
      swept->hi[axis] = std::max(swept->hi[axis], steps[i].hi[axis]);
    }
    open->lo[axis] -= push_lo;
    close->lo[axis] -= push_lo;
    open->hi[axis] += push_hi;
    close->hi[axis] += push_hi;
  }
}

// The padding for the kernels' float transform of a box this size and place.
double floatPad(const Box3& b) {
  double extent = 0, magnitude = 0;
  for (int a = 0; a < 3; ++a) {
    extent = std::max(extent, b.hi[a] - b.lo[a]);
    magnitude = std::max({magnitude, std::fabs(b.lo[a]), std::fabs(b.hi[a])});
  }
  return 1e-5 * (extent + magnitude) + 1e-30;
}

// The float box just outside [lo - pad, hi + pad]; false if it does not fit a float.
bool toAabb(const double lo[3], const double hi[3], double pad, Aabb* out) {
  for (int a = 0; a < 3; ++a) {
    out->lo[a] = nextFloatDown(roundDown(lo[a] - pad));
    out->hi[a] = nextFloatUp(roundUp(hi[a] + pad));
    if (!std::isfinite(out->lo[a]) || !std::isfinite(out->hi[a])) return false;
  }
  return true;
}

const MotionGpu& motionOf(const ObjectGpu& ob) {
  return *reinterpret_cast<const MotionGpu*>(&ob + (ob.flags >> OBJECT_MOTION_SHIFT));
}

// A moving object's swept box and linear bounds (any of them may be null).
bool movingBounds(const ObjectGpu& ob, Aabb* swept, Aabb* open, Aabb* close);

// The kernels' float intersection routines may accept a hit a little outside
// the exact shape (Moller-Trumbore on a ray grazing an edge, a sphere's
// rounded discriminant): a static shape's box grows by 2^-20 of its size (and
// one more float step, toAabb).
double staticPad(const double lo[3], const double hi[3]) {
  return std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]}) * 0x1p-20;
}

}  // namespace

bool objectBounds(const ObjectGpu& ob, Aabb* bounds) {
  double lo[3], hi[3];
  if (isPacketTriangle(ob)) {
    // Most of any scene's primitives (a mesh's): straight to the triangle's
    // box, without looking its kind up.
    return kTriangleKind.local_bounds(ob, nullptr, lo, hi) && toAabb(lo, hi, staticPad(lo, hi), bounds);
  }
  if (!localBounds(ob, lo, hi)) return false;
  if (ob.has_transform == OBJECT_MOVING) return movingBounds(ob, bounds, nullptr, nullptr);
  if (!ob.has_transform) return toAabb(lo, hi, staticPad(lo, hi), bounds);
  // The device maps rays into object space with the float matrix; its inverse
  // in double, padded, bounds the shape that matrix describes.
  double m[12];
  if (!invert(ob.world_to_object, m)) return false;
  Box3 world;
  for (int a = 0; a < 3; ++a) {
    world.lo[a] = INFINITY;
    world.hi[a] = -INFINITY;
  }
  for (int corner = 0; corner < 8; ++corner) {
    double c[3] = {(corner & 1) ? hi[0] : lo[0], (corner & 2) ? hi[1] : lo[1], (corner & 4) ? hi[2] : lo[2]};
    for (int r = 0; r < 3; ++r) {
      double w = m[4 * r] * c[0] + m[4 * r + 1] * c[1] + m[4 * r + 2] * c[2] + m[4 * r + 3];
      world.lo[r] = std::min(world.lo[r], w);
      world.hi[r] = std::max(world.hi[r], w);
    }
  }
  return toAabb(world.lo, world.hi, floatPad(world), bounds);
}

namespace {

bool movingBounds(const ObjectGpu& ob, Aabb* swept, Aabb* open, Aabb* close) {
  double lo[3], hi[3];
  if (!localBounds(ob, lo, hi)) return false;
  Box3 s, a, b;
  movingBoxes(motionOf(ob), lo, hi, &s, &a, &b);
  const double pad = floatPad(s);  // the same pad at every instant
  return (!swept || toAabb(s.lo, s.hi, pad, swept)) && (!open || toAabb(a.lo, a.hi, pad, open)) &&
         (!close || toAabb(b.lo, b.hi, pad, close));
}

}  // namespace

bool objectLinearBounds(const ObjectGpu& ob, Aabb* open, Aabb* close) {
  if (ob.has_transform == OBJECT_MOVING) return movingBounds(ob, nullptr, open, close);
  if (!objectBounds(ob, open)) return false;
  *close = *open;
  return true;
}

namespace {

// The kinds bit of one primitive, as primitiveKernelOptions counts them.
unsigned kindBit(const ObjectGpu& ob) { return ob.type >= 0 && ob.type < 32 ? 1u << ob.type : 0u; }

}  // namespace

PrimitiveSet gatherPrimitives(const std::vector<ObjectGpu>& objects, int threads) {
  PrimitiveSet set;
  const std::size_t count = primitiveCount(objects);
  // Every static object's box and index at its own place in set.bounds and
  // set.bounded, on every thread in contiguous runs: the boxes are most of the
  // work, and the arrays' first writes cost page faults, which the threads
  // then share (uninitialised_vector.h). Moving objects are bounded below, in
  // order, as the arrays are closed up over the unbounded ones. Each run also
  // notes what that needs to know: whether all its objects are bounded and
  // static (and packet triangles), the union of their boxes, and their kinds
  // (for the kernels' build options).
  struct Run {
    bool plain = true;  // every object bounded and static
    bool triangles = true;  // every object a packet triangle
    Aabb scene;
    unsigned kinds = 0;
    bool any_moving = false;
  };
  set.bounds.resize(count);
  set.bounded.resize(count);
  UninitialisedVector<unsigned char> finite(count);  // whether bounds[i] holds a box
  ThreadBudget budget(threads);
  const std::size_t runs = runsFor(budget, count, kParallelBoundsPrims);
  std::vector<Run> run_of(runs);
  forEachRun(budget, runs, [&](std::size_t r) {
    const auto [first, end] = runRange(count, r, runs);
    Run run;  // filled here, not in run_of[r], whose neighbour another thread writes
    for (std::size_t i = first; i < end; ++i) {
      const ObjectGpu& ob = objects[i];
      set.bounded[i] = static_cast<std::int32_t>(i);
      run.kinds |= kindBit(ob);
      run.triangles = run.triangles && isPacketTriangle(ob);
      if (ob.has_transform == OBJECT_MOVING) {
        finite[i] = 0;
        run.plain = false;
        run.any_moving = true;
        continue;
      }
      finite[i] = objectBounds(ob, &set.bounds[i]);
      if (finite[i]) run.scene.extend(set.bounds[i]);
      run.plain = run.plain && finite[i];
    }
    run_of[r] = run;
  });
  for (const Run& run : run_of) {
    set.kinds |= run.kinds;
    set.any_moving = set.any_moving || run.any_moving;
  }
  if (std::all_of(run_of.begin(), run_of.end(), [](const Run& run) { return run.plain; })) {
    // Every object bounded and static (a mesh scene without planes): the
    // boxes as they are.
    set.triangles_only = std::all_of(run_of.begin(), run_of.end(), [](const Run& run) { return run.triangles; });
    for (const Run& run : run_of) set.scene.extend(run.scene);
    return set;
  }
  // Closed up in place: the kept-th bounded object's box and index move from
  // place i to place kept, kept <= i, so nothing is overwritten unread.
  std::size_t kept = 0;
  for (std::size_t i = 0; i < count; ++i) {
    const ObjectGpu& ob = objects[i];
    const bool moves = ob.has_transform == OBJECT_MOVING;
    Aabb b, open, close;
    if (moves ? movingBounds(ob, &b, &open, &close) : finite[i] != 0) {
      if (!moves) b = set.bounds[i];
      if (moves && !set.moving) {  // the first moving one: the static ones so far keep one box
        set.moving = true;
        set.shutter_open = motionOf(ob).shutter_open;
        set.shutter_close = motionOf(ob).shutter_close;
        set.bounds_open.assign(set.bounds.begin(), set.bounds.begin() + static_cast<std::ptrdiff_t>(kept));
        set.bounds_close = set.bounds_open;
      }
      set.bounded[kept] = static_cast<std::int32_t>(i);
      set.bounds[kept++] = b;
      set.scene.extend(b);
      if (set.moving) {
        set.bounds_open.push_back(moves ? open : b);
        set.bounds_close.push_back(moves ? close : b);
      }
    } else {
      set.unbounded.push_back(static_cast<std::int32_t>(i));
    }
  }
  set.bounds.resize(kept);
  set.bounded.resize(kept);
  return set;
}

std::size_t primitiveCount(const std::vector<ObjectGpu>& objects) {
  std::size_t n = 0;
  while (n < objects.size() && objects[n].type != OBJECT_MOTION && objects[n].type != OBJECT_DATA &&
         objects[n].type != OBJECT_MESH)
    ++n;
  return n;
}

std::string primitiveKernelOptions(const std::vector<ObjectGpu>& objects) {
  unsigned kinds = 0;
  bool moving = false;
  const std::size_t count = primitiveCount(objects);
  for (std::size_t i = 0; i < count; ++i) {
    kinds |= kindBit(objects[i]);
    moving = moving || objects[i].has_transform == OBJECT_MOVING;
  }
  return primitiveKernelOptions(kinds, moving);
}

std::string primitiveKernelOptions(unsigned kinds, bool moving) {
  kinds |= 1u << OBJECT_SPHERE | 1u << OBJECT_BOX | 1u << OBJECT_PLANE | 1u << OBJECT_TRIANGLE;
  std::string options = moving ? std::string(kMotionKernelOption) + " " : std::string();
  return options + "-DPRISM_KINDS=" + std::to_string(kinds);
}

}  // namespace prism
