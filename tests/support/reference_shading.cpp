#include "support/reference_shading.h"

#include <algorithm>
#include <cmath>

#include "render/gpu_scene.h"

namespace prism::test {
namespace {


double transmittance(const Scene& scene, const Vec3& from, const Vec3& to) {
  RefRay r;
  r.o = from;
  r.d = normalize(to - from);
  r.tmin = 0;
  r.tmax = length(to - from);
  double carried = 1;
  for (const Object& ob : scene.objects)
    if (referenceIntersect(ob, r)) carried *= scene.materials[ob.material].transmit;
  return carried;
}

}  // namespace

RefHit referenceClosest(const Scene& scene, const RefRay& ray) {
  RefHit best;
  for (size_t k = 0; k < scene.objects.size(); ++k) {
    RefRay r = ray;
    r.tmax = std::min(r.tmax, best.t);
    if (auto t = referenceIntersect(scene.objects[k], r)) best = {static_cast<int>(k), *t};
  }
  return best;
}

Vec3 referenceNormal(const Object& ob, const Vec3& world_p) {
  Transform inv = ob.transform.inverse();
  Vec3 p = inv.applyPoint(world_p), n;
  switch (ob.type) {
    case ObjectType::Sphere: n = p - ob.center; break;
    case ObjectType::Box: {
      Vec3 c = (ob.box_min + ob.box_max) * 0.5, h = (ob.box_max - ob.box_min) * 0.5;
      Vec3 q = {(p.x - c.x) / h.x, (p.y - c.y) / h.y, (p.z - c.z) / h.z};
      Vec3 a = {std::fabs(q.x), std::fabs(q.y), std::fabs(q.z)};
      if (a.x >= a.y && a.x >= a.z) n = {q.x > 0 ? 1.0 : -1.0, 0, 0};
      else if (a.y >= a.z) n = {0, q.y > 0 ? 1.0 : -1.0, 0};
      else n = {0, 0, q.z > 0 ? 1.0 : -1.0};
      break;
    }
    case ObjectType::Plane: n = ob.normal; break;
    case ObjectType::Triangle: n = cross(ob.vertices[1] - ob.vertices[0], ob.vertices[2] - ob.vertices[0]); break;
  }
  // Normals transform by the inverse transpose: n_world = inv^T n.
  Vec3 w{inv.m[0][0] * n.x + inv.m[1][0] * n.y + inv.m[2][0] * n.z,
         inv.m[0][1] * n.x + inv.m[1][1] * n.y + inv.m[2][1] * n.z,
         inv.m[0][2] * n.x + inv.m[1][2] * n.y + inv.m[2][2] * n.z};
  return normalize(w);
}

Vec3 referenceRadiance(const Scene& scene, const RenderOptions& options, const RefRay& ray, double weight, int depth) {
  RefHit hit = referenceClosest(scene, ray);
  if (hit.object < 0) return scene.render.background;
  const Object& ob = scene.objects[hit.object];
  const Material& m = scene.materials[ob.material];
  Vec3 d = normalize(ray.d);
  Vec3 p = ray.o + ray.d * hit.t;
  Vec3 n = referenceNormal(ob, p);
  bool inside = dot(n, d) > 0;
  if (inside) n = -n;
  Vec3 v = -d;
  double eps = 1e-4 * std::max({1.0, std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)});
  Vec3 p_out = p + n * eps;

  Vec3 colour = mul(m.ambient, scene.render.ambient);
  for (const Light& light : scene.lights) {
    Vec3 l = normalize(light.position - p_out);
    double n_dot_l = dot(n, l);
    if (n_dot_l <= 0) continue;
    double spec_base = m.model == ShadingModel::Blinn ? dot(n, normalize(l + v)) : dot(n * (2 * n_dot_l) - l, v);
    double spec = spec_base > 0 ? std::pow(spec_base, m.shininess) : 0;
    Vec3 local = m.diffuse * n_dot_l + m.specular * spec;
    colour = colour + mul(light.color * light.intensity, local) * transmittance(scene, p_out, light.position);
  }
  if (depth >= options.max_depth) return colour;

  double k_reflect = m.reflect;
  if (m.transmit > 0) {
    double eta = inside ? m.ior : 1 / m.ior;
    double cos_i = -dot(n, d);
    double k = 1 - eta * eta * (1 - cos_i * cos_i);
    if (k < 0) {
      k_reflect += m.transmit;
    } else if (weight * m.transmit >= options.min_weight) {
      RefRay t;
      t.o = p - n * eps;
      t.d = d * eta + n * (eta * cos_i - std::sqrt(k));
      colour = colour + referenceRadiance(scene, options, t, weight * m.transmit, depth + 1) * m.transmit;
    }
  }
  if (k_reflect > 0 && weight * k_reflect >= options.min_weight) {
    RefRay r;
    r.o = p_out;
    r.d = d - n * (2 * dot(n, d));
    colour = colour + referenceRadiance(scene, options, r, weight * k_reflect, depth + 1) * k_reflect;
  }
  return colour;
}

RefRay referencePrimaryRay(const Scene& scene, const RenderOptions& options, int i, int j) {
  CameraBasis b = cameraBasis(scene.camera, options.width, options.height);
  double x = 2 * (i + 0.5) / options.width - 1;
  double y = 1 - 2 * (j + 0.5) / options.height;
  RefRay r;
  r.o = b.origin;
  r.d = normalize(b.forward + b.right * x + b.up * y);
  return r;
}

double referenceCookTorrance(const Vec3& n, const Vec3& l, const Vec3& v, double alpha, int distribution, double eta) {
  const double n_l = dot(n, l), n_v = dot(n, v);
  if (n_l <= 0 || n_v <= 0) return 0;
  const Vec3 h = normalize(l + v);
  const double c = dot(n, h), v_h = dot(v, h), a2 = alpha * alpha;
  if (c <= 0 || v_h <= 0) return 0;
  double d, g;
  if (distribution == 1) {
    const double k = c * c * (a2 - 1) + 1;
    d = a2 / (M_PI * k * k);
    auto g1 = [&](double x) { return 2 * x / (x + std::sqrt(a2 + (1 - a2) * x * x)); };
    g = g1(n_l) * g1(n_v);
  } else {
    const double tan2 = (1 - c * c) / (c * c);
    d = std::exp(-tan2 / a2) / (M_PI * a2 * c * c * c * c);
    g = std::min({1.0, 2 * c * n_v / v_h, 2 * c * n_l / v_h});
  }
  double f = 1;
  if (eta > 0) {
    // Fresnel's sine and tangent laws for the angle of incidence v.h.
    const double ti = std::acos(std::min(1.0, v_h)), st = std::sin(ti) / eta;
    if (st >= 1) {
      f = 1;
    } else if (ti < 1e-9) {
      f = std::pow((eta - 1) / (eta + 1), 2);
    } else {
      const double tt = std::asin(st);
      const double rs = std::sin(ti - tt) / std::sin(ti + tt), rp = std::tan(ti - tt) / std::tan(ti + tt);
      f = 0.5 * (rs * rs + rp * rp);
    }
  }
  return M_PI * f * d * g / (4 * n_v);
}

}  // namespace prism::test
