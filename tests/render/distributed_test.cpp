// Distributed (Cook) ray tracing through the whole renderer, each property fixed
// independently of the kernels: the penumbra of a quad light behind a straight
// edge against a double-precision integral of the visible part of the light;
// a light's samples spread over a pixel without changing its mean; the thin
// lens's circle of confusion from its second moment; a plane in focus rendering
// as through a pinhole; glossy and translucent lobes that neither lose nor gain
// energy; a reflected checker blurring monotonically with the gloss exponent;
// N^-1/2 convergence, stratified ahead of independent samples; bit-for-bit
// repeatability; the first-hit mode each camera gets; area lights seen directly
// and in a mirror.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "render/renderer.h"
#include "scene_format/scene_loader.h"
#include "support/reference_geometry.h"
#include "support/shared_context.h"

using namespace prism;
using namespace prism::test;

namespace {

RenderResult render(const Scene& scene, const RenderOptions& options) { return sharedRenderer().render(scene, options); }

// A number as JSON, all its digits.
std::string num(double x) {
  char text[40];
  std::snprintf(text, sizeof text, "%.17g", x);
  return text;
}

std::string vec(double x, double y, double z) { return "[" + num(x) + ", " + num(y) + ", " + num(z) + "]"; }

double red(const RenderResult& r, int i, int j) { return r.rgba[4 * (static_cast<size_t>(j) * r.width + i)]; }
double alphaOf(const RenderResult& r, int i, int j) { return r.rgba[4 * (static_cast<size_t>(j) * r.width + i) + 3]; }
Vec3 rgb(const RenderResult& r, int i, int j) {
  const float* p = &r.rgba[4 * (static_cast<size_t>(j) * r.width + i)];
  return {p[0], p[1], p[2]};
}

bool sameBits(const std::vector<float>& a, const std::vector<float>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

RenderOptions optionsFor(const Scene& scene, int spp, AaMode mode, std::uint64_t seed = 0) {
  RenderOptions o = RenderOptions::fromScene(scene);
  o.spp = spp;
  o.aa = mode;
  o.seed = seed;
  return o;
}

// Gauss-Legendre nodes and weights on [0, 1].
struct Gauss {
  std::vector<double> x, w;
};
Gauss gauss(int n) {
  Gauss g;
  for (int i = 0; i < n; ++i) {
    double z = std::cos(M_PI * (i + 0.75) / (n + 0.5)), dp = 0;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1, p1 = z;
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2 * k - 1) * z * p1 - (k - 1) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      dp = n * (z * p1 - p0) / (z * z - 1);
      const double dz = p1 / dp;
      z -= dz;
      if (std::fabs(dz) < 1e-16) break;
    }
    g.x.push_back((1 - z) / 2);
    g.w.push_back(1 / ((1 - z * z) * dp * dp));  // 2 / ((1 - z^2) P'^2), halved for [0, 1]
  }
  return g;
}

// Integral of f over [a, b] by the rule g.
double integrate(const Gauss& g, double a, double b, const std::function<double(double)>& f) {
  double s = 0;
  for (size_t k = 0; k < g.x.size(); ++k) s += g.w[k] * f(a + (b - a) * g.x[k]);
  return s * (b - a);
}

double logLogSlope(const std::vector<int>& n, const std::vector<double>& e) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  const double m = static_cast<double>(n.size());
  for (size_t k = 0; k < n.size(); ++k) {
    const double x = std::log(double(n[k])), y = std::log(e[k]);
    sx += x;
    sy += y;
    sxx += x * x;
    sxy += x * y;
  }
  return (m * sxy - sx * sy) / (m * sxx - sx * sx);
}

// Mean squared difference of the rgb channels of two images.
double mse(const std::vector<float>& a, const std::vector<float>& b) {
  double s = 0;
  size_t n = 0;
  for (size_t k = 0; k < a.size(); ++k) {
    if (k % 4 == 3) continue;
    const double d = double(a[k]) - b[k];
    s += d * d;
    ++n;
  }
  return s / n;
}

// ---------------------------------------------------------------------------
// The penumbra scene: a square quad light of side a, centred at (cx, H, 0),
// facing down; a white diffuse floor y = 0 (diffuse 1, ambient 0, no specular);
// an opaque triangle in the plane y = h covering x >= e near z = 0 (its edge is
// the line x = e); a camera at height cam_h between floor and occluder looking
// straight down, right = +x and up = -z, so film coordinates map linearly onto
// the floor.
struct Penumbra {
  double a = 1, H = 4, h = 2, e = 0.1, cx = 0.3, L = 2.5;
  double cam_x = -0.1, cam_h = 1, half_x = 0.9;  // the floor x the film spans: cam_x -+ half_x
  int W = 64, Hpx = 4;

  double tanHalf() const { return half_x / cam_h / (double(W) / Hpx); }
  double fovDegrees() const { return 2 * std::atan(tanHalf()) * 180 / M_PI; }
  // The host's own arithmetic for the vertical half-angle (scene/gpu_scene.cpp).
  double tanHalfAsRendered() const { return std::tan(fovDegrees() * M_PI / 360.0); }
  // Geometry (similar triangles): floor points x <= lit() see the whole light,
  // x >= dark() none of it; the ramp between is a h / (H - h) wide.
  double lit() const { return (e * H - (cx + a / 2) * h) / (H - h); }
  double dark() const { return (e * H - (cx - a / 2) * h) / (H - h); }

