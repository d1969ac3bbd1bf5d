// Deals the units of a frame (ranges of its sample sequence) out to several
// devices as each becomes free, so a faster device takes more of them, and a
// much slower one leaves the last units to the others (worthTaking); a device
// that fails (DeviceError) is retired with a warning and its unit goes back to
// the others. Which device traced a unit never changes its result: a unit's
// samples depend on their keys alone (render/device_tracer.h).
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace prism {

// One device's part of a frame.
struct DeviceShare {
  std::string device;           // its name
  std::uint64_t units = 0;      // units it finished (that count: none once it failed)
  std::uint64_t samples = 0;    // primary samples in them
  double busy_seconds = 0;      // wall time spent in its units
  std::uint64_t film_bytes = 0;  // device memory its film took at its largest: the frame's, or a window of it
  bool failed = false;          // retired mid-frame; its unfinished unit went to the others
  std::string failure;          // why
};

// Not traced by this process (DealResult::owner).
constexpr std::size_t kNoDevice = ~std::size_t{0};

struct DealResult {
  std::vector<std::size_t> owner;     // per unit: the device that finished it, or kNoDevice
  std::vector<std::string> warnings;  // one per retired device
  bool cancelled = false;
};

// A device's pace, as dealUnits judges whether a free device should take a unit.
struct DevicePace {
  bool live = true;                // not failed
  double samples_per_second = 0;   // 0: not known yet
  bool busy = false;               // tracing a unit, or between two
  double samples_left = 0;         // of that unit, by its pace (0 when not known)
};

// Whether device d, free now, should take a unit of `samples` samples while
// `pending` samples (this unit's among them) wait. It should not when the others
// would trace them all (after what they hold now) before d finished this one:
// a device many times slower than the rest, taking the last units, would make
// the frame wait for it. It takes the unit when its pace or any live other's is
// not known yet, and when no other live device is busy (an idle one may be
// judging the same way, and someone must take it). The others' time is the
// larger of their pooled pace over all the work and the soonest any one of them
// could finish this unit, since a unit is not split.
bool worthTaking(std::size_t d, double samples, double pending, const std::vector<DevicePace>& paces);

// Where dealUnits takes the units this process traces: a stretch of its own
// (UnitRange), or the stretches of several processes dealt as each asks
// (render/shared_stretches.h). dealUnits calls it under its lock, one call at a
// time, from whichever of its threads wants a unit.
class UnitSource {
 public:
  virtual ~UnitSource() = default;
  // The next unit (an index into the frame's units), or none: none is left,
  // and exhausted() says so from then on. May throw (a transport's failure).
  virtual std::optional<std::size_t> take() = 0;
  // Whether take would give none: known once it has (or when there never was one).
  virtual bool exhausted() const = 0;
  // At most the samples of the next unit take gives (worthTaking's `samples`).
  virtual double nextSamples() const = 0;
  // The samples left to take, as far as this process knows (worthTaking's `pending`).
  virtual double samplesLeft() const = 0;
  // The units this process may yet finish in all, those taken included
  // (progress's whole; it grows when it takes another's units).
  virtual std::size_t expectedUnits() const = 0;
};

// Units [first, last), in order.
class UnitRange : public UnitSource {
 public:
  UnitRange(const std::vector<std::uint64_t>& unit_samples, std::size_t first, std::size_t last);
  std::optional<std::size_t> take() override;
  bool exhausted() const override { return m_next == m_last; }
  double nextSamples() const override;
  double samplesLeft() const override { return m_left; }
  std::size_t expectedUnits() const override { return m_last - m_first; }

 private:
  const std::vector<std::uint64_t>& m_samples;
  std::size_t m_first, m_next, m_last;
  double m_left = 0;
};

// unit(device, u) traces unit u on device `device`; it may throw. A DeviceError
// retires the device (its unit, and the units it had finished, are dealt
// again: nothing is read back from a device that failed); any other exception (a
// cancellation, a limit in the user's terms) stops the frame and is rethrown
// once every device has stopped. progress(units finished, units) is called on
// the calling thread; returning false cancels: no unit starts after that, and
// the result says so. With one device the units run in order on the calling
// thread and a failure is rethrown as it came. Throws the last failure when
// every device has failed.
using UnitFn = std::function<void(std::size_t device, std::size_t unit)>;
// paces: each device's samples per second in earlier frames (0: not known),
// used until the device has finished a unit of this one; on return, this
// frame's where it finished one. Every device takes a first unit, so its pace is
// measured in every frame; it judges by worthTaking whether to take each unit
// after that. A device between two units counts as busy to the others.
// unit_samples: every unit of the frame; the units traced are those `source`
// gives (a unit given back by a failed device is dealt again here, before any
// other). progress's `units` is source.expectedUnits(), or the units done if more.
DealResult dealUnits(std::vector<DeviceShare>& devices, const std::vector<std::uint64_t>& unit_samples,
                     UnitSource& source, const UnitFn& unit,
                     const std::function<bool(std::size_t done, std::size_t units)>& progress,
                     std::vector<double>& paces);
// Every unit of the frame, in order.
DealResult dealUnits(std::vector<DeviceShare>& devices, const std::vector<std::uint64_t>& unit_samples,
                     const UnitFn& unit, const std::function<bool(std::size_t done, std::size_t units)>& progress,
                     std::vector<double>& paces);

}  // namespace prism
