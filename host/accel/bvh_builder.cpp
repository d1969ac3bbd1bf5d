// BVH: a binary tree by binned SAH (Wald, "On fast construction of SAH-based
// bounding volume hierarchies", 2007), subtrees built on separate threads, then
// collapsed into 8-wide nodes with structure-of-arrays child boxes
// (kernels/shared/bvh_node_gpu.h) by repeatedly opening the largest child.
//
// Costs count primitives in blocks of four, the packet width of the leaves: a
// leaf of n primitives costs ceil(n/4), a split kTraversalCost plus the
// children's area-weighted costs. Leaves hold at most kMaxLeafPrims.
#include <algorithm>
#include <atomic>
#include <cfloat>
#include <cmath>
#include <cstdint>

#include "accel/builders.h"
#include "accel/kdop_bounds.h"
#include "accel/leaf_packets.h"
#include "accel/task_group.h"
#include "kernels/shared/bvh_node_gpu.h"

namespace prism {
namespace {

constexpr int kBins = 32;
constexpr int kMaxLeafPrims = 16;      // at most 4 triangle + 4 other packets < BVH_LEAF_MAX_PACKETS
constexpr double kTraversalCost = 2.0;  // PERF-NOTES: traversal cost 2 against a 4-wide packet test of 1
constexpr int kParallelPrims = 4096;    // subtrees at least this big may get their own thread
constexpr int kMedianDepth = 48;        // below this depth, splits are object medians (bounded depth)

struct PrimRef {
  float lo[3];
  std::int32_t id;
  float hi[3];
  std::int32_t index;  // into the PrimitiveSet's arrays
  float centroid(int a) const { return lo[a] + hi[a]; }  // twice the centre: only order matters
};

struct Node2 {
  Aabb box;
  std::int32_t left = -1;  // -1: leaf
  std::int32_t right = -1;
  std::int32_t first = 0, count = 0;
};

double blocks(int n) { return static_cast<double>((n + PACKET_LANES - 1) / PACKET_LANES); }

class Bvh2Builder {
 public:
  Bvh2Builder(std::vector<PrimRef>& refs, ThreadBudget& budget) : m_refs(refs), m_budget(budget) {}

  std::vector<Node2> build() {
    const int n = static_cast<int>(m_refs.size());
    m_nodes.resize(std::max(1, 2 * n - 1));
    m_next = 1;
    buildNode(0, 0, n, 0);
    m_nodes.resize(m_next.load());
    return std::move(m_nodes);
  }

 private:
  struct Bin {
    Aabb box;
    int count = 0;
  };

  void makeLeaf(Node2& node, int begin, int end) {
    node.left = node.right = -1;
    node.first = begin;
    node.count = end - begin;
  }

  void buildNode(int index, int begin, int end, int depth) {
    Node2& node = m_nodes[index];
    const int n = end - begin;
    Aabb box, centroids;
    for (int i = begin; i < end; ++i) {
      const PrimRef& r = m_refs[i];
      for (int a = 0; a < 3; ++a) {
        box.lo[a] = std::min(box.lo[a], r.lo[a]);
        box.hi[a] = std::max(box.hi[a], r.hi[a]);
        float c = r.centroid(a);
        centroids.lo[a] = std::min(centroids.lo[a], c);
        centroids.hi[a] = std::max(centroids.hi[a], c);
      }
    }
    node.box = box;
    if (n <= 1) return makeLeaf(node, begin, end);

    int mid = -1;
    if (depth < kMedianDepth) {
      int axis = -1, split_bin = 0;
      double best_cost = INFINITY;
      findSplit(begin, end, centroids, &axis, &split_bin, &best_cost);
      const double leaf_cost = blocks(n);
      const double split_cost = kTraversalCost + best_cost / std::max(box.area(), 1e-300);
      if (n <= kMaxLeafPrims && (axis < 0 || leaf_cost <= split_cost)) return makeLeaf(node, begin, end);
      if (axis >= 0) {
        const double lo = centroids.lo[axis];
        const double scale = kBins * (1 - 1e-6) / (double(centroids.hi[axis]) - lo);
        auto it = std::partition(m_refs.begin() + begin, m_refs.begin() + end, [&](const PrimRef& r) {
          return std::min(kBins - 1, static_cast<int>((r.centroid(axis) - lo) * scale)) < split_bin;
        });
        mid = static_cast<int>(it - m_refs.begin());
        if (mid == begin || mid == end) mid = -1;
      }
    } else if (n <= kMaxLeafPrims) {
      return makeLeaf(node, begin, end);
    }
    if (mid < 0) {
      // Centroids that bins cannot separate (or a deep path): object median
      // along the widest centroid axis.
      int axis = 0;
      for (int a = 1; a < 3; ++a)
        if (centroids.hi[a] - centroids.lo[a] > centroids.hi[axis] - centroids.lo[axis]) axis = a;
      mid = begin + n / 2;
      std::nth_element(m_refs.begin() + begin, m_refs.begin() + mid, m_refs.begin() + end,
                       [axis](const PrimRef& a, const PrimRef& b) { return a.centroid(axis) < b.centroid(axis); });
    }

    const int left = m_next.fetch_add(2);
    node.left = left;
    node.right = left + 1;
    TaskGroup group(m_budget);
    group.run([=] { buildNode(left, begin, mid, depth + 1); }, mid - begin >= kParallelPrims);
    buildNode(left + 1, mid, end, depth + 1);
    group.wait();
  }