  std::string json(int spp, int samples, bool occluder) const {
    std::string s = R"({
      "camera": {"position": )" + vec(cam_x, cam_h, 0) + R"(, "look_at": )" + vec(cam_x, 0, 0) +
                    R"(, "up": [0, 0, -1], "fov": )" + num(fovDegrees()) + R"(},
      "film": {"width": )" + std::to_string(W) + R"(, "height": )" + std::to_string(Hpx) +
                    R"(, "spp": )" + std::to_string(spp) + R"(},
      "render": {"max_depth": 0, "ambient": [0, 0, 0], "background": [0, 0, 0]},
      "materials": {"floor": {"diffuse": 1, "ambient": 0, "specular": 0},
                    "blocker": {"diffuse": 0.5, "ambient": 0, "specular": 0}},
      "lights": [{"type": "quad", "corner": )" + vec(cx - a / 2, H, -a / 2) + R"(, "edge1": )" + vec(a, 0, 0) +
                    R"(, "edge2": )" + vec(0, 0, a) + R"(, "intensity": )" + num(L) +
                    R"(, "samples": )" + std::to_string(samples) + R"(}],
      "objects": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "floor"})";
    if (occluder)
      s += R"(, {"type": "triangle", "material": "blocker", "vertices": [)" + vec(e, h, -60) + ", " +
           vec(e, h, 60) + ", " + vec(e + 120, h, 0) + "]}";
    return s + "]}";
  }

  // Floor x and z ranges of pixel (i, j).
  void footprint(int i, int j, double& x0, double& x1, double& z0, double& z1) const {
    const double t = tanHalfAsRendered() * cam_h, aspect = double(W) / Hpx;
    x0 = cam_x + (2.0 * i / W - 1) * t * aspect;
    x1 = cam_x + (2.0 * (i + 1) / W - 1) * t * aspect;
    z0 = -(1 - 2.0 * j / Hpx) * t;  // up is -z
    z1 = -(1 - 2.0 * (j + 1) / Hpx) * t;
  }

  // Shading points sit this far above the floor (surface_epsilon in
  // kernels/common/math.h); the reference integrates from there.
  double lift = 1e-4;

  // The light's x below which a light point is seen from floor point x past the
  // edge (the line from the shading point through the edge x = e at height h).
  double visibleUpTo(double px, bool occluder) const {
    return occluder ? px + (e - px) * (H - lift) / (h - lift) : 1e300;
  }

  // For one floor point: the radiance g1 = L/pi * integral over the visible light
  // of cos cos / r^2 dA, and the second moment g2 of the one-feeler estimator
  // L A cos cos / (pi r^2) V with the light point uniform on the quad.
  void point(double px, double pz, bool occluder, const Gauss& g, double& g1, double& g2) const {
    const double A = a * a, lo = cx - a / 2, hi = std::min(cx + a / 2, visibleUpTo(px, occluder));
    g1 = g2 = 0;
    if (hi <= lo) return;
    const double dy = H - lift, k = L * dy * dy / M_PI;
    g1 = integrate(g, lo, hi, [&](double yx) {
      return integrate(g, -a / 2, a / 2, [&](double yz) {
        const double r2 = (yx - px) * (yx - px) + dy * dy + (yz - pz) * (yz - pz);
        return k / (r2 * r2);
      });
    });
    g2 = A * integrate(g, lo, hi, [&](double yx) {
      return integrate(g, -a / 2, a / 2, [&](double yz) {
        const double r2 = (yx - px) * (yx - px) + dy * dy + (yz - pz) * (yz - pz);
        return (k / (r2 * r2)) * (k / (r2 * r2));
      });
    });
  }

  struct Pixel {
    double mean = 0;     // expected pixel value
    double sigma2 = 0;   // variance of the pixel under independent samples
  };
  // Pixel (i, j) with spp film samples uniform over it, each with `per_hit`
  // feelers: the mean and the variance an independent-sample estimator has
  // (stratified sampling can only do better).
  Pixel pixel(int i, int j, bool occluder, int spp, int per_hit) const {
    static const Gauss g = gauss(10);
    static const Gauss gp = gauss(6);
    double x0, x1, z0, z1;
    footprint(i, j, x0, x1, z0, z1);
    // Split the pixel's x range where the integrand has kinks (ramp ends, for
    // the lifted shading point).
    const double k_lit = (e * (H - lift) - (cx + a / 2) * (h - lift)) / (H - h);
    const double k_dark = (e * (H - lift) - (cx - a / 2) * (h - lift)) / (H - h);
    std::vector<double> cuts = {x0};
    for (double c : {k_lit, k_dark})
      if (occluder && c > x0 && c < x1) cuts.push_back(c);
    cuts.push_back(x1);
    double m1 = 0, m11 = 0, m2 = 0;  // E[g1], E[g1^2], E[g2] over the footprint
    const double area = (x1 - x0) * (z1 - z0);
    for (size_t c = 0; c + 1 < cuts.size(); ++c)
      for (size_t u = 0; u < gp.x.size(); ++u)
        for (size_t v = 0; v < gp.x.size(); ++v) {
          const double px = cuts[c] + (cuts[c + 1] - cuts[c]) * gp.x[u], pz = z0 + (z1 - z0) * gp.x[v];
          const double w = gp.w[u] * gp.w[v] * (cuts[c + 1] - cuts[c]) * (z1 - z0) / area;
          double g1, g2;
          point(px, pz, occluder, g, g1, g2);
          m1 += w * g1;
          m11 += w * g1 * g1;
          m2 += w * g2;
        }
    Pixel p;
    p.mean = m1;
    p.sigma2 = std::max(0.0, m11 - m1 * m1) / spp + std::max(0.0, m2 - m11) / (double(spp) * per_hit);
    return p;
  }
};

// Checks a penumbra render against the integral, pixel by pixel.
void checkPenumbra(const Penumbra& pen, int spp, int samples) {
  const int per_hit = std::max(1, (samples + spp - 1) / spp);
  Scene with = parseScene(pen.json(spp, samples, true), "penumbra.json");
  Scene without = parseScene(pen.json(spp, samples, false), "unoccluded.json");
  RenderOptions opt = optionsFor(with, spp, AaMode::Jitter, 3);
  RenderResult r = render(with, opt), u = render(without, opt);
  const double w = pen.lit() - pen.dark();
  const double width = std::fabs(w), margin = 0.1 * width;
  INFO("spp " << spp << ", light samples " << samples << " (" << per_hit << " a hit); ramp ["
              << pen.lit() << ", " << pen.dark() << "], width " << width << " = a h / (H - h) = "
              << pen.a * pen.h / (pen.H - pen.h));
  REQUIRE(std::fabs(width - pen.a * pen.h / (pen.H - pen.h)) < 1e-12);

  // Per pixel, counted so that a wrong renderer reports once with its first case.
  int lit = 0, dark = 0, inside = 0, compared = 0;
  int lit_differs = 0, dark_lit = 0, inside_wrong = 0, off = 0, open_off = 0;
  std::string first_lit, first_dark, first_inside, first_off, first_open;
  double z2 = 0, worst = 0;
  std::ostringstream row;
  for (int j = 0; j < pen.Hpx; ++j)
    for (int i = 0; i < pen.W; ++i) {
      double x0, x1, z0, z1;
      pen.footprint(i, j, x0, x1, z0, z1);
      const double v = red(r, i, j), v_open = red(u, i, j);
      const Penumbra::Pixel ref = pen.pixel(i, j, true, spp, per_hit);
      const Penumbra::Pixel open = pen.pixel(i, j, false, spp, per_hit);
      const double sigma = std::sqrt(ref.sigma2);
      std::ostringstream what;
      what << "pixel (" << i << ", " << j << "), floor x in [" << x0 << ", " << x1 << "]: " << v << ", unoccluded "
           << v_open << "; expected " << ref.mean << " +- " << sigma << ", unoccluded " << open.mean << " +- "
           << std::sqrt(open.sigma2) << "; light fraction " << v / v_open << ", expected " << ref.mean / open.mean;
      auto note = [&](int& count, std::string& first) {
        if (count++ == 0) first = what.str();
      };
      // Where geometry puts the ramp: identical to the unoccluded render before
      // it, black past it, strictly between inside it.
      if (x1 <= pen.lit()) {
        ++lit;
        if (v != v_open) note(lit_differs, first_lit);
      } else if (x0 >= pen.dark()) {
        ++dark;
        if (v != 0) note(dark_lit, first_dark);
      } else if (x0 >= pen.lit() + margin && x1 <= pen.dark() - margin) {
        ++inside;
        if (!(v > 0 && v < v_open)) note(inside_wrong, first_inside);
      }
      // The value against the integral, within 5 sigma of the estimator.
      if (!(std::fabs(v - ref.mean) <= 5 * sigma + 1e-5 * open.mean)) note(off, first_off);
      if (!(std::fabs(v_open - open.mean) <= 5 * std::sqrt(open.sigma2) + 1e-5 * open.mean))
        note(open_off, first_open);
      if (sigma > 0) {
        const double z = (v - ref.mean) / sigma;
        z2 += z * z;
        worst = std::max(worst, std::fabs(z));
        ++compared;
      }
      if (j == 0 && i % 4 == 0) row << " " << v / v_open << "/" << ref.mean / open.mean;
    }
  // The ramp's half-light point along the row (fractions averaged over the
  // rows, interpolated between pixel centres), rendered and integrated.
  auto halfPoint = [&](const std::function<double(int, int)>& fraction) {
    std::vector<double> f(pen.W, 0.0);
    for (int i = 0; i < pen.W; ++i) {
      for (int j = 0; j < pen.Hpx; ++j) f[i] += fraction(i, j) / pen.Hpx;
    }
    for (int i = 0; i + 1 < pen.W; ++i)
      if (f[i] >= 0.5 && f[i + 1] < 0.5) {
        double x0, x1, z0, z1, y0, y1;
        pen.footprint(i, 0, x0, x1, z0, z1);
        pen.footprint(i + 1, 0, y0, y1, z0, z1);
        const double c0 = (x0 + x1) / 2, c1 = (y0 + y1) / 2;
        return c0 + (c1 - c0) * (f[i] - 0.5) / (f[i] - f[i + 1]);
      }
    return 1e30;
  };
  const double half_rendered = halfPoint([&](int i, int j) { return red(r, i, j) / red(u, i, j); });
  const double half_expected = halfPoint([&](int i, int j) {
    return pen.pixel(i, j, true, spp, per_hit).mean / pen.pixel(i, j, false, spp, per_hit).mean;
  });
  const double centre = (pen.e * pen.H - pen.cx * pen.h) / (pen.H - pen.h), step = 2 * pen.half_x / pen.W;
  INFO("half light at x = " << half_rendered << ", integral " << half_expected << ", geometric centre "
                            << centre << " (pixel footprint " << step << ")");
  CHECK(std::fabs(half_rendered - half_expected) < step / 4);
  // The half-light point of the cos-weighted fraction lies near the ramp's
  // geometric centre (lit + dark) / 2.
  CHECK(std::fabs(centre - (pen.lit() + pen.dark()) / 2) < 1e-12);
  CHECK(std::fabs(half_expected - centre) < 0.05 * width);
  INFO("row 0, light fraction rendered/expected:" << row.str());
  INFO("rms z " << std::sqrt(z2 / compared) << ", worst " << worst << " over " << compared << " pixels");
  CHECK(lit >= 4 * pen.Hpx);
  CHECK(dark >= 4 * pen.Hpx);
  CHECK(inside >= 20 * pen.Hpx);
  {
    INFO("before the ramp but not the unoccluded value: " << first_lit);
    CHECK(lit_differs == 0);
  }
  {
    INFO("past the ramp but not black: " << first_dark);
    CHECK(dark_lit == 0);
  }
  {
    INFO("inside the ramp but not strictly between black and unoccluded: " << first_inside);
    CHECK(inside_wrong == 0);
  }
  {
    INFO("off the integral by more than 5 sigma: " << first_off);
    CHECK(off == 0);
  }
  {
    INFO("unoccluded, off the integral by more than 5 sigma: " << first_open);
    CHECK(open_off == 0);
  }
  // Independent samples give rms z of 1; stratified ones less.
  CHECK(std::sqrt(z2 / compared) < 1.5);
}

}  // namespace

