// TaskPool (host/accel/task_group.h), the BVH builder's threads: every task
// offered runs once, whatever the thread count; a thread with nothing to do
// takes what another offers; the first exception comes back from run().
#include <catch2/catch.hpp>

#include <atomic>
#include <chrono>
#include <functional>
#include <set>
#include <mutex>
#include <stdexcept>
#include <thread>

#include "accel/task_group.h"

using namespace prism;

namespace {

struct Range {
  int begin, end;
};

// Splits ranges in two down to single items, offering the left half, and
// records each item once; returns how many ranges ran on another thread than
// the caller's.
int splitAll(int threads, int items, std::multiset<int>& seen) {
  ThreadBudget budget(threads);
  TaskPool<Range> pool(budget);
  std::mutex mutex;
  std::atomic<int> elsewhere{0};
  const std::thread::id caller = std::this_thread::get_id();
  std::function<void(const Range&)> run = [&](const Range& r) {
    if (std::this_thread::get_id() != caller) ++elsewhere;
    if (r.end - r.begin == 1) {
      std::lock_guard<std::mutex> lock(mutex);
      seen.insert(r.begin);
      return;
    }
    const int mid = (r.begin + r.end) / 2;
    if (!pool.offer(Range{r.begin, mid})) run(Range{r.begin, mid});
    run(Range{mid, r.end});
  };
  pool.run(Range{0, items}, run);
  return elsewhere.load();
}

}  // namespace

TEST_CASE("a task pool runs every task once, on any number of threads", "[accel][threads]") {
  for (int threads : {1, 2, 4}) {
    INFO(threads << " threads");
    std::multiset<int> seen;
    const int elsewhere = splitAll(threads, 5000, seen);
    REQUIRE(seen.size() == 5000);
    CHECK(*seen.begin() == 0);
    CHECK(*seen.rbegin() == 4999);
    CHECK(std::set<int>(seen.begin(), seen.end()).size() == 5000);  // none twice
    if (threads == 1) CHECK(elsewhere == 0);  // no thread to offer to
  }
}

TEST_CASE("an idle thread of a task pool takes the work another offers", "[accel][threads]") {
  // The first task waits until a second thread is idle, offers, and stays
  // busy until the offered task has started: only the idle thread can take it.
  ThreadBudget budget(2);
  TaskPool<int> pool(budget);
  std::atomic<bool> offered{false}, started{false};
  std::thread::id first_thread, second_thread;
  std::function<void(const int&)> run = [&](const int& k) {
    if (k == 0) {
      first_thread = std::this_thread::get_id();
      for (int tries = 0; tries < 5000 && !offered; ++tries) {
        offered = pool.offer(1);
        if (!offered) std::this_thread::sleep_for(std::chrono::milliseconds(1));
      }
      for (int tries = 0; tries < 5000 && offered && !started; ++tries)
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    } else {
      second_thread = std::this_thread::get_id();
      started = true;
    }
  };
  pool.run(0, run);
  REQUIRE(offered);
  REQUIRE(started);
  CHECK(second_thread != first_thread);
}

TEST_CASE("a task pool rethrows the first exception after every task has ended, and runs again",
          "[accel][threads]") {
  ThreadBudget budget(3);
  TaskPool<Range> pool(budget);
  std::atomic<int> ran{0};
  std::function<void(const Range&)> run = [&](const Range& r) {
    ++ran;
    if (r.end - r.begin == 1) {
      if (r.begin == 17) throw std::runtime_error("item 17");
      return;
    }
    const int mid = (r.begin + r.end) / 2;
    if (!pool.offer(Range{r.begin, mid})) run(Range{r.begin, mid});
    run(Range{mid, r.end});
  };
  CHECK_THROWS_WITH(pool.run(Range{0, 64}, run), "item 17");
  CHECK(ran > 0);
  // The pool is idle again: a second run completes, and the budget's threads
  // were all given back (a fourth could not be had).
  ran = 0;
  std::function<void(const Range&)> count = [&](const Range&) { ++ran; };
  pool.run(Range{0, 1}, count);
  CHECK(ran == 1);
  CHECK(budget.tryAcquire());
  CHECK(budget.tryAcquire());
  CHECK_FALSE(budget.tryAcquire());
}
