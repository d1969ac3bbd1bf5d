// What the C API's two ways of rendering (prismRender into a caller's buffer,
// prismRenderToResult into a PrismResult) share.
#pragma once

#include "api/api_handles.h"
#include "prism.h"
#include "render/renderer.h"

// The options (the scene's own when NULL) checked, the context's renderer
// made on first use, its progress callback attached; throws as the renderer does.
prism::RenderResult renderScene(PrismContext context, PrismScene scene, const PrismRenderOptions* options);

// PrismRenderStats from the renderer's, as far as the caller's struct_size reaches.
void fillStats(const prism::RenderStats& from, double kernel_build_seconds, PrismRenderStats* stats);
