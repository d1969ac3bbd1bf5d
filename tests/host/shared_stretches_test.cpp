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
};

// Each part on its own thread takes until none is left; `threads_per_part`
// threads of a part share one SharedStretches under a lock, as a part's devices do.
Taken dealOnce(Words& words, const std::vector<std::uint64_t>& unit_samples, std::uint32_t parts,
               std::uint16_t round, unsigned threads_per_part, std::uint32_t seed) {
  Taken taken;
  taken.by_part.resize(parts);
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
              CHECK(sources[p]->exhausted());
              return;
            }
            taken.by_part[p].push_back(*u);
          }
          // Parts of different speeds: some units take longer.
          if (rng() % 4 == 0) std::this_thread::sleep_for(std::chrono::microseconds(rng() % 200));
        }
      });
  for (std::thread& t : threads) t.join();
  return taken;
}

void checkDeal(const Taken& taken, std::size_t units, std::uint32_t parts) {
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
        for (std::uint16_t round = 1; round <= 3; ++round)
          checkDeal(dealOnce(words, samples, parts, round, threads, round), units, parts);
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