TEST_CASE("a quad light's penumbra behind a straight edge has the width and light fraction geometry gives",
          "[render][distributed][area_light]") {
  Penumbra pen;
  SECTION("one feeler a hit") { checkPenumbra(pen, 64, 64); }
  SECTION("a light's samples spread over the pixel's samples") { checkPenumbra(pen, 16, 256); }
}

TEST_CASE("a light's samples spread over a pixel's samples refine its mean without changing it",
          "[render][distributed][area_light]") {
  // The unoccluded floor under the quad light: the pixel mean is the integral
  // (Penumbra::pixel) whatever the split of samples between pixel and light.
  Penumbra pen;
  pen.W = 16;
  pen.Hpx = 4;
  struct Split {
    int spp, samples;
    AaMode mode;
  };
  for (Split s : {Split{16, 16, AaMode::Jitter}, Split{1, 16, AaMode::None}, Split{4, 64, AaMode::Jitter},
                  Split{16, 1, AaMode::Jitter}}) {
    Scene scene = parseScene(pen.json(s.spp, s.samples, false), "floor.json");
    RenderOptions opt = optionsFor(scene, s.spp, s.mode, 9);
    RenderResult r = render(scene, opt);
    const int per_hit = std::max(1, (s.samples + s.spp - 1) / s.spp);
    double sum = 0, ref = 0, var = 0;
    for (int j = 0; j < pen.Hpx; ++j)
      for (int i = 0; i < pen.W; ++i) {
        const Penumbra::Pixel p = pen.pixel(i, j, false, s.spp, per_hit);
        sum += red(r, i, j);
        ref += p.mean;
        var += p.sigma2;
      }
    const int n = pen.W * pen.Hpx;
    INFO("spp " << s.spp << ", light samples " << s.samples << " (" << per_hit << " feelers a hit): image mean "
                << sum / n << ", expected " << ref / n << " (ratio " << sum / ref << ")");
    CHECK(std::fabs(sum - ref) / n <= 5 * std::sqrt(var) / n + 1e-5 * ref / n);
  }
}

TEST_CASE("disk and sphere lights bring their closed-form irradiance to a white floor",
          "[render][distributed][area_light]") {
  // A narrow camera sees a patch of floor a few thousandths wide right under the
  // light: every pixel estimates the same point's radiance, L times the form
  // factor: R^2 / (H^2 + R^2) for a parallel disk of radius R at height H on the
  // axis, (R / d)^2 for a sphere of radius R whose centre is d straight above.
  // Heights are from the shading point, 1e-4 above the floor (surface_epsilon).
  struct Case {
    std::string light;
    double expected;
  };
  const double L = 1.5, H = 2 - 1e-4;
  for (const Case& c : {Case{R"({"type": "disk", "center": [0, 2, 0], "normal": [0, -1, 0], "radius": 0.7,
                                 "intensity": 1.5})",
                             L * 0.49 / (H * H + 0.49)},
                        Case{R"({"type": "disk", "center": [0, 2, 0], "normal": [0, 1, 0], "radius": 0.7,
                                 "intensity": 1.5})",
                             L * 0.49 / (H * H + 0.49)},  // both faces emit
                        Case{R"({"type": "sphere", "center": [0, 2, 0], "radius": 0.5, "intensity": 1.5})",
                             L * 0.25 / (H * H)}}) {
    Scene scene = parseScene(R"({"camera": {"position": [0, 1, 0], "look_at": [0, 0, 0], "up": [0, 0, -1],
          "fov": 0.5},
        "film": {"width": 32, "height": 32},
        "render": {"max_depth": 0, "ambient": [0, 0, 0]},
        "materials": {"floor": {"diffuse": 1, "ambient": 0, "specular": 0}},
        "lights": [)" + c.light + R"(],
        "objects": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "floor"}]})",
                             "irradiance.json");
    for (AaMode mode : {AaMode::Jitter, AaMode::Random}) {
      RenderResult r = render(scene, optionsFor(scene, 16, mode, 21));
      double sum = 0, sum2 = 0;
      const int n = r.width * r.height;
      for (int j = 0; j < r.height; ++j)
        for (int i = 0; i < r.width; ++i) {
          sum += red(r, i, j);
          sum2 += red(r, i, j) * red(r, i, j);
        }
      const double mean = sum / n, sd = std::sqrt(std::max(0.0, sum2 / n - mean * mean) / n);
      INFO(c.light << (mode == AaMode::Jitter ? " jitter" : " random") << ": mean " << mean << " +- " << sd
                   << ", expected " << c.expected);
      CHECK(std::fabs(mean - c.expected) < 5 * sd + 2e-5 * c.expected);
    }
  }
}

