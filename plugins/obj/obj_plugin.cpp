// The "obj" plugin's entry point: reads the file (bounded) and hands the text
// to readObj. See README.md for which library reads what.
#include "common/file_bytes.h"
#include "common/plugin_failure.h"
#include "common/sink_writer.h"
#include "obj/obj_reader.h"
#include "prism_plugin.h"

namespace {

int loadObj(const char* path, const PrismMeshSink* sink, PrismPluginError* err) {
  return prism_plugins::guardLoad(err, [&] {
    std::string bytes = prism_plugins::readFileBytes(path);
    std::string p = path;
    std::size_t slash = p.find_last_of('/');
    std::string base_dir = slash == std::string::npos ? std::string() : p.substr(0, slash + 1);
    prism_plugins::SinkWriter writer(sink);
    prism_plugins::readObj(bytes, base_dir, writer);
  });
}

const char* const kExtensions[] = {"obj", nullptr};

const PrismPluginInfo kInfo = {
    sizeof(PrismPluginInfo), PRISM_PLUGIN_ABI_VERSION, "obj", kExtensions,
    "Wavefront OBJ with MTL materials (geometry: prism's reader; MTL: tinyobjloader)", &loadObj,
    nullptr};  // no probe: OBJ has no signature to recognise

}  // namespace

extern "C" PRISM_PLUGIN_EXPORT const PrismPluginInfo* prism_plugin_entry_v1(void) { return &kInfo; }
