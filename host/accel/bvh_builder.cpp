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
#include <cstddef>
#include <cstdint>
#include <utility>

#include "accel/box4.h"
#include "accel/builders.h"
#include "accel/kdop_bounds.h"
#include "accel/leaf_packets.h"
#include "accel/task_group.h"
#include "accel/uninitialised_vector.h"
#include "kernels/shared/bvh_node_gpu.h"

namespace prism {
namespace {

constexpr int kMaxLeafPrims = 16;      // at most 4 triangle + 4 other packets < BVH_LEAF_MAX_PACKETS
constexpr double kTraversalCost = 2.0;  // PERF-NOTES: traversal cost 2 against a 4-wide packet test of 1
constexpr int kParallelPrims = 1024;    // subtrees at least this big may go to another thread
constexpr int kMedianDepth = 48;        // below this depth, splits are object medians (bounded depth)

struct PrimRef {
  float lo[3];
  std::int32_t id;
  float hi[3];
  std::int32_t index;  // into the PrimitiveSet's arrays
  float centroid(int a) const { return lo[a] + hi[a]; }  // twice the centre: only order matters
  // The box as two four-lane words (lane 3: id and index, never read).
  Float4 lo4() const { return loadFloat4(this); }
  Float4 hi4() const { return loadFloat4(reinterpret_cast<const char*>(this) + 16); }
  Float4 centroid4() const { return xyzOnly(lo4() + hi4()); }
};
static_assert(sizeof(PrimRef) == 32 && offsetof(PrimRef, hi) == 16, "PrimRef is read as two Float4 words");

// Written on several threads, each its own run (uninitialised_vector.h).
using PrimRefs = UninitialisedVector<PrimRef>;

struct Node2 {
  Aabb box;
  std::int32_t left = -1;  // -1: leaf
  std::int32_t right = -1;
  std::int32_t first = 0, count = 0;
};
using Nodes2 = UninitialisedVector<Node2>;

double blocks(int n) { return static_cast<double>((n + PACKET_LANES - 1) / PACKET_LANES); }

// What a node's references span: their boxes and their centroids. A node gets
// its own from its parent's partition, so no node reads its references once
// more just to bound them.
struct RefExtent {
  Box4 box, centroids;
  void add(const PrimRef& r) {
    const Float4 lo = r.lo4(), hi = r.hi4();
    box.extend(lo, hi);
    centroids.extend(xyzOnly(lo + hi));
  }
};

// Centroid to bin, per axis, over a node's centroid bounds: the one
// expression that both the binning and the partition use. A node of n
// references gets 4 + n / 20 bins, at most kMaxBins, as Embree's binned
// builder counts them: small nodes, most of the tree, are priced on a few
// bins. One bin per reference (up to 32) made the sweep a fifth of a build,
// for trees no better (SAH 33.4 against 32.9 on the 69k bunny; docs/accel.md).
class BinMap {
 public:
  static constexpr int kMaxBins = 32;
  BinMap(const Box4& centroids, int references)
      : m_count(std::max(1, std::min(kMaxBins, 4 + references / 20))), m_lo(xyzOnly(centroids.lo)) {
    for (int a = 0; a < 3; ++a) {
      const float extent = centroids.hi[a] - centroids.lo[a];
      m_scale[a] = extent > 0 ? float(m_count * (1 - 1e-6)) / extent : 0.0f;
      // An extent too small for its reciprocal to be a float cannot be binned.
      m_usable[a] = extent > 0 && std::isfinite(extent) && std::isfinite(m_scale[a]);
      if (!m_usable[a]) m_scale[a] = 0.0f;
    }
    m_scale[3] = 0.0f;
    const float top = static_cast<float>(m_count - 1);
    m_top = Float4{top, top, top, 0.0f};
  }
  int count() const { return m_count; }
  bool usable(int axis) const { return m_usable[axis]; }
  // Bins of r's centroid on the three axes (lane 3: 0). Clamped in float, NaN
  // to 0, before the conversion, which is only defined for values that fit.
  Int4 bins(const PrimRef& r) const {
    const Float4 x = xyzOnly((r.centroid4() - m_lo) * m_scale);
    const Float4 zero = {0, 0, 0, 0};
    const Float4 low = x >= zero ? x : zero;
    return __builtin_convertvector(low < m_top ? low : m_top, Int4);
  }

