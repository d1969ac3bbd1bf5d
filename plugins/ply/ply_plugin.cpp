// The "ply" plugin's entry point: reads the file (bounded), parses the header,
// then the body. See README.md for what it reads and why it is prism's own.
#include "common/file_bytes.h"
#include "common/plugin_failure.h"
#include "common/sink_writer.h"
#include "ply/ply_body.h"
#include "ply/ply_header.h"
#include "prism_plugin.h"

namespace {

int loadPly(const char* path, const PrismMeshSink* sink, PrismPluginError* err) {
  return prism_plugins::guardLoad(err, [&] {
    std::string bytes = prism_plugins::readFileBytes(path);
    prism_plugins::SinkWriter writer(sink);
    prism_plugins::PlyHeader header = prism_plugins::parsePlyHeader(bytes);
    prism_plugins::readPlyBody(bytes, header, writer);
  });
}

// "ply" on a line of its own opens every PLY file.
int probePly(const unsigned char* head, size_t size) {
  return size >= 4 && head[0] == 'p' && head[1] == 'l' && head[2] == 'y' && (head[3] == '\n' || head[3] == '\r');
}

const char* const kExtensions[] = {"ply", nullptr};

const PrismPluginInfo kInfo = {
    sizeof(PrismPluginInfo), PRISM_PLUGIN_ABI_VERSION, "ply", kExtensions,
    "Stanford PLY: ascii, binary little and big endian, faces and triangle strips (prism's own reader)",
    &loadPly, &probePly};

}  // namespace

extern "C" PRISM_PLUGIN_EXPORT const PrismPluginInfo* prism_plugin_entry_v1(void) { return &kInfo; }
