// Reads the JSON scene format (docs/scene-format.md) into a Scene. Every value is
// checked here, so the renderer may trust the Scene it gets; every message names the
// file and the JSON path. Mesh files and the C API's scene building live elsewhere.
#include "scene_format/scene_loader.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

#include "device/device_selector.h"
#include "mesh/mesh_cache.h"
#include "mesh/mesh_error.h"
#include "scene/animation.h"
#include "scene/camera_check.h"
#include "scene/json_reader.h"
#include "scene/light_check.h"
#include "scene/mesh_objects.h"
#include "scene/primitives/bounds_kind.h"
#include "scene/primitives/inside_test.h"
#include "scene/primitives/primitive_kind.h"
#include "scene/render_modes.h"
#include "scene/sampling_options.h"
#include "scene/value_check.h"

namespace prism {

namespace {

// nlohmann's ordered_json finds each key by a linear search as it inserts it,
// so an object of n keys parses in O(n^2) (160,000 materials: 21 s). Plain json
// sorts its keys instead; the one order that matters, the materials' (it fixes
// their indices), is recorded while parsing (ParsedJson).
struct ParsedJson {
  Json root;
  std::vector<std::string> material_order;  // the keys of the top-level "materials", first occurrences
};

constexpr int kMaxFilmSize = 32768;
constexpr int kMaxSpp = 65536;  // the renderer keeps all samples of a pixel in one 65536-ray slice
constexpr int kMaxDepth = 31;
constexpr double kMaxColour = 1e6;     // see colour()
constexpr double kMaxExponent = 1e6;   // shininess: pow_positive is checked up to it (tests/kernels/math_test.cpp)

class SceneParser : private JsonReader {
 public:
  SceneParser(std::string name, std::string base_dir, Scene& scene)
      : JsonReader(std::move(name), &scene.warnings, std::move(base_dir)),
        m_scene(scene),
        m_texels_held(imageTexelsHeld(scene)) {}

  void parse(const ParsedJson& parsed) {
    const Json& root = parsed.root;
    m_material_order = &parsed.material_order;
    if (!root.is_object()) fail("", "expected a JSON object at top level, got " + describe(root));
    static const std::vector<std::string> kTop = {"camera",    "film",   "render",   "materials",
                                                  "lights",    "objects", "animation"};
    for (auto it = root.begin(); it != root.end(); ++it) {
      bool known = false;
      for (const std::string& k : kTop) known = known || it.key() == k;
      if (!known)
        m_scene.warnings.push_back(prefix() + "unknown key '" + it.key() +
                                   "' at top level (known: " + join(kTop) + ")");
    }
    // A fixed order, whatever the file's: objects refer to materials by name.
    if (const Json* v = find(root, "camera")) parseCamera(*v, "camera");
    if (const Json* v = find(root, "film")) parseFilm(*v, "film");
    if (const Json* v = find(root, "render")) parseRender(*v, "render");
    if (const Json* v = find(root, "materials")) parseMaterials(*v, "materials");
    if (const Json* v = find(root, "lights")) parseLights(*v, "lights");
    if (const Json* v = find(root, "objects")) parseObjects(*v, "objects");
    if (const Json* v = find(root, "animation")) parseAnimation(*v, "animation");
  }

 private:
  // A colour is 3 non-negative numbers; one number stands for a grey.
  // Components in [0, kMaxColour]: the kernels multiply a colour by others and
  // by a light (color x intensity <= 1e30), and each product must stay a float.
  Vec3 colour(const Json& v, const std::string& path) const {
    static const Check inRange = [](double x) { return x >= 0 && x <= kMaxColour; };
    if (v.is_number()) return Vec3::splat(number(v, path, "a number in [0, 1e6]", inRange));
    if (!v.is_array() || v.size() != 3)
      expected(path, "a colour (an array of 3 numbers in [0, 1e6], or one number for grey)", v);
    return vec3(v, path, "a number in [0, 1e6]", inRange);
  }

