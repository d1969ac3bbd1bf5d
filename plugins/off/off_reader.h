// Reads Geomview OFF text: [ST][C][N]OFF keyword or none, '#' comments
// anywhere, blank lines, counts on the keyword line or after it, n-gon face
// records that may wrap over lines, optional per-face colours (ignored: prism
// has no per-face colour) and per-vertex normals, colours and texture
// coordinates. 4OFF / nOFF with a dimension other than 3 and binary OFF are
// refused as unsupported. Every count is checked against the bytes left before
// anything is allocated, so a lying header fails at once.
#pragma once

#include <string_view>

#include "common/sink_writer.h"

namespace prism_plugins {

// Throws PluginFailure (with the line) on malformed input.
void readOff(std::string_view text, SinkWriter& sink);

// True when the text's first token (after blank lines and comments) is an OFF
// keyword; used to recognise OFF files that have no extension.
bool looksLikeOff(std::string_view head);

}  // namespace prism_plugins
