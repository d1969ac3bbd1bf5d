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
#include <cmath>
#include <cstdint>

#include "accel/builders.h"
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
  std::int32_t pad;
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
    for (int axis = 0; axis < 3; ++axis) {
      const double lo = centroids.lo[axis];
      const double extent = double(centroids.hi[axis]) - lo;
      if (!(extent > 0)) continue;
      const double scale = kBins * (1 - 1e-6) / extent;
      Bin bins[kBins];
      for (int i = begin; i < end; ++i) {
        const PrimRef& r = m_refs[i];
        int b = std::min(kBins - 1, static_cast<int>((r.centroid(axis) - lo) * scale));
        Bin& bin = bins[b];
        ++bin.count;
        for (int a = 0; a < 3; ++a) {
          bin.box.lo[a] = std::min(bin.box.lo[a], r.lo[a]);
          bin.box.hi[a] = std::max(bin.box.hi[a], r.hi[a]);
        }
      }
      double right_cost[kBins];
      Aabb acc;
      int count = 0;
      for (int b = kBins - 1; b > 0; --b) {
        acc.extend(bins[b].box);
        count += bins[b].count;
        right_cost[b] = count ? acc.area() * blocks(count) : 0;
      }
      acc = Aabb();
      count = 0;
      for (int b = 1; b < kBins; ++b) {
        acc.extend(bins[b - 1].box);
        count += bins[b - 1].count;
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
class WideFlattener {
 public:
  WideFlattener(const std::vector<ObjectGpu>& objects, const std::vector<Node2>& nodes,
                const std::vector<PrimRef>& refs, DeviceAccel& out)
      : m_objects(objects), m_nodes(nodes), m_refs(refs), m_out(out) {
    m_ids.reserve(kMaxLeafPrims);
  }

  void run(double root_area) {
    m_root_area = root_area > 0 ? root_area : 1;
    m_wide.reserve(m_nodes.size() / 4 + 1);
    if (m_refs.empty()) {
      m_wide.push_back(emptyNode());
    } else if (m_nodes[0].left < 0) {
      // A single leaf: a root with one child.
      m_wide.push_back(emptyNode());
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
    appendNodeWords(m_out.nodes, m_wide.data(), m_wide.size());
  }

 private:
  static BvhNodeGpu emptyNode() {
    BvhNodeGpu n{};
    for (int i = 0; i < BVH_WIDTH; ++i) {
      n.lo_x[i] = n.lo_y[i] = n.lo_z[i] = INFINITY;
      n.hi_x[i] = n.hi_y[i] = n.hi_z[i] = -INFINITY;
      n.child[i] = 0;
    }
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
    BvhNodeGpu& n = m_wide[wide];
    n.lo_x[slot] = c.box.lo[0];
    n.lo_y[slot] = c.box.lo[1];
    n.lo_z[slot] = c.box.lo[2];
    n.hi_x[slot] = c.box.hi[0];
    n.hi_y[slot] = c.box.hi[1];
    n.hi_z[slot] = c.box.hi[2];
    n.child[slot] = code;
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
    m_wide.push_back(emptyNode());
    m_sah += m_nodes[node2].box.area() / m_root_area;
    // The traversal keeps at most count - 1 siblings on the stack per level.
    for (int i = 0; i < count; ++i) setChild(index, i, kids[i], depth + 1, stack + count - 1);
    return index;
  }

  const std::vector<ObjectGpu>& m_objects;
  const std::vector<Node2>& m_nodes;
  const std::vector<PrimRef>& m_refs;
  DeviceAccel& m_out;
  std::vector<BvhNodeGpu> m_wide;
  std::vector<std::int32_t> m_ids;
  AccelStats m_stats;
  std::size_t m_leaves = 0;
  double m_sah = 0, m_root_area = 1;
  int m_max_stack = 0;
};

}  // namespace

void buildBvh(const std::vector<ObjectGpu>& objects, const PrimitiveSet& prims, const AccelBuildOptions& options,
              DeviceAccel& out) {
  std::vector<PrimRef> refs(prims.bounded.size());
  for (std::size_t i = 0; i < refs.size(); ++i) {
    const Aabb& b = prims.bounds[i];
    refs[i] = PrimRef{{b.lo[0], b.lo[1], b.lo[2]}, prims.bounded[i], {b.hi[0], b.hi[1], b.hi[2]}, 0};
  }
  ThreadBudget budget(options.threads);
  std::vector<Node2> nodes = refs.empty() ? std::vector<Node2>{} : Bvh2Builder(refs, budget).build();
  writeSceneHeader(prims.scene, out);
  WideFlattener(objects, nodes, refs, out).run(prims.scene.area());
  out.stats.references = refs.size();
  out.stats.mean_prims_per_leaf = out.stats.leaf_count ? double(refs.size()) / out.stats.leaf_count : 0;
  out.stats.duplication = 1;
}

}  // namespace prism