 private:
  int m_count;
  Float4 m_lo, m_scale = {0, 0, 0, 0}, m_top;
  bool m_usable[3];
};

// A split of a node's references: on which axis (-1: none found), where (a
// bin: the first of the right side), and its unnormalised SAH
// cost (sum of area * blocks over the two sides).
struct Split {
  int axis = -1;
  int at = 0;
  double cost = INFINITY;
};

constexpr int kTwoBinSetsPrims = 1024;  // nodes this big bin into two sets (binnedSplit)

// The bins of one node on the three axes: the boxes and counts of the
// references whose centroids fall in each (the first `bins` of each axis used,
// and only those made empty: small nodes, most of the tree, use few bins).
struct BinSet {
  static constexpr int kBins = BinMap::kMaxBins;
  // A box as its two corners (Box4's own members would all be initialised).
  Float4 lo[3][kBins], hi[3][kBins];
  int counts[3][kBins];
  int bins;

  explicit BinSet(int count) : bins(count) {
    const Box4 empty;
    for (int axis = 0; axis < 3; ++axis)
      for (int b = 0; b < bins; ++b) {
        lo[axis][b] = empty.lo;
        hi[axis][b] = empty.hi;
        counts[axis][b] = 0;
      }
  }
  void add(const PrimRef& r, Int4 bin) {
    const Float4 l = r.lo4(), h = r.hi4();
    for (int axis = 0; axis < 3; ++axis) {
      const int b = bin[axis];
      lo[axis][b] = lowerOf(l, lo[axis][b]);
      hi[axis][b] = upperOf(h, hi[axis][b]);
      ++counts[axis][b];
    }
  }
  void add(const BinSet& other) {
    for (int axis = 0; axis < 3; ++axis)
      for (int b = 0; b < bins; ++b) {
        lo[axis][b] = lowerOf(other.lo[axis][b], lo[axis][b]);
        hi[axis][b] = upperOf(other.hi[axis][b], hi[axis][b]);
        counts[axis][b] += other.counts[axis][b];
      }
  }
};

class Bvh2Builder {
 public:
  Bvh2Builder(PrimRefs& refs, ThreadBudget& budget) : m_refs(refs), m_pool(budget) {}

  // `all`: what every reference spans.
  Nodes2 build(const RefExtent& all) {
    const int n = static_cast<int>(m_refs.size());
    // Room for the most nodes n references can make (2n - 1), left
    // untouched until used: a tree of leaves of about 11 references claims a
    // fifth of it, and initialising all of it took 50 ms at 1.1M references.
    m_nodes.resize(std::max(1, 2 * n - 1));
    m_next = 1;
    m_pool.run(Subtree{0, 0, n, 0, all},
               [this](const Subtree& t) { buildNode(t.index, t.begin, t.end, t.depth, t.extent); },
               n >= 2 * kParallelPrims);
    m_nodes.resize(m_next.load());  // the tree in place, its unused room never touched
    return std::move(m_nodes);
  }

 private:
  static constexpr int kBins = BinMap::kMaxBins;

  void makeLeaf(Node2& node, int begin, int end) {
    node.left = node.right = -1;
    node.first = begin;
    node.count = end - begin;
  }

