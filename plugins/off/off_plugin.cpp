// The "off" plugin's entry point: reads the file (bounded) and hands the text
// to readOff. See README.md for what it reads.
#include "common/file_bytes.h"
#include "common/plugin_failure.h"
#include "common/sink_writer.h"
#include "off/off_reader.h"
#include "prism_plugin.h"

#include <string_view>

namespace {

int loadOff(const char* path, const PrismMeshSink* sink, PrismPluginError* err) {
  return prism_plugins::guardLoad(err, [&] {
    std::string bytes = prism_plugins::readFileBytes(path);
    prism_plugins::SinkWriter writer(sink);
    prism_plugins::readOff(bytes, writer);
  });
}

int probeOff(const unsigned char* head, size_t size) {
  return prism_plugins::looksLikeOff(std::string_view(reinterpret_cast<const char*>(head), size)) ? 1 : 0;
}

const char* const kExtensions[] = {"off", nullptr};

const PrismPluginInfo kInfo = {
    sizeof(PrismPluginInfo), PRISM_PLUGIN_ABI_VERSION, "off", kExtensions,
    "Geomview OFF: OFF, COFF, NOFF, STOFF, n-gons, comments (prism's own reader)", &loadOff, &probeOff};

}  // namespace

extern "C" PRISM_PLUGIN_EXPORT const PrismPluginInfo* prism_plugin_entry_v1(void) { return &kInfo; }
