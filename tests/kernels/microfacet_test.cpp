// Cook-Torrance's microfacet highlight (kernels/shading/microfacet.h), run on
// the device through a probe kernel: the distributions integrate to 1 over the
// hemisphere, the Fresnel factor meets the Fresnel equations' closed forms, the
// BRDF is reciprocal, and its directional albedo with F = 1 matches a
// double-precision quadrature and never exceeds 1.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <vector>

#include "support/reference_shading.h"
#include "support/shared_context.h"

using namespace prism;

namespace {

const char* kProbe = R"(
#include "shading/microfacet.h"
/* in: 8 floats a case (l xyz, v xyz, alpha, eta; n = +z) and its distribution;
 * out: D at the half vector, F at v.h, and cook_torrance. */
__kernel void microfacet_probe(__global const float* in, __global const int* dist, __global float* out, int count) {
  int k = get_global_id(0);
  if (k >= count) return;
  float3 n = (float3)(0.0f, 0.0f, 1.0f);
  float3 l = vload3(0, in + 8 * k), v = vload3(0, in + 8 * k + 3);
  float alpha = in[8 * k + 6], eta = in[8 * k + 7];
  float3 h = sb_normalize(l + v);
  out[3 * k] = microfacet_d(sb_dot(n, h), alpha, dist[k]);
  out[3 * k + 1] = fresnel_dielectric(sb_dot(v, h), eta);
  out[3 * k + 2] = cook_torrance(n, l, v, alpha, dist[k], eta);
}
)";

struct Case {
  Vec3 l, v;
  double alpha, eta;
  int distribution;  // MICROFACET_BECKMANN 0, MICROFACET_GGX 1
};

struct Out {
  double d, f, term;
};

std::vector<Out> probe(const std::vector<Case>& cases) {
  std::vector<float> in;
  std::vector<int> dist;
  for (const Case& c : cases) {
    for (double x : {c.l.x, c.l.y, c.l.z, c.v.x, c.v.y, c.v.z, c.alpha, c.eta}) in.push_back(static_cast<float>(x));
    dist.push_back(c.distribution);
  }
  Context& ctx = test::sharedContext();
  cl_kernel kernel = ctx.kernelFromText(kProbe, "microfacet_probe.cl", "microfacet_probe");
  Buffer in_buf(ctx, in.size() * sizeof(float)), dist_buf(ctx, dist.size() * sizeof(int)),
      out_buf(ctx, 3 * cases.size() * sizeof(float));
  in_buf.writeVector(in);
  dist_buf.writeVector(dist);
  const int count = static_cast<int>(cases.size());
  ctx.launch(kernel).arg(in_buf).arg(dist_buf).arg(out_buf).arg(count).run(cases.size());
  std::vector<float> raw = out_buf.readVector<float>(3 * cases.size());
  std::vector<Out> out;
  for (size_t k = 0; k < cases.size(); ++k) out.push_back({raw[3 * k], raw[3 * k + 1], raw[3 * k + 2]});
  return out;
}

Vec3 spherical(double theta, double phi) {
  return {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
}

}  // namespace

TEST_CASE("microfacet distributions integrate to 1 over the hemisphere", "[kernels][microfacet]") {
  // The integral of D(h) (n.h) dw_h; v is fixed at the normal, so h = normalize(l + v)
  // is probed by choosing l as the reflection of h about v.
  const int steps = 20000;
  for (int distribution : {0, 1}) {
    for (double alpha : {0.05, 0.2, 0.5, 1.0}) {
      std::vector<Case> cases;
      for (int i = 0; i < steps; ++i) {
        const double theta_h = (i + 0.5) * (M_PI / 2) / steps;
        const Vec3 h = spherical(theta_h, 0.3), v{0, 0, 1};
        cases.push_back({h * (2 * dot(v, h)) - v, v, alpha, 1.5, distribution});
      }
      std::vector<Out> out = probe(cases);
      double integral = 0;
      for (int i = 0; i < steps; ++i) {
        const double theta_h = (i + 0.5) * (M_PI / 2) / steps;
        integral += out[i].d * std::cos(theta_h) * std::sin(theta_h) * (M_PI / 2) / steps * 2 * M_PI;
      }
      INFO("distribution " << distribution << ", roughness " << alpha);
      CHECK(integral == Approx(1.0).epsilon(2e-3));
    }
  }
}

