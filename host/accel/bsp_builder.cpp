// BSP: an SAH kd-tree with axis-aligned planes, in the manner of Wald and
// Havran, "On building fast kd-trees for ray tracing, and on doing that in
// O(N log^2 N)" (2006):
//   - candidate planes come from the primitives' perfect-split bounds (each
//     primitive clipped to the cell, exact_predicates.h); a plane is placed one
//     float step outside a bound, so the primitive whose bound it is lies
//     wholly on one side instead of touching the plane. Cells of more than
//     kExactSweepPrims primitives take candidates from kBins bins instead
//     (O(N) per cell); smaller ones sort their bounds (O(N log N) per cell,
//     O(N log^2 N) in all);
//   - cost of a split: C_T + C_I (A_L N_L + A_R N_R) / A, times the empty-space
//     bonus lambda when one side is empty (AccelBuildOptions::bsp_*);
//   - termination rule: a cell becomes a leaf when it holds at most one
//     primitive, when its depth reaches 8 + 1.3 log2(N) (N the scene's
//     primitives, at most kMaxDepth), or when the best split costs at least as
//     much as the leaf, C_I N.
// Primitives go to every side they meet, decided exactly (CGAL), so one lying
// on a splitting plane is kept on both sides.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>
#include <memory>

#include "accel/builders.h"
#include "accel/exact_predicates.h"
#include "accel/leaf_packets.h"
#include "accel/task_group.h"
#include "kernels/shared/bsp_node_gpu.h"

namespace prism {
namespace {

constexpr std::size_t kExactSweepPrims = 1024;
constexpr int kBins = 256;
constexpr int kMaxDepth = 48;
constexpr std::size_t kParallelPrims = 4096;

struct Item {
  std::int32_t item;  // position in PrimitiveSet::bounded
  Aabb clip;          // bounds of the part inside the cell
};

struct KdNode {
  CellBox box;
  int axis = -1;  // -1: leaf
  float split = 0;
  std::unique_ptr<KdNode> below, above;
  std::vector<std::int32_t> items;  // leaves
};

struct Split {
  int axis = -1;
  float pos = 0;
  double cost = INFINITY;
};

const float kInf = std::numeric_limits<float>::infinity();

class BspBuilder {
 public:
  BspBuilder(const std::vector<ObjectGpu>& objects, const PrimitiveSet& prims, const AccelBuildOptions& options)
      : m_objects(objects), m_prims(prims), m_options(options), m_budget(options.threads) {
    const double n = std::max<double>(1, prims.bounded.size());
    m_max_depth = std::min(kMaxDepth, static_cast<int>(std::lround(8 + 1.3 * std::log2(n))));
  }

  std::unique_ptr<KdNode> build(const CellBox& root) {
    std::vector<Item> items(m_prims.bounded.size());
    for (std::size_t i = 0; i < items.size(); ++i) items[i] = Item{static_cast<std::int32_t>(i), m_prims.bounds[i]};
    auto node = std::make_unique<KdNode>();
    node->box = root;
    buildNode(*node, std::move(items), 0);
    return node;
  }

  std::size_t exactTests() const { return m_exact_tests.load(); }

 private:
  void makeLeaf(KdNode& node, const std::vector<Item>& items) {
    node.axis = -1;
    node.items.reserve(items.size());
    for (const Item& it : items) node.items.push_back(it.item);
  }

  double splitCost(const CellBox& box, int axis, double pos, std::size_t nl, std::size_t nr) const {
    CellBox l = box, r = box;
    l.hi[axis] = pos;
    r.lo[axis] = pos;
    const double area = std::max(box.area(), 1e-300);
    double cost = m_options.bsp_traversal_cost +
                  m_options.bsp_intersection_cost * (l.area() * nl + r.area() * nr) / area;
    if (nl == 0 || nr == 0) cost *= m_options.bsp_empty_bonus;
    return cost;
  }

  void consider(Split& best, const CellBox& box, int axis, float pos, std::size_t nl, std::size_t nr) const {
    if (!(pos > box.lo[axis] && pos < box.hi[axis])) return;
    double cost = splitCost(box, axis, pos, nl, nr);
    if (cost < best.cost) best = Split{axis, pos, cost};
  }

