// Affine transforms (object to world) for scene objects: a 3x4 matrix whose last
// row (0 0 0 1) is implicit.
#pragma once

#include <string>

#include "scene/vec3.h"

namespace prism {

struct Transform {
  double m[3][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}};

  static Transform identity() { return {}; }
  static Transform translate(const Vec3& t);
  static Transform scale(const Vec3& s);
  // Rotation by `degrees` about `axis` (right-handed, counter-clockwise looking down the axis).
  static Transform rotate(const Vec3& axis, double degrees);

  bool isIdentity() const;
  // this ∘ other: applies `other` first.
  Transform operator*(const Transform& other) const;
  Vec3 applyPoint(const Vec3& p) const;
  Vec3 applyVector(const Vec3& v) const;
  // Determinant of the linear part; zero means the transform cannot be inverted.
  double determinant() const;
  Transform inverse() const;  // requires determinant() != 0
};

// Entries of an object's transform and of its inverse (which the kernels use)
// are at most this in magnitude, so both fit in single-precision floats.
constexpr double kMaxTransformEntry = 1e15;

// "" when `t` can place an object, else what is wrong with it, as the end of
// a sentence ("expected ..., got ..."). Shared by the scene loader (which adds
// the JSON path) and the C API (which adds the function and argument), so both
// give the same rule and the same message.
std::string transformProblem(const Transform& t);

}  // namespace prism
