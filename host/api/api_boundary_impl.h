// Template body of prism::guarded (api_boundary.h).
#pragma once

#include <new>
#include <stdexcept>

#include "device/cl_error.h"
#include "mesh/mesh_error.h"
#include "render/image_writer.h"
#include "render/renderer.h"
#include "scene/scene_error.h"

namespace prism {

template <typename Body>
PrismStatus guarded(const char* function, Body&& body) {
  auto fail = [function](PrismStatus status, const std::string& message) {
    return prism::fail(status, namedAfter(function, message));
  };
  try {
    return body();
  } catch (const SceneIoError& e) {
    return fail(PRISM_ERROR_IO, e.what());
  } catch (const SceneError& e) {
    return fail(PRISM_ERROR_PARSE, e.what());
  } catch (const KernelBuildError& e) {
    return fail(PRISM_ERROR_KERNEL_BUILD, e.what());
  } catch (const DeviceError& e) {
    return fail(PRISM_ERROR_DEVICE, e.what());
  } catch (const MeshError& e) {
    return fail(PRISM_ERROR_PARSE, e.what());
  } catch (const ImageError& e) {
    return fail(PRISM_ERROR_IO, e.what());
  } catch (const FilmTooLarge& e) {
    return fail(PRISM_ERROR_OUT_OF_MEMORY, e.what());
  } catch (const RenderCancelled& e) {
    return fail(PRISM_ERROR_INVALID_OPERATION, e.what());
  } catch (const std::invalid_argument& e) {
    return fail(PRISM_ERROR_INVALID_ARGUMENT, e.what());
  } catch (const std::bad_alloc&) {
    return fail(PRISM_ERROR_OUT_OF_MEMORY, "out of memory");
  } catch (const std::exception& e) {
    return fail(PRISM_ERROR_UNKNOWN, e.what());
  } catch (...) {
    return fail(PRISM_ERROR_UNKNOWN, "unknown error");
  }
}

}  // namespace prism
