#include "render/shared_stretches.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "render/frame_parts.h"

namespace prism {

std::uint64_t SharedStretches::encode(const Word& w) {
  return (std::uint64_t{w.round} << 48) | (std::uint64_t{w.front} << 24) | std::uint64_t{w.back};
}

SharedStretches::Word SharedStretches::decode(std::uint64_t bits) {
  Word w;
  w.round = static_cast<std::uint16_t>(bits >> 48);
  w.front = static_cast<std::uint32_t>((bits >> 24) & kMaxStretch);
  w.back = static_cast<std::uint32_t>(bits & kMaxStretch);
  return w;
}

SharedStretches::SharedStretches(const std::vector<std::uint64_t>& unit_samples, std::uint32_t part,
                                 std::uint32_t parts, std::uint16_t round, CompareSwap compare_swap)
    : m_units(unit_samples.size()), m_part(part), m_parts(parts), m_round(round), m_swap(std::move(compare_swap)),
      m_seen(parts, 0) {
  if (parts == 0 || part >= parts) throw std::invalid_argument("SharedStretches: part must be below parts");
  if (!m_swap) throw std::invalid_argument("SharedStretches: no compare-and-swap");
  if ((unit_samples.size() + parts - 1) / parts > kMaxStretch)  // the longest stretch
    throw std::invalid_argument("frame parts: " + std::to_string(unit_samples.size()) + " units over " +
                                std::to_string(parts) + " parts is more than " + std::to_string(kMaxStretch) +
                                " units a part");
  double all = 0;
  for (std::uint64_t s : unit_samples) {
    m_largest = std::max(m_largest, static_cast<double>(s));
    all += static_cast<double>(s);
  }
  m_mean = unit_samples.empty() ? 0.0 : all / static_cast<double>(unit_samples.size());
  m_exhausted = unit_samples.empty();
}

SharedStretches::Word SharedStretches::seen(std::uint32_t q) const {
  const Word w = decode(m_seen[q]);
  return w.round == m_round ? w : Word{m_round, 0, 0};
}

std::size_t SharedStretches::leftIn(std::uint32_t q) const {
  const auto [first, last] = partUnits(m_units, q, m_parts);
  const Word w = seen(q);
  const std::size_t taken = std::size_t{w.front} + w.back;
  return last - first > taken ? last - first - taken : 0;
}

std::optional<std::size_t> SharedStretches::takeFrom(std::uint32_t q, bool from_back) {
  const auto [first, last] = partUnits(m_units, q, m_parts);
  for (;;) {
    if (leftIn(q) == 0) return std::nullopt;  // the words only grow within a round
    Word next = seen(q);
    const std::size_t unit = from_back ? last - 1 - next.back : first + next.front;
    (from_back ? next.back : next.front) += 1;
    const std::uint64_t expected = m_seen[q], desired = encode(next);
    const std::uint64_t found = m_swap(q, expected, desired);
    if (found == expected) {
      m_seen[q] = desired;
      ++m_taken;
      return unit;
    }
    m_seen[q] = found;  // another part took one: judge again
  }
}

void SharedStretches::markOwnWord() {
  const std::uint64_t fresh = encode(Word{m_round, 0, 0});
  while (decode(m_seen[m_part]).round != m_round) {
    const std::uint64_t found = m_swap(m_part, m_seen[m_part], fresh);
    m_seen[m_part] = found == m_seen[m_part] ? fresh : found;
  }
}

std::optional<std::size_t> SharedStretches::take() {
  if (m_exhausted) return std::nullopt;
  if (!m_began) {
    m_began = true;
    const auto [first, last] = partUnits(m_units, m_part, m_parts);
    if (first == last) markOwnWord();
  }
  if (const std::optional<std::size_t> own = takeFrom(m_part, false)) return own;
  // Its own stretch is done: the back of the stretch with the most left, as
  // read now (a read is a swap that changes nothing).
  for (;;) {
    std::uint32_t most = m_parts;
    for (std::uint32_t q = 0; q < m_parts; ++q) {
      if (q == m_part) continue;
      m_seen[q] = m_swap(q, m_seen[q], m_seen[q]);
      if (leftIn(q) > 0 && (most == m_parts || leftIn(q) > leftIn(most))) most = q;
    }
    if (most == m_parts) {
      m_exhausted = true;
      return std::nullopt;
    }
    if (const std::optional<std::size_t> theirs = takeFrom(most, true)) return theirs;
  }
}

double SharedStretches::samplesLeft() const {
  // Its own stretch while it lasts; then its share of the others' as last read
  // (the other parts take from them too).
  const std::size_t own = leftIn(m_part);
  if (own > 0) return static_cast<double>(own) * m_mean;
  std::size_t others = 0;
  for (std::uint32_t q = 0; q < m_parts; ++q) others += q == m_part ? 0 : leftIn(q);
  return static_cast<double>(others) * m_mean / static_cast<double>(m_parts);
}

std::size_t SharedStretches::expectedUnits() const { return m_taken + leftIn(m_part); }

}  // namespace prism