  void parseCamera(const Json& v, const std::string& path) {
    checkObject(v, path,
                {"position", "look_at", "up", "fov", "aperture", "focus_distance", "shutter", "position_end",
                 "look_at_end"});
    Camera& c = m_scene.camera;
    if (const Json* p = find(v, "position")) c.position = vec3(*p, member(path, "position"));
    if (const Json* p = find(v, "look_at")) c.look_at = vec3(*p, member(path, "look_at"));
    if (const Json* p = find(v, "up")) c.up = vec3(*p, member(path, "up"));
    if (const Json* p = find(v, "fov"))
      c.fov =
          number(*p, member(path, "fov"), "a number in (0, 180)", [](double x) { return x > 0 && x < 180; });
    // Points first: the up check below takes their difference.
    for (auto [point, key] : {std::pair{&c.position, "position"}, std::pair{&c.look_at, "look_at"}})
      if (const std::string p = vectorProblem(*point, key); !p.empty()) fail(path, p);
    const Vec3 view = c.look_at - c.position;
    if (view == Vec3())
      fail(member(path, "look_at"),
           "expected a point different from camera.position, got " + formatVec(c.look_at) + " for both");
    // sin(angle between up and view) below 1e-9 leaves no usable image plane.
    if (c.up == Vec3() || !(length(cross(unitVector(c.up), unitVector(view))) > 1e-9))
      fail(member(path, "up"), "expected a direction not parallel to the view direction " + formatVec(view) +
                                   ", got " + formatVec(c.up));
    static const Check nonNegative = [](double x) { return x >= 0; };
    if (const Json* p = find(v, "aperture"))
      c.aperture = number(*p, member(path, "aperture"), "a lens radius >= 0 (0: a pinhole)", nonNegative);
    if (const Json* p = find(v, "focus_distance"))
      c.focus_distance = number(*p, member(path, "focus_distance"), "a positive distance",
                                [](double x) { return x > 0; });
    if (const Json* p = find(v, "shutter")) {
      const std::string at = member(path, "shutter");
      if (!p->is_array() || p->size() != 2) expected(at, "an array [open, close] of 2 numbers", *p);
      c.shutter_open = number((*p)[0], element(at, 0));
      c.shutter_close = number((*p)[1], element(at, 1));
    }
    const Json* pe = find(v, "position_end");
    const Json* le = find(v, "look_at_end");
    if (pe || le) {
      c.moving = true;
      c.position_end = pe ? vec3(*pe, member(path, "position_end")) : c.position;
      c.look_at_end = le ? vec3(*le, member(path, "look_at_end")) : c.look_at;
    }
    const std::string problem = cameraProblem(c);
    if (!problem.empty()) fail(path, problem);
  }

  // After the camera: the frames' shutters follow from its own.
  void parseAnimation(const Json& v, const std::string& path) {
    checkObject(v, path, {"frames", "step"});
    Animation& a = m_scene.animation;
    if (const Json* p = find(v, "frames"))
      a.frames = int(integer(*p, member(path, "frames"), 1, kMaxAnimationFrames));
    if (const Json* p = find(v, "step"))
      a.step = number(*p, member(path, "step"), "a time > 0 and at most 1e15",
                      [](double x) { return x > 0 && x <= 1e15; });
    const std::string problem = animationProblem(m_scene);
    if (!problem.empty()) fail(path, problem);
  }

  void parseFilm(const Json& v, const std::string& path) {
    checkObject(v, path, {"width", "height", "spp", "aa", "filter", "aa_threshold", "aa_max_level"});
    Film& f = m_scene.film;
    if (const Json* p = find(v, "width")) f.width = int(integer(*p, member(path, "width"), 1, kMaxFilmSize));
    if (const Json* p = find(v, "height"))
      f.height = int(integer(*p, member(path, "height"), 1, kMaxFilmSize));
    if (const Json* p = find(v, "spp")) f.spp = int(integer(*p, member(path, "spp"), 1, kMaxSpp));
    // Anti-aliasing (docs/sampling.md): names checked by the sampler's own parsers.
    SamplingOptions sampling;
    if (const Json* p = find(v, "aa")) {
      const std::string name = string(*p, member(path, "aa"), "a string (" + aaModeNames() + ", auto)");
      if (name != "auto") {
        try {
          sampling.mode = parseAaMode(name);
        } catch (const std::invalid_argument&) {
          fail(member(path, "aa"), "unknown anti-aliasing mode '" + name + "' (expected " + aaModeNames() + " or auto)");
        }
        f.aa = name;
      }
    }
    if (f.aa.empty()) sampling.mode = f.spp > 1 ? AaMode::Jitter : AaMode::None;
    if (const Json* p = find(v, "filter")) {
      const std::string name = string(*p, member(path, "filter"), "a string (" + filterNames() + ")");
      try {
        sampling.filter = parseFilterKind(name);
      } catch (const std::invalid_argument&) {
        fail(member(path, "filter"), "unknown filter '" + name + "' (expected " + filterNames() + ")");
      }
      f.filter = name;
    }
    if (const Json* p = find(v, "aa_threshold"))
      f.aa_threshold = number(*p, member(path, "aa_threshold"), "a number >= 0", [](double x) { return x >= 0; });
    if (const Json* p = find(v, "aa_max_level"))
      f.aa_max_level = int(integer(*p, member(path, "aa_max_level"), 0, kMaxAdaptiveLevel));
    sampling.spp = f.spp;
    sampling.adaptive_threshold = f.aa_threshold;
    sampling.adaptive_max_level = f.aa_max_level;
    try {
      sampling.validate();  // e.g. grid with a spp that is not a square
    } catch (const std::invalid_argument& e) {
      fail(member(path, find(v, "spp") ? "spp" : "aa"), e.what());
    }
  }