  // Best binned SAH split: its axis (-1 if none), the first bin of the right
  // side, and its unnormalised cost (sum of area * blocks).
  void findSplit(int begin, int end, const Aabb& centroids, int* best_axis, int* best_bin, double* best_cost) {
    // One pass over the references bins all three axes (three passes read the
    // references three times: this was the builder's hottest loop). The bin of
    // each axis is the same expression as before, so the tree is unchanged.
    double lo[3], scale[3];
    bool usable[3];
    for (int axis = 0; axis < 3; ++axis) {
      lo[axis] = centroids.lo[axis];
      const double extent = double(centroids.hi[axis]) - lo[axis];
      usable[axis] = extent > 0;
      scale[axis] = usable[axis] ? kBins * (1 - 1e-6) / extent : 0;
    }
    Bin bins[3][kBins];
    for (int i = begin; i < end; ++i) {
      const PrimRef& r = m_refs[i];
      for (int axis = 0; axis < 3; ++axis) {
        const int b = std::min(kBins - 1, static_cast<int>((r.centroid(axis) - lo[axis]) * scale[axis]));
        Bin& bin = bins[axis][b];
        ++bin.count;
        for (int a = 0; a < 3; ++a) {
          bin.box.lo[a] = std::min(bin.box.lo[a], r.lo[a]);
          bin.box.hi[a] = std::max(bin.box.hi[a], r.hi[a]);
        }
      }
    }
    for (int axis = 0; axis < 3; ++axis) {
      if (!usable[axis]) continue;
      double right_cost[kBins];
      Aabb acc;
      int count = 0;
      for (int b = kBins - 1; b > 0; --b) {
        acc.extend(bins[axis][b].box);
        count += bins[axis][b].count;
        right_cost[b] = count ? acc.area() * blocks(count) : 0;
      }
      acc = Aabb();
      count = 0;
      for (int b = 1; b < kBins; ++b) {
        acc.extend(bins[axis][b - 1].box);
        count += bins[axis][b - 1].count;
        if (count == 0 || count == end - begin) continue;
        double cost = acc.area() * blocks(count) + right_cost[b];
        if (cost < *best_cost) {
          *best_cost = cost;
          *best_axis = axis;
          *best_bin = b;
        }
      }
    }
  }

