// libFuzzer target for the OBJ plugin's reader (plugins/obj/). mtllib names
// resolve against an empty folder, so material libraries come only from what
// the input names absolutely; the reader refuses non-regular files itself.
#include "fuzz_sink.h"
#include "obj/obj_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return fuzzOneInput(data, size, [](std::string_view text, prism_plugins::SinkWriter& sink) {
    prism_plugins::readObj(text, "/nonexistent-prism-fuzz-dir/", sink);
  });
}
