#include "scene/patches/patch_subdivision.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>
#include <stdexcept>

namespace prism {
namespace {

// Knots closer than this are not cut again: 2^-20 of a patch is far below
// float's resolution of any patch a renderer meets.
constexpr double kMinKnotGap = 1.0 / (1 << 20);

// An edge curve's four control points, and the same read backwards.
using CurveKey = std::array<double, 12>;

void edgeCurve(const BezierPatch& p, bool along_u, int side, Vec3 out[4]) {
  for (int k = 0; k < 4; ++k) out[k] = along_u ? p.at(k, side ? 3 : 0) : p.at(side ? 3 : 0, k);
}

CurveKey keyOf(const Vec3 c[4]) {
  CurveKey k;
  for (int i = 0; i < 4; ++i) k[3 * i] = c[i].x, k[3 * i + 1] = c[i].y, k[3 * i + 2] = c[i].z;
  return k;
}

// The curve in the orientation both patches sharing it use: the smaller key.
// Returns whether that is the curve read backwards.
bool canonicalCurve(const Vec3 c[4], Vec3 out[4]) {
  const Vec3 r[4] = {c[3], c[2], c[1], c[0]};
  const bool reversed = keyOf(r) < keyOf(c);
  std::copy(reversed ? r : c, (reversed ? r : c) + 4, out);
  return reversed;
}

// Directions of patches (2 per patch: u, v) joined into chains by shared
// edges, each member knowing whether it runs against the chain's root.
class Chains {
 public:
  explicit Chains(std::size_t n) : m_parent(n), m_flip(n, false) {
    for (std::size_t i = 0; i < n; ++i) m_parent[i] = i;
  }
  std::size_t root(std::size_t x, bool* flip) {
    bool f = false;
    std::size_t r = x;
    while (m_parent[r] != r) f ^= m_flip[r], r = m_parent[r];
    // Path compression, keeping each node's parity to the root.
    bool g = f;
    while (m_parent[x] != x) {
      const std::size_t next = m_parent[x];
      const bool fx = m_flip[x];
      m_parent[x] = r;
      m_flip[x] = g;
      g ^= fx;
      x = next;
    }
    *flip = f;
    return r;
  }
  void join(std::size_t a, std::size_t b, bool flip) {
    bool fa, fb;
    const std::size_t ra = root(a, &fa), rb = root(b, &fb);
    if (ra == rb) return;  // (a twisted loop of patches keeps its first orientation)
    m_parent[rb] = ra;
    m_flip[rb] = fa ^ fb ^ flip;
  }

