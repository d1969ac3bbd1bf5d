// The frame's units dealt over parts as their devices come free
// (render/shared_stretches.h), with the parts' words in memory: every unit is
// taken once, whoever takes it and however the takes interleave; a part takes
// its own stretch from the front, in order, and the others' from the back; the
// same words serve deal after deal without a reset.
#include <catch2/catch.hpp>

#include <atomic>
#include <chrono>
#include <memory>
#include <mutex>
#include <random>
#include <thread>
#include <vector>

#include "render/frame_parts.h"
#include "render/shared_stretches.h"

using namespace prism;

namespace {

// The parts' words, as a transport keeps them.
struct Words {
  explicit Words(std::uint32_t parts) : words(parts) {
    for (auto& w : words) w = 0;
  }
  CompareSwap swap() {
    return [this](std::uint32_t word, std::uint64_t expected, std::uint64_t desired) {
      words.at(word).compare_exchange_strong(expected, desired);
      return expected;  // the value found, as compare_exchange leaves it
    };
  }
  std::vector<std::atomic<std::uint64_t>> words;
};

struct Taken {
  std::vector<std::vector<std::size_t>> by_part;  // in the order each part took them
  std::atomic<int> not_exhausted{0};               // takes that gave none without saying so
};

// Each part on its own thread takes until none is left; `threads_per_part`
// threads of a part share one SharedStretches under a lock, as a part's devices do.
void dealOnce(Taken& taken, Words& words, const std::vector<std::uint64_t>& unit_samples, std::uint32_t parts,
               std::uint16_t round, unsigned threads_per_part, std::uint32_t seed) {
  taken.by_part.assign(parts, {});
  taken.not_exhausted = 0;
  std::vector<std::thread> threads;
  std::vector<std::unique_ptr<SharedStretches>> sources;
  std::vector<std::unique_ptr<std::mutex>> locks;
  for (std::uint32_t p = 0; p < parts; ++p) {
    sources.push_back(std::make_unique<SharedStretches>(unit_samples, p, parts, round, words.swap()));
    locks.push_back(std::make_unique<std::mutex>());
  }
  for (std::uint32_t p = 0; p < parts; ++p)
    for (unsigned t = 0; t < threads_per_part; ++t)
      threads.emplace_back([&, p, t] {
        std::mt19937 rng(seed + 31 * p + t);
        for (;;) {
          {
            std::lock_guard<std::mutex> lock(*locks[p]);
            const std::optional<std::size_t> u = sources[p]->take();
            if (!u) {
              // Checked after the join: Catch2's assertions are not thread-safe.
              if (!sources[p]->exhausted()) ++taken.not_exhausted;
              return;
            }
            taken.by_part[p].push_back(*u);
          }
          // Parts of different speeds: some units take longer.
          if (rng() % 4 == 0) std::this_thread::sleep_for(std::chrono::microseconds(rng() % 200));
        }
      });
  for (std::thread& t : threads) t.join();
}

void checkDeal(const Taken& taken, std::size_t units, std::uint32_t parts) {
  CHECK(taken.not_exhausted == 0);
  std::vector<int> times(units, 0);
  for (std::uint32_t p = 0; p < parts; ++p) {
    const auto [first, last] = partUnits(units, p, parts);
    // Its own units come first, from the front, in order.
    std::size_t next_own = first;
    bool stealing = false;
    for (std::size_t u : taken.by_part[p]) {
      REQUIRE(u < units);
      ++times[u];
      if (u >= first && u < last) {
        CHECK_FALSE(stealing);
        CHECK(u == next_own);
        ++next_own;
      } else {
        stealing = true;
      }
    }
  }
  for (std::size_t u = 0; u < units; ++u) {
    INFO("unit " << u);
    CHECK(times[u] == 1);
  }
}

}  // namespace

