// Messages on stderr, in one "prism: error: ..." shape so scripts and people can grep them.
#include <cstdio>

#include "commands.h"
#include "prism.h"

namespace prism_cli {

void printError(const std::string& message) { std::fprintf(stderr, "prism: error: %s\n", message.c_str()); }

void printWarning(const std::string& message) { std::fprintf(stderr, "prism: warning: %s\n", message.c_str()); }

int failWithLastError() {
  const char* message = prismGetLastError();
  printError(message && *message ? message : "unknown failure (the library gave no message)");
  return kExitFailure;
}

}  // namespace prism_cli