  // Sorted bounds: N_L(s) = #(lo <= s), N_R(s) = #(hi >= s) at every candidate.
  void sweepExact(const KdNode& node, const std::vector<Item>& items, Split& best) const {
    const std::size_t n = items.size();
    std::vector<float> los(n), his(n);
    for (int axis = 0; axis < 3; ++axis) {
      if (!(node.box.hi[axis] > node.box.lo[axis])) continue;
      for (std::size_t i = 0; i < n; ++i) {
        los[i] = items[i].clip.lo[axis];
        his[i] = items[i].clip.hi[axis];
      }
      std::sort(los.begin(), los.end());
      std::sort(his.begin(), his.end());
      // Candidates in increasing order (a merge of the two sorted lists), with
      // the counts advanced alongside: linear after the sorts.
      std::size_t i = 0, j = 0, below = 0, ended = 0;
      float last = -kInf;
      while (i < n || j < n) {
        float s;
        if (j >= n || (i < n && std::nextafter(los[i], -kInf) <= std::nextafter(his[j], kInf)))
          s = std::nextafter(los[i++], -kInf);
        else
          s = std::nextafter(his[j++], kInf);
        if (s == last) continue;
        last = s;
        while (below < n && los[below] <= s) ++below;
        while (ended < n && his[ended] < s) ++ended;
        consider(best, node.box, axis, s, below, n - ended);
      }
    }
  }

  // Histograms of the bounds over kBins bins per axis; planes at bin edges.
  void sweepBinned(const KdNode& node, const std::vector<Item>& items, Split& best) const {
    for (int axis = 0; axis < 3; ++axis) {
      const double lo = node.box.lo[axis], extent = node.box.hi[axis] - lo;
      if (!(extent > 0)) continue;
      const double scale = kBins / extent;
      std::vector<std::size_t> starts(kBins, 0), ends(kBins, 0);
      for (const Item& it : items) {
        int b0 = static_cast<int>((it.clip.lo[axis] - lo) * scale);
        int b1 = static_cast<int>((it.clip.hi[axis] - lo) * scale);
        ++starts[std::clamp(b0, 0, kBins - 1)];
        ++ends[std::clamp(b1, 0, kBins - 1)];
      }
      std::size_t nl = 0, nr = items.size();
      for (int b = 1; b < kBins; ++b) {
        nl += starts[b - 1];  // bounds starting before edge b
        nr -= ends[b - 1];    // bounds ending before edge b
        consider(best, node.box, axis, static_cast<float>(lo + b / scale), nl, nr);
      }
    }
  }

  void buildNode(KdNode& node, std::vector<Item> items, int depth) {
    const std::size_t n = items.size();
    if (n <= 1 || depth >= m_max_depth) return makeLeaf(node, items);
    Split best;
    if (n > kExactSweepPrims)
      sweepBinned(node, items, best);
    else
      sweepExact(node, items, best);
    if (best.axis < 0 || !(best.cost < m_options.bsp_intersection_cost * n)) return makeLeaf(node, items);

    const int axis = best.axis;
    const float s = best.pos;
    CellBox below_box = node.box, above_box = node.box;
    below_box.hi[axis] = s;
    above_box.lo[axis] = s;
    std::vector<Item> below, above;
    below.reserve(n / 2 + 16);
    above.reserve(n / 2 + 16);
    std::size_t tests = 0;
    for (const Item& it : items) {
      const Aabb& b = m_prims.bounds[it.item];
      if (b.hi[axis] < s) {
        below.push_back(it);
      } else if (b.lo[axis] > s) {
        above.push_back(it);
      } else {
        const ObjectGpu& ob = m_objects[m_prims.bounded[it.item]];
        if (overlapsCell(ob, b, below_box, &tests)) below.push_back(Item{it.item, clipped(ob, b, below_box)});
        if (overlapsCell(ob, b, above_box, &tests)) above.push_back(Item{it.item, clipped(ob, b, above_box)});
      }
    }
    m_exact_tests += tests;
    items.clear();
    items.shrink_to_fit();

    node.axis = axis;
    node.split = s;
    node.below = std::make_unique<KdNode>();
    node.above = std::make_unique<KdNode>();
    node.below->box = below_box;
    node.above->box = above_box;
    KdNode* lo = node.below.get();
    TaskGroup group(m_budget);
    const bool big = below.size() >= kParallelPrims && above.size() >= kParallelPrims;
    group.run([this, lo, list = std::move(below), depth]() mutable { buildNode(*lo, std::move(list), depth + 1); },
              big);
    buildNode(*node.above, std::move(above), depth + 1);
    group.wait();
  }

