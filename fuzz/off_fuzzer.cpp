// libFuzzer target for the OFF plugin's reader (plugins/off/off_reader.cpp).
#include "fuzz_sink.h"
#include "off/off_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return fuzzOneInput(data, size, [](std::string_view text, prism_plugins::SinkWriter& sink) {
    prism_plugins::looksLikeOff(text);
    prism_plugins::readOff(text, sink);
  });
}