// ---------------------------------------------------------------------------
// Depth of field.

namespace {

// A small sphere light on the axis at depth D, seen through a thin lens of
// radius A focused at F, nothing else: camera at the origin looking down -z.
struct Defocus {
  double D, r, F, A;
  int size = 64, spp = 64;
  double fov = 30;

  std::string json(double aperture) const {
    return R"({"camera": {"position": [0, 0, 0], "look_at": [0, 0, -1], "fov": )" + num(fov) +
           R"(, "aperture": )" + num(aperture) + R"(, "focus_distance": )" + num(F) + R"(},
      "film": {"width": )" + std::to_string(size) + R"(, "height": )" + std::to_string(size) + R"(},
      "render": {"max_depth": 0, "ambient": [0, 0, 0], "background": [0, 0, 0]},
      "lights": [{"type": "sphere", "center": )" + vec(0, 0, -D) + R"(, "radius": )" + num(r) +
           R"(, "intensity": 1}],
      "objects": [{"type": "sphere", "center": [0, 0, 500], "radius": 1}]})";
  }
  double pixelsPerUnitAtF() const { return (size / 2.0) / (F * std::tan(fov * M_PI / 360)); }
  // The circle of confusion: a point at depth D images on the plane in focus to
  // a disc of radius A |D - F| / D.
  double blurRadius() const { return A * std::fabs(D - F) / D * pixelsPerUnitAtF(); }
  // The sphere's own image through a pinhole: tan of its angular radius.
  double sphereRadius() const { return r / std::sqrt(D * D - r * r) * F * pixelsPerUnitAtF(); }
};

struct Moments {
  double m0 = 0, cx = 0, cy = 0, m2 = 0;
};
Moments moments(const RenderResult& r) {
  Moments m;
  for (int j = 0; j < r.height; ++j)
    for (int i = 0; i < r.width; ++i) {
      const double v = red(r, i, j);
      m.m0 += v;
      m.cx += v * (i + 0.5);
      m.cy += v * (j + 0.5);
    }
  m.cx /= m.m0;
  m.cy /= m.m0;
  for (int j = 0; j < r.height; ++j)
    for (int i = 0; i < r.width; ++i) {
      const double dx = i + 0.5 - m.cx, dy = j + 0.5 - m.cy;
      m.m2 += red(r, i, j) * (dx * dx + dy * dy);
    }
  m.m2 /= m.m0;
  return m;
}

}  // namespace

TEST_CASE("a point off the plane in focus blurs to the thin lens's circle of confusion",
          "[render][distributed][dof]") {
  // Nearer (D < F) and farther (D > F) than the plane in focus.
  for (Defocus d : {Defocus{5, 0.125, 10, 1}, Defocus{20, 0.33, 10, 1}}) {
    d.spp = 128;
    Scene lens = parseScene(d.json(d.A), "defocus.json"), pinhole = parseScene(d.json(0), "pinhole.json");
    RenderOptions opt = optionsFor(lens, d.spp, AaMode::Jitter, 5);
    const Moments ml = moments(render(lens, opt)), mp = moments(render(pinhole, opt));
    // The image is the sphere's disc (radius Rs) convolved with the circle of
    // confusion (radius Rb): second moments add, R^2 / 2 for a uniform disc, and
    // grouping into pixels adds 1/12 per axis (Sheppard).
    const double rb = d.blurRadius(), rs = d.sphereRadius();
    const double measured = std::sqrt(2 * (ml.m2 - 1.0 / 6) - rs * rs);
    const double pin_rs = std::sqrt(2 * (mp.m2 - 1.0 / 6));
    INFO("depth " << d.D << ", focus " << d.F << ", lens radius " << d.A << ": blur radius " << measured
                  << " px, expected " << rb << "; sphere radius through the pinhole " << pin_rs << " px, expected "
                  << rs << "; light " << ml.m0 << " with the lens, " << mp.m0 << " without, expected "
                  << M_PI * rs * rs << "; centroid (" << ml.cx << ", " << ml.cy << ")");
    CHECK(std::fabs(measured / rb - 1) < 0.03);
    CHECK(std::fabs(pin_rs / rs - 1) < 0.05);
    // The lens moves light around, it does not add or remove any.
    CHECK(std::fabs(ml.m0 / mp.m0 - 1) < 0.03);
    CHECK(std::fabs(mp.m0 / (M_PI * rs * rs) - 1) < 0.03);
    // On the axis: centred on the image centre.
    CHECK(std::fabs(ml.cx - d.size / 2.0) < 0.3);
    CHECK(std::fabs(ml.cy - d.size / 2.0) < 0.3);
  }
}

TEST_CASE("a plane in focus renders as through a pinhole, one out of focus does not", "[render][distributed][dof]") {
  auto json = [](double depth, double aperture) {
    return R"({"camera": {"position": [0, 0, 0], "look_at": [0, 0, -1], "fov": 40, "aperture": )" + num(aperture) +
           R"(, "focus_distance": 10},
      "film": {"width": 48, "height": 40},
      "render": {"max_depth": 0, "ambient": [1, 1, 1]},
      "materials": {"chart": {"ambient": 1, "diffuse": 0, "specular": 0,
                              "texture": {"type": "checker", "color1": 0.9, "color2": 0.1, "scale": 0.4}}},
      "objects": [{"type": "plane", "point": )" +
           vec(0, 0, -depth) + R"(, "normal": [0, 0, 1], "material": "chart"}]})";
  };
  Scene focused = parseScene(json(10, 0.8), "focused.json"), pin = parseScene(json(10, 0), "pinhole.json");
  RenderOptions opt = optionsFor(focused, 4, AaMode::Jitter, 2);
  RenderResult a = render(focused, opt), b = render(pin, opt);
  CHECK(a.stats.first_hit == FirstHitMode::Trace);
  const size_t pixels = static_cast<size_t>(opt.width) * opt.height;
  size_t same = 0;
  double worst = 0;
  for (size_t p = 0; p < pixels; ++p) {
    const double diff = std::fabs(double(a.rgba[4 * p]) - b.rgba[4 * p]);
    worst = std::max(worst, diff);
    if (diff <= 1e-5) ++same;
  }
  INFO(same << " of " << pixels << " pixels within 1e-5 of the pinhole's, worst " << worst);
  // A sample may land on the other side of a checker edge by float rounding.
  CHECK(same >= pixels * 995 / 1000);
  CHECK(worst <= 0.8 / 4 + 1e-5);  // at most one sample of four flips

  // The same plane farther away, out of focus: blurred, unlike the pinhole's.
  Scene far_lens = parseScene(json(14, 0.8), "far.json"), far_pin = parseScene(json(14, 0), "far_pinhole.json");
  RenderResult c = render(far_lens, opt), e = render(far_pin, opt);
  size_t differ = 0;
  for (size_t p = 0; p < pixels; ++p)
    if (std::fabs(double(c.rgba[4 * p]) - e.rgba[4 * p]) > 0.05) ++differ;
  INFO(differ << " pixels of the out-of-focus plane differ by more than 0.05");
  CHECK(differ > pixels / 4);
}

// ---------------------------------------------------------------------------
// Glossy and translucent lobes under a uniform background.

namespace {

std::string uniformSky(const std::string& material, const std::string& objects, const std::string& camera) {
  return R"({"camera": )" + camera + R"(,
    "film": {"width": 40, "height": 32},
    "render": {"max_depth": 4, "min_weight": 0.001, "ambient": [1, 1, 1], "background": [0.3, 0.5, 0.7]},
    "materials": {"m": )" + material + R"(},
    "objects": )" + objects + "}";
}