  void buildNode(int index, int begin, int end, int depth, const RefExtent& extent) {
    Node2& node = m_nodes[index] = Node2{};
    const int n = end - begin;
    node.box = extent.box.aabb();
    if (n <= 1) return makeLeaf(node, begin, end);

    // A leaf of at most 2 packets costs no more than the node step alone, so
    // no split can beat it: no need to price them.
    if (blocks(n) <= kTraversalCost && n <= kMaxLeafPrims) return makeLeaf(node, begin, end);
    int mid = -1;
    RefExtent left, right;
    if (depth < kMedianDepth) {
      const BinMap map(extent.centroids, n);
      const Split split = binnedSplit(begin, end, map);
      const double leaf_cost = blocks(n);
      const double split_cost = kTraversalCost + split.cost / std::max(node.box.area(), 1e-300);
      if (n <= kMaxLeafPrims && (split.axis < 0 || leaf_cost <= split_cost)) return makeLeaf(node, begin, end);
      if (split.axis >= 0) {
        mid = partition(begin, end, map, split.axis, split.at, &left, &right);
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
        if (extent.centroids.hi[a] - extent.centroids.lo[a] > extent.centroids.hi[axis] - extent.centroids.lo[axis])
          axis = a;
      mid = begin + n / 2;
      std::nth_element(m_refs.begin() + begin, m_refs.begin() + mid, m_refs.begin() + end,
                       [axis](const PrimRef& a, const PrimRef& b) { return a.centroid(axis) < b.centroid(axis); });
      left = right = RefExtent();
      for (int i = begin; i < mid; ++i) left.add(m_refs[i]);
      for (int i = mid; i < end; ++i) right.add(m_refs[i]);
    }

    const int first_child = m_next.fetch_add(2);
    node.left = first_child;
    node.right = first_child + 1;
    if (mid - begin < kParallelPrims || !m_pool.offer(Subtree{first_child, begin, mid, depth + 1, left}))
      buildNode(first_child, begin, mid, depth + 1, left);
    buildNode(first_child + 1, mid, end, depth + 1, right);
  }

  // Moves the references whose bin on `axis` lies before `split_bin` to the
  // front of [begin, end) and returns where the others start; bounds both sides
  // after. In place and without branches on the references (a branch per
  // reference mispredicts half the time): each reference swaps with the first
  // of those found going right so far, and the left side grows by one where it
  // goes left (where it goes right, two of the right side trade places). Out of
  // place through a scratch array and back, whole builds took a fifth longer
  // (docs/accel.md, "The partition in place"): a second copy of every
  // reference at every level, and at the root the scratch's first touch on
  // one thread.
  int partition(int begin, int end, const BinMap& map, int axis, int split_bin, RefExtent* left, RefExtent* right) {
    PrimRef* refs = m_refs.data();
    int front = begin;
    for (int i = begin; i < end; ++i) {
      const PrimRef ref = refs[i];
      const bool goes_left = map.bins(ref)[axis] < split_bin;
      refs[i] = refs[front];
      refs[front] = ref;
      front += goes_left;
    }
    RefExtent l, r;
    for (int i = begin; i < front; ++i) l.add(refs[i]);
    for (int i = front; i < end; ++i) r.add(refs[i]);
    *left = l;
    *right = r;
    return front;
  }

  // Best binned SAH split: its axis (-1 if none), the first bin of the right
  // side, and its unnormalised cost (sum of area * blocks). One pass over the
  // references bins all three axes.
  Split binnedSplit(int begin, int end, const BinMap& map) const {
    const int bins = map.count();
    BinSet set(bins);
    int i = begin;
    if (end - begin >= kTwoBinSetsPrims) {
      // Neighbouring references mostly fall in the same bins, and each update
      // would wait for the last one's store: even and odd references go to
      // two sets of bins, summed after.
      BinSet odd(bins);
      for (; i + 1 < end; i += 2) {
        set.add(m_refs[i], map.bins(m_refs[i]));
        odd.add(m_refs[i + 1], map.bins(m_refs[i + 1]));
      }
      set.add(odd);
    }
    for (; i < end; ++i) set.add(m_refs[i], map.bins(m_refs[i]));
    // A split after an empty bin costs what the split before it does, so only
    // splits after a filled bin are priced (most bins of a small node are empty).
    Split best;
    for (int axis = 0; axis < 3; ++axis) {
      if (!map.usable(axis)) continue;
      const int* count_of = set.counts[axis];
      double right_cost[kBins];
      Box4 acc;
      int count = 0;
      double cost_here = 0;
      for (int b = bins - 1; b > 0; --b) {
        if (count_of[b]) {
          acc.extend(set.lo[axis][b], set.hi[axis][b]);
          count += count_of[b];
          cost_here = acc.area() * blocks(count);
        }
        right_cost[b] = cost_here;
      }
      acc = Box4();
      count = 0;
      for (int b = 1; b < bins; ++b) {
        if (!count_of[b - 1]) continue;
        acc.extend(set.lo[axis][b - 1], set.hi[axis][b - 1]);
        count += count_of[b - 1];
        if (count == end - begin) break;
        const double cost = acc.area() * blocks(count) + right_cost[b];
        if (cost < best.cost) best = Split{axis, b, cost};
      }
    }
    return best;
  }

  PrimRefs& m_refs;
  // A node still to build: its room, its references and what they span.
  struct Subtree {
    int index, begin, end, depth;
    RefExtent extent;
  };
  TaskPool<Subtree> m_pool;
  Nodes2 m_nodes;  // node i written when buildNode claims it
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
void childrenFirst(const Nodes2& nodes, Leaf leaf, Join join) {
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
MotionBoxes nodeMotionBoxes(const PrimitiveSet& prims, const Nodes2& nodes,
                            const PrimRefs& refs) {
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
                                             const Nodes2& nodes, const PrimRefs& refs) {
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

// The binary tree's leaves that hold references, in the order of their
// references (a node's left child holds the front of its range).
std::vector<std::int32_t> leavesInOrder(const Nodes2& nodes) {
  std::vector<std::int32_t> leaves, todo;
  if (nodes.empty()) return leaves;
  leaves.reserve(nodes.size() / 2 + 1);
  todo.push_back(0);
  while (!todo.empty()) {
    const Node2& n = nodes[todo.back()];
    if (n.left < 0) {
      if (n.count > 0) leaves.push_back(todo.back());
      todo.pop_back();
      continue;
    }
    todo.back() = n.right;
    todo.push_back(n.left);
  }
  return leaves;
}

// Every binary leaf's packets (indexed by node; inner nodes get none). The
// leaves are taken in the order of their references, cut into one run per
// thread of about the same number of references, each written on its own
// thread. Reading the leaves' objects is most of the work (they lie scattered
// in memory), hence the threads and the prefetching. Where every primitive is
// a packet triangle (`triangles_only`, a mesh scene), a leaf of n takes
// ceil(n / 4) packets, so each run writes straight to its leaves' places in
// `packets`, its pages first touched on its own thread; otherwise the runs'
// packets are joined in order after. Either way the packets lie in leaf
// order, so the result does not depend on the thread count.
std::vector<PacketRange> writeLeafPackets(const std::vector<ObjectGpu>& objects, const Nodes2& nodes,
                                          const PrimRefs& refs, bool triangles_only, ThreadBudget& budget,
                                          PacketVector& packets) {
  std::vector<PacketRange> ranges(nodes.size());
  const std::vector<std::int32_t> leaves = leavesInOrder(nodes);
  const std::size_t runs = runsFor(budget, refs.size(), kParallelBoundsPrims);
  std::vector<std::size_t> run_start(runs + 1, leaves.size());
  run_start[0] = 0;
  for (std::size_t r = 1, leaf = 0; r < runs; ++r) {
    const std::size_t refs_before = runRange(refs.size(), r, runs).first;
    while (leaf < leaves.size() && static_cast<std::size_t>(nodes[leaves[leaf]].first) < refs_before) ++leaf;
    run_start[r] = leaf;
  }
  if (triangles_only) {
    std::uint32_t next = static_cast<std::uint32_t>(packets.size());
    for (std::int32_t leaf : leaves) {
      const auto count = static_cast<std::uint32_t>((nodes[leaf].count + PACKET_LANES - 1) / PACKET_LANES);
      ranges[leaf] = PacketRange{next, count};
      next += count;
    }
    packets.resize(next);
  }
  std::vector<PacketVector> run_packets(triangles_only ? 0 : runs);
  auto writeRun = [&](std::size_t r) {
    PacketVector* out = triangles_only ? nullptr : &run_packets[r];
    // A leaf of n triangles takes ceil(n / 4) packets, at most n / 4 + 1 (a
    // leaf mixing kinds may take more: only the room's first guess); the first
    // run makes room for every run's, as the others are joined onto it.
    if (out) {
      const std::size_t leaves_in = r == 0 ? leaves.size() : run_start[r + 1] - run_start[r];
      const std::size_t refs_in = r == 0 ? refs.size() : refs.size() / runs + 1;
      out->reserve(refs_in / PACKET_LANES + leaves_in);
    }
    std::int32_t ids[kMaxLeafPrims];  // every leaf holds at most kMaxLeafPrims
    for (std::size_t k = run_start[r]; k < run_start[r + 1]; ++k) {
      const Node2& leaf = nodes[leaves[k]];
      // The objects of a leaf a few leaves ahead, on their way into the cache.
      if (k + 4 < run_start[r + 1]) {
        const Node2& ahead = nodes[leaves[k + 4]];
        for (int i = 0; i < ahead.count; ++i) __builtin_prefetch(&objects[refs[ahead.first + i].id]);
      }
      for (int i = 0; i < leaf.count; ++i) ids[i] = refs[leaf.first + i].id;
      if (out)
        ranges[leaves[k]] = appendLeafPackets(objects, ids, leaf.count, *out);
      else
        writeTrianglePackets(objects, ids, leaf.count, &packets[ranges[leaves[k]].start]);
    }
  };
  forEachRun(budget, runs, writeRun);
  if (triangles_only) return ranges;
  std::size_t total = packets.size();
  for (const auto& run : run_packets) total += run.size();
  for (std::size_t r = 0; r < runs; ++r) {
    const auto offset = static_cast<std::uint32_t>(packets.size());
    for (std::size_t k = run_start[r]; k < run_start[r + 1]; ++k) ranges[leaves[k]].start += offset;
    if (packets.empty()) {  // the first run in place, usually with room for the rest
      packets = std::move(run_packets[r]);
      packets.reserve(total);
    } else {
      packets.insert(packets.end(), run_packets[r].begin(), run_packets[r].end());
    }
  }
  return ranges;
}

class WideFlattener {
 public:
  // `motion`: the nodes' linear bounds, for a tree over moving primitives (nodes
  // then carry their children's boxes at shutter open and at close); else null.
  // `kdop`: every binary node's diagonal slabs, for a tree whose nodes carry
  // them; else null.
  // `leaf_packets`: each binary leaf's packets, already in out.packets.
  WideFlattener(const Nodes2& nodes, const std::vector<PacketRange>& leaf_packets,
                const MotionBoxes* motion, const std::vector<DiagonalSlabs>* kdop, DeviceAccel& out)
      : m_nodes(nodes), m_leaf_packets(leaf_packets), m_motion(motion), m_kdop(kdop), m_out(out) {}

  void run(double root_area) {
    m_root_area = root_area > 0 ? root_area : 1;
    m_wide.reserve(m_nodes.size() / 4 + 1);
    if (m_nodes.empty()) {
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
      const PacketRange r = m_leaf_packets[node2];
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

  const Nodes2& m_nodes;
  const std::vector<PacketRange>& m_leaf_packets;
  const MotionBoxes* m_motion;
  const std::vector<DiagonalSlabs>* m_kdop;
  DeviceAccel& m_out;
  std::vector<BvhNodeGpu> m_wide;
  std::vector<BvhMotionBoundsGpu> m_close;  // m_wide[i]'s children at shutter close
  std::vector<BvhKdopGpu> m_slabs;          // m_wide[i]'s children's diagonal slabs
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
  // The references, and what they span, written on every thread in runs.
  PrimRefs refs(prims.bounded.size());
  ThreadBudget budget(options.threads);
  const std::size_t runs = runsFor(budget, refs.size(), kParallelBoundsPrims);
  std::vector<RefExtent> run_extent(runs);
  forEachRun(budget, runs, [&](std::size_t r) {
    const auto [first, end] = runRange(refs.size(), r, runs);
    RefExtent extent;  // here, not in run_extent[r], which shares a cache line with the next run's
    for (std::size_t i = first; i < end; ++i) {
      Aabb b = prims.bounds[i];
      if (linear)
        for (int a = 0; a < 3; ++a) {
          b.lo[a] = 0.5f * prims.bounds_open[i].lo[a] + 0.5f * prims.bounds_close[i].lo[a];
          b.hi[a] = 0.5f * prims.bounds_open[i].hi[a] + 0.5f * prims.bounds_close[i].hi[a];
        }
      refs[i] = PrimRef{{b.lo[0], b.lo[1], b.lo[2]}, prims.bounded[i], {b.hi[0], b.hi[1], b.hi[2]},
                        static_cast<std::int32_t>(i)};
      extent.add(refs[i]);
    }
    run_extent[r] = extent;
  });
  RefExtent all;
  for (const RefExtent& e : run_extent) {
    all.box.extend(e.box);
    all.centroids.extend(e.centroids);
  }
  Nodes2 nodes = refs.empty() ? Nodes2{} : Bvh2Builder(refs, budget).build(all);
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
  const std::vector<PacketRange> leaf_packets =
      writeLeafPackets(objects, nodes, refs, prims.triangles_only, budget, out.packets);
  WideFlattener(nodes, leaf_packets, moving ? &motion : nullptr, slabs.empty() ? nullptr : &slabs, out)
      .run(prims.scene.area());
  out.stats.references = refs.size();
  out.stats.mean_prims_per_leaf = out.stats.leaf_count ? double(refs.size()) / out.stats.leaf_count : 0;
  out.stats.duplication = 1;
}

}  // namespace prism
