// The glossy and translucent lobes of kernels/shading/material.h, run on the
// device through a probe kernel: sample_phong_lobe's directions against the
// density (n + 1) / (2 pi) cos^n around the axis (the distribution of cos^(n+1),
// the azimuth, both jointly, the mean), fold_to_side against the mirror image
// across the tangent plane, and material_reflect_dir / material_transmit_dir:
// never on the wrong side, and the folded lobe's mean elevation equal to its
// double-precision integral.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "kernels/shared/material_gpu.h"
#include "scene/vec3.h"
#include "support/shared_context.h"

using namespace prism;

namespace {

const char* kProbe = R"(
#include "common/math.h"
#include "shading/material.h"
/* 9 floats a case: v0 (3), v1 (3), u (2), s; mode 0: sample_phong_lobe(v0, s, u),
 * 1: fold_to_side(v0, v1, s), 2: material_reflect_dir(m, v0, v1, u),
 * 3: material_transmit_dir(m, v0, v1, u). */
__kernel void lobe_probe(int mode, __global const float* in, __global const MaterialGpu* m, __global float* out,
                         int count) {
  int k = get_global_id(0);
  if (k >= count) return;
  __global const float* c = in + 9 * k;
  float3 v0 = vload3(0, c), v1 = vload3(0, c + 3);
  float2 u = (float2)(c[6], c[7]);
  float s = c[8];
  float3 r;
  if (mode == 0) r = sample_phong_lobe(v0, s, u);
  else if (mode == 1) r = fold_to_side(v0, v1, s);
  else if (mode == 2) r = material_reflect_dir(m, v0, v1, u);
  else r = material_transmit_dir(m, v0, v1, u);
  vstore3(r, 0, out + 3 * k);
}
)";

struct Case {
  Vec3 v0, v1;
  float u0 = 0, u1 = 0, s = 0;
};

// The probe's outputs (3 floats a case) for `cases` in `mode`, with material `m`.
std::vector<Vec3> probe(int mode, const std::vector<Case>& cases, const MaterialGpu& m) {
  std::vector<float> in;
  for (const Case& c : cases)
    for (double v : {c.v0.x, c.v0.y, c.v0.z, c.v1.x, c.v1.y, c.v1.z, double(c.u0), double(c.u1), double(c.s)})
      in.push_back(static_cast<float>(v));
  Context& ctx = test::sharedContext();
  cl_kernel kernel = ctx.kernelFromText(kProbe, "lobe_probe.cl", "lobe_probe", "-DPRISM_LOBES");  // as for a scene with lobes
  Buffer in_buf(ctx, in.size() * sizeof(float)), out_buf(ctx, cases.size() * 3 * sizeof(float));
  Buffer m_buf(ctx, sizeof(MaterialGpu));
  in_buf.writeVector(in);
  m_buf.write(&m, sizeof m);
  ctx.launch(kernel).arg(static_cast<cl_int>(mode)).arg(in_buf).arg(m_buf).arg(out_buf)
      .arg(static_cast<cl_int>(cases.size())).run(cases.size());
  std::vector<float> out = out_buf.readVector<float>(cases.size() * 3);
  std::vector<Vec3> r(cases.size());
  for (size_t k = 0; k < cases.size(); ++k) r[k] = {out[3 * k], out[3 * k + 1], out[3 * k + 2]};
  return r;
}

// The float the probe sees for a case vector (so references use its input).
// Through volatile: GCC 12 at -O3 -frounding-math was seen to drop the plain
// double -> float -> double round trip here.
Vec3 asFloat(const Vec3& v) {
  volatile float f[3] = {float(v.x), float(v.y), float(v.z)};
  return {f[0], f[1], f[2]};
}

struct Rng {
  std::mt19937_64 gen;
  std::uniform_real_distribution<double> u{0, 1};
  explicit Rng(unsigned seed) : gen(seed) {}
  // In [0, 1) as a float.
  float unit() {
    float x = static_cast<float>(u(gen));
    return x < 1.0f ? x : 0x1.fffffep-1f;
  }
  Vec3 direction() {
    std::normal_distribution<double> g;
    for (;;) {
      Vec3 v{g(gen), g(gen), g(gen)};
      if (length(v) > 1e-3) return normalize(v);
    }
  }
};

// Two unit vectors completing unit `a` to an orthonormal frame (built here, in
// double, independently of the kernel's).
void frame(const Vec3& a, Vec3& t, Vec3& b) {
  Vec3 helper = std::fabs(a.x) < 0.6 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
  t = normalize(cross(helper, a));
  b = cross(a, t);
}

MaterialGpu material(float gloss, float translucency) {
  MaterialGpu m{};
  m.gloss = gloss;
  m.translucency = translucency;
  m.reflect = 1;
  m.transmit = 1;
  m.ior = 1;
  return m;
}

