#include "render/work_dealer.h"

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <deque>
#include <exception>
#include <limits>
#include <mutex>
#include <stdexcept>
#include <thread>

#include "device/cl_error.h"

namespace prism {
namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// This frame's pace where the device has finished a unit of it, else the
// earlier frames'.
double paceOf(const DeviceShare& share, double earlier) {
  return share.samples > 0 && share.busy_seconds > 0 ? static_cast<double>(share.samples) / share.busy_seconds
                                                     : earlier;
}

}  // namespace

bool worthTaking(std::size_t d, double samples, double pending, const std::vector<DevicePace>& paces) {
  const double own = paces.at(d).samples_per_second;
  if (own <= 0) return true;
  double pooled = 0, held = 0, soonest = std::numeric_limits<double>::infinity();
  bool other_busy = false;
  for (std::size_t e = 0; e < paces.size(); ++e) {
    const DevicePace& p = paces[e];
    if (e == d || !p.live) continue;
    if (p.samples_per_second <= 0) return true;
    other_busy = other_busy || p.busy;
    const double left = p.busy ? p.samples_left : 0;
    pooled += p.samples_per_second;
    held += left;
    soonest = std::min(soonest, (left + samples) / p.samples_per_second);
  }
  if (!other_busy) return true;
  return samples / own < std::max((pending + held) / pooled, soonest);
}

UnitRange::UnitRange(const std::vector<std::uint64_t>& unit_samples, std::size_t first, std::size_t last)
    : m_samples(unit_samples), m_first(first), m_next(first), m_last(last) {
  if (first > last || last > unit_samples.size()) throw std::invalid_argument("UnitRange: not a range of the units");
  for (std::size_t u = first; u < last; ++u) m_left += static_cast<double>(unit_samples[u]);
}

std::optional<std::size_t> UnitRange::take() {
  if (m_next == m_last) return std::nullopt;
  m_left -= static_cast<double>(m_samples[m_next]);
  return m_next++;
}

double UnitRange::nextSamples() const { return m_next == m_last ? 0.0 : static_cast<double>(m_samples[m_next]); }

DealResult dealUnits(std::vector<DeviceShare>& devices, const std::vector<std::uint64_t>& unit_samples,
                     const UnitFn& unit, const std::function<bool(std::size_t done, std::size_t units)>& progress,
                     std::vector<double>& paces) {
  UnitRange all(unit_samples, 0, unit_samples.size());
  return dealUnits(devices, unit_samples, all, unit, progress, paces);
}

