// What the C API's opaque handles point at.
#pragma once

#include <memory>

#include "device/context.h"
#include "prism.h"
#include "render/renderer.h"
#include "scene/scene.h"

struct PrismContextImpl {
  std::unique_ptr<prism::Context> context;
  std::unique_ptr<prism::Renderer> renderer;  // built on first render
  prism::RenderResult last;                   // AOVs of the last render
  bool has_render = false;
  PrismProgressFn progress = nullptr;
  void* progress_user = nullptr;
};

struct PrismSceneImpl {
  prism::Scene scene;
};