TEST_CASE("shared stretches: every unit is taken once, own units first from the front, deal after deal") {
  for (std::size_t units : {0u, 1u, 2u, 7u, 64u, 500u}) {
    for (std::uint32_t parts : {1u, 2u, 3u, 5u}) {
      for (unsigned threads : {1u, 3u}) {
        INFO(units << " units, " << parts << " parts, " << threads << " threads a part");
        const std::vector<std::uint64_t> samples(units, 100);
        Words words(parts);
        // The same words through several deals, as a renderer's frames use them.
        for (std::uint16_t round = 1; round <= 3; ++round) {
          Taken taken;
          dealOnce(taken, words, samples, parts, round, threads, round);
          checkDeal(taken, units, parts);
        }
      }
    }
  }
}

TEST_CASE("shared stretches: a part that takes nothing leaves its stretch to the others, from the back") {
  const std::size_t units = 30;
  const std::vector<std::uint64_t> samples(units, 10);
  Words words(3);
  SharedStretches fast(samples, 0, 3, 1, words.swap());
  std::vector<std::size_t> got;
  while (const auto u = fast.take()) got.push_back(*u);
  CHECK(fast.exhausted());
  REQUIRE(got.size() == units);
  // Its own 0..9, then the back of the stretch with the most left (ties: the
  // lower part), one unit at a time.
  for (std::size_t i = 0; i < 10; ++i) CHECK(got[i] == i);
  CHECK(got[10] == 19);  // part 1's back (a tie: the lower part)
  CHECK(got[11] == 29);  // part 2 now has the most left
  CHECK(got[12] == 18);
  // The slow parts find their stretches empty.
  SharedStretches slow(samples, 1, 3, 1, words.swap());
  CHECK_FALSE(slow.take().has_value());
  CHECK(slow.exhausted());
  // The next deal's round reads the words as untouched.
  SharedStretches next(samples, 1, 3, 2, words.swap());
  CHECK(next.take() == std::optional<std::size_t>(10));
  CHECK(next.expectedUnits() == 10);
}

TEST_CASE("shared stretches: the round wraps at 65,536 deals without reading an old word as this deal's") {
  // 3 units over 5 parts: parts 0 and 2 (partUnits) have empty stretches, so
  // no one takes from their words; their owners mark them each deal, or after
  // 65,536 deals a word left from the first would read as this round's.
  const std::vector<std::uint64_t> few(3, 10), many(10, 10);
  Words words(5);
  std::uint16_t round = 1;
  // The parts one after another on this thread (65,536 deals on threads would be slow).
  const auto deal = [&](const std::vector<std::uint64_t>& units) {
    std::vector<int> times(units.size(), 0);
    std::vector<std::unique_ptr<SharedStretches>> parts;
    for (std::uint32_t p = 0; p < 5; ++p)
      parts.push_back(std::make_unique<SharedStretches>(units, p, 5, round, words.swap()));
    ++round;
    for (auto& part : parts)
      while (const auto u = part->take()) ++times.at(*u);
    for (int t : times)
      if (t != 1) return false;
    return true;
  };
  REQUIRE(deal(many));  // every stretch has two units: every word at round 1
  bool all = true;
  for (int k = 0; k < 65535; ++k) all = deal(few) && all;  // rounds 2 to 65,535, then 0
  CHECK(all);
  REQUIRE(round == 1);
  CHECK(deal(many));  // round 1 again: would find parts 0 and 2's words of the first deal taken
}

TEST_CASE("shared stretches: the word's fields round-trip, and a stretch too long for them is refused") {
  const SharedStretches::Word w{65535, SharedStretches::kMaxStretch, 12345};
  const SharedStretches::Word back = SharedStretches::decode(SharedStretches::encode(w));
  CHECK(back.round == w.round);
  CHECK(back.front == w.front);
  CHECK(back.back == w.back);
  Words words(2);
  const std::vector<std::uint64_t> many(2 * SharedStretches::kMaxStretch + 2, 1);
  CHECK_THROWS_AS(SharedStretches(many, 0, 2, 1, words.swap()), std::invalid_argument);
  const std::vector<std::uint64_t> fits(2 * SharedStretches::kMaxStretch, 1);
  CHECK_NOTHROW(SharedStretches(fits, 0, 2, 1, words.swap()));
  CHECK_THROWS_AS(SharedStretches(fits, 2, 2, 1, words.swap()), std::invalid_argument);
}
