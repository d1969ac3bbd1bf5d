// The firewall between C callers and the C++ library: every C API body runs
// inside guarded(), which turns each exception into a status code and a
// thread-local message, so nothing thrown or aborted crosses the boundary.
#pragma once

#include <string>

#include "prism.h"

namespace prism {

void setLastError(const std::string& message);
void clearLastError();
const char* lastError();
PrismStatus fail(PrismStatus status, const std::string& message);

// "function: message", unless message already starts with "function:".
std::string namedAfter(const char* function, const std::string& message);

// Runs `body` (returning PrismStatus) and maps exceptions, each message named
// after `function` (the C function called: pass __func__):
//   SceneIoError → IO, SceneError → PARSE, KernelBuildError → KERNEL_BUILD,
//   DeviceError → DEVICE, MeshError → PARSE, ImageError → IO, FilmTooLarge → OUT_OF_MEMORY,
//   RenderCancelled → INVALID_OPERATION, std::invalid_argument → INVALID_ARGUMENT,
//   std::bad_alloc → OUT_OF_MEMORY, anything else → UNKNOWN.
template <typename Body>
PrismStatus guarded(const char* function, Body&& body);

}  // namespace prism

#include "api/api_boundary_impl.h"
