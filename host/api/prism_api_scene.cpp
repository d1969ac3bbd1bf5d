// C API: building a scene in code. Every call turns its arguments into a
// fragment of the scene format and hands it to the scene loader
// (addSceneFragment), so a call is checked by the same code, and refused with
// the same message, as the same value in a file.
#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

#include "api/api_boundary.h"
#include "api/api_enums.h"
#include "api/api_fragments.h"
#include "api/api_handles.h"
#include "scene_format/scene_loader.h"

using namespace prism;
using Json = nlohmann::json;

void prism::addCallFragment(Scene& scene, const Json& fragment) {
  try {
    addSceneFragment(scene, fragment, "", "");
  } catch (const SceneIoError&) {
    throw;
  } catch (const SceneError& e) {
    throw std::invalid_argument(e.what());
  }
}

namespace {

#define PRISM_REQUIRE(cond, message) \
  if (!(cond)) return fail(PRISM_ERROR_INVALID_ARGUMENT, message)

Json matrix(const float* m) {
  Json a = Json::array();
  for (int i = 0; i < 16; ++i) a.push_back(m[i]);
  return Json{{"matrix", a}};
}

void addChecked(PrismScene scene, const Json& fragment) { addCallFragment(scene->scene, fragment); }

const char* modelName(uint32_t model) {
  switch (model) {
    case PRISM_SHADING_PHONG: return "phong";
    case PRISM_SHADING_BLINN: return "blinn";
    case PRISM_SHADING_COOK_TORRANCE: return "cook-torrance";
  }
  return "?";
}

Json materialJson(const PrismMaterial& m) {
  Json j{{"model", modelName(m.model)},
         {"ambient", jsonTriple(m.ambient)},
         {"diffuse", jsonTriple(m.diffuse)},
         {"specular", jsonTriple(m.specular)},
         {"shininess", m.shininess},
         {"reflect", m.reflect},
         {"transmit", m.transmit},
         {"ior", m.ior},
         {"gloss", m.gloss},
         {"translucency", m.translucency}};
  if (m.model == PRISM_SHADING_COOK_TORRANCE) {
    j["roughness"] = m.roughness;
    j["distribution"] = m.distribution == PRISM_MICROFACET_GGX ? "ggx" : m.distribution == PRISM_MICROFACET_BECKMANN ? "beckmann" : "?";
  }
  if (m.checker)
    j["texture"] = Json{{"type", "checker"},
                        {"color1", jsonTriple(m.checker_color1)},
                        {"color2", jsonTriple(m.checker_color2)},
                        {"scale", m.checker_scale}};
  return j;
}

Json objectJson(const PrismObject& o) {
  Json j;
  switch (o.type) {
    case PRISM_OBJECT_SPHERE:
      j = Json{{"type", "sphere"}, {"center", jsonTriple(o.center)}, {"radius", o.radius}};
      break;
    case PRISM_OBJECT_BOX:
      j = Json{{"type", "box"}, {"min", jsonTriple(o.box_min)}, {"max", jsonTriple(o.box_max)}};
      break;
    case PRISM_OBJECT_PLANE:
      j = Json{{"type", "plane"}, {"point", jsonTriple(o.point)}, {"normal", jsonTriple(o.normal)}};
      break;
    case PRISM_OBJECT_TRIANGLE:
      j = Json{{"type", "triangle"},
               {"vertices", Json::array({jsonTriple(o.vertices), jsonTriple(o.vertices + 3), jsonTriple(o.vertices + 6)})}};
      break;
    case PRISM_OBJECT_QUADRIC: {
      Json coefficients = Json::array();
      for (float c : o.coefficients) coefficients.push_back(c);
      j = Json{{"type", "quadric"},
               {"coefficients", coefficients},
               {"clip", Json{{"min", jsonTriple(o.clip_min)}, {"max", jsonTriple(o.clip_max)}}},
               {"capped", o.capped != 0}};
      break;
    }
  }
  if (o.material) j["material"] = o.material;
  if (o.object_to_world) j["transform"] = matrix(o.object_to_world);
  if (o.object_to_world_end) j["transform_end"] = matrix(o.object_to_world_end);
  return j;
}

}  // namespace