  unsigned long long seed(const Json& v, const std::string& path) const {
    if (v.is_number_unsigned()) return v.get<unsigned long long>();
    if (v.is_number_float()) {
      const double x = v.get<double>();
      if (std::isfinite(x) && x >= 0 && x == std::floor(x) && x < 18446744073709551616.0)
        return static_cast<unsigned long long>(x);
    }
    expected(path, "a non-negative integer", v);
  }

  // A render setting that names one of a fixed list; `parse` says whether the name is on it.
  template <typename Mode>
  std::string namedMode(const Json& v, const std::string& path, const char* names, const char* noun,
                        bool (*parse)(const std::string&, Mode*)) const {
    const std::string name = string(v, path, std::string("a string (") + names + ")");
    Mode mode;
    if (!parse(name, &mode)) fail(path, "unknown " + std::string(noun) + " '" + name + "' (expected " + names + ")");
    return name;
  }

  void parseRender(const Json& v, const std::string& path) {
    checkObject(v, path,
                {"max_depth", "min_weight", "ambient", "background", "seed", "accel", "first_hit", "inside_test",
                 "shadows", "bounds", "device"});
    RenderSettings& r = m_scene.render;
    if (const Json* p = find(v, "max_depth"))
      r.max_depth = int(integer(*p, member(path, "max_depth"), 0, kMaxDepth));
    if (const Json* p = find(v, "min_weight"))
      r.min_weight = number(*p, member(path, "min_weight"), "a number in [0, 1]",
                            [](double x) { return x >= 0 && x <= 1; });
    if (const Json* p = find(v, "ambient")) r.ambient = colour(*p, member(path, "ambient"));
    if (const Json* p = find(v, "background")) r.background = colour(*p, member(path, "background"));
    if (const Json* p = find(v, "seed")) r.seed = seed(*p, member(path, "seed"));
    if (const Json* p = find(v, "accel")) {
      const std::string name = string(*p, member(path, "accel"), "a string (auto, bvh, octree, bsp, none)");
      if (name != "auto" && name != "bvh" && name != "octree" && name != "bsp" && name != "none")
        fail(member(path, "accel"),
             "unknown acceleration structure '" + name + "' (expected auto, bvh, octree, bsp, none)");
      r.accel = name;
    }
    if (const Json* p = find(v, "first_hit"))
      r.first_hit = namedMode(*p, member(path, "first_hit"), kFirstHitModeNames, "first-hit mode", tryParseFirstHitMode);
    if (const Json* p = find(v, "inside_test"))
      r.inside_test = namedMode(*p, member(path, "inside_test"), kInsideTestNames, "inside test", tryParseInsideTest);
    if (const Json* p = find(v, "shadows"))
      r.shadows = namedMode(*p, member(path, "shadows"), kShadowModeNames, "shadow mode", tryParseShadowMode);
    if (const Json* p = find(v, "bounds"))
      r.bounds = namedMode(*p, member(path, "bounds"), kBoundsKindNames, "bounds", tryParseBoundsKind);
    if (const Json* p = find(v, "device")) {
      const std::string selector =
          string(*p, member(path, "device"), "a string (an index, cpu, gpu, part of a name, all, or a list such as 0,2)");
      try {
        deviceSelectorParts(selector);
      } catch (const std::invalid_argument& e) {
        fail(member(path, "device"), e.what());
      }
      r.device = selector;
    }
  }

  void parseMaterials(const Json& v, const std::string& path) {
    if (!v.is_object()) expected(path, "an object mapping material names to materials", v);
    for (const std::string& name : *m_material_order) {  // file order: it fixes the indices
      if (name.empty()) fail(path, "expected a non-empty material name, got \"\"");
      Material m = parseMaterial(v.at(name), member(path, name));
      m.name = name;
      // "default" replaces the built-in material rather than adding a second one.
      if (name == "default") {
        m_scene.materials[0] = m;
        m_texels_held = imageTexelsHeld(m_scene);  // the one it replaced may have held an image
      } else {
        // A file's keys are unique; a scene built in parts can repeat a name.
        if (!materialsByName().emplace(name, static_cast<int>(m_scene.materials.size())).second)
          fail(member(path, name), "a material named '" + name + "' already exists");
        m_scene.materials.push_back(m);
      }
    }
  }