DealResult dealUnits(std::vector<DeviceShare>& devices, const std::vector<std::uint64_t>& unit_samples,
                     UnitSource& source, const UnitFn& unit,
                     const std::function<bool(std::size_t done, std::size_t units)>& progress,
                     std::vector<double>& paces) {
  const std::size_t units = unit_samples.size();
  DealResult result;
  result.owner.assign(units, kNoDevice);
  if (devices.empty()) throw std::logic_error("dealUnits: no device");
  paces.resize(devices.size(), 0.0);
  struct KeepPaces {  // on every way out, cancelled or failed too
    std::vector<DeviceShare>& devices;
    std::vector<double>& paces;
    ~KeepPaces() {
      for (std::size_t d = 0; d < devices.size(); ++d)
        if (!devices[d].failed) paces[d] = paceOf(devices[d], paces[d]);
    }
  } keep{devices, paces};
  const auto expected = [&](std::size_t done) { return std::max(done, source.expectedUnits()); };
  // The last (done, whole) given to progress. A shared source's whole shrinks
  // when another part takes units of this part's stretch, which may happen
  // after this part's last unit is reported; the end is then reported once
  // more, so that progress ends at its whole (51 of 52 otherwise, seen in
  // deal_from_source_test under ASan).
  std::size_t reported_done = 0, reported_whole = 0;
  const auto report = [&](std::size_t done, std::size_t whole) {
    reported_done = done;
    reported_whole = whole;
    return progress(done, whole);
  };
  const auto reportEnd = [&](std::size_t done) {
    const std::size_t whole = expected(done);
    if (progress && reported_whole > 0 && (reported_done != done || reported_whole != whole)) report(done, whole);
  };

  if (devices.size() == 1) {
    DeviceShare& share = devices.front();
    if (share.failed) throw std::logic_error("dealUnits: the only device has failed");
    std::size_t done = 0;
    while (const std::optional<std::size_t> u = source.take()) {
      const auto start = std::chrono::steady_clock::now();
      unit(0, *u);
      share.busy_seconds += secondsSince(start);
      ++share.units;
      share.samples += unit_samples[*u];
      result.owner[*u] = 0;
      ++done;
      if (progress && !report(done, expected(done))) {
        result.cancelled = true;
        break;
      }
    }
    if (!result.cancelled) reportEnd(done);
    return result;
  }

  // Shared state: the units given back by failed devices (dealt before the
  // source's), how many units are taken and finished, and the first exception
  // that is not a device failure.
  std::mutex mutex;
  std::condition_variable changed;
  std::deque<std::size_t> returned;
  double returned_samples = 0;
  std::size_t taken = 0, finished = 0, working = devices.size(), busy = 0;
  bool stop = false;
  std::exception_ptr fatal, last_failure;
  std::vector<std::vector<std::size_t>> done_by(devices.size());
  // What each device holds now, for worthTaking. A device counts as busy
  // unless it is waiting for a unit: between two units it is about to take the
  // next, and must not look idle to the others.
  std::vector<std::chrono::steady_clock::time_point> since(devices.size());
  std::vector<double> holding(devices.size(), 0.0);
  std::vector<char> waiting(devices.size(), 0), took(devices.size(), 0);
  std::vector<DevicePace> pace(devices.size());
  auto nothing_left = [&] { return returned.empty() && source.exhausted(); };  // under the lock
  auto worth = [&](std::size_t d) {  // under the lock
    if (!took[d]) return true;  // its first unit of the frame: its pace, measured afresh
    for (std::size_t e = 0; e < devices.size(); ++e) {
      DevicePace& p = pace[e];
      p.live = !devices[e].failed;
      p.samples_per_second = paceOf(devices[e], paces[e]);
      p.busy = holding[e] > 0 || !waiting[e];
      p.samples_left = p.busy && p.samples_per_second > 0
                           ? std::max(0.0, holding[e] - p.samples_per_second * secondsSince(since[e]))
                           : 0.0;
    }
    const double next = returned.empty() ? source.nextSamples() : static_cast<double>(unit_samples[returned.front()]);
    return worthTaking(d, next, returned_samples + source.samplesLeft(), pace);
  };
  auto release = [&](std::size_t d) {  // under the lock: device d holds no unit any more
    --busy;
    holding[d] = 0;
    changed.notify_all();
  };

  auto worker = [&](std::size_t d) {
    DeviceShare& share = devices[d];
    while (!share.failed) {
      std::size_t u;
      {
        std::unique_lock<std::mutex> lock(mutex);
        // With nothing left to take, stay while another device is busy: its
        // unit comes back if that device fails. A unit not worth taking now
        // may be after the others' next step, or their failure.
        waiting[d] = 1;
        changed.notify_all();  // the others judge again with this device idle
        changed.wait(lock, [&] { return stop || (nothing_left() ? busy == 0 : worth(d)); });
        if (stop || nothing_left()) break;  // still waiting: idle from now on
        std::optional<std::size_t> next;
        if (!returned.empty()) {
          next = returned.front();
          returned.pop_front();
          returned_samples -= static_cast<double>(unit_samples[*next]);
        } else {
          try {
            next = source.take();  // the source's transport may fail
          } catch (...) {
            if (!fatal) fatal = std::current_exception();
            stop = true;
            changed.notify_all();
            break;
          }
          if (!next) continue;  // the source ran dry: judge again
          ++taken;
        }
        waiting[d] = 0;
        took[d] = 1;
        u = *next;
        holding[d] = static_cast<double>(unit_samples[u]);
        since[d] = std::chrono::steady_clock::now();
        ++busy;
      }
      try {
        unit(d, u);
      } catch (const DeviceError& e) {
        std::lock_guard<std::mutex> lock(mutex);
        release(d);
        share.failed = true;
        share.failure = e.what();
        // Its unit and every unit it finished go to the others: a failed
        // device's memory is not read again.
        returned.push_front(u);
        returned_samples += static_cast<double>(unit_samples[u]);
        for (std::size_t v : done_by[d]) {
          returned.push_front(v);
          returned_samples += static_cast<double>(unit_samples[v]);
          result.owner[v] = kNoDevice;
        }
        finished -= done_by[d].size();
        done_by[d].clear();
        share.units = 0;
        share.samples = 0;
        last_failure = std::current_exception();
        result.warnings.push_back("device '" + share.device + "' failed mid-frame and was left out; the others " +
                                  "traced its part of the frame: " + e.what());
        break;
      } catch (...) {
        std::lock_guard<std::mutex> lock(mutex);
        release(d);
        if (!fatal) fatal = std::current_exception();
        stop = true;
        break;
      }
      std::lock_guard<std::mutex> lock(mutex);
      share.busy_seconds += secondsSince(since[d]);
      ++share.units;
      share.samples += unit_samples[u];
      result.owner[u] = d;
      done_by[d].push_back(u);
      ++finished;
      release(d);
    }
    std::lock_guard<std::mutex> lock(mutex);
    --working;
    changed.notify_all();
  };

  std::vector<std::thread> threads;
  threads.reserve(devices.size());
  for (std::size_t d = 0; d < devices.size(); ++d) threads.emplace_back(worker, d);
  {
    std::unique_lock<std::mutex> lock(mutex);
    std::size_t reported = 0;
    // Units finished and not yet reported are reported even when every worker
    // has already ended: the workers may finish the whole frame before this
    // thread first takes the lock, and progress must still hear of it.
    for (;;) {
      changed.wait(lock, [&] { return working == 0 || (finished > reported && !stop); });
      if (!(finished > reported && !stop)) break;  // every worker has ended
      reported = finished;
      if (progress) {
        const std::size_t done = finished, whole = expected(done);
        lock.unlock();
        const bool go_on = report(done, whole);
        lock.lock();
        if (!go_on) {
          stop = true;
          result.cancelled = true;
          changed.notify_all();
        }
      }
    }
  }
  for (std::thread& t : threads) t.join();
  if (fatal) std::rethrow_exception(fatal);
  if (result.cancelled) return result;
  if (finished < taken || !source.exhausted()) {  // every device has failed
    if (last_failure) std::rethrow_exception(last_failure);
    throw DeviceError("every device has failed");
  }
  reportEnd(finished);
  return result;
}

}  // namespace prism