  // Perfect-split bounds in a child; the object's box cut by the cell when
  // rounding left nothing of a primitive CGAL says touches it.
  static Aabb clipped(const ObjectGpu& ob, const Aabb& b, const CellBox& cell) {
    Aabb c = clippedBounds(ob, b, cell);
    if (!c.empty()) return c;
    for (int a = 0; a < 3; ++a) {
      c.lo[a] = std::max(b.lo[a], roundDown(cell.lo[a]));
      c.hi[a] = std::min(b.hi[a], roundUp(cell.hi[a]));
      if (c.lo[a] > c.hi[a]) c.lo[a] = c.hi[a] = static_cast<float>(cell.lo[a]);
    }
    return c;
  }

  const std::vector<ObjectGpu>& m_objects;
  const PrimitiveSet& m_prims;
  const AccelBuildOptions& m_options;
  ThreadBudget m_budget;
  int m_max_depth = kMaxDepth;
  std::atomic<std::size_t> m_exact_tests{0};
};

class BspFlattener {
 public:
  BspFlattener(const std::vector<ObjectGpu>& objects, const PrimitiveSet& prims, DeviceAccel& out)
      : m_objects(objects), m_prims(prims), m_out(out), m_refs(prims.bounded.size(), 0) {}

  void run(const KdNode& root) {
    m_root_area = std::max(root.box.area(), 1e-300);
    flatten(root, 0);
    AccelStats& s = m_out.stats;
    s.node_count = m_nodes.size();
    s.max_depth = m_max_depth;
    s.sah_cost = m_sah;
    finishReferenceStats(m_refs, s);
    m_out.kernel_options = "-DPRISM_ACCEL_BSP " + stackOption(m_max_depth + 2);
    appendNodeWords(m_out.nodes, m_nodes.data(), m_nodes.size());
  }

 private:
  int flatten(const KdNode& node, int depth) {
    m_max_depth = std::max(m_max_depth, depth);
    const int index = static_cast<int>(m_nodes.size());
    m_nodes.emplace_back();
    const double rel = node.box.area() / m_root_area;
    if (node.axis < 0) {
      m_ids.clear();
      for (std::int32_t item : node.items) {
        m_ids.push_back(m_prims.bounded[item]);
        ++m_refs[item];
      }
      PacketRange r = appendLeafPackets(m_objects, m_ids.data(), m_ids.size(), m_out.packets);
      m_nodes[index].word = static_cast<int>(r.start << 2) | BSP_LEAF;
      m_nodes[index].payload = static_cast<int>(r.count);
      m_sah += rel * node.items.size();
      if (node.items.empty())
        ++m_out.stats.empty_leaf_count;
      else
        ++m_out.stats.leaf_count;
      return index;
    }
    m_sah += rel;
    flatten(*node.below, depth + 1);
    const int above = flatten(*node.above, depth + 1);
    m_nodes[index].word = (above << 2) | node.axis;
    std::memcpy(&m_nodes[index].payload, &node.split, sizeof(float));
    return index;
  }

  const std::vector<ObjectGpu>& m_objects;
  const PrimitiveSet& m_prims;
  DeviceAccel& m_out;
  std::vector<int> m_refs;
  std::vector<BspNodeGpu> m_nodes;
  std::vector<std::int32_t> m_ids;
  double m_sah = 0, m_root_area = 1;
  int m_max_depth = 0;
};

}  // namespace

void buildBsp(const std::vector<ObjectGpu>& objects, const PrimitiveSet& prims, const AccelBuildOptions& options,
              DeviceAccel& out) {
  CellBox root = toCell(prims.scene);
  if (prims.bounded.empty()) root = CellBox{{0, 0, 0}, {0, 0, 0}};
  BspBuilder builder(objects, prims, options);
  std::unique_ptr<KdNode> tree = builder.build(root);
  writeSceneHeader(prims.scene, out);
  BspFlattener(objects, prims, out).run(*tree);
  out.stats.exact_tests = builder.exactTests();
}

}  // namespace prism
