#include "render/frame_parts.h"

#include <cstring>
#include <stdexcept>
#include <string>

namespace prism {

std::pair<std::size_t, std::size_t> partUnits(std::size_t units, std::uint32_t part, std::uint32_t parts) {
  if (parts == 0 || part >= parts) throw std::invalid_argument("partUnits: part must be below parts");
  const auto at = [&](std::uint64_t p) { return static_cast<std::size_t>(units * p / parts); };
  return {at(part), at(part + 1u)};
}

void ByteWriter::putRaw(const void* data, std::size_t size) {
  if (size == 0) return;
  const auto* p = static_cast<const std::uint8_t*>(data);
  m_bytes.insert(m_bytes.end(), p, p + size);
}

void ByteWriter::putString(const std::string& s) {
  put<std::uint64_t>(s.size());
  putRaw(s.data(), s.size());
}

void ByteReader::getRaw(void* data, std::size_t size) {
  if (size > m_bytes.size() - m_at)
    throw std::runtime_error("frame parts: a part sent fewer bytes than expected (different builds of prism, "
                             "or a different scene or options on another part?)");
  if (size == 0) return;  // an empty part's bytes may have no storage at all
  std::memcpy(data, m_bytes.data() + m_at, size);
  m_at += size;
}

void ByteReader::expectDone() const {
  if (!done())
    throw std::runtime_error("frame parts: a part sent more bytes than expected (different builds of prism, "
                             "or a different scene or options on another part?)");
}

std::uint64_t frameFingerprint(const GpuScene& scene, const RenderOptions& options, FirstHitMode first_hit,
                               ShadowMode shadows, AccelKind accel, bool dealt_as_devices_come_free) {
  std::uint64_t hash = 14695981039346656037ull;
  const auto add = [&hash](const void* data, std::size_t size) {
    const auto* p = static_cast<const std::uint8_t*>(data);
    for (std::size_t i = 0; i < size; ++i) hash = (hash ^ p[i]) * 1099511628211ull;
  };
  const auto value = [&add](auto v) { add(&v, sizeof v); };
  value(std::int64_t{options.width});
  value(std::int64_t{options.height});
  value(std::int64_t{options.spp});
  value(std::int64_t{options.max_depth});
  value(options.min_weight);
  value(options.seed);
  value(static_cast<std::int64_t>(options.aaMode()));
  value(static_cast<std::int64_t>(options.filter));
  value(options.aa_threshold);
  value(std::int64_t{options.aa_max_level});
  value(static_cast<std::int64_t>(options.inside_test));
  value(static_cast<std::int64_t>(options.bounds));
  value(static_cast<std::int64_t>(first_hit));
  value(static_cast<std::int64_t>(shadows));
  value(static_cast<std::int64_t>(accel));
  value(std::int64_t{dealt_as_devices_come_free});
  value(std::int64_t{options.check_nan});
  add(&scene.camera, sizeof scene.camera);  // every field 4 bytes, the padding explicit and zero
  add(scene.ambient, sizeof scene.ambient);
  add(scene.background, sizeof scene.background);
  value(std::uint64_t{scene.objects.size()});
  value(std::uint64_t{scene.primitive_count});
  value(std::uint64_t{scene.materials.size()});
  value(std::uint64_t{scene.lights.size()});
  value(std::uint64_t{scene.texels.size()});
  add(scene.triangles.data(), scene.triangles.size() * sizeof(std::uint32_t));
  add(scene.mesh_data.data(), scene.mesh_data.size() * sizeof(float));
  return hash;
}

std::string ByteReader::getString() {
  const auto n = get<std::uint64_t>();
  std::string s(n <= m_bytes.size() - m_at ? static_cast<std::size_t>(n) : 0, '\0');
  getRaw(s.data(), static_cast<std::size_t>(n));
  return s;
}

namespace {

// The runs [first, last) of consecutive units u below `units` where mine(u).
template <typename Mine>
std::vector<std::pair<std::size_t, std::size_t>> runsWhere(std::size_t units, Mine&& mine) {
  std::vector<std::pair<std::size_t, std::size_t>> runs;
  for (std::size_t u = 0; u < units; ++u) {
    if (!mine(u)) continue;
    if (!runs.empty() && runs.back().second == u)
      ++runs.back().second;
    else
      runs.emplace_back(u, u + 1);
  }
  return runs;
}

}  // namespace

void packUnitRuns(ByteWriter& out, const std::vector<std::size_t>& owner, std::size_t no_owner) {
  const auto runs = runsWhere(owner.size(), [&](std::size_t u) { return owner[u] != no_owner; });
  out.put<std::uint64_t>(runs.size());
  for (const auto& [first, last] : runs) {
    out.put<std::uint64_t>(first);
    out.put<std::uint64_t>(last);
  }
}

void unpackUnitRuns(ByteReader& in, std::uint32_t part, std::vector<std::uint32_t>& part_of) {
  const auto runs = in.get<std::uint64_t>();
  std::uint64_t after = 0;  // the runs come in order, apart
  for (std::uint64_t r = 0; r < runs; ++r) {
    const auto first = in.get<std::uint64_t>(), last = in.get<std::uint64_t>();
    if (first < after || last <= first || last > part_of.size())
      throw std::runtime_error("frame parts: part " + std::to_string(part) + " sent a list of units out of order");
    for (std::uint64_t u = first; u < last; ++u) {
      if (part_of[u] != kNoPart)
        throw std::runtime_error("frame parts: parts " + std::to_string(part_of[u]) + " and " + std::to_string(part) +
                                 " both traced unit " + std::to_string(u));
      part_of[u] = part;
    }
    after = last;
  }
}

void checkUnitsCovered(const std::vector<std::uint32_t>& part_of) {
  for (std::size_t u = 0; u < part_of.size(); ++u)
    if (part_of[u] == kNoPart) throw std::runtime_error("frame parts: no part traced unit " + std::to_string(u));
}

std::vector<std::pair<std::size_t, std::size_t>> unitRuns(const std::vector<std::uint32_t>& part_of,
                                                          std::uint32_t part) {
  return runsWhere(part_of.size(), [&](std::size_t u) { return part_of[u] == part; });
}

void packUnitCounts(ByteWriter& out, const RenderStats* counts, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i) {
    const RenderStats& c = counts[i];
    out.putArray(c.rays_by_kind.data(), c.rays_by_kind.size());
    out.putArray(c.rays_per_depth.data(), c.rays_per_depth.size());
    out.put<std::int32_t>(c.waves);
    out.put<std::int32_t>(c.film_batches);
    out.put<std::uint8_t>(c.nan.has_value());
    if (c.nan) out.put(*c.nan);
  }
}