  Material parseMaterial(const Json& v, const std::string& path) {
    checkObject(
        v, path,
        {"model", "ambient", "diffuse", "specular", "shininess", "reflect", "transmit", "ior", "texture", "gloss",
         "translucency", "roughness", "distribution"});
    static const Check unit = [](double x) { return x >= 0 && x <= 1; };
    Material m = defaultMaterial();
    if (const Json* p = find(v, "model")) {
      const std::string model = string(*p, member(path, "model"), "a string (phong, blinn, cook-torrance)");
      if (model == "phong")
        m.model = ShadingModel::Phong;
      else if (model == "blinn")
        m.model = ShadingModel::Blinn;
      else if (model == "cook-torrance")
        m.model = ShadingModel::CookTorrance;
      else
        fail(member(path, "model"), "unknown shading model '" + model + "' (expected phong, blinn, cook-torrance)");
    }
    // Cook-Torrance's Fresnel factor needs an index: a plastic's unless given.
    if (m.model == ShadingModel::CookTorrance) m.ior = 1.5;
    if (const Json* p = find(v, "roughness"))
      m.roughness = number(*p, member(path, "roughness"), "a number in [0.001, 1]",
                           [](double x) { return x >= 1e-3 && x <= 1; });
    if (const Json* p = find(v, "distribution")) {
      const std::string name = string(*p, member(path, "distribution"), "a string (beckmann, ggx)");
      if (name == "beckmann")
        m.distribution = MicrofacetDistribution::Beckmann;
      else if (name == "ggx")
        m.distribution = MicrofacetDistribution::Ggx;
      else
        fail(member(path, "distribution"), "unknown microfacet distribution '" + name + "' (expected beckmann, ggx)");
    }
    if (const Json* p = find(v, "ambient")) m.ambient = colour(*p, member(path, "ambient"));
    if (const Json* p = find(v, "diffuse")) m.diffuse = colour(*p, member(path, "diffuse"));
    if (const Json* p = find(v, "specular")) m.specular = colour(*p, member(path, "specular"));
    if (const Json* p = find(v, "shininess"))
      m.shininess = number(*p, member(path, "shininess"), "a number in [0, 1e6]",
                           [](double x) { return x >= 0 && x <= kMaxExponent; });
    if (const Json* p = find(v, "reflect"))
      m.reflect = number(*p, member(path, "reflect"), "a number in [0, 1]", unit);
    if (const Json* p = find(v, "transmit"))
      m.transmit = number(*p, member(path, "transmit"), "a number in [0, 1]", unit);
    if (const Json* p = find(v, "ior"))
      m.ior = number(*p, member(path, "ior"), "a positive number", [](double x) { return x > 0; });
    if (const Json* p = find(v, "texture")) m.texture = parseTexture(*p, member(path, "texture"));
    // Lobe exponents: 0 is the ideal direction; beyond 1e6 a lobe is narrower
    // than float directions resolve.
    static const Check exponent = [](double x) { return x >= 0 && x <= 1e6; };
    if (const Json* p = find(v, "gloss"))
      m.gloss = number(*p, member(path, "gloss"), "a number in [0, 1e6] (0: a perfect mirror)", exponent);
    if (const Json* p = find(v, "translucency"))
      m.translucency =
          number(*p, member(path, "translucency"), "a number in [0, 1e6] (0: clear refraction)", exponent);
    return m;
  }

  Texture parseTexture(const Json& v, const std::string& path) {
    Texture t;
    const std::string type =
        string(require(v, path, "type"), member(path, "type"), "a string (checker, image)");
    if (type == "image") {
      checkObject(v, path, {"type", "file", "wrap", "srgb", "scale"});
      t.kind = Texture::Kind::Image;
      const std::string file_at = member(path, "file");
      const std::string file = filePath(string(require(v, path, "file"), file_at, "an image file name (.png, .jpg, .exr, ...)"));
      std::optional<bool> srgb;
      if (const Json* p = find(v, "srgb")) {
        if (!p->is_boolean()) expected(member(path, "srgb"), "true or false", *p);
        srgb = p->get<bool>();
      }
      try {
        t.image = readImageTexture(file, srgb, m_texels_held);
      } catch (const ImageTextureError& e) {
        fail(file_at, e.what());
      }
      m_texels_held += static_cast<std::size_t>(t.image->width) * t.image->height;
      if (const Json* p = find(v, "wrap")) {
        const std::string wrap = string(*p, member(path, "wrap"), "a string (repeat, clamp, mirror)");
        if (wrap == "repeat") t.wrap = Texture::Wrap::Repeat;
        else if (wrap == "clamp") t.wrap = Texture::Wrap::Clamp;
        else if (wrap == "mirror") t.wrap = Texture::Wrap::Mirror;
        else fail(member(path, "wrap"), "unknown wrap mode '" + wrap + "' (expected repeat, clamp, mirror)");
      }
    } else if (type == "checker") {
      checkObject(v, path, {"type", "color1", "color2", "scale"});
      t.kind = Texture::Kind::Checker;
      if (const Json* p = find(v, "color1")) t.color1 = colour(*p, member(path, "color1"));
      if (const Json* p = find(v, "color2")) t.color2 = colour(*p, member(path, "color2"));
    } else {
      fail(member(path, "type"), "unknown texture type '" + type + "' (expected checker, image)");
    }
    if (const Json* p = find(v, "scale"))
      // It divides coordinates of up to 1e15 in float (kernels/shading/texture.h).
      t.scale = number(*p, member(path, "scale"), "a number in [1e-15, 1e15]",
                       [](double x) { return x >= 1e-15 && x <= kMaxCoordinate; });
    return t;
  }