  std::vector<PrimRef>& m_refs;
  ThreadBudget& m_budget;
  std::vector<Node2> m_nodes;
  std::atomic<int> m_next{1};
};

// Collapses the binary tree into 8-wide nodes and writes the leaves' packets.
// Linear bounds of each binary node (motion blur): its boxes at shutter open
// and close, the unions of its primitives' (prim_ref.h, objectLinearBounds).
struct MotionBoxes {
  std::vector<Aabb> open, close;
};

// Visits every binary node children first: leaf(node) for a leaf, then for an
// inner node join(node, child) for each of its two children.
template <typename Leaf, typename Join>
void childrenFirst(const std::vector<Node2>& nodes, Leaf leaf, Join join) {
  std::vector<std::pair<int, bool>> todo{{0, false}};
  while (!todo.empty()) {
    auto [node, children_done] = todo.back();
    todo.pop_back();
    const Node2& n = nodes[node];
    if (n.left < 0) {
      leaf(node);
    } else if (!children_done) {
      todo.push_back({node, true});
      todo.push_back({n.left, false});
      todo.push_back({n.right, false});
    } else {
      join(node, n.left);
      join(node, n.right);
    }
  }
}

// The nodes' linear bounds from the primitives' (PrimitiveSet::bounds_open and
// bounds_close).
MotionBoxes nodeMotionBoxes(const PrimitiveSet& prims, const std::vector<Node2>& nodes,
                            const std::vector<PrimRef>& refs) {
  MotionBoxes m;
  m.open.resize(nodes.size());
  m.close.resize(nodes.size());
  childrenFirst(
      nodes,
      [&](int node) {
        const Node2& n = nodes[node];
        for (int i = 0; i < n.count; ++i) {
          m.open[node].extend(prims.bounds_open[refs[n.first + i].index]);
          m.close[node].extend(prims.bounds_close[refs[n.first + i].index]);
        }
      },
      [&](int node, int child) {
        m.open[node].extend(m.open[child]);
        m.close[node].extend(m.close[child]);
      });
  return m;
}

// The diagonal slabs of every binary node (kdop_bounds.h).
std::vector<DiagonalSlabs> nodeDiagonalSlabs(const std::vector<ObjectGpu>& objects, const PrimitiveSet& prims,
                                             const std::vector<Node2>& nodes, const std::vector<PrimRef>& refs) {
  std::vector<DiagonalSlabs> slabs(nodes.size(), DiagonalSlabs::empty());
  childrenFirst(
      nodes,
      [&](int node) {
        const Node2& n = nodes[node];
        for (int i = 0; i < n.count; ++i) {
          const PrimRef& r = refs[n.first + i];
          slabs[node].extend(primitiveDiagonalSlabs(objects[r.id], prims.bounds[r.index]));
        }
      },
      [&](int node, int child) { slabs[node].extend(slabs[child]); });
  return slabs;
}

class WideFlattener {
 public:
  // `motion`: the nodes' linear bounds, for a tree over moving primitives (nodes
  // then carry their children's boxes at shutter open and at close); else null.
  // `kdop`: every binary node's diagonal slabs, for a tree whose nodes carry
  // them; else null.
  WideFlattener(const std::vector<ObjectGpu>& objects, const std::vector<Node2>& nodes,
                const std::vector<PrimRef>& refs, const MotionBoxes* motion, const std::vector<DiagonalSlabs>* kdop,
                DeviceAccel& out)
      : m_objects(objects), m_nodes(nodes), m_refs(refs), m_motion(motion), m_kdop(kdop), m_out(out) {
    m_ids.reserve(kMaxLeafPrims);
  }

  void run(double root_area) {
    m_root_area = root_area > 0 ? root_area : 1;
    m_wide.reserve(m_nodes.size() / 4 + 1);
    if (m_refs.empty()) {
      pushNode();
    } else if (m_nodes[0].left < 0) {
      // A single leaf: a root with one child.
      pushNode();
      setChild(0, 0, 0);
      m_stats.max_depth = 1;
      m_max_stack = 1;
    } else {
      flatten(0, 1, 0);
    }
    AccelStats& s = m_out.stats;
    s.node_count = m_wide.size() + m_leaves;
    s.leaf_count = m_leaves;
    s.sah_cost = m_sah;
    s.max_depth = m_stats.max_depth;
    m_out.kernel_options = "-DPRISM_ACCEL_BVH " + stackOption(m_max_stack + 1);
    if (m_motion) m_out.kernel_options += " -DPRISM_BVH_MOTION";
    if (m_kdop) m_out.kernel_options += " -DPRISM_BVH_KDOP";
    if (!m_motion && !m_kdop) {
      appendNodeWords(m_out.nodes, m_wide.data(), m_wide.size());
      return;
    }
    for (std::size_t i = 0; i < m_wide.size(); ++i) {
      appendNodeWords(m_out.nodes, &m_wide[i], 1);
      if (m_motion) appendNodeWords(m_out.nodes, &m_close[i], 1);
      if (m_kdop) appendNodeWords(m_out.nodes, &m_slabs[i], 1);
    }
  }