void unpackUnitCounts(ByteReader& in, RenderStats* counts, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i) {
    RenderStats& c = counts[i];
    in.getArray(c.rays_by_kind.data(), c.rays_by_kind.size());
    in.getArray(c.rays_per_depth.data(), c.rays_per_depth.size());
    c.waves = in.get<std::int32_t>();
    c.film_batches = in.get<std::int32_t>();
    if (in.get<std::uint8_t>()) c.nan = in.get<NanFinding>();
  }
}

void packShares(ByteWriter& out, const RenderStats& stats) {
  out.put<std::uint64_t>(stats.devices.size());
  for (const DeviceShare& d : stats.devices) {
    out.putString(d.device);
    out.put(d.units);
    out.put(d.samples);
    out.put(d.busy_seconds);
    out.put(d.film_bytes);
    out.put<std::uint8_t>(d.failed);
    out.putString(d.failure);
  }
  out.put<std::uint64_t>(stats.warnings.size());
  for (const std::string& w : stats.warnings) out.putString(w);
}

void unpackShares(ByteReader& in, std::uint32_t part, RenderStats& stats) {
  const std::string prefix = "part " + std::to_string(part) + ": ";
  const auto devices = in.get<std::uint64_t>();
  for (std::uint64_t i = 0; i < devices; ++i) {
    DeviceShare d;
    d.device = prefix + in.getString();
    d.units = in.get<std::uint64_t>();
    d.samples = in.get<std::uint64_t>();
    d.busy_seconds = in.get<double>();
    d.film_bytes = in.get<std::uint64_t>();
    d.failed = in.get<std::uint8_t>() != 0;
    d.failure = in.getString();
    stats.devices.push_back(std::move(d));
  }
  const auto warnings = in.get<std::uint64_t>();
  for (std::uint64_t i = 0; i < warnings; ++i) stats.warnings.push_back(prefix + in.getString());
}

}  // namespace prism