  void parseLights(const Json& v, const std::string& path) {
    if (!v.is_array()) expected(path, "an array of lights", v);
    static const Check nonNegative = [](double x) { return x >= 0; };
    static const Check positive = [](double x) { return x > 0; };
    double brightness = 0;  // of the scene's lights together (scene/light_check.h)
    for (const Light& l : m_scene.lights) brightness += lightBrightness(l);
    for (std::size_t i = 0; i < v.size(); ++i) {
      const std::string at = element(path, m_scene.lights.size());  // its index in the scene
      const Json& l = v[i];
      if (!l.is_object()) expected(at, "an object", l);
      Light light;
      std::string type = "point";
      if (const Json* p = find(l, "type")) type = string(*p, member(at, "type"), "a string (point, quad, rect, disk, sphere)");
      if (type == "point") {
        checkObject(l, at, {"type", "position", "color", "intensity"});
        light.position = vec3(require(l, at, "position"), member(at, "position"));
      } else if (type == "quad" || type == "rect") {
        checkObject(l, at, {"type", "corner", "edge1", "edge2", "color", "intensity", "samples"});
        light.type = LightType::Quad;
        light.corner = vec3(require(l, at, "corner"), member(at, "corner"));
        light.edge1 = nonZeroVec3(require(l, at, "edge1"), member(at, "edge1"));
        light.edge2 = nonZeroVec3(require(l, at, "edge2"), member(at, "edge2"));
      } else if (type == "disk") {
        checkObject(l, at, {"type", "center", "normal", "radius", "color", "intensity", "samples"});
        light.type = LightType::Disk;
        light.center = vec3(require(l, at, "center"), member(at, "center"));
        light.normal = unitVector(nonZeroVec3(require(l, at, "normal"), member(at, "normal")));
        light.radius = number(require(l, at, "radius"), member(at, "radius"), "a positive number", positive);
      } else if (type == "sphere") {
        checkObject(l, at, {"type", "center", "radius", "color", "intensity", "samples"});
        light.type = LightType::Sphere;
        light.center = vec3(require(l, at, "center"), member(at, "center"));
        light.radius = number(require(l, at, "radius"), member(at, "radius"), "a positive number", positive);
      } else {
        fail(member(at, "type"), "unknown light type '" + type + "' (expected point, quad, rect, disk, sphere)");
      }
      if (const Json* p = find(l, "color")) light.color = colour(*p, member(at, "color"));
      if (const Json* p = find(l, "intensity"))
        light.intensity = number(*p, member(at, "intensity"), "a non-negative number", nonNegative);
      if (const Json* p = find(l, "samples"); p && light.type != LightType::Point)  // a point needs one
        light.samples = int(integer(*p, member(at, "samples"), 1, kMaxLightSamples));
      brightness += lightBrightness(light);
      std::string problem = lightProblem(light);
      if (problem.empty()) problem = lightsTogetherProblem(brightness, m_scene.lights.size() + 1);
      if (!problem.empty()) fail(at, problem);
      m_scene.lights.push_back(light);
    }
  }

  void parseObjects(const Json& v, const std::string& path) {
    if (!v.is_array()) expected(path, "an array of objects", v);
    for (std::size_t i = 0; i < v.size(); ++i) {
      const std::string at = element(path, m_scene.objects.size());  // its index in the scene
      Object o = parseObject(v[i], at);
      if (o.type == ObjectType::Mesh) {
        const std::string problem = meshPlacementProblem(*o.mesh, o.transform, o.moving ? &o.transform_end : nullptr);
        if (!problem.empty()) fail(at, problem);
        Object& mesh = addMeshObject(m_scene, o.mesh, o.material_override ? o.material : -1, o.transform, o.smooth);
        mesh.moving = o.moving;
        mesh.transform_end = o.transform_end;
        mesh.polygon_faces = std::move(o.polygon_faces);
      } else {
        m_scene.objects.push_back(std::move(o));
      }
    }
  }

