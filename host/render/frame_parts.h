// A frame shared by several processes (MPI ranks, or whatever transport a
// program embedding prism has): every part renders the same scene with the same
// options, traces a contiguous share of the frame's units on its own devices,
// and part 0 gathers what it needs to resolve the image. The image is the one a
// single process makes, bit for bit: a unit's samples depend on their keys
// alone, and part 0 sums the units' counts and resolves the film in unit order.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <utility>
#include <vector>

#include "render/gpu_scene.h"
#include "render/render_options.h"
#include "render/render_stats.h"

namespace prism {

using Bytes = std::vector<std::uint8_t>;

struct FrameParts {
  std::uint32_t part = 0;   // this process (0 resolves the frame)
  std::uint32_t parts = 1;  // processes sharing each frame
  // Collective: every part calls it, in the same order, with its own bytes.
  // to_all: every part receives every part's bytes, indexed by part; otherwise
  // part 0 does and the others receive nothing. Throws when the transport fails.
  std::function<std::vector<Bytes>(bool to_all, const Bytes& mine)> exchange;
  // Optional: an atomic compare-and-swap on one of `parts` 64-bit words that
  // every part sees, zero when the parts are set (render/shared_stretches.h).
  // With it, the units are dealt as each part's devices come free; without it,
  // each part traces its own stretch (partUnits). Called from any of the
  // render's threads, one call at a time. Throws when the transport fails.
  std::function<std::uint64_t(std::uint32_t word, std::uint64_t expected, std::uint64_t desired)> compare_swap;
  // The deals made on those words so far (their round, render/shared_stretches.h):
  // kept with the parts, so that every render given these parts goes on from
  // the last; a FrameParts made for fresh words starts a counter of its own.
  std::shared_ptr<std::uint32_t> deals = std::make_shared<std::uint32_t>(0);

  bool shared() const { return parts > 1; }
};

// The units [first, last) that part `part` of `parts` starts from (and, without
// FrameParts::compare_swap, traces): contiguous stretches of the unit
// sequence, in part order, as equal as they can be.
std::pair<std::size_t, std::size_t> partUnits(std::size_t units, std::uint32_t part, std::uint32_t parts);

// Packing for the exchanges. The parts run on machines of one byte order and
// one build of prism (the same struct layouts).
class ByteWriter {
 public:
  template <typename T>
  void put(const T& value) { putRaw(&value, sizeof(T)); }
  template <typename T>
  void putArray(const T* values, std::size_t n) { putRaw(values, n * sizeof(T)); }
  void putString(const std::string& s);
  Bytes take() { return std::move(m_bytes); }

 private:
  void putRaw(const void* data, std::size_t size);
  Bytes m_bytes;
};

class ByteReader {
 public:
  explicit ByteReader(const Bytes& bytes) : m_bytes(bytes) {}
  template <typename T>
  T get() {
    T value;
    getRaw(&value, sizeof(T));
    return value;
  }
  template <typename T>
  void getArray(T* values, std::size_t n) { getRaw(values, n * sizeof(T)); }
  std::string getString();
  bool done() const { return m_at == m_bytes.size(); }
  // Throws std::runtime_error unless every byte was read: another part sent more.
  void expectDone() const;

 private:
  // Throws std::runtime_error past the end: another part sent something else.
  void getRaw(void* data, std::size_t size);
  const Bytes& m_bytes;
  std::size_t m_at = 0;
};

// What must be the same on every part for their units to make one frame: the
// options, the choices made from them, the camera, the mesh data and the counts
// of objects, materials and lights, and how the units are dealt (every part
// with a compare-and-swap, or none), hashed (FNV-1a, 64 bits).
std::uint64_t frameFingerprint(const GpuScene& scene, const RenderOptions& options, FirstHitMode first_hit,
                               ShadowMode shadows, AccelKind accel, bool dealt_as_devices_come_free);

// Which part traced each unit, from each part's own list: every part sends
// the runs of units it traced (packUnitRuns) and reads everyone's
// (unpackUnitRuns into `part_of`, kNoPart where no one has yet). Throws
// std::runtime_error when two parts claim a unit, or, once every part is read
// (checkUnitsCovered), one that no part traced.
constexpr std::uint32_t kNoPart = ~std::uint32_t{0};
void packUnitRuns(ByteWriter& out, const std::vector<std::size_t>& owner, std::size_t no_owner);
void unpackUnitRuns(ByteReader& in, std::uint32_t part, std::vector<std::uint32_t>& part_of);
void checkUnitsCovered(const std::vector<std::uint32_t>& part_of);
// The runs [first, last) of consecutive units that part `part` traced, in order.
std::vector<std::pair<std::size_t, std::size_t>> unitRuns(const std::vector<std::uint32_t>& part_of,
                                                          std::uint32_t part);

// The counts of a run of units (rays, waves, film trips, the NaN finding).
void packUnitCounts(ByteWriter& out, const RenderStats* counts, std::size_t n);
void unpackUnitCounts(ByteReader& in, RenderStats* counts, std::size_t n);

// A part's devices and warnings, for part 0's report.
void packShares(ByteWriter& out, const RenderStats& stats);
// Appends another part's devices (their names prefixed "part p: ") and warnings.
void unpackShares(ByteReader& in, std::uint32_t part, RenderStats& stats);

}  // namespace prism
