// What the C API's opaque handles point at.
#pragma once

#include <memory>

struct PrismSceneImpl;

#include "device/context.h"
#include "prism.h"
#include "render/ray_queries.h"
#include "render/renderer.h"
#include "scene/scene.h"

struct PrismContextImpl {
  std::unique_ptr<prism::Context> context;
  std::unique_ptr<prism::Renderer> renderer;  // built on first render
  prism::RenderResult last;                   // AOVs of the last render
  bool has_render = false;
  PrismProgressFn progress = nullptr;
  void* progress_user = nullptr;
  // The ray-query engine of the last prismIntersect / prismOccluded, reused while
  // the scene (and its revision) and the structure stay the same.
  std::unique_ptr<prism::RayQueryEngine> queries;
  const PrismSceneImpl* queries_scene = nullptr;
  unsigned long long queries_revision = 0;
  prism::AccelKind queries_accel = prism::AccelKind::None;
};

struct PrismSceneImpl {
  prism::Scene scene;
  unsigned long long revision = 0;  // bumped by every change to the scene's geometry
};
