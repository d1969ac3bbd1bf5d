// Fork-join parallelism for the builders: a task goes to a new std::thread
// while the build's thread budget (the cores given to it) has one free, and
// runs inline otherwise. Recursive builders fork their big subtrees, so both
// cores stay busy once the top of the tree is split.
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <utility>
#include <vector>

namespace prism {

class ThreadBudget {
 public:
  // `threads` in all, the calling one included; 0 = hardware concurrency.
  explicit ThreadBudget(int threads) {
    if (threads <= 0) threads = static_cast<int>(std::thread::hardware_concurrency());
    m_total = threads < 1 ? 1 : threads;
    m_free = m_total - 1;
  }
  int total() const { return m_total; }
  bool tryAcquire() {
    int free = m_free.load();
    while (free > 0)
      if (m_free.compare_exchange_weak(free, free - 1)) return true;
    return false;
  }
  void release() { m_free.fetch_add(1); }

 private:
  int m_total = 1;
  std::atomic<int> m_free{0};
};

class TaskGroup {
 public:
  explicit TaskGroup(ThreadBudget& budget) : m_budget(budget) {}
  TaskGroup(const TaskGroup&) = delete;
  TaskGroup& operator=(const TaskGroup&) = delete;
  ~TaskGroup() {
    for (std::thread& t : m_threads) t.join();
  }

  // Runs `task`, on its own thread when `big` and a thread is free.
  template <typename F>
  void run(F&& task, bool big) {
    if (big && m_budget.tryAcquire()) {
      m_threads.emplace_back([this, task = std::forward<F>(task)]() mutable {
        try {
          task();
        } catch (...) {
          std::lock_guard<std::mutex> lock(m_mutex);
          if (!m_error) m_error = std::current_exception();
        }
        m_budget.release();
      });
    } else {
      task();
    }
  }

  // Joins every task; rethrows the first exception one of them threw.
  void wait() {
    for (std::thread& t : m_threads) t.join();
    m_threads.clear();
    if (m_error) std::rethrow_exception(std::exchange(m_error, nullptr));
  }

 private:
  ThreadBudget& m_budget;
  std::vector<std::thread> m_threads;
  std::mutex m_mutex;
  std::exception_ptr m_error;
};

// Threads that take tasks as they are offered, for recursive builders: a
// thread splitting a node offers one side while another thread of the pool
// is idle, and keeps it otherwise. TaskGroup forks only where a thread is free
// at the moment of a split, so a thread that ran out of work waited for its
// sibling's whole subtree (the 69k bunny's tree took 11 ms on 2 threads
// against 16.5 on one, 2.5 ms more than the halved work); here it takes the
// next side offered. Idle threads take the newest task first (depth first, as
// one thread would). What a task computes must not depend on which thread
// runs it.
template <typename Task>
class TaskPool {
 public:
  using Runner = std::function<void(const Task&)>;
  explicit TaskPool(ThreadBudget& budget) : m_budget(budget) {}
  TaskPool(const TaskPool&) = delete;
  TaskPool& operator=(const TaskPool&) = delete;

  // Runs run(first), and run(t) for every t offered meanwhile, on this thread
  // and, when `parallel`, the budget's free threads (a small job is not
  // worth starting them); returns when all are done, rethrowing the first
  // exception one of them threw.
  void run(const Task& first, const Runner& run, bool parallel = true) {
    m_run = &run;
    m_pending = 1;
    std::vector<std::thread> helpers;
    while (parallel && m_budget.tryAcquire()) {
      try {
        helpers.emplace_back([this] {
          work();
          m_budget.release();
        });
      } catch (...) {  // no thread to be had: go on with those there are
        m_budget.release();
        break;
      }
    }
    execute(first);
    work();
    for (std::thread& t : helpers) t.join();
    m_run = nullptr;
    if (m_error) std::rethrow_exception(std::exchange(m_error, nullptr));
  }

  // Queues `task` for an idle thread; false when no idle thread is left
  // without a queued task (then the caller runs it itself).
  bool offer(const Task& task) {
    if (m_idle.load(std::memory_order_relaxed) == 0) return false;
    {
      std::lock_guard<std::mutex> lock(m_mutex);
      if (static_cast<int>(m_tasks.size()) >= m_idle.load()) return false;
      m_tasks.push_back(task);
      ++m_pending;
    }
    m_wake.notify_one();
    return true;
  }

 private:
  void execute(const Task& task) {
    try {
      (*m_run)(task);
    } catch (...) {
      std::lock_guard<std::mutex> lock(m_mutex);
      if (!m_error) m_error = std::current_exception();
    }
    std::lock_guard<std::mutex> lock(m_mutex);
    if (--m_pending == 0) m_wake.notify_all();
  }

  // Takes queued tasks until none is queued or running.
  void work() {
    std::unique_lock<std::mutex> lock(m_mutex);
    for (;;) {
      if (!m_tasks.empty()) {
        const Task task = m_tasks.back();
        m_tasks.pop_back();
        lock.unlock();
        execute(task);
        lock.lock();
        continue;
      }
      if (m_pending == 0) return;
      m_idle.fetch_add(1);
      m_wake.wait(lock);
      m_idle.fetch_sub(1);
    }
  }

  ThreadBudget& m_budget;
  const Runner* m_run = nullptr;
  std::mutex m_mutex;
  std::condition_variable m_wake;
  std::vector<Task> m_tasks;         // guarded by m_mutex
  std::size_t m_pending = 0;         // queued or running; guarded by m_mutex
  std::atomic<int> m_idle{0};        // threads waiting in work()
  std::exception_ptr m_error;        // guarded by m_mutex
};

// How many runs a pass over `count` items is cut into: one per thread of the
// budget from `parallel_from` items on, else one.
inline std::size_t runsFor(const ThreadBudget& budget, std::size_t count, std::size_t parallel_from) {
  return count >= parallel_from ? static_cast<std::size_t>(budget.total()) : 1;
}

// The items [first, end) of run r of `runs` over `count`: contiguous, in order.
inline std::pair<std::size_t, std::size_t> runRange(std::size_t count, std::size_t r, std::size_t runs) {
  return {count * r / runs, count * (r + 1) / runs};
}

// Calls run(r) for every r below `runs`: runs 1 on on threads of their own,
// run 0 on this one; returns when all are done (rethrowing the first
// exception). Whatever the threads, each r is one call, so a pass whose runs
// write their own parts gives the same result on any number of threads.
template <typename Run>
void forEachRun(ThreadBudget& budget, std::size_t runs, Run&& run) {
  TaskGroup group(budget);
  for (std::size_t r = 1; r < runs; ++r) group.run([&run, r] { run(r); }, true);
  run(std::size_t{0});
  group.wait();
}

}  // namespace prism