  Object parseObject(const Json& v, const std::string& path) {
    if (!v.is_object()) expected(path, "an object", v);
    const std::string typePath = member(path, "type");
    const std::string type =
        string(require(v, path, "type"), typePath, "a string (" + primitiveKindNames() + ", mesh)");
    Object o;
    const PrimitiveKind* kind = primitiveKindNamed(type);
    if (type == "mesh") {
      checkObject(v, path, {"type", "material", "transform", "transform_end", "file", "smooth", "polygons"});
      o.type = ObjectType::Mesh;
      parseMesh(v, path, o);
    } else if (kind) {
      o.type = kind->type;
      kind->parse(*this, v, path, type, o);
    } else {
      fail(typePath, "unknown object type '" + type + "' (expected " + primitiveKindNames() + ", mesh)");
    }
    if (const Json* p = find(v, "material")) {
      o.material = materialIndex(*p, member(path, "material"));
      o.material_override = true;
    }
    if (const Json* p = find(v, "transform")) o.transform = parseTransform(*p, member(path, "transform"));
    if (const Json* p = find(v, "transform_end")) {
      o.moving = true;
      o.transform_end = parseTransform(*p, member(path, "transform_end"));
    }
    if (kind && o.type == kind->type) {  // (a polyhedron given by faces becomes a mesh)
      // Kinds the kernels keep in world space take a static transform into their geometry.
      if (kind->bake && !o.transform.isIdentity() && !o.moving) {
        kind->bake(o);
        o.transform = Transform::identity();
      }
      const std::string problem = kind->problem(o);
      if (!problem.empty()) fail(path, problem);
    }
    return o;
  }

  // A mesh file, relative to the scene file, read once however many objects
  // name it (MeshCache). Only the mesh and `smooth` are read here; the object is
  // completed by addMeshObject in parseObjects.
  void parseMesh(const Json& v, const std::string& path, Object& o) {
    const std::string file_at = member(path, "file");
    std::string file = string(require(v, path, "file"), file_at, "a mesh file name (.obj, .ply, .off, ...)");
    const std::filesystem::path resolved(filePath(file));
    try {
      o.mesh = MeshCache::global().load(resolved.string());
    } catch (const MeshError& e) {
      fail(file_at, e.what());
    }
    if (o.mesh->triangleCount() == 0)
      fail(file_at, "'" + resolved.string() + "' holds " + std::to_string(o.mesh->vertexCount()) +
                         " vertices and no faces (a point cloud?): nothing to render");
    for (const std::string& w : o.mesh->warnings) m_scene.warnings.push_back(resolved.string() + ": " + w);
    if (const Json* p = find(v, "smooth")) {
      if (!p->is_boolean()) expected(member(path, "smooth"), "true or false", *p);
      o.smooth = p->get<bool>();
    }
    if (const Json* p = find(v, "polygons")) {
      if (!p->is_boolean()) expected(member(path, "polygons"), "true or false", *p);
      if (p->get<bool>()) {
        std::size_t kept = 0;
        o.polygon_faces = polygonFacePlan(*o.mesh, &kept);
        if (kept)
          m_scene.warnings.push_back(prefix() + member(path, "polygons") + ": " + std::to_string(kept) +
                                     " face(s) of more than 3 corners are not planar or not simple, and stay triangles");
      }
    }
  }

  // Name -> index into m_scene.materials, built on first use from the scene's
  // materials (a scene built in parts already has some).
  std::unordered_map<std::string, int>& materialsByName() {
    if (!m_material_index_built) {
      for (std::size_t i = 0; i < m_scene.materials.size(); ++i)
        m_material_index.emplace(m_scene.materials[i].name, static_cast<int>(i));
      m_material_index_built = true;
    }
    return m_material_index;
  }

  int materialIndex(const Json& v, const std::string& path) {
    const std::string name = string(v, path, "a material name (a string)");
    const auto& index = materialsByName();
    auto it = index.find(name);
    if (it != index.end()) return it->second;
    constexpr std::size_t kListed = 20;  // an error names at most this many
    std::vector<std::string> known;
    for (std::size_t i = 0; i < m_scene.materials.size() && i < kListed; ++i) known.push_back(m_scene.materials[i].name);
    std::string more;
    if (m_scene.materials.size() > kListed) more = " and " + std::to_string(m_scene.materials.size() - kListed) + " more";
    fail(path, "unknown material '" + name + "' (known: " + join(known) + more + ")");
  }

  // An object of steps, or an array of them applied first to last.
  Transform parseTransform(const Json& v, const std::string& path) {
    Transform t;
    if (v.is_array()) {
      for (std::size_t i = 0; i < v.size(); ++i) t = parseTransformStep(v[i], element(path, i)) * t;
    } else if (v.is_object()) {
      t = parseTransformStep(v, path);
    } else {
      expected(path, "a transform (an object, or an array of objects)", v);
    }
    const std::string problem = transformProblem(t);
    if (!problem.empty()) fail(path, problem);
    return t;
  }

