#include "render/renderer.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>

#include "kernels/shared/ray_gpu.h"
#include "device/cl_error.h"
#include "render/held_units.h"
#include "render/light_buffer.h"
#include "render/part_resolve.h"
#include "render/shared_stretches.h"
#include "render/work_dealer.h"

namespace prism {
namespace {

// Each of a scene's values is held within float's range where it is read, but
// extreme ones together can still pass it in the kernels' products (a colour
// of 1e6 on a texture of 1e6 under lights of 1e30; a sharp Cook-Torrance
// highlight seen at a grazing angle): the image says so rather than hand back
// such pixels without a word.
void warnNotFinite(RenderResult& result, bool check_nan) {
  std::size_t not_finite = 0;
  for (std::size_t i = 0; i < result.rgba.size(); i += 4)
    not_finite += !(std::isfinite(result.rgba[i]) && std::isfinite(result.rgba[i + 1]) &&
                    std::isfinite(result.rgba[i + 2]) && std::isfinite(result.rgba[i + 3]));
  if (not_finite > 0)
    result.stats.warnings.push_back(std::to_string(not_finite) + " of the colour image's " +
                                    std::to_string(result.rgba.size() / 4) +
                                    " pixels are not finite (infinite or NaN): the scene's brightest values together "
                                    "may pass float's range" +
                                    (check_nan ? std::string()
                                               : "; check_nan (prism render --check-nan) names the first ray that "
                                                 "brought one"));
}

}  // namespace

Renderer::Renderer(Context& context) : Renderer(std::vector<Context*>{&context}) {}

Renderer::Renderer(const std::vector<Context*>& contexts) : m_contexts(contexts) {
  if (contexts.empty()) throw std::invalid_argument("Renderer: no device");
  for (size_t i = 0; i < contexts.size(); ++i)
    for (size_t j = 0; j < i; ++j)
      if (contexts[i] == contexts[j]) throw std::invalid_argument("Renderer: the same device context twice");
  for (Context* c : contexts) m_tracers.push_back(std::make_unique<DeviceTracer>(*c));
}

Renderer::~Renderer() = default;

RenderResult Renderer::render(const Scene& scene, const RenderOptions& options, const ProgressFn& progress) {
  options.validate();
  for (Context* c : m_contexts) c->takeFirstLaunchSeconds();  // launches before this render are not its start-up
  auto start = std::chrono::steady_clock::now();
  const SamplingOptions sampling = options.sampling();
  // The first-hit pass serves rays that leave one point at one instant.
  const bool pinhole = scene.camera.isPinhole();
  FirstHitMode first_hit = options.first_hit;
  if (first_hit == FirstHitMode::ZBuffer && !pinhole)
    throw std::invalid_argument(std::string("first hit zbuffer needs a pinhole camera, but this one has ") +
                                (scene.camera.aperture > 0 ? "an aperture (depth of field)"
                                                           : "a shutter interval (motion blur)") +
                                ": its primary rays do not share one origin and instant; use first hit trace or auto");

  GpuScene gpu = flattenScene(scene, options);
  if (first_hit == FirstHitMode::Auto) {
    const std::uint64_t samples = sampling.mode == AaMode::Adaptive
                                      ? static_cast<std::uint64_t>(options.width + 1) * (options.height + 1)
                                      : sampleCount(sampling.mode, options.width, options.height, sampling.spp);
    first_hit = pinhole && zbufferPays(gpu, samples) ? FirstHitMode::ZBuffer : FirstHitMode::Trace;
  }
  RenderResult result;
  result.width = options.width;
  result.height = options.height;
  result.stats.aa = sampling.mode;
  result.stats.filter = sampling.effectiveFilter();
  result.stats.first_hit = first_hit;
  if (options.profile)
    for (Context* c : m_contexts) c->profile().start();
  struct Reset {
    Renderer* r;
    ~Reset() {
      for (Context* c : r->m_contexts) c->profile().discard();  // what a finished render did not take
      for (auto& t : r->m_tracers) t->unload();
    }
  } reset{this};

  // Built once on the host, whichever devices trace the frame.
  AccelBuildOptions build = m_accel_build;
  build.kdop_objects = build.kdop_bvh = options.bounds == BoundsKind::Kdop;
  const std::unique_ptr<DeviceAccel> accel = buildAccel(options.accel, gpu.objects, build);
  result.stats.accel = accel->kind;  // what auto chose
  result.stats.accel_stats = accel->stats;
  // Point lights' feelers: through the light buffer or the structure.
  LightBuffer light_buffer;
  result.stats.shadows = planShadows(options.shadows, accel->kind, gpu.objects, gpu.lights, &light_buffer);
  if (result.stats.shadows == ShadowMode::LightBuffer) result.stats.light_buffer_candidates = light_buffer.mean_candidates;

  if (m_parts.shared())
    checkSameFrame(frameFingerprint(gpu, options, first_hit, result.stats.shadows, accel->kind,
                                    static_cast<bool>(m_parts.compare_swap)));

  FrameSetup frame;
  frame.scene = &gpu;
  frame.accel = accel.get();
  frame.light_buffer = &light_buffer;
  frame.use_light_buffer = result.stats.shadows == ShadowMode::LightBuffer;
  frame.options = &options;
  frame.sampling = sampling;
  frame.zbuffer = first_hit == FirstHitMode::ZBuffer;
  frame.distributed_camera = !pinhole;
  // Every device gets the scene. With several, one that fails here is left out
  // (a warning), as it would be mid-frame.
  const size_t k = m_tracers.size();
  m_device_stats.assign(k, RenderStats{});
  result.stats.devices.assign(k, DeviceShare{});
  for (size_t i = 0; i < k; ++i) {
    DeviceShare& share = result.stats.devices[i];
    share.device = m_contexts[i]->device().name;
    try {
      m_tracers[i]->load(frame, m_device_stats[i], k > 1 || m_parts.shared());
    } catch (const DeviceError& e) {
      if (k == 1) throw;
      share.failed = true;
      share.failure = e.what();
      result.stats.warnings.push_back("device '" + share.device + "' could not take the scene and was left out: " +
                                      e.what());
    }
  }
  if (survivor(result.stats) == k) throw DeviceError("no device could take the scene: " + result.stats.devices[0].failure);
  // Devices of different kinds give the same bits only where each rounds
  // division and sqrt correctly and keeps subnormals (kernels/common/same_bits_math.h).
  for (size_t i = 0; k > 1 && i < k; ++i) {
    const DeviceDescription& d = m_contexts[i]->device();
    if (const char* shortfall = d.sameBitsShortfall(); shortfall && !result.stats.devices[i].failed)
      result.stats.warnings.push_back("device '" + d.name + "' " + shortfall +
                                      ": the frame may differ in its last bits from one traced on another device");
  }

  result.stats.setup_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (sampling.mode == AaMode::Adaptive)
    renderAdaptive(sampling, options, result, progress);
  else
    renderSamples(sampling, options, result, progress);

  RenderStats& stats = result.stats;
  const size_t pixels = static_cast<size_t>(options.width) * options.height;
  stats.rays_per_pixel = static_cast<double>(stats.rays_by_kind[RAY_KIND_PRIMARY]) / static_cast<double>(pixels);
  if (sampling.mode != AaMode::Adaptive) gatherAovs(result);  // adaptive: after its first pass
  if (m_parts.part != 0) result.rgba.assign(4 * pixels, 0.f);  // the image is part 0's
  for (size_t i = 0; i < m_tracers.size(); ++i) stats.devices[i].film_bytes = m_tracers[i]->filmPeakBytes();
  for (auto& t : m_tracers) t->unload();
  if (m_parts.shared()) {
    // Part 0 reports every part's devices and warnings.
    ByteWriter out;
    if (m_parts.part != 0) packShares(out, stats);
    const std::vector<Bytes> got = m_parts.exchange(false, out.take());
    if (m_parts.part == 0) {
      for (DeviceShare& d : stats.devices) d.device = "part 0: " + d.device;
      for (std::string& w : stats.warnings) w = "part 0: " + w;
      for (std::uint32_t p = 1; p < m_parts.parts; ++p) {
        ByteReader in(got.at(p));
        unpackShares(in, p, stats);
        in.expectDone();
      }
    }
  }
  if (m_parts.part == 0) warnNotFinite(result, options.check_nan);
  stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  // The devices start up side by side: the frame waited for the slowest.
  for (Context* c : m_contexts) stats.first_launch_seconds = std::max(stats.first_launch_seconds, c->takeFirstLaunchSeconds());
  if (options.profile) {
    for (Context* c : m_contexts) mergeKernelTimes(stats.kernels, c->profile().stop());
  }
  return result;
}

void Renderer::gatherAovs(RenderResult& result) {
  const size_t pixels = static_cast<size_t>(result.width) * static_cast<size_t>(result.height);
  const auto merge = [&](const float* depth, const float* normal, const std::int32_t* primid, const float* albedo) {
    for (size_t p = 0; p < pixels; ++p) {
      if (primid[p] == DeviceTracer::kAovUnwritten) continue;
      result.primid[p] = primid[p];
      result.depth[p] = depth[p];
      for (int c = 0; c < 3; ++c) {
        result.normal[3 * p + c] = normal[3 * p + c];
        result.albedo[3 * p + c] = albedo[3 * p + c];
      }
    }
  };
  std::vector<float> depth, normal, albedo;
  std::vector<std::int32_t> primid;
  const size_t first = survivor(result.stats);
  m_tracers[first]->readAovs(result.depth, result.normal, result.primid, result.albedo);
  for (size_t i = first + 1; i < m_tracers.size(); ++i) {
    if (result.stats.devices[i].failed) continue;
    m_tracers[i]->readAovs(depth, normal, primid, albedo);
    merge(depth.data(), normal.data(), primid.data(), albedo.data());
  }
  if (!m_parts.shared()) return;
  ByteWriter out;
  if (m_parts.part != 0) {
    out.putArray(result.depth.data(), pixels);
    out.putArray(result.normal.data(), 3 * pixels);
    out.putArray(result.primid.data(), pixels);
    out.putArray(result.albedo.data(), 3 * pixels);
  }
  const std::vector<Bytes> got = m_parts.exchange(false, out.take());
  if (m_parts.part != 0) {
    result.depth.assign(pixels, 0.f);
    result.normal.assign(3 * pixels, 0.f);
    result.primid.assign(pixels, -1);
    result.albedo.assign(3 * pixels, 0.f);
    return;
  }
  depth.resize(pixels);
  normal.resize(3 * pixels);
  primid.resize(pixels);
  albedo.resize(3 * pixels);
  for (std::uint32_t p = 1; p < m_parts.parts; ++p) {
    ByteReader in(got.at(p));
    in.getArray(depth.data(), pixels);
    in.getArray(normal.data(), 3 * pixels);
    in.getArray(primid.data(), pixels);
    in.getArray(albedo.data(), 3 * pixels);
    in.expectDone();
    merge(depth.data(), normal.data(), primid.data(), albedo.data());
  }
}

void Renderer::checkSameFrame(std::uint64_t fingerprint) {
  ByteWriter out;
  out.put(fingerprint);
  // Every part sees every fingerprint, so all of them stop alike.
  const std::vector<Bytes> got = m_parts.exchange(true, out.take());
  for (std::uint32_t p = 0; p < m_parts.parts; ++p) {
    ByteReader in(got.at(p));
    const auto theirs = in.get<std::uint64_t>();
    in.expectDone();
    if (theirs != fingerprint)
      throw std::invalid_argument("frame parts: part " + std::to_string(p) + " of " + std::to_string(m_parts.parts) +
                                  " renders a different frame (scene, options or mesh data), or deals its units otherwise (a " +
                                  "compare_swap on some parts only), from part " +
                                  std::to_string(m_parts.part) + ": every part must render the same");
  }
}

void Renderer::setFrameParts(FrameParts parts) {
  if (parts.parts == 0 || parts.part >= parts.parts)
    throw std::invalid_argument("Renderer::setFrameParts: part must be below parts");
  if (parts.shared() && !parts.exchange) throw std::invalid_argument("Renderer::setFrameParts: no exchange");
  m_parts = std::move(parts);
}

void Renderer::setFilmBatchSlices(size_t slices) {
  for (auto& t : m_tracers) t->setFilmBatchSlices(slices);
}

void Renderer::injectDeviceFault(size_t device, std::uint64_t unit) {
  if (device >= m_tracers.size()) throw std::invalid_argument("injectDeviceFault: no such device");
  m_faults.emplace_back(device, unit);
}

size_t Renderer::holdWholeFilm(const RenderStats& stats, const std::function<void(DeviceTracer&)>& hold) {
  std::exception_ptr refused;
  for (size_t i = 0; i < m_tracers.size(); ++i) {
    if (stats.devices[i].failed) continue;
    try {
      hold(*m_tracers[i]);
      return i;
    } catch (const FilmTooLarge&) {
      if (!refused) refused = std::current_exception();
    }
  }
  if (refused) std::rethrow_exception(refused);
  throw DeviceError("no device is left to resolve the frame");
}

size_t Renderer::deviceIndex(const DeviceTracer& tracer) const {
  for (size_t i = 0; i < m_tracers.size(); ++i)
    if (m_tracers[i].get() == &tracer) return i;
  throw std::logic_error("Renderer::deviceIndex: not this renderer's tracer");
}

size_t Renderer::survivor(const RenderStats& stats) const {
  for (size_t i = 0; i < stats.devices.size(); ++i)
    if (!stats.devices[i].failed) return i;
  return stats.devices.size();
}

Renderer::DealtUnits Renderer::deal(const std::vector<std::uint64_t>& unit_samples,
                                    const std::function<void(DeviceTracer&, size_t unit)>& unit,
                                    RenderResult& result, const ProgressFn& progress) {
  const size_t units = unit_samples.size();
  std::unique_ptr<UnitSource> source;
  if (m_parts.shared() && m_parts.compare_swap) {
    // A deal without units touches no word, and takes no round.
    const std::uint32_t round = units > 0 ? ++*m_parts.deals : *m_parts.deals;
    source = std::make_unique<SharedStretches>(unit_samples, m_parts.part, m_parts.parts,
                                               static_cast<std::uint16_t>(round), m_parts.compare_swap);
  } else {
    const auto [first, last] = partUnits(units, m_parts.part, m_parts.parts);
    source = std::make_unique<UnitRange>(unit_samples, first, last);
  }
  std::vector<std::uint64_t> started(m_tracers.size(), 0);
  // Counts are kept per unit, so that a unit traced again after its device
  // failed counts once, whoever traced it.
  std::vector<RenderStats> counts(units);
  const UnitFn traced = [&](size_t d, size_t u) {
    for (const auto& [device, at] : m_faults)
      if (d == device && started[d] == at)
        throw DeviceError("injected fault (Renderer::injectDeviceFault) at its unit " + std::to_string(at));
    ++started[d];
    RenderStats& tracer_counts = m_device_stats[d];  // where the tracer counts (DeviceTracer::load)
    tracer_counts = RenderStats{};
    unit(*m_tracers[d], u);
    counts[u] = std::move(tracer_counts);
  };
  // With one device alone, progress comes chunk by chunk from the unit itself.
  // Its whole grows when this part takes another's units: the fraction shown never goes back.
  std::function<bool(size_t, size_t)> step;
  double shown = 0;
  if (unitsOfSlices() && progress)
    step = [&](size_t done, size_t whole) {
      shown = std::max(shown, static_cast<double>(done) / static_cast<double>(whole));
      return progress(shown);
    };
  DealResult dealt = dealUnits(result.stats.devices, unit_samples, *source, traced, step, m_paces);
  for (std::string& w : dealt.warnings) result.stats.warnings.push_back(std::move(w));
  if (dealt.cancelled) throw RenderCancelled();
  DealtUnits out{std::move(dealt.owner), std::vector<std::uint32_t>(units, m_parts.shared() ? kNoPart : 0)};
  if (m_parts.shared()) {
    // Every part learns who traced what; part 0 gets the counts of every unit.
    ByteWriter runs;
    packUnitRuns(runs, out.owner, kNoDevice);
    const std::vector<Bytes> lists = m_parts.exchange(true, runs.take());
    for (std::uint32_t p = 0; p < m_parts.parts; ++p) {
      ByteReader in(lists.at(p));
      unpackUnitRuns(in, p, out.part_of);
      in.expectDone();
    }
    checkUnitsCovered(out.part_of);
    ByteWriter mine;
    if (m_parts.part != 0)
      for (const auto& [first, last] : unitRuns(out.part_of, m_parts.part))
        packUnitCounts(mine, counts.data() + first, last - first);
    const std::vector<Bytes> got = m_parts.exchange(false, mine.take());
    for (std::uint32_t p = 1; m_parts.part == 0 && p < m_parts.parts; ++p) {
      ByteReader in(got.at(p));
      for (const auto& [first, last] : unitRuns(out.part_of, p)) unpackUnitCounts(in, counts.data() + first, last - first);
      in.expectDone();
    }
  }
  // In unit order: the first non-finite contribution is the first unit's that
  // found one (render order, as on one device).
  RenderStats& stats = result.stats;
  for (const RenderStats& c : counts) {
    for (size_t j = 0; j < stats.rays_by_kind.size(); ++j) stats.rays_by_kind[j] += c.rays_by_kind[j];
    for (size_t j = 0; j < stats.rays_per_depth.size(); ++j) stats.rays_per_depth[j] += c.rays_per_depth[j];
    stats.waves = std::max(stats.waves, c.waves);
    stats.film_batches += c.film_batches;
    if (c.nan && !stats.nan) stats.nan = c.nan;
  }
  return out;
}

void Renderer::renderSamples(const SamplingOptions& sampling, const RenderOptions& opt, RenderResult& result,
                             const ProgressFn& progress) {
  const std::uint64_t total = sampleCount(sampling.mode, opt.width, opt.height, sampling.spp);
  const bool several = unitsOfSlices();
  // Units: a slice (one chunk), or the Z-buffer's batch, which it rasterises at once.
  const std::uint64_t unit_size =
      result.stats.first_hit == FirstHitMode::ZBuffer ? DeviceTracer::kZBufferBatch : DeviceTracer::kSliceRays;
  std::vector<std::uint64_t> unit_samples;
  for (std::uint64_t first = 0; first < total; first += unit_size) unit_samples.push_back(std::min(unit_size, total - first));
  // The device that resolves the frame (at part 0: the first whose memory holds
  // it) holds the whole film. Every other holds a window of one unit and hands
  // each unit to the host as it ends, on its own thread; the resolver's thread
  // writes them into its film between its own units. A device need not hold
  // the frame to share it. A part other than 0 resolves its runs piece by
  // piece after the deal, so none of its devices holds the frame.
  const size_t resolver =
      m_parts.part == 0 ? holdWholeFilm(result.stats, [&](DeviceTracer& t) { t.beginSampleFilm(total); })
                        : m_tracers.size();
  const auto hands_over = [&](size_t d) { return d != resolver; };
  for (size_t i = 0; i < m_tracers.size(); ++i)
    if (!result.stats.devices[i].failed && hands_over(i)) m_tracers[i]->beginSampleFilm(total, unit_size);
  HeldUnits held(unit_size, unit_samples.size());
  std::vector<char> gathered(unit_samples.size(), 0);  // written into the resolver's film by its thread
  const DealtUnits dealt = deal(
      unit_samples,
      [&](DeviceTracer& tracer, size_t u) {
        const std::uint64_t first = u * unit_size;
        tracer.traceSamples(first, first + unit_samples[u], [&](std::uint64_t done) {
          if (!several && progress && !progress(static_cast<double>(done) / static_cast<double>(total)))
            throw RenderCancelled();
        });
        if (hands_over(deviceIndex(tracer))) {
          held.take(u, unit_samples[u], tracer);
        } else {
          auto waiting = held.takeWaiting();
          for (const auto& unit : waiting) gathered[unit.first] = 1;  // before the writes, which may fail
          held.write(waiting, tracer);
        }
      },
      result, progress);
  if (m_parts.part != 0) {
    resolveAcrossParts(sampling, opt, dealt.part_of, unit_size, held, *m_tracers[survivor(result.stats)], result);
    return;
  }
  // The resolver, unless it failed: then the first device left that can takes
  // the whole film (its own units were all handed over), and the units the
  // failed one had gathered from the others are traced again on it.
  size_t resolving_device = resolver;
  std::vector<size_t> lost;
  if (result.stats.devices[resolver].failed) {
    resolving_device = holdWholeFilm(result.stats, [&](DeviceTracer& t) { t.holdSamples(0, total); });
    for (size_t u = 0; u < dealt.owner.size(); ++u)
      if (dealt.owner[u] != kNoDevice && gathered[u] && !held.holds(u)) lost.push_back(u);
  }
  DeviceTracer& resolving = *m_tracers[resolving_device];
  held.write(held.takeWaiting(), resolving);
  // (Its ray counts were counted when the unit was first traced.)
  for (size_t u : lost) resolving.traceSamples(u * unit_size, u * unit_size + unit_samples[u], {});
  if (!lost.empty())
    result.stats.warnings.push_back("device '" + result.stats.devices[resolver].device +
                                    "', which was to resolve the frame, failed holding " + std::to_string(lost.size()) +
                                    " units the others had traced; they were traced again on '" +
                                    result.stats.devices[resolving_device].device + "'");
  if (m_parts.shared())
    resolveAcrossParts(sampling, opt, dealt.part_of, unit_size, held, resolving, result);
  else
    result.rgba = resolving.resolvePixels();
}

void Renderer::resolveAcrossParts(const SamplingOptions& sampling, const RenderOptions& opt,
                                  const std::vector<std::uint32_t>& part_of, std::uint64_t unit_size,
                                  HeldUnits& held, DeviceTracer& resolving, RenderResult& result) {
  // Part 0 resolves the frame; each other part sends it, for each run of
  // consecutive units it traced, the pixels it can resolve alone and the
  // samples part 0 needs for the rest (render/part_resolve.h), or, in quincunx
  // mode, whose corner samples are shared by neighbouring pixels, all its samples.
  const std::uint64_t total = sampleCount(sampling.mode, opt.width, opt.height, sampling.spp);
  const std::uint64_t pixels = static_cast<std::uint64_t>(opt.width) * static_cast<std::uint64_t>(opt.height);
  // As the resolve kernel reaches: ceil(r - 1/2) rows and columns, in float.
  const auto reach_rows = static_cast<std::uint64_t>(filterReach(sampling.effectiveFilter()));
  const auto partOf = [&](std::uint32_t p) {
    std::vector<PartResolve> runs;
    for (const auto& [first_unit, last_unit] : unitRuns(part_of, p)) {
      const std::uint64_t first = std::min<std::uint64_t>(total, first_unit * unit_size);
      const std::uint64_t end = std::min<std::uint64_t>(total, last_unit * unit_size);
      if (sampling.mode == AaMode::Quincunx) {
        PartResolve all;
        if (end > first) all.samples.emplace_back(first, end);
        runs.push_back(all);
      } else {
        runs.push_back(partResolve(first, end, static_cast<std::uint64_t>(sampling.spp),
                                   reach_rows * (static_cast<std::uint64_t>(opt.width) + 1)));
      }
    }
    return runs;
  };
  SampleRun run;
  ByteWriter out;
  if (m_parts.part != 0) {
    // Its devices handed every unit over. The pixels it resolves go through the
    // resolver's window a piece at a time, each piece with the samples its
    // pixels reach (all inside the run: partResolve), so no device holds a run.
    const std::uint64_t spp = static_cast<std::uint64_t>(sampling.spp);
    const std::uint64_t reach_pixels = reach_rows * (static_cast<std::uint64_t>(opt.width) + 1);
    const std::uint64_t piece = std::max<std::uint64_t>(1, m_resolve_piece_samples / spp);  // pixels
    for (const PartResolve& mine : partOf(m_parts.part)) {
      for (std::uint64_t a = mine.first_pixel; a < mine.end_pixel; a += piece) {
        const std::uint64_t b = std::min(mine.end_pixel, a + piece);
        const std::uint64_t lo = (a - reach_pixels) * spp, hi = (b + reach_pixels) * spp;
        run.resize(static_cast<size_t>(hi - lo));
        held.copy(lo, hi, run.rgba.data(), run.xy.data());
        resolving.holdSamples(lo, hi - lo);
        resolving.writeSamples(lo, run.size(), run.rgba.data(), run.xy.data());
        const std::vector<float> own = resolving.resolvePixels(static_cast<size_t>(a), static_cast<size_t>(b - a));
        out.putArray(own.data(), own.size());
      }
      for (const auto& [first, end] : mine.samples) {
        run.resize(static_cast<size_t>(end - first));
        held.copy(first, end, run.rgba.data(), run.xy.data());
        out.putArray(run.rgba.data(), run.rgba.size());
        out.putArray(run.xy.data(), run.xy.size());
      }
    }
  }
  const std::vector<Bytes> got = m_parts.exchange(false, out.take());
  if (m_parts.part != 0) return;  // render() gives the other parts zeros
  result.rgba.assign(4 * pixels, 0.f);
  std::vector<std::pair<std::uint64_t, std::uint64_t>> resolved;  // by the other parts
  for (std::uint32_t p = 1; p < m_parts.parts; ++p) {
    ByteReader in(got.at(p));
    for (const PartResolve& theirs : partOf(p)) {
      in.getArray(result.rgba.data() + 4 * theirs.first_pixel, 4 * (theirs.end_pixel - theirs.first_pixel));
      if (theirs.end_pixel > theirs.first_pixel) resolved.emplace_back(theirs.first_pixel, theirs.end_pixel);
      for (const auto& [first, end] : theirs.samples) {
        run.resize(static_cast<size_t>(end - first));
        in.getArray(run.rgba.data(), run.rgba.size());
        in.getArray(run.xy.data(), run.xy.size());
        resolving.writeSamples(first, run.size(), run.rgba.data(), run.xy.data());
      }
    }
    in.expectDone();
  }
  // Part 0 resolves the pixels between those.
  std::sort(resolved.begin(), resolved.end());
  std::uint64_t from = 0;
  resolved.emplace_back(pixels, pixels);
  for (const auto& [first, end] : resolved) {
    if (first > from) {
      const std::vector<float> own = resolving.resolvePixels(static_cast<size_t>(from), static_cast<size_t>(first - from));
      std::copy(own.begin(), own.end(), result.rgba.begin() + static_cast<std::ptrdiff_t>(4 * from));
    }
    from = end;
  }
}

void Renderer::renderAdaptive(const SamplingOptions& sampling, const RenderOptions& opt, RenderResult& result,
                              const ProgressFn& progress) {
  const std::int64_t w = opt.width, h = opt.height;
  // Passes: the corners, then at most one per level. Progress counts passes, each
  // in proportion to its chunks (with several devices, its units) done.
  const double passes = 1.0 + sampling.adaptive_max_level;
  const bool several = unitsOfSlices();
  int pass = 0;
  std::uint64_t traced = 0;  // positions of the passes before
  TraceFn trace = [&](const std::vector<float>& xy) {
    const size_t n = xy.size() / 2;
    // The corner (i, j) of pixel (i, j) is its first sample and writes its AOVs
    // (every corner comes in the first pass; later points are never corners).
    std::vector<std::int32_t> aov(n, -1);
    for (size_t k = 0; k < n; ++k) {
      const float x = xy[2 * k], y = xy[2 * k + 1];
      if (x == std::floor(x) && y == std::floor(y) && x < w && y < h)
        aov[k] = static_cast<std::int32_t>(static_cast<std::int64_t>(y) * w + static_cast<std::int64_t>(x));
    }
    // One unit with one device alone; with several, or parts, whole chunks (or
    // Z-buffer batches), counted from the pass's first position as one device
    // counts them.
    const size_t unit_size = !several ? std::max<size_t>(n, 1)
                             : result.stats.first_hit == FirstHitMode::ZBuffer ? DeviceTracer::kZBufferBatch
                                                                               : DeviceTracer::kSliceRays;
    std::vector<std::uint64_t> unit_samples;
    for (size_t first = 0; first < n; first += unit_size) unit_samples.push_back(std::min(unit_size, n - first));
    std::vector<float> rgba(4 * n);
    const DealtUnits dealt = deal(
        unit_samples,
        [&](DeviceTracer& tracer, size_t u) {
          const size_t first = u * unit_size, m = static_cast<size_t>(unit_samples[u]);
          const std::vector<float> part_xy(xy.begin() + 2 * first, xy.begin() + 2 * (first + m));
          const std::vector<std::int32_t> part_aov(aov.begin() + first, aov.begin() + first + m);
          const std::vector<float> part = tracer.traceFilmPositions(part_xy, part_aov, traced + first, [&](size_t done) {
            if (!several && progress && !progress(std::min(1.0, (pass + static_cast<double>(done) / n) / passes)))
              throw RenderCancelled();
          });
          std::copy(part.begin(), part.end(), rgba.begin() + 4 * first);
        },
        result,
        several && progress ? ProgressFn([&](double f) { return progress(std::min(1.0, (pass + f) / passes)); })
                            : ProgressFn());
    if (m_parts.shared()) {
      // Every part chooses the next pass's points from every colour of this
      // one: each sends those of the positions of its runs of units.
      const auto each_run = [&](std::uint32_t p, auto&& positions) {
        for (const auto& [first, last] : unitRuns(dealt.part_of, p))
          positions(std::min(n, first * unit_size), std::min(n, last * unit_size));
      };
      ByteWriter out;
      each_run(m_parts.part, [&](size_t lo, size_t hi) { out.putArray(rgba.data() + 4 * lo, 4 * (hi - lo)); });
      const std::vector<Bytes> got = m_parts.exchange(true, out.take());
      for (std::uint32_t p = 0; p < m_parts.parts; ++p) {
        if (p == m_parts.part) continue;
        ByteReader in(got.at(p));
        each_run(p, [&](size_t lo, size_t hi) { in.getArray(rgba.data() + 4 * lo, 4 * (hi - lo)); });
        in.expectDone();
      }
    }
    // Only the first pass writes AOVs (its corners). Gathered now, they survive a
    // device that fails in a later pass, whose memory is not read again.
    if (pass == 0) gatherAovs(result);
    ++pass;
    traced += n;
    return rgba;
  };
  AdaptiveResult adaptive =
      adaptiveSample(opt.width, opt.height, sampling.adaptive_threshold, sampling.adaptive_max_level, trace);
  result.rgba = std::move(adaptive.pixels);
  if (progress && !progress(1.0)) throw RenderCancelled();
}

}  // namespace prism