extern "C" {

PRISM_API PrismStatus prismAddSceneJson(PrismScene scene, const char* json) {
  PRISM_REQUIRE(scene && json, "prismAddSceneJson: NULL argument");
  return guarded(__func__, [&] {
    addSceneJson(scene->scene, json, "json", "");
    scene->changed();
    return PRISM_OK;
  });
}

PRISM_API void prismDefaultMaterial(PrismMaterial* material) {
  if (!material) return;
  const Material d = defaultMaterial();
  *material = PrismMaterial{};
  material->struct_size = sizeof(PrismMaterial);
  material->model = d.model == ShadingModel::Blinn ? PRISM_SHADING_BLINN : PRISM_SHADING_PHONG;
  putVec3(material->ambient, d.ambient);
  putVec3(material->diffuse, d.diffuse);
  putVec3(material->specular, d.specular);
  material->shininess = static_cast<float>(d.shininess);
  material->reflect = static_cast<float>(d.reflect);
  material->transmit = static_cast<float>(d.transmit);
  material->ior = static_cast<float>(d.ior);
  material->gloss = static_cast<float>(d.gloss);
  material->translucency = static_cast<float>(d.translucency);
  material->roughness = static_cast<float>(d.roughness);
  material->distribution = static_cast<uint32_t>(d.distribution);
  const Texture t;
  putVec3(material->checker_color1, t.color1);
  putVec3(material->checker_color2, t.color2);
  material->checker_scale = static_cast<float>(t.scale);
}

PRISM_API PrismStatus prismAddMaterial(PrismScene scene, const char* name, const PrismMaterial* material,
                                       uint32_t* out_material) {
  PRISM_REQUIRE(scene && name && material, "prismAddMaterial: NULL argument");
  PRISM_REQUIRE(material->struct_size >= sizeof(PrismMaterial), "prismAddMaterial: struct_size is too small");
  PRISM_REQUIRE(material->model <= PRISM_SHADING_COOK_TORRANCE,
                "prismAddMaterial: model must be PRISM_SHADING_PHONG, PRISM_SHADING_BLINN or PRISM_SHADING_COOK_TORRANCE");
  return guarded(__func__, [&] {
    addChecked(scene, Json{{"materials", Json{{name, materialJson(*material)}}}});
    if (out_material) {
      const std::vector<Material>& all = scene->scene.materials;
      *out_material = std::string(name) == all[0].name ? 0u : static_cast<uint32_t>(all.size() - 1);
    }
    return PRISM_OK;
  });
}

PRISM_API void prismDefaultObject(PrismObject* object, PrismObjectType type) {
  if (!object) return;
  *object = PrismObject{};
  object->struct_size = sizeof(PrismObject);
  object->type = static_cast<uint32_t>(enumValue(type));
  object->radius = 1;
  for (int k = 0; k < 3; ++k) object->box_min[k] = object->clip_min[k] = -1, object->box_max[k] = object->clip_max[k] = 1;
  object->normal[1] = 1;
}

PRISM_API PrismStatus prismAddObject(PrismScene scene, const PrismObject* object, uint32_t* out_object) {
  PRISM_REQUIRE(scene && object, "prismAddObject: NULL argument");
  PRISM_REQUIRE(object->struct_size >= sizeof(PrismObject), "prismAddObject: struct_size is too small");
  PRISM_REQUIRE(object->type <= PRISM_OBJECT_QUADRIC,
                "prismAddObject: type must be PRISM_OBJECT_SPHERE, PRISM_OBJECT_BOX, PRISM_OBJECT_PLANE, "
                "PRISM_OBJECT_TRIANGLE or PRISM_OBJECT_QUADRIC");
  return guarded(__func__, [&] {
    addChecked(scene, Json{{"objects", Json::array({objectJson(*object)})}});
    scene->changed();
    if (out_object) *out_object = static_cast<uint32_t>(scene->scene.objects.size() - 1);
    return PRISM_OK;
  });
}

PRISM_API PrismStatus prismAddPointLight(PrismScene scene, const float position[3], const float color[3],
                                         float intensity) {
  PRISM_REQUIRE(scene && position && color, "prismAddPointLight: NULL argument");
  return guarded(__func__, [&] {
    addChecked(scene, Json{{"lights", Json::array({Json{{"type", "point"},
                                                         {"position", jsonTriple(position)},
                                                         {"color", jsonTriple(color)},
                                                         {"intensity", intensity}}})}});
    return PRISM_OK;
  });
}

PRISM_API PrismStatus prismAddAreaLight(PrismScene scene, const PrismAreaLight* light) {
  PRISM_REQUIRE(scene && light, "prismAddAreaLight: NULL argument");
  PRISM_REQUIRE(light->struct_size >= sizeof(PrismAreaLight), "prismAddAreaLight: struct_size is too small");
  Json j{{"color", jsonTriple(light->color)}, {"intensity", light->intensity}, {"samples", light->samples}};
  switch (enumValue(light->type)) {
    case PRISM_LIGHT_QUAD:
      j.update(Json{{"type", "quad"}, {"corner", jsonTriple(light->corner)}, {"edge1", jsonTriple(light->edge1)},
                    {"edge2", jsonTriple(light->edge2)}});
      break;
    case PRISM_LIGHT_DISK:
      j.update(Json{{"type", "disk"}, {"center", jsonTriple(light->center)}, {"normal", jsonTriple(light->normal)},
                    {"radius", light->radius}});
      break;
    case PRISM_LIGHT_SPHERE:
      j.update(Json{{"type", "sphere"}, {"center", jsonTriple(light->center)}, {"radius", light->radius}});
      break;
    default:
      return fail(PRISM_ERROR_INVALID_ARGUMENT,
                  "prismAddAreaLight: type must be PRISM_LIGHT_QUAD, PRISM_LIGHT_DISK or PRISM_LIGHT_SPHERE");
  }
  return guarded(__func__, [&] {
    addChecked(scene, Json{{"lights", Json::array({j})}});
    return PRISM_OK;
  });
}

PRISM_API PrismStatus prismSetBackground(PrismScene scene, const float color[3]) {
  PRISM_REQUIRE(scene && color, "prismSetBackground: NULL argument");
  return guarded(__func__, [&] {
    addChecked(scene, Json{{"render", Json{{"background", jsonTriple(color)}}}});
    return PRISM_OK;
  });
}

PRISM_API PrismStatus prismSetAmbient(PrismScene scene, const float color[3]) {
  PRISM_REQUIRE(scene && color, "prismSetAmbient: NULL argument");
  return guarded(__func__, [&] {
    addChecked(scene, Json{{"render", Json{{"ambient", jsonTriple(color)}}}});
    return PRISM_OK;
  });
}

}  // extern "C"