  Transform parseTransformStep(const Json& v, const std::string& path) {
    checkObject(v, path, {"scale", "rotate", "translate", "matrix"});
    if (const Json* p = find(v, "matrix")) {
      for (const char* k : {"scale", "rotate", "translate"})
        if (find(v, k))
          fail(path, std::string("expected 'matrix' alone, got 'matrix' together with '") + k + "'");
      return parseMatrix(*p, member(path, "matrix"));
    }
    Transform t;
    if (const Json* p = find(v, "scale")) {
      const std::string at = member(path, "scale");
      const char* what = "a non-zero number or an array of 3 non-zero numbers";
      static const Check nonZero = [](double x) { return x != 0; };
      if (p->is_number())
        t = Transform::scale(Vec3::splat(number(*p, at, what, nonZero)));
      else if (p->is_array() && p->size() == 3)
        t = Transform::scale(vec3(*p, at, "a non-zero number", nonZero));
      else
        expected(at, what, *p);
    }
    if (const Json* p = find(v, "rotate")) {
      const std::string at = member(path, "rotate");
      checkObject(*p, at, {"axis", "angle"});
      const Vec3 axis = nonZeroVec3(require(*p, at, "axis"), member(at, "axis"));
      const double angle = number(require(*p, at, "angle"), member(at, "angle"));
      t = Transform::rotate(axis, angle) * t;
    }
    if (const Json* p = find(v, "translate"))
      t = Transform::translate(vec3(*p, member(path, "translate"))) * t;
    return t;
  }

  Transform parseMatrix(const Json& v, const std::string& path) const {
    if (!v.is_array() || v.size() != 16) expected(path, "an array of 16 numbers (4x4, row-major)", v);
    double a[16];
    for (int i = 0; i < 16; ++i) a[i] = number(v[i], element(path, i));
    if (a[12] != 0 || a[13] != 0 || a[14] != 0 || a[15] != 1)
      fail(path, "expected the last row to be 0 0 0 1, got " + formatNumber(a[12]) + " " +
                     formatNumber(a[13]) + " " + formatNumber(a[14]) + " " + formatNumber(a[15]));
    Transform t;
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 4; ++c) t.m[r][c] = a[4 * r + c];
    return t;
  }

  Scene& m_scene;
  // Texels of the scene's images so far, kept as they are read (a count each
  // time would be quadratic in the materials), and counted again where a
  // "default" material replaces one that may have held an image.
  std::size_t m_texels_held;
  const std::vector<std::string>* m_material_order = nullptr;  // the materials' keys in file order
  std::unordered_map<std::string, int> m_material_index;       // materialsByName(): name -> index
  bool m_material_index_built = false;
};

// nlohmann's messages start with "[json.exception.parse_error.101] parse error at
// line L, column C: "; keep only the reason after that.
std::string jsonReason(const char* what) {
  std::string s = what;
  const std::size_t bracket = s.find("] ");
  if (s.rfind("[json.exception.", 0) == 0 && bracket != std::string::npos) s.erase(0, bracket + 2);
  if (s.rfind("parse error", 0) == 0) {
    const std::size_t colon = s.find(": ");
    if (colon != std::string::npos) s.erase(0, colon + 2);
  }
  return s;
}

// Line and column (both 1-based) of the byte-th character of text (1-based).
std::string lineColumn(const std::string& text, std::size_t byte) {
  const std::size_t end = std::min(byte > 0 ? byte - 1 : 0, text.size());
  std::size_t line = 1, lineStart = 0;
  for (std::size_t i = 0; i < end; ++i)
    if (text[i] == '\n') ++line, lineStart = i + 1;
  const std::size_t column = (byte > 0 ? byte : 1) - lineStart;
  return std::to_string(line) + ":" + std::to_string(column);
}

// The keys of the top-level "materials" object in file order, first
// occurrences only: a SAX pass, since nlohmann's DOM parser with a callback
// rescans the parent at the end of every object (quadratic again).
class MaterialOrder : public nlohmann::json_sax<Json> {
 public:
  std::vector<std::string> keys;

  bool null() override { return true; }
  bool boolean(bool) override { return true; }
  bool number_integer(number_integer_t) override { return true; }
  bool number_unsigned(number_unsigned_t) override { return true; }
  bool number_float(number_float_t, const string_t&) override { return true; }
  bool string(string_t&) override { return true; }
  bool binary(binary_t&) override { return true; }
  bool start_object(std::size_t) override { return ++m_depth, true; }
  bool end_object() override { return --m_depth, true; }
  bool start_array(std::size_t) override { return ++m_depth, true; }
  bool end_array() override { return --m_depth, true; }
  bool key(string_t& k) override {
    if (m_depth == 1) {
      m_top = k;
    } else if (m_depth == 2 && m_top == "materials" && m_seen.insert(k).second) {
      keys.push_back(k);
    }
    return true;
  }
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception&) override { return false; }

 private:
  int m_depth = 0;  // containers open; the root object's keys come at 1
  std::string m_top;
  std::unordered_set<std::string> m_seen;
};

