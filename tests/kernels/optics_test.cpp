// The reflected and refracted directions of kernels/shading/optics.h, run on the
// device through a probe kernel, against the law of reflection, Snell's law and
// the critical angle of total internal reflection.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "support/shared_context.h"

using namespace prism;

namespace {

const char* kProbe = R"(
#include "shading/optics.h"
__kernel void optics_probe(__global const float* in, __global float* out, int count) {
  int k = get_global_id(0);
  if (k >= count) return;
  float3 i = vload3(0, in + 7 * k), n = vload3(0, in + 7 * k + 3);
  float eta = in[7 * k + 6];
  float3 t = (float3)(0.0f);
  bool ok = refract_dir(i, n, eta, &t);
  vstore3(reflect_dir(i, n), 0, out + 7 * k);
  vstore3(t, 0, out + 7 * k + 3);
  out[7 * k + 6] = ok ? 1.0f : 0.0f;
}
)";

struct Case {
  Vec3 i, n;
  double eta;
};

}  // namespace

TEST_CASE("reflection and refraction directions obey the laws of optics", "[kernels][optics]") {
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> u(-1, 1);
  auto unit = [&] {
    for (;;) {
      Vec3 v{u(rng), u(rng), u(rng)};
      if (length(v) > 0.1 && length(v) < 1) return normalize(v);
    }
  };
  std::vector<Case> cases;
  const double etas[] = {1 / 1.5, 1.5, 1 / 1.33, 1.33, 2.4, 1.0};
  for (int k = 0; k < 6000; ++k) {
    Vec3 n = unit(), i = unit();
    if (dot(i, n) > 0) i = -i;  // incident against the normal
    if (dot(i, n) > -1e-3) continue;
    cases.push_back({i, n, etas[k % 6]});
  }
  std::vector<float> in;
  for (const Case& c : cases)
    for (double v : {c.i.x, c.i.y, c.i.z, c.n.x, c.n.y, c.n.z, c.eta}) in.push_back(static_cast<float>(v));

  Context& ctx = test::sharedContext();
  cl_kernel kernel = ctx.kernelFromText(kProbe, "optics_probe.cl", "optics_probe");
  Buffer in_buf(ctx, in.size() * sizeof(float)), out_buf(ctx, in.size() * sizeof(float));
  in_buf.writeVector(in);
  int count = static_cast<int>(cases.size());
  ctx.launch(kernel).arg(in_buf).arg(out_buf).arg(count).run(cases.size());
  std::vector<float> out = out_buf.readVector<float>(in.size());

  int refracted = 0, total_internal = 0;
  for (size_t k = 0; k < cases.size(); ++k) {
    // Recompute from the float inputs the kernel saw.
    Vec3 i{in[7 * k], in[7 * k + 1], in[7 * k + 2]}, n{in[7 * k + 3], in[7 * k + 4], in[7 * k + 5]};
    double eta = in[7 * k + 6];
    Vec3 r{out[7 * k], out[7 * k + 1], out[7 * k + 2]}, t{out[7 * k + 3], out[7 * k + 4], out[7 * k + 5]};
    bool ok = out[7 * k + 6] != 0;
    INFO("case " << k << " eta " << eta);

    // Reflection: the angle of reflection equals the angle of incidence, r lies in
    // the plane of i and n on the same side as the normal, and |r| = |i|.
    CHECK(std::fabs(dot(r, n) + dot(i, n)) < 1e-5);
    CHECK(std::fabs(dot(cross(i, n), r)) < 1e-5);
    CHECK(std::fabs(length(r) - 1) < 1e-5);

    // Refraction: total internal reflection exactly beyond the critical angle.
    double cos_i = -dot(i, n), sin_i = std::sqrt(std::max(0.0, 1 - cos_i * cos_i));
    double sin_t = eta * sin_i;
    if (std::fabs(sin_t - 1) < 1e-4) continue;  // at the critical angle: too close to call
    CHECK(ok == (sin_t < 1));
    if (!ok) {
      ++total_internal;
      continue;
    }
    ++refracted;
    // Snell: n1 sin(theta_i) = n2 sin(theta_t) with eta = n1 / n2; the refracted
    // ray is a unit vector on the far side of the surface, in the plane of
    // incidence, bent towards the same tangent direction as i.
    double cos_t = -dot(t, n);
    CHECK(std::fabs(length(t) - 1) < 1e-5);
    CHECK(cos_t > 0);
    CHECK(std::fabs(std::sqrt(std::max(0.0, 1 - cos_t * cos_t)) - sin_t) < 2e-4);
    CHECK(std::fabs(dot(cross(i, n), t)) < 1e-5);
    CHECK(dot(t - n * dot(t, n), i - n * dot(i, n)) >= -1e-6);
  }
  CHECK(refracted > 2000);
  CHECK(total_internal > 300);
}
