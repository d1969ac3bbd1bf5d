// Messages on stderr, in one "prism: error: ..." shape so scripts and people can grep them.
#include <cctype>
#include <cstdio>
#include <string>

#include "commands.h"
#include "prism.h"

namespace prism_cli {

void printError(const std::string& message) { std::fprintf(stderr, "prism: error: %s\n", message.c_str()); }

void printWarning(const std::string& message) { std::fprintf(stderr, "prism: warning: %s\n", message.c_str()); }

// The library names the C function at fault ("prismRender: ..."); the command
// line's user gave options, not calls, so that name is left out.
std::string lastErrorForUser() {
  const char* message = prismGetLastError();
  std::string text = message && *message ? message : "unknown failure (the library gave no message)";
  std::size_t end = 0;
  if (text.compare(0, 5, "prism") == 0) {
    end = 5;
    while (end < text.size() && std::isalnum(static_cast<unsigned char>(text[end]))) ++end;
    end = text.compare(end, 2, ": ") == 0 ? end + 2 : 0;
  }
  return text.substr(end);
}

int failWithLastError() {
  printError(lastErrorForUser());
  return kExitFailure;
}

}  // namespace prism_cli
