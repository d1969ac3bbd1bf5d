// libFuzzer target for sequences of C API calls: the input is read as a program
// of calls on up to three scene handles (some of them NULL), with arguments
// drawn from the input (extreme floats, NaN and infinities among them,
// arbitrary names, JSON text, mesh arrays with indices out of range, sizes that
// lie). It covers every call that needs no OpenCL device: building scenes,
// cameras, lights, materials, objects and meshes from arrays, scene fragments
// and whole scenes from text, render options and their checks, the names and
// parsers. The API's promises are asserted on every call: a status from the
// enum, a message from prismGetLastError after every failure, a readable name
// or NULL from every *Name call. A crash, a sanitizer report, a leak or a
// broken promise is a finding.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "prism.h"

namespace {

class Reader {
 public:
  Reader(const std::uint8_t* data, std::size_t size) : m_data(data), m_size(size) {}
  bool done() const { return m_at >= m_size; }
  std::uint8_t byte() { return m_at < m_size ? m_data[m_at++] : 0; }
  std::uint32_t u32() {
    std::uint32_t v = 0;
    for (int i = 0; i < 4; ++i) v = v << 8 | byte();
    return v;
  }
  // Mostly values at the edges of what the API accepts; sometimes raw bits.
  float number() {
    static const float kValues[] = {0.0f, 1.0f, -1.0f, 0.5f, 2.0f, 1e-30f, -1e-30f, 1e6f, 1e6f * 1.0001f, 1e15f,
                                    1e16f, -1e15f, 3.4e38f, -3.4e38f, 179.9f, 180.0f, 1e-45f, 0.001f, 4096.0f,
                                    NAN, INFINITY, -INFINITY};
    const std::uint8_t b = byte();
    if (b & 0x80) {
      const std::uint32_t bits = u32();
      float f;
      std::memcpy(&f, &bits, sizeof f);
      return f;
    }
    return kValues[b % (sizeof kValues / sizeof kValues[0])];
  }
  void numbers(float* out, int n) {
    for (int i = 0; i < n; ++i) out[i] = number();
  }
  // A short name, often one a scene already uses.
  std::string name() {
    static const char* const kNames[] = {"default", "m", "glass", "", "bvh", "octree", "bsp", "none", "auto",
                                         "jitter", "quincunx", "adaptive", "box", "tent", "zbuffer", "trace",
                                         "crossing", "radial", "left-right", "accel", "lightbuffer", "aabb", "kdop"};
    const std::uint8_t b = byte();
    if (b < 200) return kNames[b % (sizeof kNames / sizeof kNames[0])];
    std::string s;
    for (int n = byte() % 24; n > 0; --n) s += static_cast<char>(byte() | 1);  // no NUL inside
    return s;
  }
  // Text up to a NUL byte or the end: JSON for the scene calls.
  std::string text() {
    std::string s;
    while (!done()) {
      const char c = static_cast<char>(byte());
      if (c == '\0') break;
      s += c;
    }
    return s;
  }