TEST_CASE("the Fresnel factor meets the Fresnel equations' closed forms", "[kernels][microfacet]") {
  // F is probed at v.h = cos_i by mirroring v about a chosen h.
  std::vector<Case> cases;
  std::vector<double> cos_i;
  const double etas[] = {1.5, 1.33, 2.4, 1 / 1.5};
  for (double eta : etas) {
    const double brewster = std::atan(eta);  // rp = 0 there
    for (double theta : {0.0, brewster, 1.2, 1.5, 1.5707}) {
      const Vec3 v = spherical(theta, 0.0), h{0, 0, 1};
      cases.push_back({h * (2 * dot(v, h)) - v, v, 0.3, eta, 0});
      cos_i.push_back(std::cos(theta));
    }
  }
  std::vector<Out> out = probe(cases);
  for (size_t k = 0; k < cases.size(); ++k) {
    const double eta = cases[k].eta, c = cos_i[k], s2 = 1 - c * c;
    INFO("eta " << eta << ", cos_i " << c);
    if (c == 1) {
      CHECK(out[k].f == Approx(std::pow((eta - 1) / (eta + 1), 2)).epsilon(1e-5));  // normal incidence
    } else if (s2 / (eta * eta) >= 1) {
      CHECK(out[k].f == 1.0);  // total internal reflection
    } else if (std::fabs(std::atan(std::sqrt(s2) / c) - std::atan(eta)) < 1e-9) {
      // Brewster's angle: only the s-polarised half reflects, rs = -cos(2 theta_i) ... as sin(i - t)/sin(i + t).
      const double ti = std::acos(c), tt = std::asin(std::sqrt(s2) / eta);
      const double rs = std::sin(ti - tt) / std::sin(ti + tt);
      CHECK(out[k].f == Approx(0.5 * rs * rs).epsilon(1e-4));
    } else {
      // Fresnel's sine and tangent laws, another form of the same equations.
      const double ti = std::acos(c), tt = std::asin(std::sqrt(s2) / eta);
      const double rs = std::sin(ti - tt) / std::sin(ti + tt), rp = std::tan(ti - tt) / std::tan(ti + tt);
      CHECK(out[k].f == Approx(0.5 * (rs * rs + rp * rp)).margin(1e-5));
    }
  }
}

TEST_CASE("the Cook-Torrance BRDF is reciprocal", "[kernels][microfacet]") {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<Case> cases;
  for (int k = 0; k < 4000; ++k) {
    const Vec3 l = spherical(std::acos(0.05 + 0.95 * u(rng)), 2 * M_PI * u(rng));
    const Vec3 v = spherical(std::acos(0.05 + 0.95 * u(rng)), 2 * M_PI * u(rng));
    const double alpha = 0.05 + 0.95 * u(rng), eta = 1.2 + u(rng);
    const int distribution = k % 2;
    cases.push_back({l, v, alpha, eta, distribution});
    cases.push_back({v, l, alpha, eta, distribution});
  }
  std::vector<Out> out = probe(cases);
  for (size_t k = 0; k < cases.size(); k += 2) {
    // term = pi f (n.l): f(l, v) = term / (pi n.l) must equal f(v, l) = term' / (pi n.v).
    const double f_lv = out[k].term / (M_PI * cases[k].l.z), f_vl = out[k + 1].term / (M_PI * cases[k].v.z);
    INFO("case " << k / 2);
    CHECK(f_lv == Approx(f_vl).epsilon(2e-4).margin(1e-6));
  }
}

TEST_CASE("the directional albedo matches a double-precision quadrature and stays at most 1",
          "[kernels][microfacet]") {
  // A(v) = integral of f (n.l) dw_l = (1 / pi) integral of the kernel's term, with
  // F = 1 (eta <= 0): what the microfacets reflect in all, which G may only lessen.
  const int nt = 400, np = 200;
  for (int distribution : {0, 1}) {
    for (double alpha : {0.1, 0.3, 0.7}) {
      for (double theta_v : {0.0, 0.6, 1.2, 1.45}) {
        const Vec3 v = spherical(theta_v, 0.0);
        std::vector<Case> cases;
        for (int i = 0; i < nt; ++i)
          for (int j = 0; j < np; ++j)
            cases.push_back({spherical((i + 0.5) * (M_PI / 2) / nt, (j + 0.5) * 2 * M_PI / np), v, alpha, -1, distribution});
        std::vector<Out> out = probe(cases);
        double kernel = 0, reference = 0;
        for (int i = 0; i < nt; ++i) {
          const double theta = (i + 0.5) * (M_PI / 2) / nt, dw = std::sin(theta) * (M_PI / 2) / nt * 2 * M_PI / np;
          for (int j = 0; j < np; ++j) {
            const size_t k = static_cast<size_t>(i) * np + j;
            kernel += out[k].term / M_PI * dw;
            reference += test::referenceCookTorrance({0, 0, 1}, cases[k].l, v, alpha, distribution, -1) / M_PI * dw;
          }
        }
        INFO("distribution " << distribution << ", roughness " << alpha << ", theta_v " << theta_v);
        CHECK(kernel == Approx(reference).epsilon(1e-3));
        CHECK(kernel <= 1.0 + 1e-3);
        if (alpha <= 0.1 && theta_v < 1) CHECK(kernel > 0.9);  // smooth: nearly all reflected
      }
    }
  }
}
