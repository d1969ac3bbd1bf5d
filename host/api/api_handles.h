// What the C API's opaque handles point at.
#pragma once

#include <memory>
#include <vector>

struct PrismSceneImpl;

#include "device/context.h"
#include "prism.h"
#include "render/ray_queries.h"
#include "render/renderer.h"
#include "scene/scene.h"

struct PrismContextImpl {
  std::unique_ptr<prism::Context> context;  // the first device: ray queries, and the frame's resolve
  std::vector<std::unique_ptr<prism::Context>> more;  // further devices a frame is dealt out over
  std::unique_ptr<prism::Renderer> renderer;  // built on first render
  prism::RenderResult last;                   // AOVs of the last render
  bool has_render = false;
  bool last_check_nan = false;  // the last render watched for NaN (prismGetNanReport)
  PrismProgressFn progress = nullptr;
  void* progress_user = nullptr;
  prism::FrameParts parts;  // prismSetFrameParts: the processes sharing each frame
  // The ray-query engine of the last prismIntersect / prismOccluded, reused while
  // the scene (and its revision) and the structure stay the same.
  std::unique_ptr<prism::RayQueryEngine> queries;
  unsigned long long queries_revision = 0;  // the scene revision `queries` was built for
  prism::AccelKind queries_accel = prism::AccelKind::None;
};

// A process-wide stamp: a scene takes a fresh one when it is made and at every
// change to its geometry, so no two scene states share one, not even those of a
// scene that reuses a released scene's address. A context's cached ray-query
// structure is valid while the scene's revision is the one it was built for.
unsigned long long nextSceneRevision();

struct PrismSceneImpl {
  prism::Scene scene;
  unsigned long long revision = nextSceneRevision();
  void changed() { revision = nextSceneRevision(); }
};