ParsedJson parseJson(const std::string& text, const std::string& name) {
  try {
    ParsedJson out;
    out.root = Json::parse(text, nullptr, /*allow_exceptions=*/true, /*ignore_comments=*/true);
    if (out.root.is_object() && out.root.contains("materials") && out.root["materials"].is_object()) {
      MaterialOrder order;
      Json::sax_parse(text, &order, nlohmann::detail::input_format_t::json, /*strict=*/true, /*ignore_comments=*/true);
      out.material_order = std::move(order.keys);
    }
    return out;
  } catch (const Json::parse_error& e) {
    throw SceneError(name + ":" + lineColumn(text, e.byte) + ": invalid JSON: " + jsonReason(e.what()));
  } catch (const Json::exception& e) {
    // Number overflow (1e999) comes without a position: find the literal it quotes.
    const std::string reason = jsonReason(e.what());
    const std::size_t open = reason.find('\''), close = reason.rfind('\'');
    std::string where;
    if (open != std::string::npos && close > open + 1) {
      const std::size_t at = text.find(reason.substr(open + 1, close - open - 1));
      if (at != std::string::npos) where = ":" + lineColumn(text, at + 1);
    }
    throw SceneError(name + where + ": invalid JSON: " + reason);
  }
}

}  // namespace

Scene parseScene(const std::string& json_text, const std::string& name) {
  Scene scene;
  scene.source = name;
  addSceneJson(scene, json_text, name, std::filesystem::path(name).parent_path().string());
  return scene;
}

namespace {

// What a failed addition must put back: the parser appends lights, objects,
// materials and warnings, and overwrites the camera, film, render settings and
// the default material.
class SceneRollback {
 public:
  explicit SceneRollback(Scene& scene)
      : m_scene(scene), m_camera(scene.camera), m_animation(scene.animation), m_film(scene.film), m_render(scene.render),
        m_default_material(scene.materials.at(0)), m_materials(scene.materials.size()),
        m_lights(scene.lights.size()), m_objects(scene.objects.size()), m_warnings(scene.warnings.size()) {}
  ~SceneRollback() {
    if (m_committed) return;
    m_scene.camera = m_camera;
    m_scene.animation = m_animation;
    m_scene.film = m_film;
    m_scene.render = m_render;
    m_scene.materials.resize(m_materials);
    m_scene.materials[0] = m_default_material;
    m_scene.lights.resize(m_lights);
    m_scene.objects.resize(m_objects);
    m_scene.warnings.resize(m_warnings);
  }
  void commit() { m_committed = true; }

 private:
  Scene& m_scene;
  Camera m_camera;
  Animation m_animation;
  Film m_film;
  RenderSettings m_render;
  Material m_default_material;
  std::size_t m_materials, m_lights, m_objects, m_warnings;
  bool m_committed = false;
};

void addParsed(Scene& scene, const ParsedJson& fragment, const std::string& name, const std::string& base_dir) {
  if (scene.materials.empty()) scene.materials.push_back(defaultMaterial());
  SceneRollback rollback(scene);
  try {
    SceneParser(name, base_dir, scene).parse(fragment);
  } catch (const Json::exception& e) {
    // The parser checks types before every access; this is a last line of defence.
    throw SceneError((name.empty() ? "" : name + ": ") + "unexpected value: " + jsonReason(e.what()));
  }
  rollback.commit();
}

}  // namespace

void addSceneJson(Scene& scene, const std::string& json_text, const std::string& name, const std::string& base_dir) {
  addParsed(scene, parseJson(json_text, name), name, base_dir);
}

void addSceneFragment(Scene& scene, const nlohmann::json& fragment, const std::string& name,
                      const std::string& base_dir) {
  ParsedJson parsed;
  parsed.root = fragment;
  if (const auto it = fragment.find("materials"); it != fragment.end() && it->is_object())
    for (auto m = it->begin(); m != it->end(); ++m) parsed.material_order.push_back(m.key());
  addParsed(scene, parsed, name, base_dir);
}

Scene loadSceneFile(const std::string& path) {
  // Only a regular file: opening a FIFO blocks until a writer comes, and a
  // device such as /dev/zero never ends.
  std::error_code ec;
  const std::filesystem::file_status st = std::filesystem::status(path, ec);
  if (std::filesystem::exists(st) && !std::filesystem::is_regular_file(st) && !std::filesystem::is_directory(st))
    throw SceneIoError(path + ": cannot read scene file: not a regular file");
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) throw SceneIoError(path + ": cannot open scene file: " + std::strerror(errno));
  std::string text;
  char buf[65536];
  std::size_t n;
  while ((n = std::fread(buf, 1, sizeof buf, f)) > 0) text.append(buf, n);
  const bool failed = std::ferror(f) != 0;
  const int err = errno;
  std::fclose(f);
  // A directory opens but cannot be read (EISDIR).
  if (failed) throw SceneIoError(path + ": cannot read scene file: " + std::strerror(err));
  return parseScene(text, path);
}

}  // namespace prism
