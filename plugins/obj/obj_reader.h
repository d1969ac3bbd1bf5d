// Reads Wavefront OBJ geometry strictly: v (with optional w or r g b), vt,
// vn, f in every index form (v, v/vt, v//vn, v/vt/vn, negative = relative),
// n-gons of any size, backslash line continuations, usemtl, mtllib (several
// libraries per line, names with spaces; read by mtl_library.h). g, o, s
// are accepted and ignored, l and p elements and free-form statements are
// ignored with a warning. Malformed numbers, index 0, indices outside the
// vertices defined so far, faces of fewer than 3 corners and NUL bytes (UTF-16
// text) are errors naming the line.
//
// OBJ gives normals and texture coordinates per face corner; prism keeps them
// per vertex. They are kept when every corner of a vertex agrees, and dropped
// with a warning otherwise (smooth shading then computes vertex normals).
#pragma once

#include <string>
#include <string_view>

#include "common/sink_writer.h"

namespace prism_plugins {

// base_dir: the OBJ file's folder, against which mtllib names are resolved.
void readObj(std::string_view text, const std::string& base_dir, SinkWriter& sink);

}  // namespace prism_plugins
