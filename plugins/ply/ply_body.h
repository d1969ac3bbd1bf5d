// The PLY body: rows of every element in header order, ascii (one row per
// line, checked for too few and too many values) or binary of either byte
// order. Reads vertex (x y z, normals, colours, texture coordinates), face
// (vertex_indices / vertex_index lists of any integer type, beside any other
// properties, lists included) and tristrips (-1 separated strips, expanded
// into triangles, skipping their degenerate joins); skips other elements.
// Indices are checked against the header's vertex count as they are read, so
// a face element may come before the vertex element.
#pragma once

#include <string_view>

#include "common/sink_writer.h"
#include "ply/ply_header.h"

namespace prism_plugins {

// Throws PluginFailure on malformed or truncated data.
void readPlyBody(std::string_view bytes, const PlyHeader& header, SinkWriter& sink);

}  // namespace prism_plugins