 private:
  std::vector<std::size_t> m_parent;
  std::vector<bool> m_flip;
};

bool collapsed(const Vec3 c[4]) { return c[0] == c[1] && c[1] == c[2] && c[2] == c[3]; }

// Whether to cut this cell along u (else along v): where it bends more, or,
// bending alike (a twist), across its longer sides.
bool cutAlongU(const BezierPatch& cell) {
  const double bu = bendAlongU(cell), bv = bendAlongV(cell);
  if (bu != bv) return bu > bv;
  const double lu = length(cell.at(3, 0) - cell.at(0, 0)) + length(cell.at(3, 3) - cell.at(0, 3));
  const double lv = length(cell.at(0, 3) - cell.at(0, 0)) + length(cell.at(3, 3) - cell.at(3, 0));
  return lu >= lv;
}

std::vector<double> oriented(const std::vector<double>& knots, bool flip) {
  if (!flip) return knots;
  std::vector<double> out;
  for (auto it = knots.rbegin(); it != knots.rend(); ++it) out.push_back(1 - *it);  // exact on dyadic knots
  return out;
}

}  // namespace

double patchSetSize(const std::vector<BezierPatch>& patches) {
  Vec3 lo, hi;
  patchBounds(patches.front(), lo, hi);
  for (const BezierPatch& p : patches) {
    Vec3 a, b;
    patchBounds(p, a, b);
    lo = {std::min(lo.x, a.x), std::min(lo.y, a.y), std::min(lo.z, a.z)};
    hi = {std::max(hi.x, b.x), std::max(hi.y, b.y), std::max(hi.z, b.z)};
  }
  return length(hi - lo);
}

std::vector<PatchGrid> planSubdivision(const std::vector<BezierPatch>& patches, double tolerance,
                                       std::size_t max_triangles) {
  const std::size_t n = patches.size();
  Chains chains(2 * n);  // direction d of patch k: 2k + d, d = 0 for u
  std::map<CurveKey, std::pair<std::size_t, bool>> first_use;
  for (std::size_t k = 0; k < n; ++k)
    for (int d = 0; d < 2; ++d)
      for (int side = 0; side < 2; ++side) {
        Vec3 c[4], canon[4];
        edgeCurve(patches[k], d == 0, side, c);
        if (collapsed(c)) continue;  // a patch's apex: shared by many, and has no knots to share
        const bool reversed = canonicalCurve(c, canon);
        const auto [it, fresh] = first_use.emplace(keyOf(canon), std::make_pair(2 * k + d, reversed));
        if (!fresh) chains.join(it->second.first, 2 * k + d, it->second.second ^ reversed);
      }
  std::map<std::size_t, std::vector<double>> knots;  // per chain root, in the root's orientation
  auto knotsOf = [&](std::size_t dir) {
    bool flip;
    const std::size_t r = chains.root(dir, &flip);
    auto it = knots.emplace(r, std::vector<double>{0, 1}).first;
    return oriented(it->second, flip);
  };
  for (;;) {
    std::set<std::pair<std::size_t, double>> cuts;  // (chain root, knot in its orientation)
    std::size_t triangles = 0;
    for (std::size_t k = 0; k < n; ++k) {
      const std::vector<double> ku = knotsOf(2 * k), kv = knotsOf(2 * k + 1);
      triangles += 2 * (ku.size() - 1) * (kv.size() - 1);
      for (std::size_t a = 0; a + 1 < ku.size(); ++a)
        for (std::size_t b = 0; b + 1 < kv.size(); ++b) {
          const BezierPatch cell = subPatch(patches[k], ku[a], ku[a + 1], kv[b], kv[b + 1]);
          if (flatnessBound(cell) <= tolerance) continue;
          bool along_u = cutAlongU(cell);
          const bool u_open = ku[a + 1] - ku[a] > kMinKnotGap, v_open = kv[b + 1] - kv[b] > kMinKnotGap;
          if (!u_open && !v_open) continue;  // as fine as float can tell apart
          if (along_u ? !u_open : !v_open) along_u = !along_u;
          const double mid = along_u ? 0.5 * (ku[a] + ku[a + 1]) : 0.5 * (kv[b] + kv[b + 1]);
          bool flip;
          const std::size_t r = chains.root(2 * k + (along_u ? 0 : 1), &flip);
          cuts.emplace(r, flip ? 1 - mid : mid);
        }
    }
    if (triangles > max_triangles)
      throw std::length_error("tolerance " + std::to_string(tolerance) + " needs more than " +
                              std::to_string(max_triangles) + " triangles: raise it");
    if (cuts.empty()) break;
    for (const auto& [r, knot] : cuts) {
      std::vector<double>& ks = knots[r];
      ks.insert(std::lower_bound(ks.begin(), ks.end(), knot), knot);
    }
  }
  std::vector<PatchGrid> plan(n);
  for (std::size_t k = 0; k < n; ++k) plan[k] = {knotsOf(2 * k), knotsOf(2 * k + 1)};
  return plan;
}

std::shared_ptr<TriangleMesh> tessellatePatches(const std::vector<BezierPatch>& patches,
                                                const std::vector<PatchGrid>& plan, const std::string& source) {
  auto mesh = std::make_shared<TriangleMesh>();
  mesh->source = source;
  auto put = [](std::vector<float>& v, const Vec3& p) {
    v.push_back(static_cast<float>(p.x));
    v.push_back(static_cast<float>(p.y));
    v.push_back(static_cast<float>(p.z));
  };
  for (std::size_t k = 0; k < patches.size(); ++k) {
    const BezierPatch& patch = patches[k];
    const std::vector<double>&ku = plan[k].u, &kv = plan[k].v;
    const std::uint32_t first = static_cast<std::uint32_t>(mesh->vertexCount()), rows = kv.size();
    for (std::size_t a = 0; a < ku.size(); ++a)
      for (std::size_t b = 0; b < kv.size(); ++b) {
        const double u = ku[a], v = kv[b];
        Vec3 p;
        // A point of an edge comes from the edge's curve in its shared
        // orientation, so the patch on the other side gets the same bits.
        const bool u_edge = a == 0 || a + 1 == ku.size(), v_edge = b == 0 || b + 1 == kv.size();
        if (u_edge || v_edge) {
          Vec3 c[4], canon[4];
          edgeCurve(patch, !u_edge, u_edge ? (a != 0) : (b != 0), c);
          const double t = u_edge ? v : u;
          p = curvePoint(canon, canonicalCurve(c, canon) ? 1 - t : t);
        } else {
          p = evaluate(patch, u, v).p;
        }
        put(mesh->positions, p);
        put(mesh->normals, patchNormal(patch, u, v));
        mesh->texcoords.push_back(static_cast<float>(u));
        mesh->texcoords.push_back(static_cast<float>(v));
      }
    for (std::uint32_t a = 0; a + 1 < ku.size(); ++a)
      for (std::uint32_t b = 0; b + 1 < kv.size(); ++b) {
        const std::uint32_t i00 = first + a * rows + b, i10 = i00 + rows, i01 = i00 + 1, i11 = i10 + 1;
        for (std::uint32_t i : {i00, i10, i11, i00, i11, i01}) mesh->indices.push_back(i);
      }
  }
  mesh->face_count = mesh->triangleCount();
  for (std::size_t t = 0; t < mesh->triangleCount(); ++t) {
    auto at = [&](int c) {
      const std::uint32_t i = mesh->indices[3 * t + c];
      return Vec3{mesh->positions[3 * i], mesh->positions[3 * i + 1], mesh->positions[3 * i + 2]};
    };
    if (length(cross(at(1) - at(0), at(2) - at(0))) == 0) ++mesh->degenerate_count;
  }
  return mesh;
}

std::vector<PatchPiece> patchPieces(const std::vector<BezierPatch>& patches) {
  // A piece bends by at most this fraction of its size: Newton's start from
  // its corner triangles is then close, and its normals turn little.
  constexpr double kPieceFlatness = 0.05;
  constexpr int kMaxDepth = 12;
  std::vector<PatchPiece> pieces;
  struct Todo {
    PatchPiece piece;
    int depth;
  };
  for (const BezierPatch& patch : patches) {
    std::vector<Todo> todo = {{{patch, 0, 1, 0, 1}, 0}};
    while (!todo.empty()) {
      Todo t = todo.back();
      todo.pop_back();
      Vec3 lo, hi;
      patchBounds(t.piece.patch, lo, hi);
      if (t.depth >= kMaxDepth || flatnessBound(t.piece.patch) <= kPieceFlatness * length(hi - lo)) {
        pieces.push_back(t.piece);
        continue;
      }
      const bool along_u = cutAlongU(t.piece.patch);
      PatchPiece a = t.piece, b = t.piece;
      splitPatch(t.piece.patch, along_u, a.patch, b.patch);
      if (along_u) {
        a.u1 = b.u0 = 0.5 * (t.piece.u0 + t.piece.u1);
      } else {
        a.v1 = b.v0 = 0.5 * (t.piece.v0 + t.piece.v1);
      }
      todo.push_back({b, t.depth + 1});
      todo.push_back({a, t.depth + 1});
    }
  }
  return pieces;
}

}  // namespace prism
