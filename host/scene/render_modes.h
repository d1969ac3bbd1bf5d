// The render block's mode names (render.first_hit, render.shadows; --first-hit,
// --shadows; PrismRenderOptions.first_hit, .shadows): one rule, read by the
// scene loader and by the render options (render/render_options.h), which say
// what each mode does.
#pragma once

#include <string>

namespace prism {

// How primary visibility is found: the Z-buffer pass, traced rays, or the
// Z-buffer where the camera and the scene make it pay.
enum class FirstHitMode { Auto, ZBuffer, Trace };
constexpr const char* kFirstHitModeNames = "auto, zbuffer, trace";

// False for an unknown name.
inline bool tryParseFirstHitMode(const std::string& name, FirstHitMode* mode) {
  if (name == "auto") *mode = FirstHitMode::Auto;
  else if (name == "zbuffer") *mode = FirstHitMode::ZBuffer;
  else if (name == "trace") *mode = FirstHitMode::Trace;
  else return false;
  return true;
}

inline const char* firstHitName(FirstHitMode mode) {
  return mode == FirstHitMode::ZBuffer ? "zbuffer" : mode == FirstHitMode::Trace ? "trace" : "auto";
}

// How point lights' shadow feelers find what is in the way: the acceleration
// structure, the light buffer, or whichever should be faster.
enum class ShadowMode { Auto, Accel, LightBuffer };
constexpr const char* kShadowModeNames = "auto, accel, lightbuffer";

// False for an unknown name.
inline bool tryParseShadowMode(const std::string& name, ShadowMode* mode) {
  if (name == "auto") *mode = ShadowMode::Auto;
  else if (name == "accel") *mode = ShadowMode::Accel;
  else if (name == "lightbuffer") *mode = ShadowMode::LightBuffer;
  else return false;
  return true;
}

inline const char* shadowModeName(ShadowMode mode) {
  return mode == ShadowMode::Accel ? "accel" : mode == ShadowMode::LightBuffer ? "lightbuffer" : "auto";
}

}  // namespace prism