 private:
  // BvhNodeGpu and BvhMotionBoundsGpu share their six slabs of child boxes.
  template <typename Slabs>
  static void putBox(Slabs& n, int slot, const Aabb& box) {
    n.lo_x[slot] = box.lo[0];
    n.lo_y[slot] = box.lo[1];
    n.lo_z[slot] = box.lo[2];
    n.hi_x[slot] = box.hi[0];
    n.hi_y[slot] = box.hi[1];
    n.hi_z[slot] = box.hi[2];
  }

  // Every slot an inverted box, lo = big and hi = -big, that no ray meets.
  template <typename Slabs>
  static void invertSlots(Slabs& n, float big) {
    Aabb inverted;
    for (int a = 0; a < 3; ++a) {
      inverted.lo[a] = big;
      inverted.hi[a] = -big;
    }
    for (int i = 0; i < BVH_WIDTH; ++i) putBox(n, i, inverted);
  }

  // An empty slot of a motion node is inverted by +-FLT_MAX, not +-inf: the
  // kernel's lerp of inf and inf would be NaN, which fmin/fmax then ignore.
  void pushNode() {
    m_wide.push_back(emptyNode());
    if (m_kdop) {
      BvhKdopGpu k;
      const DiagonalSlabs none = DiagonalSlabs::empty();
      for (int slot = 0; slot < BVH_WIDTH; ++slot) putSlabs(k, slot, none);
      m_slabs.push_back(k);
    }
    if (!m_motion) return;
    invertSlots(m_wide.back(), FLT_MAX);
    m_close.emplace_back();
    invertSlots(m_close.back(), FLT_MAX);
  }

  static void putSlabs(BvhKdopGpu& k, int slot, const DiagonalSlabs& s) {
    for (int j = 0; j < BVH_KDOP_DIAGONALS; ++j) {
      k.slab[2 * j][slot] = s.lo[j];
      k.slab[2 * j + 1][slot] = s.hi[j];
    }
  }

  static BvhNodeGpu emptyNode() {
    BvhNodeGpu n{};
    invertSlots(n, INFINITY);
    for (int i = 0; i < BVH_WIDTH; ++i) n.child[i] = 0;
    return n;
  }

  // Puts binary node `node2` into slot `slot` of wide node `wide`: its box and
  // its code (a leaf's packets, or the wide node flattened from it).
  void setChild(int wide, int slot, int node2, int depth = 1, int stack = 0) {
    const Node2& c = m_nodes[node2];
    int code;
    if (c.left < 0) {
      m_ids.clear();
      for (int i = 0; i < c.count; ++i) m_ids.push_back(m_refs[c.first + i].id);
      PacketRange r = appendLeafPackets(m_objects, m_ids.data(), m_ids.size(), m_out.packets);
      code = ~static_cast<int>((r.start << BVH_LEAF_COUNT_BITS) | (r.count - 1));
      ++m_leaves;
      m_sah += c.box.area() / m_root_area * c.count;
      m_stats.max_depth = std::max(m_stats.max_depth, depth);
      m_max_stack = std::max(m_max_stack, stack);
    } else {
      code = flatten(node2, depth, stack);
    }
    putBox(m_wide[wide], slot, m_motion ? m_motion->open[node2] : c.box);
    m_wide[wide].child[slot] = code;
    if (m_motion) putBox(m_close[wide], slot, m_motion->close[node2]);
    if (m_kdop) putSlabs(m_slabs[wide], slot, (*m_kdop)[node2]);
  }