// Every pixel is coverage * (k * background) + (1 - coverage) * background:
// each sample on the object brings exactly k times the background.
void checkUniform(const Scene& scene, double k, int& covered) {
  RenderOptions opt = optionsFor(scene, 9, AaMode::Jitter, 4);
  RenderResult r = render(scene, opt);
  const Vec3 b = scene.render.background;
  covered = 0;
  double worst = 0;
  for (int j = 0; j < opt.height; ++j)
    for (int i = 0; i < opt.width; ++i) {
      const double a = alphaOf(r, i, j);
      if (a == 1) ++covered;
      const Vec3 expected = b * (a * k + (1 - a));
      const Vec3 v = rgb(r, i, j);
      worst = std::max({worst, std::fabs(v.x - expected.x), std::fabs(v.y - expected.y), std::fabs(v.z - expected.z)});
    }
  INFO("worst difference from coverage * k * background + (1 - coverage) * background: " << worst);
  CHECK(worst < 2e-6);
}

}  // namespace

TEST_CASE("a glossy mirror under a uniform sky reflects exactly k times the sky at every gloss",
          "[render][distributed][gloss]") {
  const std::string sphere = R"([{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "m"}])";
  const std::string plane = R"([{"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "m"}])";
  const std::string at_sphere = R"({"position": [0, 0, 3.5], "look_at": [0, 0, 0], "fov": 45})";
  const std::string at_floor = R"({"position": [0, 0.6, 3], "look_at": [0, 0, -3], "fov": 60})";
  for (double gloss : {1.0, 5.0, 50.0, 5000.0}) {
    const std::string m =
        R"({"ambient": 0, "diffuse": 0, "specular": 0, "reflect": 0.6, "gloss": )" + num(gloss) + "}";
    INFO("gloss " << gloss);
    int covered = 0;
    checkUniform(parseScene(uniformSky(m, sphere, at_sphere), "glossy_sphere.json"), 0.6, covered);
    CHECK(covered > 300);
    // A floor seen at grazing angles: many lobe samples fall under it and fold back.
    checkUniform(parseScene(uniformSky(m, plane, at_floor), "glossy_floor.json"), 0.6, covered);
    CHECK(covered > 300);
  }
}

TEST_CASE("a translucent sphere of ior 1 under a uniform sky passes exactly k_trans^2 of the sky",
          "[render][distributed][translucency]") {
  // In at the front and out at the back, k_trans each time; the lobes' folding
  // keeps the entering ray inside and the leaving one outside.
  const std::string sphere = R"([{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "m"}])";
  const std::string camera = R"({"position": [0, 0, 3.5], "look_at": [0, 0, 0], "fov": 45})";
  for (double translucency : {1.0, 5.0, 50.0, 5000.0}) {
    const std::string m = R"({"ambient": 0, "diffuse": 0, "specular": 0, "reflect": 0, "transmit": 0.7, "ior": 1,
                              "translucency": )" +
                          num(translucency) + "}";
    INFO("translucency " << translucency);
    int covered = 0;
    checkUniform(parseScene(uniformSky(m, sphere, camera), "translucent.json"), 0.7 * 0.7, covered);
    CHECK(covered > 300);
  }
}

namespace {

// A glossy floor reflecting a checkered wall lit by the ambient term alone.
std::string glossyChecker(double gloss, int width, int height) {
  return R"({"camera": {"position": [0, 1, 4], "look_at": [0, 0.2, -2], "fov": 40},
    "film": {"width": )" + std::to_string(width) + R"(, "height": )" + std::to_string(height) + R"(},
    "render": {"max_depth": 1, "ambient": [1, 1, 1], "background": [0, 0, 0]},
    "materials": {
      "floor": {"ambient": 0, "diffuse": 0, "specular": 0, "reflect": 1, "gloss": )" +
         num(gloss) + R"(},
      "wall": {"ambient": 1, "diffuse": 0, "specular": 0,
               "texture": {"type": "checker", "color1": 1, "color2": 0, "scale": 0.5}}},
    "objects": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "floor"},
                {"type": "plane", "point": [0, 0, -6], "normal": [0, 0, 1], "material": "wall"}]})";
}

}  // namespace

TEST_CASE("a reflected checker loses contrast as the gloss exponent falls", "[render][distributed][gloss]") {
  const int w = 64, h = 48;
  Scene sharp = parseScene(glossyChecker(0, w, h), "mirror.json");
  RenderOptions opt = optionsFor(sharp, 64, AaMode::Jitter, 6);
  RenderResult s = render(sharp, opt);
  // The floor's pixels: a primary ray through the pixel centre meets the floor
  // before the wall.
  std::vector<size_t> floor_pixels;
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) {
      RefRay ray;
      const Vec3 o{0, 1, 4}, f = normalize(Vec3{0, 0.2, -2} - o), right = normalize(cross(f, Vec3{0, 1, 0}));
      const Vec3 up = cross(right, f);
      const double t = std::tan(20 * M_PI / 180);
      ray.o = o;
      ray.d = normalize(f + right * ((2 * (i + 0.5) / w - 1) * t * w / h) + up * ((1 - 2 * (j + 0.5) / h) * t));
      if (ray.d.y >= -0.02) continue;
      const double t_floor = -ray.o.y / ray.d.y, z = ray.o.z + t_floor * ray.d.z;
      if (z > -5.5) floor_pixels.push_back(static_cast<size_t>(j) * w + i);
    }
  REQUIRE(floor_pixels.size() > 600);
  double ms = 0;
  for (size_t p : floor_pixels) ms += s.rgba[4 * p];
  ms /= floor_pixels.size();
  double ss = 0;
  for (size_t p : floor_pixels) ss += (s.rgba[4 * p] - ms) * (s.rgba[4 * p] - ms);
  // Contrast: the image's projection onto the mirror image's pattern
  // (1 for the mirror; noise, being uncorrelated with the pattern, adds ~0), and
  // the plain variance of the region.
  std::vector<double> projection, variance;
  const std::vector<double> exponents = {1e4, 1000, 100, 10};
  for (double gloss : exponents) {
    Scene scene = parseScene(glossyChecker(gloss, w, h), "gloss.json");
    RenderResult r = render(scene, opt);
    double m = 0;
    for (size_t p : floor_pixels) m += r.rgba[4 * p];
    m /= floor_pixels.size();
    double dot = 0, var = 0;
    for (size_t p : floor_pixels) {
      dot += (r.rgba[4 * p] - m) * (s.rgba[4 * p] - ms);
      var += (r.rgba[4 * p] - m) * (r.rgba[4 * p] - m);
    }
    projection.push_back(dot / ss);
    variance.push_back(var / floor_pixels.size());
  }
  std::ostringstream table;
  for (size_t k = 0; k < exponents.size(); ++k)
    table << "gloss " << exponents[k] << ": projection " << projection[k] << ", variance " << variance[k] << "; ";
  INFO(table.str() << "mirror variance " << ss / floor_pixels.size());
  CHECK(projection[0] < 1);
  CHECK(variance[0] < ss / floor_pixels.size());
  for (size_t k = 1; k < exponents.size(); ++k) {
    CHECK(projection[k] < projection[k - 1]);
    CHECK(variance[k] < variance[k - 1]);
  }
  CHECK(projection[0] > 0.5);  // 1e4: barely blurred
  CHECK(projection.back() > 0);
}

