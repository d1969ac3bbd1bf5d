// Octree: an adaptive subdivision of a box around the scene into eight octants
// at a time (kernels/shared/octree_node_gpu.h). Termination rule: a cell splits
// while it holds more than AccelBuildOptions::octree_leaf_prims primitives and
// its depth is below octree_max_depth, unless
//   - the split makes no progress: two or more octants would each receive all
//     of the cell's primitives (many large primitives crossing the cell);
//   - the octants would hold more than octree_max_growth times the cell's
//     references in all: the cells have become smaller than the primitives,
//     and halving them again mostly copies references (on a scanned mesh this
//     is what bounds memory, PERF notes in docs/accel.md);
//   - the cell is too small to halve in float. A primitive goes into every octant it meets, decided exactly
// (exact_predicates.h); octants left empty are not stored.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <memory>

#include "accel/builders.h"
#include "accel/exact_predicates.h"
#include "accel/leaf_packets.h"
#include "accel/task_group.h"
#include "kernels/shared/octree_node_gpu.h"

namespace prism {
namespace {

constexpr std::size_t kParallelPrims = 2048;

struct Cell {
  CellBox box;
  float center[3] = {0, 0, 0};
  Aabb content;                     // the contents' bounds clipped to `box`
  std::vector<std::int32_t> items;  // positions in PrimitiveSet::bounded (leaves only)
  std::unique_ptr<Cell> kids[8];
  bool leaf = true;
};

class OctreeBuilder {
 public:
  OctreeBuilder(const std::vector<ObjectGpu>& objects, const PrimitiveSet& prims, const AccelBuildOptions& options)
      : m_objects(objects), m_prims(prims), m_options(options), m_budget(options.threads) {}

  std::unique_ptr<Cell> build(const CellBox& root) {
    std::vector<std::int32_t> all(m_prims.bounded.size());
    for (std::size_t i = 0; i < all.size(); ++i) all[i] = static_cast<std::int32_t>(i);
    auto cell = std::make_unique<Cell>();
    cell->box = root;
    buildCell(*cell, std::move(all), 0);
    return cell;
  }

  std::size_t exactTests() const { return m_exact_tests.load(); }

 private:
  void buildCell(Cell& cell, std::vector<std::int32_t> items, int depth) {
    const std::size_t n = items.size();
    float c[3];
    bool can_halve = true;
    for (int a = 0; a < 3; ++a) {
      c[a] = static_cast<float>(0.5 * (cell.box.lo[a] + cell.box.hi[a]));
      if (!(c[a] > cell.box.lo[a] && c[a] < cell.box.hi[a])) can_halve = false;
    }
    if (n <= static_cast<std::size_t>(m_options.octree_leaf_prims) || depth >= m_options.octree_max_depth ||
        !can_halve) {
      makeLeaf(cell, std::move(items));
      return;
    }

    std::vector<std::int32_t> lists[8];
    std::size_t tests = 0;
    for (std::int32_t item : items) {
      const Aabb& b = m_prims.bounds[item];
      const ObjectGpu& ob = m_objects[m_prims.bounded[item]];
      // Octants the box reaches on each axis: bit 0 the low side, bit 1 the high side.
      int sides[3];
      for (int a = 0; a < 3; ++a) sides[a] = (b.lo[a] <= c[a] ? 1 : 0) | (b.hi[a] >= c[a] ? 2 : 0);
      bool single = sides[0] != 3 && sides[1] != 3 && sides[2] != 3;
      for (int k = 0; k < 8; ++k) {
        if (!(sides[0] & (k & 1 ? 2 : 1)) || !(sides[1] & (k & 2 ? 2 : 1)) || !(sides[2] & (k & 4 ? 2 : 1))) continue;
        // One candidate octant: the primitive meets the cell and lies in the
        // octant's half-spaces, so it meets the octant.
        if (single || overlapsCell(ob, b, octant(cell.box, c, k), &tests)) lists[k].push_back(item);
      }
    }
    m_exact_tests += tests;

    // No progress: two or more octants and each of them would hold everything.
    // (One octant holding everything is progress: the cell shrinks around it.)
    bool progress = false;
    std::size_t total = 0, occupied = 0;
    for (auto& l : lists) {
      if (!l.empty() && l.size() < n) progress = true;
      occupied += l.empty() ? 0 : 1;
      total += l.size();
    }
    if (occupied == 1) progress = true;
    if (total > m_options.octree_max_growth * n) progress = false;
    if (!progress) {
      makeLeaf(cell, std::move(items));
      return;
    }
    items.clear();
    items.shrink_to_fit();

    cell.leaf = false;
    std::copy(c, c + 3, cell.center);
    TaskGroup group(m_budget);
    for (int k = 0; k < 8; ++k) {
      if (lists[k].empty()) continue;
      cell.kids[k] = std::make_unique<Cell>();
      Cell* kid = cell.kids[k].get();
      kid->box = octant(cell.box, c, k);
      const bool big = lists[k].size() >= kParallelPrims;
      group.run([this, kid, list = std::move(lists[k]), depth]() mutable { buildCell(*kid, std::move(list), depth + 1); },
                big);
    }
    group.wait();
    for (const auto& kid : cell.kids)
      if (kid) cell.content.extend(kid->content);
  }

  void makeLeaf(Cell& cell, std::vector<std::int32_t> items) {
    cell.items = std::move(items);
    for (std::int32_t item : cell.items) {
      // Exact: the cell's corners are floats.
      Aabb b = m_prims.bounds[item];
      for (int a = 0; a < 3; ++a) {
        b.lo[a] = std::max(b.lo[a], static_cast<float>(cell.box.lo[a]));
        b.hi[a] = std::min(b.hi[a], static_cast<float>(cell.box.hi[a]));
      }
      cell.content.extend(b);
    }
  }

