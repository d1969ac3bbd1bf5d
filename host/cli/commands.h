// The prism commands and the exit codes they share. Each command takes the arguments
// after its name, prints its own output, and returns the process exit code; usage
// mistakes are thrown as UsageError for main() to report.
#pragma once

#include <string>
#include <vector>

namespace prism_cli {

constexpr int kExitOk = 0;
constexpr int kExitFailure = 1;      // the work failed: bad scene, no device, write error
constexpr int kExitUsage = 2;        // the command line was wrong
constexpr int kExitNotFinite = 3;    // render --check-nan found NaN or infinity (the image is written)
constexpr int kExitInterrupted = 130;  // Ctrl-C, as shells report SIGINT

int runDevices(const std::vector<std::string>& args);
int runRender(const std::vector<std::string>& args);
int runInfo(const std::vector<std::string>& args);
int runPlugins(const std::vector<std::string>& args);
int runTrace(const std::vector<std::string>& args);

// "prism: error: <message>" on stderr.
void printError(const std::string& message);
// "prism: warning: <message>" on stderr.
void printWarning(const std::string& message);
// Reports the library's last error (prismGetLastError) and returns kExitFailure.
int failWithLastError();
// The library's last message without the C function's name.
std::string lastErrorForUser();

}  // namespace prism_cli
