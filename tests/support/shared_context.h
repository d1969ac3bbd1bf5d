// One OpenCL context per test binary, so each kernel program is compiled once
// and shared by every test in the binary (PoCL compiles slowly).
#pragma once

#include "device/context.h"
#include "render/renderer.h"

namespace prism::test {

Context& sharedContext();
Renderer& sharedRenderer();

}  // namespace prism::test
