// The --help texts. They are written for someone who has never used prism: what each
// command and option does, the defaults, accepted values, and where to read more.
#pragma once

namespace prism_cli {

extern const char* const kMainHelp;
extern const char* const kRenderHelp;
extern const char* const kDevicesHelp;
extern const char* const kInfoHelp;
extern const char* const kPluginsHelp;
extern const char* const kTraceHelp;

}  // namespace prism_cli
