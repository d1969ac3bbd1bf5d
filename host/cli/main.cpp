// The prism command line: picks the command and turns failures into exit codes.
// It uses the public C API (prism.h) alone, like any other program embedding prism.
#include <cstdio>
#include <exception>
#include <new>
#include <string>
#include <vector>

#include "args.h"
#include "commands.h"
#include "help_text.h"
#include "mpi_ranks.h"
#include "prism.h"

namespace {

using namespace prism_cli;

bool isHelp(const std::string& arg) { return arg == "--help" || arg == "-h" || arg == "help"; }

int showHelp(const std::vector<std::string>& args) {
  // "prism help render" reads like "prism render --help".
  const std::string topic = args.size() > 1 ? args[1] : "";
  if (topic == "render") {
    std::fputs(kRenderHelp, stdout);
  } else if (topic == "devices") {
    std::fputs(kDevicesHelp, stdout);
  } else if (topic == "info") {
    std::fputs(kInfoHelp, stdout);
  } else if (topic == "trace") {
    std::fputs(kTraceHelp, stdout);
  } else if (topic == "plugins") {
    std::fputs(kPluginsHelp, stdout);
  } else if (topic.empty()) {
    std::fputs(kMainHelp, stdout);
  } else {
    throw UsageError("no help on '" + topic + "' (commands: render, trace, devices, info, plugins)");
  }
  return kExitOk;
}

int dispatch(const std::vector<std::string>& args) {
  if (args.empty()) throw UsageError("no command given (commands: render, trace, devices, info, plugins)");
  const std::string& command = args[0];
  const std::vector<std::string> rest(args.begin() + 1, args.end());
  if (isHelp(command)) return showHelp(args);
  if (command == "--version" || command == "-V" || command == "version") {
    std::printf("prism %s\n", prismGetVersionString());
    return kExitOk;
  }
  if (command == "render") return runRender(rest);
  if (command == "devices") return runDevices(rest);
  if (command == "info") return runInfo(rest);
  if (command == "plugins") return runPlugins(rest);
  if (command == "trace") return runTrace(rest);
  if (!command.empty() && command[0] == '-') {
    throw UsageError("unknown option '" + command +
                     "' (options follow a command, as in 'prism render scene.json -o out.png --spp 4')");
  }
  throw UsageError("unknown command '" + command + "' (commands: render, trace, devices, info, plugins)");
}

std::string helpHint(const std::vector<std::string>& args) {
  if (!args.empty() && (args[0] == "render" || args[0] == "devices" || args[0] == "info" || args[0] == "plugins" ||
                         args[0] == "trace"))
    return "prism " + args[0] + " --help";
  return "prism --help";
}

int run(const std::vector<std::string>& args) {
  try {
    return dispatch(args);
  } catch (const UsageError& e) {
    printError(e.what());
    std::fprintf(stderr, "Try '%s'.\n", helpHint(args).c_str());
    return kExitUsage;
  } catch (const std::bad_alloc&) {
    printError("out of memory (is the image size what you meant?)");
    return kExitFailure;
  } catch (const std::exception& e) {
    printError(e.what());
    return kExitFailure;
  }
}

}  // namespace

int main(int argc, char** argv) {
  // Under mpirun, a failure on one rank ends them all (endRanks).
  return endRanks(run(std::vector<std::string>(argv + 1, argv + argc)));
}