  int flatten(int node2, int depth, int stack) {
    int kids[BVH_WIDTH] = {m_nodes[node2].left, m_nodes[node2].right};
    int count = 2;
    while (count < BVH_WIDTH) {
      int best = -1;
      double best_area = -1;
      for (int i = 0; i < count; ++i) {
        const Node2& k = m_nodes[kids[i]];
        if (k.left >= 0 && k.box.area() > best_area) {
          best_area = k.box.area();
          best = i;
        }
      }
      if (best < 0) break;
      const Node2& open = m_nodes[kids[best]];
      kids[best] = open.left;
      kids[count++] = open.right;
    }
    const int index = static_cast<int>(m_wide.size());
    pushNode();
    m_sah += m_nodes[node2].box.area() / m_root_area;
    // The traversal keeps at most count - 1 siblings on the stack per level.
    for (int i = 0; i < count; ++i) setChild(index, i, kids[i], depth + 1, stack + count - 1);
    return index;
  }

  const std::vector<ObjectGpu>& m_objects;
  const std::vector<Node2>& m_nodes;
  const std::vector<PrimRef>& m_refs;
  const MotionBoxes* m_motion;
  const std::vector<DiagonalSlabs>* m_kdop;
  DeviceAccel& m_out;
  std::vector<BvhNodeGpu> m_wide;
  std::vector<BvhMotionBoundsGpu> m_close;  // m_wide[i]'s children at shutter close
  std::vector<BvhKdopGpu> m_slabs;          // m_wide[i]'s children's diagonal slabs
  std::vector<std::int32_t> m_ids;
  AccelStats m_stats;
  std::size_t m_leaves = 0;
  double m_sah = 0, m_root_area = 1;
  int m_max_stack = 0;
};

}  // namespace

void buildBvh(const std::vector<ObjectGpu>& objects, const PrimitiveSet& prims, const AccelBuildOptions& options,
              DeviceAccel& out) {
  // Over moving primitives with linear bounds, the tree groups primitives by
  // their boxes at mid-shutter (the SAH of the time-averaged box, roughly) and
  // each node keeps its children's boxes at open and close, which a ray
  // interpolates to its time; without, it is built over the swept boxes.
  const bool linear = prims.moving && options.bvh_linear_bounds && !prims.bounded.empty();
  std::vector<PrimRef> refs(prims.bounded.size());
  for (std::size_t i = 0; i < refs.size(); ++i) {
    Aabb b = prims.bounds[i];
    if (linear)
      for (int a = 0; a < 3; ++a) {
        b.lo[a] = 0.5f * prims.bounds_open[i].lo[a] + 0.5f * prims.bounds_close[i].lo[a];
        b.hi[a] = 0.5f * prims.bounds_open[i].hi[a] + 0.5f * prims.bounds_close[i].hi[a];
      }
    refs[i] = PrimRef{{b.lo[0], b.lo[1], b.lo[2]}, prims.bounded[i], {b.hi[0], b.hi[1], b.hi[2]},
                      static_cast<std::int32_t>(i)};
  }
  ThreadBudget budget(options.threads);
  std::vector<Node2> nodes = refs.empty() ? std::vector<Node2>{} : Bvh2Builder(refs, budget).build();
  writeSceneHeader(prims.scene, out);
  MotionBoxes motion;
  const bool moving = linear && !nodes.empty();
  if (moving) {
    motion = nodeMotionBoxes(prims, nodes, refs);
    out.nodes[0].v[3] = prims.shutter_open;
    out.nodes[1].v[3] = prims.shutter_close;
  }
  std::vector<DiagonalSlabs> slabs;
  if (options.kdop_bvh && !nodes.empty()) slabs = nodeDiagonalSlabs(objects, prims, nodes, refs);
  WideFlattener(objects, nodes, refs, moving ? &motion : nullptr, slabs.empty() ? nullptr : &slabs, out)
      .run(prims.scene.area());
  out.stats.references = refs.size();
  out.stats.mean_prims_per_leaf = out.stats.leaf_count ? double(refs.size()) / out.stats.leaf_count : 0;
  out.stats.duplication = 1;
}

}  // namespace prism
