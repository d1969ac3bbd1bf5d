// The wavefront Whitted renderer: sample positions → primary rays (or the
// first-hit Z-buffer) → extend → shade → occlude, wave after wave, with stable
// compaction of the ray queues in between and deterministic accumulation into a
// per-sample film, which the resolve kernel filters into pixels (kernels/*.cl,
// docs/architecture.md, docs/sampling.md).
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <stdexcept>
#include <utility>
#include <vector>

#include "accel/accel_buffers.h"
#include "accel/accel_structure.h"
#include "device/context.h"
#include "device/kernel_profile.h"
#include "render/device_tracer.h"
#include "render/firsthit.h"
#include "render/frame_parts.h"
#include "render/gpu_scene.h"
#include "render/render_options.h"
#include "render/render_stats.h"
#include "render/sampler.h"
#include "scene/scene.h"

namespace prism {

class HeldUnits;

struct RenderResult {
  int width = 0, height = 0;
  std::vector<float> rgba;          // width*height*4, linear, rows top to bottom
  std::vector<float> depth;         // width*height
  std::vector<float> normal;        // width*height*3
  std::vector<std::int32_t> primid; // width*height
  std::vector<float> albedo;        // width*height*3
  RenderStats stats;
};

class RenderCancelled : public std::runtime_error {
 public:
  RenderCancelled() : std::runtime_error("render cancelled by the progress callback") {}
};


// Fraction done in [0, 1]; returns false to cancel.
using ProgressFn = std::function<bool(double)>;

// The frame: what it needs (the scene flattened for the kernels, its structure
// and light buffer built on the host, the first-hit and shadow choices), which
// units of the sample sequence make it, dealt out over one or more devices
// (render/work_dealer.h), and their film resolved into pixels. The tracing
// itself is a DeviceTracer's (render/device_tracer.h), one per device. The
// image is the same bit for bit whatever the number and order of devices of
// one kind: a unit is a whole number of the chunks a single device traces.
class Renderer {
 public:
  explicit Renderer(Context& context);
  // Several devices (the first resolves the frame, unless it fails); none twice.
  explicit Renderer(const std::vector<Context*>& contexts);
  ~Renderer();
  RenderResult render(const Scene& scene, const RenderOptions& options, const ProgressFn& progress = {});

  static constexpr size_t kSliceRays = DeviceTracer::kSliceRays;

  // How many slices of adaptive sample positions the device film holds at once
  // (256 by default: 16M positions, 256 MiB); the colours go back to the host
  // after each batch. The image does not depend on it; tests set it low to
  // exercise batching on small images.
  void setFilmBatchSlices(size_t slices);
  size_t filmBatchSlices() const { return m_tracers.front()->filmBatchSlices(); }

  // How many samples a part other than 0 (setFrameParts) puts through its
  // resolver's film window at once to resolve its own pixels (16 slices, 24 MiB,
  // by default). The image does not depend on it; tests set it low to cut a
  // run of units into several pieces.
  static constexpr std::uint64_t kResolvePieceSamples = 16 * DeviceTracer::kSliceRays;
  void setResolvePieceSamples(std::uint64_t samples) { m_resolve_piece_samples = samples > 0 ? samples : 1; }

  // How the next renders build their acceleration structure (the defaults
  // unless set); the image does not depend on it.
  void setAccelBuildOptions(const AccelBuildOptions& options) { m_accel_build = options; }

  // A fault to inject (tests): device `device` (its position among this
  // renderer's) throws DeviceError when it starts its unit number `unit` (from
  // 0) of each later render; its part goes to the others. Faults add up;
  // clearDeviceFaults forgets them.
  void injectDeviceFault(size_t device, std::uint64_t unit);
  void clearDeviceFaults() { m_faults.clear(); }

  // Share the next frames with other processes (render/frame_parts.h): this one
  // traces its part of the units, and only part 0's result holds the image, its
  // AOVs and the frame's counts (the other parts' hold zeros and their own).
  void setFrameParts(FrameParts parts);

 private:
  // The sampling modes whose positions come from kernels/supersample.cl, resolved
  // by kernels/resolve.cl.
  void renderSamples(const SamplingOptions& sampling, const RenderOptions& options, RenderResult& result,
                     const ProgressFn& progress);
  // Adaptive sampling: adaptiveSample (render/sampler.h) driving the tracers'
  // traceFilmPositions.
  void renderAdaptive(const SamplingOptions& sampling, const RenderOptions& options, RenderResult& result,
                      const ProgressFn& progress);
  // Who traced each unit of a frame.
  struct DealtUnits {
    std::vector<size_t> owner;           // this process's device, or kNoDevice (another part)
    std::vector<std::uint32_t> part_of;  // the part (0 when the frame is not shared)
  };
  // Runs unit(tracer, u) over the devices for the units this process takes
  // (its stretch, or as its devices come free with FrameParts::compare_swap);
  // fills result.stats.devices and its warnings, adds the units' counts to
  // result.stats (at part 0, every part's).
  DealtUnits deal(const std::vector<std::uint64_t>& unit_samples,
                  const std::function<void(DeviceTracer&, size_t unit)>& unit, RenderResult& result,
                  const ProgressFn& progress);
  // With frame parts: part 0 gathers what it needs from the others and resolves
  // the frame (render/part_resolve.h); the units this part's devices handed
  // over are in `held`.
  void resolveAcrossParts(const SamplingOptions& sampling, const RenderOptions& opt,
                          const std::vector<std::uint32_t>& part_of, std::uint64_t unit_size, HeldUnits& held,
                          DeviceTracer& resolving, RenderResult& result);
  // Units of slices (with several devices, or parts) rather than one unit a pass.
  bool unitsOfSlices() const { return m_tracers.size() > 1 || m_parts.shared(); }
  // Throws on every part unless every part renders the same frame.
  void checkSameFrame(std::uint64_t fingerprint);
  // The AOVs: each pixel from the device (and the part) whose sample wrote it.
  void gatherAovs(RenderResult& result);
  // The first device that did not fail this frame.
  size_t survivor(const RenderStats& stats) const;
  // The first live device on which hold(tracer) does not throw FilmTooLarge
  // (a film of the whole frame), or the first device's FilmTooLarge.
  size_t holdWholeFilm(const RenderStats& stats, const std::function<void(DeviceTracer&)>& hold);
  // The position of a tracer among this renderer's.
  size_t deviceIndex(const DeviceTracer& tracer) const;

  std::vector<Context*> m_contexts;
  std::vector<std::unique_ptr<DeviceTracer>> m_tracers;
  std::vector<RenderStats> m_device_stats;  // where each tracer counts its current unit
  std::vector<double> m_paces;  // each device's samples per second in the last frame (dealUnits)
  AccelBuildOptions m_accel_build;
  std::vector<std::pair<size_t, std::uint64_t>> m_faults;  // (device, unit)
  FrameParts m_parts;
  std::uint64_t m_resolve_piece_samples = kResolvePieceSamples;
};

}  // namespace prism
