// libFuzzer target for the PLY plugin's reader (plugins/ply/): header, then
// body, ascii or binary.
#include "fuzz_sink.h"
#include "ply/ply_body.h"
#include "ply/ply_header.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return fuzzOneInput(data, size, [](std::string_view bytes, prism_plugins::SinkWriter& sink) {
    prism_plugins::PlyHeader header = prism_plugins::parsePlyHeader(bytes);
    prism_plugins::readPlyBody(bytes, header, sink);
  });
}