// ---------------------------------------------------------------------------
// Convergence.

namespace {

struct Convergence {
  std::vector<double> jitter, random;
};

// RMSE of renders at each N against `reference` (with its own variance
// `ref_var` taken out of the mean squared error).
Convergence convergence(const Scene& scene, const std::vector<int>& ns, const std::vector<float>& reference,
                        double ref_var, const std::function<void(Scene&, int)>& per_n = {}) {
  Convergence c;
  for (int n : ns) {
    Scene s = scene;
    if (per_n) per_n(s, n);
    for (AaMode mode : {AaMode::Jitter, AaMode::Random}) {
      RenderResult r = render(s, optionsFor(s, n, mode, 11));
      const double e = std::sqrt(std::max(1e-30, mse(r.rgba, reference) - ref_var));
      (mode == AaMode::Jitter ? c.jitter : c.random).push_back(e);
    }
  }
  return c;
}

// A reference from two high-sample renders with different seeds: their mean, and
// the variance of that mean per channel, E[(a - b)^2] / 4.
std::vector<float> reference(const Scene& scene, int spp, double& var) {
  RenderResult a = render(scene, optionsFor(scene, spp, AaMode::Jitter, 1001));
  RenderResult b = render(scene, optionsFor(scene, spp, AaMode::Jitter, 2002));
  var = mse(a.rgba, b.rgba) / 4;
  std::vector<float> m(a.rgba.size());
  for (size_t k = 0; k < m.size(); ++k) m[k] = 0.5f * (a.rgba[k] + b.rgba[k]);
  return m;
}

void checkConvergence(const char* what, const std::vector<int>& ns, const Convergence& c) {
  const double sj = logLogSlope(ns, c.jitter), sr = logLogSlope(ns, c.random);
  std::ostringstream table;
  for (size_t k = 0; k < ns.size(); ++k)
    table << "N " << ns[k] << ": jitter " << c.jitter[k] << ", random " << c.random[k] << "; ";
  INFO(what << ": " << table.str() << "slopes: jitter " << sj << ", random " << sr);
  // Independent samples: RMSE exactly proportional to N^-1/2.
  CHECK(sr == Approx(-0.5).margin(0.1));
  // Stratified: at least as fast, and lower at every N.
  CHECK(sj <= -0.5 + 0.05);
  for (size_t k = 0; k < ns.size(); ++k) CHECK(c.jitter[k] < c.random[k]);
}

}  // namespace

TEST_CASE("every distributed effect converges at least as N^-1/2, stratified ahead of independent",
          "[render][distributed][convergence]") {
  const std::vector<int> ns = {4, 16, 64};
  SECTION("soft shadows") {
    // Against the integral itself.
    Penumbra pen;
    pen.W = 48;
    pen.Hpx = 8;
    pen.half_x = 0.9;
    std::vector<float> ref(static_cast<size_t>(pen.W) * pen.Hpx * 4, 0.0f);
    for (int j = 0; j < pen.Hpx; ++j)
      for (int i = 0; i < pen.W; ++i) {
        const double v = pen.pixel(i, j, true, 1, 1).mean;
        for (int c = 0; c < 3; ++c) ref[4 * (static_cast<size_t>(j) * pen.W + i) + c] = static_cast<float>(v);
      }
    Scene scene = parseScene(pen.json(1, 1, true), "penumbra.json");
    // One feeler a hit at every N: the light's samples follow the pixel's.
    Convergence c = convergence(scene, ns, ref, 0, [](Scene& s, int n) { s.lights[0].samples = n; });
    checkConvergence("soft shadows", ns, c);
  }
  SECTION("depth of field") {
    Scene scene = parseScene(R"({"camera": {"position": [0, 0, 0], "look_at": [0, 0, -1], "fov": 30,
        "aperture": 0.4, "focus_distance": 10},
      "film": {"width": 32, "height": 32},
      "render": {"max_depth": 0, "ambient": [1, 1, 1]},
      "materials": {"chart": {"ambient": 1, "diffuse": 0, "specular": 0,
                              "texture": {"type": "checker", "color1": 1, "color2": 0, "scale": 0.5}}},
      "objects": [{"type": "plane", "point": [0, 0, -14], "normal": [0, 0, 1], "material": "chart"}]})",
                             "dof.json");
    double var = 0;
    std::vector<float> ref = reference(scene, 1024, var);
    checkConvergence("depth of field", ns, convergence(scene, ns, ref, var));
  }
  SECTION("gloss") {
    Scene scene = parseScene(glossyChecker(100, 32, 24), "gloss.json");
    double var = 0;
    std::vector<float> ref = reference(scene, 1024, var);
    checkConvergence("gloss", ns, convergence(scene, ns, ref, var));
  }
  SECTION("translucency") {
    // A frosted sphere in front of a checker chart: what it shows is the chart
    // blurred through the refracted lobe.
    Scene scene = parseScene(R"({"camera": {"position": [0, 0, 4], "look_at": [0, 0, 0], "fov": 35},
      "film": {"width": 32, "height": 24},
      "render": {"max_depth": 3, "ambient": [1, 1, 1]},
      "materials": {"frosted": {"ambient": 0, "diffuse": 0, "transmit": 1, "ior": 1.3, "translucency": 60},
                    "chart": {"ambient": 1, "diffuse": 0,
                              "texture": {"type": "checker", "color1": 1, "color2": 0, "scale": 0.25}}},
      "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "frosted"},
                  {"type": "plane", "point": [0, 0, -3], "normal": [0, 0, 1], "material": "chart"}]})",
                             "translucency.json");
    double var = 0;
    std::vector<float> ref = reference(scene, 1024, var);
    checkConvergence("translucency", ns, convergence(scene, ns, ref, var));
  }
  SECTION("motion blur") {
    // A white sphere sliding across a dark chart during the shutter.
    Scene scene = parseScene(R"({"camera": {"position": [0, 0, 6], "look_at": [0, 0, 0], "fov": 30, "shutter": [0, 1]},
      "film": {"width": 32, "height": 24},
      "render": {"max_depth": 0, "ambient": [1, 1, 1]},
      "materials": {"white": {"ambient": 1, "diffuse": 0},
                    "chart": {"ambient": 1, "diffuse": 0,
                              "texture": {"type": "checker", "color1": 0.3, "color2": 0, "scale": 0.5}}},
      "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 0.6, "material": "white",
                   "transform": {"translate": [-1, 0, 0]}, "transform_end": {"translate": [1, 0.3, 0]}},
                  {"type": "plane", "point": [0, 0, -1], "normal": [0, 0, 1], "material": "chart"}]})",
                             "motion.json");
    double var = 0;
    std::vector<float> ref = reference(scene, 1024, var);
    checkConvergence("motion blur", ns, convergence(scene, ns, ref, var));
  }
}