// Mean of |w . n| over the Phong lobe (n+1)/(2 pi) cos^e around an axis at angle
// theta from n: what a folded lobe's mean elevation must be. In double: w = c^(e+1)
// is uniform, c the cosine to the axis; the azimuth integral of
// |c cos(theta) + s cos(phi) sin(theta)| is closed-form.
double foldedMeanElevation(double e, double theta) {
  const int steps = 200000;
  double sum = 0;
  for (int k = 0; k < steps; ++k) {
    const double w = (k + 0.5) / steps;
    const double c = std::pow(w, 1.0 / (e + 1)), s = std::sqrt(std::max(0.0, 1 - c * c));
    const double A = c * std::cos(theta), B = s * std::sin(theta);
    double az;  // (1 / 2 pi) * integral over phi of |A + B cos(phi)|
    if (B <= std::fabs(A)) {
      az = std::fabs(A);
    } else {
      const double phi0 = std::acos(-A / B);
      az = (2 * A * (2 * phi0 - M_PI) + 4 * B * std::sin(phi0)) / (2 * M_PI);
    }
    sum += az;
  }
  return sum / steps;
}

}  // namespace

TEST_CASE("Phong lobe directions have the density (n+1)/(2 pi) cos^n around their axis", "[kernels][lobe]") {
  const int count = 40000;
  for (double e : {0.0, 1.0, 10.0, 100.0, 1e4}) {
    Rng rng(17 + static_cast<unsigned>(e));
    std::vector<Case> cases(count);
    for (Case& c : cases) {
      c.v0 = asFloat(rng.direction());
      // A few axes on the basis's seam (n.z near -1 and 0) among the random ones.
      if (&c - cases.data() < 200) c.v0 = asFloat(normalize(Vec3{0.01 * rng.unit(), 0.02, -1}));
      c.u0 = rng.unit();
      c.u1 = rng.unit();
      c.s = static_cast<float>(e);
    }
    std::vector<Vec3> d = probe(0, cases, material(0, 0));
    INFO("exponent " << e);

    // w = cos^(n+1) is uniform on [0, 1) and the azimuth uniform on [0, 2 pi),
    // independently: an 8 x 8 chi-square on (w, azimuth), a KS test on w, and
    // the mean cosine (n+1)/(n+2).
    const int bins = 8;
    std::vector<int> cells(bins * bins, 0);
    std::vector<double> ws;
    double sum_c = 0, worst_len = 0;
    int below = 0;
    for (int k = 0; k < count; ++k) {
      const Vec3 a = normalize(cases[k].v0);
      const double len = length(d[k]);
      worst_len = std::max(worst_len, std::fabs(len - 1));
      const Vec3 dn = d[k] / len;
      // 1 - cos from the chord, which keeps its digits for narrow lobes.
      const Vec3 chord = dn - a;
      const double c = 1 - dot(chord, chord) / 2;
      if (c < -1e-6) ++below;
      sum_c += c;
      const double w = std::clamp(std::pow(std::max(c, 0.0), e + 1), 0.0, 1.0);
      ws.push_back(w);
      Vec3 t, b;
      frame(a, t, b);
      double phi = std::atan2(dot(dn, b), dot(dn, t));
      if (phi < 0) phi += 2 * M_PI;
      const int iw = std::min(bins - 1, static_cast<int>(w * bins));
      const int ip = std::min(bins - 1, static_cast<int>(phi / (2 * M_PI) * bins));
      ++cells[iw * bins + ip];
    }
    CHECK(worst_len < 1e-5);
    CHECK(below == 0);
    double chi2 = 0;
    const double expected = double(count) / (bins * bins);
    for (int n : cells) chi2 += (n - expected) * (n - expected) / expected;
    // 63 degrees of freedom: mean 63, standard deviation 11.2.
    CHECK(chi2 < 63 + 5 * 11.2);
    std::sort(ws.begin(), ws.end());
    double ks = 0;
    for (int k = 0; k < count; ++k)
      ks = std::max({ks, std::fabs(ws[k] - double(k) / count), std::fabs(ws[k] - double(k + 1) / count)});
    CHECK(ks * std::sqrt(double(count)) < 1.95);  // 0.1% level
    const double mean_c = (e + 1) / (e + 2);
    const double var_c = (e + 1) / (e + 3) - mean_c * mean_c;
    CHECK(std::fabs(sum_c / count - mean_c) < 5 * std::sqrt(var_c / count) + 1e-6);
  }
}