  static CellBox octant(const CellBox& box, const float c[3], int k) {
    CellBox o = box;
    for (int a = 0; a < 3; ++a) {
      if (k & (1 << a))
        o.lo[a] = c[a];
      else
        o.hi[a] = c[a];
    }
    return o;
  }

  const std::vector<ObjectGpu>& m_objects;
  const PrimitiveSet& m_prims;
  const AccelBuildOptions& m_options;
  ThreadBudget m_budget;
  std::atomic<std::size_t> m_exact_tests{0};
};

class OctreeFlattener {
 public:
  OctreeFlattener(const std::vector<ObjectGpu>& objects, const PrimitiveSet& prims, DeviceAccel& out)
      : m_objects(objects), m_prims(prims), m_out(out), m_refs(prims.bounded.size(), 0) {}

  void run(const Cell& root) {
    m_root_area = std::max(root.box.area(), 1e-300);
    m_nodes.emplace_back();
    flatten(root, 0, 0);
    AccelStats& s = m_out.stats;
    s.node_count = m_nodes.size();
    s.max_depth = m_max_depth;
    s.sah_cost = m_sah;
    finishReferenceStats(m_refs, s);
    // One ray's closest hits push up to four octants per cell, or all eight
    // where its centre-plane crossings tie (octree_push); shadow rays and
    // packets (kernels/accel/octree_packets.h) push every stored octant: at
    // most seven left waiting a level.
    m_out.kernel_options = "-DPRISM_ACCEL_OCTREE " + stackOption(7 * m_max_depth + 2);
    appendNodeWords(m_out.nodes, m_nodes.data(), m_nodes.size());
  }

 private:
  void flatten(const Cell& cell, std::size_t index, int depth) {
    m_max_depth = std::max(m_max_depth, depth);
    const double rel = cell.box.area() / m_root_area;
    if (cell.leaf) {
      m_ids.clear();
      for (std::int32_t item : cell.items) {
        m_ids.push_back(m_prims.bounded[item]);
        ++m_refs[item];
      }
      PacketRange r = appendLeafPackets(m_objects, m_ids.data(), m_ids.size(), m_out.packets);
      OctreeNodeGpu& n = m_nodes[index];
      n = nodeWithBox(cell);
      n.first = static_cast<int>(r.start);
      n.packet_count = static_cast<int>(r.count);
      m_sah += rel * cell.items.size();
      if (cell.items.empty())
        ++m_out.stats.empty_leaf_count;
      else
        ++m_out.stats.leaf_count;
      return;
    }
    m_sah += rel;
    int mask = 0;
    for (int k = 0; k < 8; ++k)
      if (cell.kids[k]) mask |= 1 << k;
    const std::size_t first = m_nodes.size();
    m_nodes.resize(first + __builtin_popcount(mask));
    OctreeNodeGpu& n = m_nodes[index];
    n = nodeWithBox(cell);
    n.cx = cell.center[0];
    n.cy = cell.center[1];
    n.cz = cell.center[2];
    n.first = static_cast<int>(first);
    n.child_mask = mask;
    std::size_t slot = first;
    for (int k = 0; k < 8; ++k)
      if (cell.kids[k]) flatten(*cell.kids[k], slot++, depth + 1);
  }

  static OctreeNodeGpu nodeWithBox(const Cell& cell) {
    OctreeNodeGpu n{};
    n.lo_x = cell.content.lo[0];
    n.lo_y = cell.content.lo[1];
    n.lo_z = cell.content.lo[2];
    n.hi_x = cell.content.hi[0];
    n.hi_y = cell.content.hi[1];
    n.hi_z = cell.content.hi[2];
    return n;
  }

  const std::vector<ObjectGpu>& m_objects;
  const PrimitiveSet& m_prims;
  DeviceAccel& m_out;
  std::vector<int> m_refs;
  std::vector<OctreeNodeGpu> m_nodes;
  std::vector<std::int32_t> m_ids;
  double m_sah = 0, m_root_area = 1;
  int m_max_depth = 0;
};

}  // namespace

void buildOctree(const std::vector<ObjectGpu>& objects, const PrimitiveSet& prims, const AccelBuildOptions& options,
                 DeviceAccel& out) {
  // A cube around the scene, a little larger so no primitive touches its faces
  // by rounding; its corners are floats, like every split point below.
  CellBox root{{0, 0, 0}, {0, 0, 0}};
  if (!prims.bounded.empty()) {
    double half = 0;
    for (int a = 0; a < 3; ++a) half = std::max(half, 0.5 * (double(prims.scene.hi[a]) - prims.scene.lo[a]));
    half = half * (1 + 1e-4) + 1e-6 * std::max(1.0, half);
    for (int a = 0; a < 3; ++a) {
      double mid = 0.5 * (double(prims.scene.lo[a]) + prims.scene.hi[a]);
      root.lo[a] = roundDown(std::min<double>(mid - half, prims.scene.lo[a]));
      root.hi[a] = roundUp(std::max<double>(mid + half, prims.scene.hi[a]));
    }
  }
  OctreeBuilder builder(objects, prims, options);
  std::unique_ptr<Cell> tree = builder.build(root);
  Aabb header;
  for (int a = 0; a < 3; ++a) {
    header.lo[a] = static_cast<float>(root.lo[a]);
    header.hi[a] = static_cast<float>(root.hi[a]);
  }
  if (prims.bounded.empty()) header = Aabb();
  writeSceneHeader(header, out);
  OctreeFlattener(objects, prims, out).run(*tree);
  out.stats.exact_tests = builder.exactTests();
}

}  // namespace prism
