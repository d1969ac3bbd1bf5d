#include "support/shared_context.h"

#include <cstdlib>
#include <memory>

namespace prism::test {

Context& sharedContext() {
  // PRISM_TEST_DEVICE picks the device like --device; default: the first CPU
  // device, which every CI machine has through PoCL.
  static std::unique_ptr<Context> context = [] {
    const char* selector = std::getenv("PRISM_TEST_DEVICE");
    return std::make_unique<Context>(selectDevice(selector && *selector ? selector : "cpu"), true);
  }();
  return *context;
}

Renderer& sharedRenderer() {
  static Renderer renderer(sharedContext());
  return renderer;
}

}  // namespace prism::test