// ---------------------------------------------------------------------------
// Determinism, first-hit modes, area lights seen directly.

namespace {

const char* kEffects[][2] = {
    {"area lights", R"({"camera": {"position": [0, 2, 5], "look_at": [0, 0.5, 0], "fov": 45},
      "film": {"width": 40, "height": 30},
      "render": {"max_depth": 2, "ambient": [0.05, 0.05, 0.05]},
      "materials": {"white": {"diffuse": 0.8, "specular": 0.3, "shininess": 20}},
      "lights": [{"type": "quad", "corner": [-1, 3, -1], "edge1": [2, 0, 0], "edge2": [0, 0, 1], "samples": 8},
                 {"type": "disk", "center": [2, 2, 1], "normal": [-1, -1, 0], "radius": 0.5, "intensity": 0.5,
                  "samples": 4},
                 {"type": "sphere", "center": [-2, 1.5, 1], "radius": 0.3, "intensity": 0.7, "samples": 4},
                 {"position": [0, 5, 5], "intensity": 0.2}],
      "objects": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "white"},
                  {"type": "box", "min": [-0.5, 0, -0.5], "max": [0.5, 1, 0.5], "material": "white"}]})"},
    {"gloss", R"({"camera": {"position": [0, 1, 4], "look_at": [0, 0.5, 0], "fov": 45},
      "film": {"width": 40, "height": 30},
      "render": {"max_depth": 3, "background": [0.2, 0.3, 0.5]},
      "materials": {"glossy": {"diffuse": 0.1, "reflect": 0.8, "gloss": 30},
                    "floor": {"texture": {"type": "checker", "color1": 0.9, "color2": 0.1, "scale": 0.5}}},
      "lights": [{"position": [2, 4, 3]}],
      "objects": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "floor"},
                  {"type": "sphere", "center": [0, 0.8, 0], "radius": 0.8, "material": "glossy"}]})"},
    {"translucency", R"({"camera": {"position": [0, 1, 4], "look_at": [0, 0.5, 0], "fov": 45},
      "film": {"width": 40, "height": 30},
      "render": {"max_depth": 4, "background": [0.2, 0.3, 0.5]},
      "materials": {"frosted": {"diffuse": 0, "transmit": 0.9, "ior": 1.4, "translucency": 40},
                    "floor": {"texture": {"type": "checker", "color1": 0.9, "color2": 0.1, "scale": 0.5}}},
      "lights": [{"position": [2, 4, 3]}],
      "objects": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "floor"},
                  {"type": "sphere", "center": [0, 0.8, 0], "radius": 0.8, "material": "frosted"}]})"},
    {"depth of field", R"({"camera": {"position": [0, 1, 4], "look_at": [0, 0.5, 0], "fov": 45,
                                      "aperture": 0.2, "focus_distance": 3},
      "film": {"width": 40, "height": 30},
      "render": {"max_depth": 1},
      "materials": {"floor": {"texture": {"type": "checker", "color1": 0.9, "color2": 0.1, "scale": 0.5}}},
      "lights": [{"position": [2, 4, 3]}],
      "objects": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "floor"},
                  {"type": "sphere", "center": [0.5, 0.5, -1], "radius": 0.5}]})"},
    {"moving objects", R"({"camera": {"position": [0, 1, 4], "look_at": [0, 0.5, 0], "fov": 45, "shutter": [0, 1]},
      "film": {"width": 40, "height": 30},
      "render": {"max_depth": 1},
      "materials": {"floor": {"texture": {"type": "checker", "color1": 0.9, "color2": 0.1, "scale": 0.5}}},
      "lights": [{"position": [2, 4, 3]}],
      "objects": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "floor"},
                  {"type": "sphere", "center": [0.5, 0.5, -1], "radius": 0.5,
                   "transform_end": [{"rotate": {"axis": [0, 1, 0], "angle": 40}}, {"translate": [-0.5, 0.2, 0]}]}]})"},
    {"moving camera", R"({"camera": {"position": [0, 1, 4], "look_at": [0, 0.5, 0], "fov": 45,
                                     "shutter": [0, 1], "position_end": [0.5, 1.2, 4], "look_at_end": [0.2, 0.5, 0]},
      "film": {"width": 40, "height": 30},
      "render": {"max_depth": 1},
      "materials": {"floor": {"texture": {"type": "checker", "color1": 0.9, "color2": 0.1, "scale": 0.5}}},
      "lights": [{"position": [2, 4, 3]}],
      "objects": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "floor"},
                  {"type": "sphere", "center": [0.5, 0.5, -1], "radius": 0.5}]})"},
};

}  // namespace

TEST_CASE("every distributed effect repeats bit for bit for one seed and changes with the seed",
          "[render][distributed][determinism]") {
  for (const auto& effect : kEffects) {
    INFO(effect[0]);
    Scene scene = parseScene(effect[1], "effect.json");
    for (int spp : {1, 4}) {
      INFO("spp " << spp);
      RenderOptions opt = optionsFor(scene, spp, spp == 1 ? AaMode::None : AaMode::Jitter, 7);
      RenderResult a = render(scene, opt), b = render(scene, opt);
      CHECK(sameBits(a.rgba, b.rgba));
      CHECK(a.stats.totalRays() == b.stats.totalRays());
      opt.seed = 8;
      RenderResult c = render(scene, opt);
      CHECK_FALSE(sameBits(a.rgba, c.rgba));
    }
  }
}