TEST_CASE("fold_to_side mirrors a direction on the wrong side across the tangent plane and keeps the others",
          "[kernels][lobe]") {
  Rng rng(5);
  std::vector<Case> cases(20000);
  for (Case& c : cases) {
    c.v0 = asFloat(rng.direction());
    c.v1 = asFloat(rng.direction());
    c.s = rng.unit() < 0.5f ? 1.0f : -1.0f;
  }
  std::vector<Vec3> r = probe(1, cases, material(0, 0));
  int kept = 0, folded = 0;
  for (size_t k = 0; k < cases.size(); ++k) {
    const Vec3 d = cases[k].v0, n = cases[k].v1;
    const double side = cases[k].s;
    INFO("case " << k);
    const float dn = static_cast<float>(dot(d, n));
    if (dn * side > 0.02) {
      ++kept;
      CHECK(r[k] == d);
    } else if (dn * side < -0.02) {
      ++folded;
      // Same tangential part, normal part negated, on the side asked for.
      const Vec3 t_in = d - n * dot(d, n), t_out = r[k] - n * dot(r[k], n);
      CHECK(length(t_out - t_in) < 1e-5);
      CHECK(std::fabs(dot(r[k], n) + dot(d, n)) < 1e-5);
      CHECK(dot(r[k], n) * side > 0);
      CHECK(std::fabs(length(r[k]) - 1) < 1e-5);
    }
  }
  CHECK(kept > 8000);
  CHECK(folded > 8000);
}

TEST_CASE("glossy and translucent directions stay on their side with the folded lobe's mean elevation",
          "[kernels][lobe]") {
  const int count = 20000;
  for (double e : {1.0, 10.0, 100.0})
    for (double theta_deg : {0.0, 60.0, 85.0}) {
      const double theta = theta_deg * M_PI / 180;
      Rng rng(100 + static_cast<unsigned>(e * 7 + theta_deg));
      // Reflection: incident i at angle theta to nf's opposite; the mirror
      // direction is at angle theta from nf. Transmission (ior 1): the refracted
      // direction is i itself, at angle theta from -nf.
      std::vector<Case> reflect(count), transmit(count);
      for (int k = 0; k < count; ++k) {
        const Vec3 nf = rng.direction();
        Vec3 t, b;
        frame(nf, t, b);
        const double phi = 2 * M_PI * rng.unit();
        const Vec3 tangent = t * std::cos(phi) + b * std::sin(phi);
        const Vec3 i = asFloat(tangent * std::sin(theta) - nf * std::cos(theta));
        reflect[k].v0 = transmit[k].v0 = i;
        reflect[k].v1 = transmit[k].v1 = asFloat(nf);
        reflect[k].u0 = transmit[k].u0 = rng.unit();
        reflect[k].u1 = transmit[k].u1 = rng.unit();
      }
      const MaterialGpu m = material(static_cast<float>(e), static_cast<float>(e));
      std::vector<Vec3> r = probe(2, reflect, m), tr = probe(3, transmit, m);
      const double expected = foldedMeanElevation(e, theta);
      double sum_r = 0, sum_r2 = 0, sum_t = 0, sum_t2 = 0;
      int wrong_r = 0, wrong_t = 0;
      for (int k = 0; k < count; ++k) {
        const Vec3 n = reflect[k].v1;
        const double er = dot(r[k], n) / length(r[k]), et = -dot(tr[k], n) / length(tr[k]);
        if (er < 0) ++wrong_r;
        if (et < 0) ++wrong_t;
        sum_r += er;
        sum_r2 += er * er;
        sum_t += et;
        sum_t2 += et * et;
      }
      INFO("exponent " << e << ", incidence " << theta_deg << " degrees: expected mean elevation " << expected
                       << ", reflected " << sum_r / count << ", transmitted " << sum_t / count);
      CHECK(wrong_r == 0);
      CHECK(wrong_t == 0);
      const double sd_r = std::sqrt(std::max(0.0, sum_r2 / count - (sum_r / count) * (sum_r / count)) / count);
      const double sd_t = std::sqrt(std::max(0.0, sum_t2 / count - (sum_t / count) * (sum_t / count)) / count);
      CHECK(std::fabs(sum_r / count - expected) < 5 * sd_r + 1e-5);
      CHECK(std::fabs(sum_t / count - expected) < 5 * sd_t + 1e-5);
    }

  // Exponent 0: the ideal directions themselves.
  Rng rng(3);
  std::vector<Case> cases(1000);
  for (Case& c : cases) {
    c.v1 = asFloat(rng.direction());
    c.v0 = rng.direction();
    if (dot(c.v0, c.v1) > 0) c.v0 = -c.v0;
    c.v0 = asFloat(c.v0);
    c.u0 = rng.unit();
    c.u1 = rng.unit();
  }
  std::vector<Vec3> mirror = probe(2, cases, material(0, 0)), straight = probe(3, cases, material(0, 0));
  for (size_t k = 0; k < cases.size(); ++k) {
    const Vec3 i = cases[k].v0, n = cases[k].v1;
    CHECK(length(mirror[k] - (i - n * (2 * dot(i, n)))) < 1e-5);
    CHECK(straight[k] == i);
  }
}