 private:
  const std::uint8_t* m_data;
  std::size_t m_size;
  std::size_t m_at = 0;
};

void broken(const char* promise, const char* call) {
  std::fprintf(stderr, "api_fuzzer: %s: %s\n", call, promise);
  std::abort();
}

// Every status is one of the enum's, and every failure leaves a message.
PrismStatus checked(PrismStatus status, const char* call) {
  if (static_cast<unsigned>(status) > PRISM_ERROR_UNKNOWN) broken("a status outside PrismStatus", call);
  if (status != PRISM_OK) {
    const char* message = prismGetLastError();
    if (!message || !*message) broken("a failure without a message", call);
    if (!prismStatusName(status)) broken("a status without a name", call);
  }
  return status;
}

void checkName(const char* name, const char* call) {
  if (name && std::strlen(name) > 256) broken("a name longer than any the API has", call);
}

// A 4x4 matrix, the identity with entries changed from the input, or NULL.
const float* matrix(Reader& in, float* storage) {
  const std::uint8_t b = in.byte();
  if (b % 3 == 0) return nullptr;
  for (int i = 0; i < 16; ++i) storage[i] = (i % 5 == 0) ? 1.0f : 0.0f;
  for (int n = b % 5; n > 0; --n) storage[in.byte() % 16] = in.number();
  return storage;
}

void step(Reader& in, PrismScene (&scenes)[3]) {
  PrismScene& slot = scenes[in.byte() % 3];
  PrismScene scene = slot;  // may be NULL: every call must refuse it
  switch (in.byte() % 17) {
    case 0:
      prismReleaseScene(slot);
      slot = nullptr;
      checked(prismNewScene(&slot), "prismNewScene");
      break;
    case 1:
      prismReleaseScene(slot);
      slot = nullptr;
      break;
    case 2: {
      float p[3], c[3];
      in.numbers(p, 3);
      in.numbers(c, 3);
      checked(prismAddPointLight(scene, p, c, in.number()), "prismAddPointLight");
      break;
    }
    case 3: {
      PrismAreaLight l;
      std::memset(&l, 0, sizeof l);
      l.struct_size = in.byte() % 4 == 0 ? in.byte() : sizeof l;
      l.type = static_cast<PrismAreaLightType>(in.byte() % 5);
      in.numbers(l.corner, 3);
      in.numbers(l.edge1, 3);
      in.numbers(l.edge2, 3);
      in.numbers(l.center, 3);
      in.numbers(l.normal, 3);
      l.radius = in.number();
      in.numbers(l.color, 3);
      l.intensity = in.number();
      l.samples = static_cast<int>(in.u32());
      checked(prismAddAreaLight(scene, &l), "prismAddAreaLight");
      break;
    }
    case 4: {
      PrismMaterial m;
      prismDefaultMaterial(&m);
      if (in.byte() % 8 == 0) m.struct_size = in.byte();
      for (int n = in.byte() % 6; n > 0; --n) {
        switch (in.byte() % 12) {
          case 0: m.model = in.byte() % 5; break;
          case 1: in.numbers(m.diffuse, 3); break;
          case 2: in.numbers(m.specular, 3); break;
          case 3: m.shininess = in.number(); break;
          case 4: m.reflect = in.number(); break;
          case 5: m.transmit = in.number(); break;
          case 6: m.ior = in.number(); break;
          case 7: m.gloss = in.number(); break;
          case 8: m.translucency = in.number(); break;
          case 9: m.checker = in.byte() % 2; m.checker_scale = in.number(); break;
          case 10: m.roughness = in.number(); m.distribution = in.byte() % 3; break;
          default: in.numbers(m.ambient, 3); break;
        }
      }
      const std::string name = in.name();
      std::uint32_t index = 0;
      checked(prismAddMaterial(scene, in.byte() % 16 == 0 ? nullptr : name.c_str(), &m, &index),
              "prismAddMaterial");
      break;
    }
    case 5: {
      PrismObject o;
      prismDefaultObject(&o, static_cast<PrismObjectType>(in.byte() % 7));
      if (in.byte() % 8 == 0) o.struct_size = in.byte();
      const std::string material = in.name();
      o.material = in.byte() % 2 ? material.c_str() : nullptr;
      float m0[16], m1[16];
      o.object_to_world = matrix(in, m0);
      o.object_to_world_end = in.byte() % 4 == 0 ? matrix(in, m1) : nullptr;
      for (int n = in.byte() % 6; n > 0; --n) {
        switch (in.byte() % 7) {
          case 0: in.numbers(o.center, 3); o.radius = in.number(); break;
          case 1: in.numbers(o.box_min, 3); in.numbers(o.box_max, 3); break;
          case 2: in.numbers(o.point, 3); in.numbers(o.normal, 3); break;
          case 3: in.numbers(o.vertices, 9); break;
          case 4: in.numbers(o.coefficients, 10); break;
          case 5: in.numbers(o.clip_min, 3); in.numbers(o.clip_max, 3); break;
          default: o.capped = in.byte() % 3; break;
        }
      }
      std::uint32_t index = 0;
      checked(prismAddObject(scene, &o, in.byte() % 2 ? &index : nullptr), "prismAddObject");
      break;
    }
    case 6: {
      PrismCamera c;
      std::memset(&c, 0, sizeof c);
      c.struct_size = sizeof c;
      if (scene) checked(prismGetCamera(scene, &c), "prismGetCamera");
      if (in.byte() % 8 == 0) c.struct_size = in.byte();
      for (int n = in.byte() % 5; n > 0; --n) {
        switch (in.byte() % 7) {
          case 0: in.numbers(c.position, 3); break;
          case 1: in.numbers(c.look_at, 3); break;
          case 2: in.numbers(c.up, 3); break;
          case 3: c.fov_degrees = in.number(); break;
          case 4: c.aperture = in.number(); c.focus_distance = in.number(); break;
          case 5: c.shutter_open = in.number(); c.shutter_close = in.number(); break;
          default: c.moving = in.byte() % 2; in.numbers(c.position_end, 3); in.numbers(c.look_at_end, 3); break;
        }
      }
      checked(prismSetCamera(scene, &c), "prismSetCamera");
      break;
    }
    case 7: {
      float c[3];
      in.numbers(c, 3);
      checked(in.byte() % 2 ? prismSetBackground(scene, c) : prismSetAmbient(scene, c), "prismSetBackground/Ambient");
      break;
    }
    case 8: {
      const std::string json = in.text();
      checked(prismAddSceneJson(scene, json.c_str()), "prismAddSceneJson");
      break;
    }
    case 9: {
      const std::string json = in.text();
      PrismScene loaded = nullptr;
      if (checked(prismLoadSceneFromString(json.c_str(), "fuzz.json", &loaded), "prismLoadSceneFromString") ==
          PRISM_OK) {
        prismReleaseScene(slot);
        slot = loaded;
      } else if (loaded) {
        broken("a failed load handed out a scene", "prismLoadSceneFromString");
      }
      break;
    }
    case 10: {
      std::uint32_t count = 0;
      checked(prismGetSceneObjectCount(scene, &count), "prismGetSceneObjectCount");
      const char* device = nullptr;
      if (checked(prismGetSceneDevice(scene, &device), "prismGetSceneDevice") == PRISM_OK && !device)
        broken("no selector string (even an empty one) for a scene", "prismGetSceneDevice");
      // An animation's frames (the scene text may carry an "animation" block).
      if (checked(prismGetFrameCount(scene, &count), "prismGetFrameCount") == PRISM_OK) {
        PrismScene frame = nullptr;
        const std::uint32_t index = in.byte() % 2 ? count - 1 : in.u32() % (count + 1);
        if (checked(prismGetFrameScene(scene, index, &frame), "prismGetFrameScene") == PRISM_OK) {
          std::uint32_t frames = 0;
          if (!frame || index >= count || prismGetFrameCount(frame, &frames) != PRISM_OK || frames != 1)
            broken("a frame past the count, or not a scene of one frame", "prismGetFrameScene");
        }
        prismReleaseScene(frame);
      }
      if (checked(prismGetSceneWarningCount(scene, &count), "prismGetSceneWarningCount") == PRISM_OK) {
        const char* message = nullptr;
        const std::uint32_t index = in.byte() % 2 ? count : in.u32() % (count + 2);
        if (checked(prismGetSceneWarning(scene, index, &message), "prismGetSceneWarning") == PRISM_OK &&
            (!message || index >= count))
          broken("a warning past the count, or none where one was promised", "prismGetSceneWarning");
      }
      break;
    }
    case 11: {
      const std::size_t vertices = in.byte() % 12, triangles = in.byte() % 8;
      std::vector<float> positions(3 * vertices + 1);
      for (float& p : positions) p = in.byte() % 4 ? static_cast<float>(in.byte() % 7) - 3.0f : in.number();
      std::vector<std::uint32_t> indices(3 * triangles + 1);
      for (std::uint32_t& i : indices) i = in.byte() % 8 ? in.byte() % (vertices + 1) : in.u32();
      const std::string material = in.name();
      float m[16];
      const float* to_world = matrix(in, m);
      // Counts that lie about the arrays are the caller's bug (undefined); the
      // counts here always fit them.
      checked(prismAddMeshArrays(scene, in.byte() % 16 ? positions.data() : nullptr, vertices,
                                 in.byte() % 16 ? indices.data() : nullptr, triangles,
                                 in.byte() % 2 ? material.c_str() : nullptr, to_world, nullptr),
              "prismAddMeshArrays");
      break;
    }
    case 12: {
      PrismRenderOptions o;
      std::memset(&o, 0, sizeof o);
      o.struct_size = sizeof o;
      if (scene) checked(prismGetRenderOptions(scene, &o), "prismGetRenderOptions");
      if (in.byte() % 8 == 0) o.struct_size = in.byte();
      for (int n = in.byte() % 6; n > 0; --n) {
        switch (in.byte() % 12) {
          case 0: o.width = in.u32(); break;
          case 1: o.height = in.u32(); break;
          case 2: o.spp = in.u32(); break;
          case 3: o.max_depth = in.u32(); break;
          case 4: o.min_weight = in.number(); break;
          case 5: o.accel = in.byte() % 7; break;
          case 6: o.aa = in.byte() % 9; break;
          case 7: o.filter = in.byte() % 6; break;
          case 8: o.first_hit = in.byte() % 5; break;
          case 9: o.aa_threshold = in.number(); o.aa_max_level = in.u32(); break;
          case 10: o.shadows = in.byte() % 5; o.bounds = in.byte() % 4; break;
          default: o.inside_test = in.byte() % 5; o.check_nan = in.byte(); break;
        }
      }
      checked(prismCheckRenderOptions(&o), "prismCheckRenderOptions");
      break;
    }
    case 13: {
      const std::string text = in.name();
      PrismAccel a;
      PrismAa aa;
      PrismFilter f;
      PrismFirstHit h;
      PrismInsideTest t;
      PrismShadows s;
      PrismBounds b;
      switch (in.byte() % 7) {
        case 0: checked(prismParseAccel(text.c_str(), &a), "prismParseAccel"); break;
        case 1: checked(prismParseAa(text.c_str(), &aa), "prismParseAa"); break;
        case 2: checked(prismParseFilter(text.c_str(), &f), "prismParseFilter"); break;
        case 3: checked(prismParseFirstHit(text.c_str(), &h), "prismParseFirstHit"); break;
        case 4: checked(prismParseInsideTest(text.c_str(), &t), "prismParseInsideTest"); break;
        case 5: checked(prismParseShadows(text.c_str(), &s), "prismParseShadows"); break;
        default: checked(prismParseBounds(in.byte() % 8 ? text.c_str() : nullptr, &b), "prismParseBounds"); break;
      }
      break;
    }
    case 14: {
      const std::uint32_t v = in.byte() % 2 ? in.byte() % 10 : in.u32();
      checkName(prismAccelName(static_cast<PrismAccel>(v)), "prismAccelName");
      checkName(prismAaName(static_cast<PrismAa>(v)), "prismAaName");
      checkName(prismFilterName(static_cast<PrismFilter>(v)), "prismFilterName");
      checkName(prismFirstHitName(static_cast<PrismFirstHit>(v)), "prismFirstHitName");
      checkName(prismInsideTestName(static_cast<PrismInsideTest>(v)), "prismInsideTestName");
      checkName(prismShadowsName(static_cast<PrismShadows>(v)), "prismShadowsName");
      checkName(prismBoundsName(static_cast<PrismBounds>(v)), "prismBoundsName");
      if (!prismStatusName(static_cast<PrismStatus>(v))) broken("a status value without a name", "prismStatusName");
      break;
    }
    case 15: {
      std::uint32_t count = 0;
      checked(prismGetSceneObjectCount(in.byte() % 2 ? scene : nullptr, in.byte() % 8 ? &count : nullptr),
              "prismGetSceneObjectCount");
      break;
    }
    default: {
      PrismCamera c;
      c.struct_size = in.byte() % 2 ? sizeof c : in.byte();
      checked(prismGetCamera(scene, in.byte() % 8 ? &c : nullptr), "prismGetCamera");
      break;
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  Reader in(data, size);
  PrismScene scenes[3] = {nullptr, nullptr, nullptr};
  for (int calls = 0; calls < 64 && !in.done(); ++calls) step(in, scenes);
  for (PrismScene& s : scenes) prismReleaseScene(s);
  return 0;
}
