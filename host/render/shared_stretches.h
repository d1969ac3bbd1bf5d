// A frame's units dealt over the processes that share it (frame_parts.h) as
// their devices come free, so that a process with faster devices takes more of
// them. Part p takes from the front of its own stretch (partUnits), so its
// units stay contiguous; with its stretch done, it takes from the back of the
// stretch with the most units left. The state is one 64-bit word per part that
// every part can compare-and-swap (FrameParts::compare_swap; over MPI, a window
// on rank 0): the deal's round (16 bits) and the units taken from the
// stretch's front and back. A word of another round reads as untouched, so the
// words need no reset between deals: every part starts the next deal only
// after an exchange that follows everyone's last take of this one, and every
// word is brought to the round in every deal with units (a stretch with units
// is emptied; the owner of an empty one marks it at its first take), so a
// stale word is one round old and the round's wrap at 65,536 is harmless.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "render/work_dealer.h"

namespace prism {

// Atomically: returns word `word`'s value, and sets it to `desired` if that was `expected`.
using CompareSwap = std::function<std::uint64_t(std::uint32_t word, std::uint64_t expected, std::uint64_t desired)>;

class SharedStretches : public UnitSource {
 public:
  // The most units a stretch can hold (24 bits of the word count each end).
  static constexpr std::size_t kMaxStretch = (std::size_t{1} << 24) - 1;

  // round: the deal's, counted by the parts alike (deals without units take
  // none). Throws std::invalid_argument unless part < parts and every stretch
  // fits kMaxStretch.
  SharedStretches(const std::vector<std::uint64_t>& unit_samples, std::uint32_t part, std::uint32_t parts,
                  std::uint16_t round, CompareSwap compare_swap);

  std::optional<std::size_t> take() override;
  bool exhausted() const override { return m_exhausted; }
  double nextSamples() const override { return m_largest; }
  double samplesLeft() const override;
  std::size_t expectedUnits() const override;

  // What one word holds (exposed for the tests).
  struct Word {
    std::uint16_t round = 0;
    std::uint32_t front = 0, back = 0;  // units taken from either end
  };
  static std::uint64_t encode(const Word& w);
  static Word decode(std::uint64_t bits);

 private:
  // The word of part q as last seen, read as of this round.
  Word seen(std::uint32_t q) const;
  std::size_t leftIn(std::uint32_t q) const;
  // Takes a unit from the front (own stretch) or back of part q's stretch;
  // none once it is empty.
  std::optional<std::size_t> takeFrom(std::uint32_t q, bool from_back);
  // Brings this part's word to this round (its stretch is empty).
  void markOwnWord();

  std::size_t m_units;  // in the frame
  std::uint32_t m_part, m_parts;
  std::uint16_t m_round;
  CompareSwap m_swap;
  std::vector<std::uint64_t> m_seen;  // each part's word as last read
  double m_largest = 0, m_mean = 0;
  std::size_t m_taken = 0;
  bool m_exhausted = false;
  bool m_began = false;  // take has been called
};

}  // namespace prism