TEST_CASE("first hit auto traces for a lens or a shutter interval and zbuffer refuses them with the reason",
          "[render][distributed][firsthit]") {
  const std::string base = R"({"camera": {"position": [0, 2, 5], "look_at": [0, 0.5, 0], "fov": 45 CAMERA},
      "film": {"width": 32, "height": 24, "spp": 4},
      "render": {"max_depth": 1, "ambient": [0.05, 0.05, 0.05]},
      "materials": {"white": {"diffuse": 0.8, "specular": 0.3, "shininess": 20},
                    "mirror": {"diffuse": 0, "reflect": 0.8}},
      "lights": [{"type": "quad", "corner": [-1, 3, -1], "edge1": [2, 0, 0], "edge2": [0, 0, 1], "samples": 8},
                 {"type": "disk", "center": [2, 2, 1], "normal": [-1, -1, 0], "radius": 0.5, "samples": 4}],
      "objects": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "white"},
                  {"type": "sphere", "center": [0.8, 0.6, 0], "radius": 0.6, "material": "mirror"},
                  {"type": "box", "min": [-1.2, 0, -0.5], "max": [-0.4, 1, 0.3], "material": "white"}]})";
  auto scene = [&](const std::string& camera) {
    std::string json = base;
    json.replace(json.find(" CAMERA"), 7, camera);
    return parseScene(json, "firsthit.json");
  };

  // A pinhole with area lights: the Z-buffer can serve it, and gives the traced
  // image; auto traces (the plane would be tested at every sample, firsthit.h).
  Scene pin = scene("");
  RenderOptions opt = RenderOptions::fromScene(pin);
  RenderResult automatic = render(pin, opt);
  CHECK(automatic.stats.first_hit == FirstHitMode::Trace);
  opt.first_hit = FirstHitMode::ZBuffer;
  RenderResult z = render(pin, opt);
  opt.first_hit = FirstHitMode::Trace;
  RenderResult t = render(pin, opt);
  CHECK(t.stats.first_hit == FirstHitMode::Trace);
  const size_t pixels = static_cast<size_t>(opt.width) * opt.height;
  size_t close = 0;
  for (size_t p = 0; p < pixels; ++p) {
    double diff = 0;
    for (int c = 0; c < 4; ++c) diff = std::max(diff, std::fabs(double(z.rgba[4 * p + c]) - t.rgba[4 * p + c]));
    if (diff < 1e-4) ++close;
  }
  INFO(close << " of " << pixels << " pixels agree within 1e-4 between zbuffer and trace");
  CHECK(close >= pixels * 995 / 1000);

  struct Case {
    const char* camera;
    const char* reason;
  };
  for (Case c : {Case{R"(, "aperture": 0.1, "focus_distance": 4)", "aperture"},
                 Case{R"(, "shutter": [0, 1])", "shutter"},
                 Case{R"(, "shutter": [0, 1], "position_end": [0.3, 2, 5])", "shutter"}}) {
    INFO(c.camera);
    Scene s = scene(c.camera);
    RenderOptions o = RenderOptions::fromScene(s);
    CHECK(render(s, o).stats.first_hit == FirstHitMode::Trace);
    o.first_hit = FirstHitMode::ZBuffer;
    try {
      render(s, o);
      FAIL("first hit zbuffer rendered a camera that is not a pinhole");
    } catch (const std::invalid_argument& e) {
      const std::string what = e.what();
      INFO(what);
      CHECK(what.find("zbuffer") != std::string::npos);
      CHECK(what.find("pinhole") != std::string::npos);
      CHECK(what.find(c.reason) != std::string::npos);
    }
    // The scene file's render.first_hit says the same.
    std::string json = base;
    json.replace(json.find(" CAMERA"), 7, c.camera);
    json.replace(json.find(R"("max_depth": 1)"), 14, R"("max_depth": 1, "first_hit": "zbuffer")");
    Scene from_file = parseScene(json, "zbuffer.json");
    CHECK_THROWS_AS(render(from_file, RenderOptions::fromScene(from_file)), std::invalid_argument);
  }
}

TEST_CASE("an area light seen directly or in a mirror shows its radiance, from either face",
          "[render][distributed][area_light]") {
  // A quad light standing at z = -1 facing the camera (or away from it), a
  // mirror floor of k_refl 0.7, a uniform background. Pixel centres (aa none),
  // classified in double: on the light (L), on the floor seeing the light (0.7 L)
  // or the background (0.7 B), or on the background (B).
  const Vec3 L{3, 1.5, 0.75}, B{0.1, 0.2, 0.3};
  const Vec3 corner{-0.6, 1.0, -1};
  for (bool front : {true, false}) {
    const Vec3 e1 = front ? Vec3{1.2, 0, 0} : Vec3{0, 0.8, 0}, e2 = front ? Vec3{0, 0.8, 0} : Vec3{1.2, 0, 0};
    const std::string json = R"({"camera": {"position": [0, 1, 5], "look_at": [0, 0.8, 0], "fov": 50},
      "film": {"width": 48, "height": 36},
      "render": {"max_depth": 2, "ambient": [1, 1, 1], "background": )" +
                             vec(B.x, B.y, B.z) + R"(},
      "materials": {"mirror": {"ambient": 0, "diffuse": 0, "specular": 0, "reflect": 0.7}},
      "lights": [{"type": "quad", "corner": )" + vec(corner.x, corner.y, corner.z) +
                             R"(, "edge1": )" + vec(e1.x, e1.y, e1.z) + R"(, "edge2": )" + vec(e2.x, e2.y, e2.z) +
                             R"(, "color": [1, 0.5, 0.25], "intensity": 3, "samples": 4}],
      "objects": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "mirror"}]})";
    Scene scene = parseScene(json, "seen.json");
    RenderOptions opt = RenderOptions::fromScene(scene);
    RenderResult r = render(scene, opt);
    INFO((front ? "front face" : "back face") << " towards the camera");
    // Where a ray meets the light's rectangle x in [-0.6, 0.6], y in [1, 1.8] at
    // z = -1: 1 inside with margin, 0 outside with margin, -1 too close to call.
    auto onLight = [](const Vec3& o, const Vec3& d) {
      if (d.z >= 0 || o.z <= -1) return 0;
      const double t = (-1 - o.z) / d.z;
      const Vec3 p = o + d * t;
      const double m = 0.02;
      const bool in = p.x > -0.6 + m && p.x < 0.6 - m && p.y > 1 + m && p.y < 1.8 - m;
      const bool out = p.x < -0.6 - m || p.x > 0.6 + m || p.y < 1 - m || p.y > 1.8 + m;
      return in ? 1 : (out ? 0 : -1);
    };
    int direct = 0, mirrored = 0, sky = 0, floor_sky = 0;
    for (int j = 0; j < opt.height; ++j)
      for (int i = 0; i < opt.width; ++i) {
        RefRay ray;
        const Vec3 o{0, 1, 5}, f = normalize(Vec3{0, 0.8, 0} - o), right = normalize(cross(f, Vec3{0, 1, 0}));
        const Vec3 up = cross(right, f);
        const double th = std::tan(25 * M_PI / 180);
        const Vec3 d =
            normalize(f + right * ((2 * (i + 0.5) / opt.width - 1) * th * opt.width / opt.height) +
                      up * ((1 - 2 * (j + 0.5) / opt.height) * th));
        const double t_floor = d.y < 0 ? -o.y / d.y : 1e30;
        const double t_light = d.z < 0 ? (-1 - o.z) / d.z : 1e30;
        const int on_direct = t_light < t_floor ? onLight(o, d) : 0;
        if (on_direct < 0) continue;
        Vec3 expected;
        double alpha;
        if (on_direct) {
          expected = L;
          alpha = 1;
          ++direct;
        } else if (t_floor < 1e30) {
          const Vec3 p = o + d * t_floor, rd{d.x, -d.y, d.z};
          const int on = onLight(p, rd);
          if (on < 0) continue;
          expected = (on ? L : B) * 0.7;
          alpha = 1;
          (on ? mirrored : floor_sky)++;
        } else {
          expected = B;
          alpha = 0;
          ++sky;
        }
        const Vec3 v = rgb(r, i, j);
        INFO("pixel (" << i << ", " << j << "): (" << v.x << ", " << v.y << ", " << v.z << "), expected ("
                       << expected.x << ", " << expected.y << ", " << expected.z << ")");
        CHECK(std::fabs(v.x - expected.x) < 1e-5 * (1 + expected.x));
        CHECK(std::fabs(v.y - expected.y) < 1e-5 * (1 + expected.y));
        CHECK(std::fabs(v.z - expected.z) < 1e-5 * (1 + expected.z));
        CHECK(alphaOf(r, i, j) == alpha);
      }
    INFO(direct << " pixels on the light, " << mirrored << " seeing it in the mirror, " << floor_sky
                << " seeing the sky in it, " << sky << " on the sky");
    CHECK(direct > 30);
    CHECK(mirrored > 20);
    CHECK(floor_sky > 100);
    CHECK(sky > 50);
  }
}
