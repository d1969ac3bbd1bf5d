// Judges one candidate plugin library; see plugin_library.h.
#include "mesh/plugin_library.h"

#include <dlfcn.h>

#include <cctype>
#include <cstddef>
#include <cstring>

namespace prism {

namespace {

// The last field of PrismPluginInfo (ABI 1) that this host reads.
constexpr std::size_t kInfoSizeRead = offsetof(PrismPluginInfo, load) + sizeof(PrismPluginLoadFn);
// Bounds on what a plugin may claim, so a broken one cannot make us walk
// through unbounded memory.
constexpr std::size_t kMaxNameLength = 64;
constexpr std::size_t kMaxDescriptionLength = 200;
constexpr std::size_t kMaxExtensions = 32;
constexpr std::size_t kMaxExtensionLength = 16;

// A short identifier: letters, digits, '_', '-', '.'.
bool isPlainToken(const char* s, std::size_t max_length) {
  if (s == nullptr) return false;
  std::size_t n = strnlen(s, max_length + 1);
  if (n == 0 || n > max_length) return false;
  for (std::size_t i = 0; i < n; ++i) {
    unsigned char c = static_cast<unsigned char>(s[i]);
    if (!(std::isalnum(c) || c == '_' || c == '-' || c == '.')) return false;
  }
  return true;
}

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// Fills `c` from the plugin's description, or returns the reason it is unfit.
std::string readInfo(const PrismPluginInfo* info, PluginCandidate& c) {
  if (info == nullptr) return std::string(PRISM_PLUGIN_ENTRY_SYMBOL) + " returned NULL";
  if (info->abi_version != PRISM_PLUGIN_ABI_VERSION)
    return "ABI " + std::to_string(info->abi_version) + ", expected " + std::to_string(PRISM_PLUGIN_ABI_VERSION);
  if (info->struct_size < kInfoSizeRead)
    return "PrismPluginInfo is " + std::to_string(info->struct_size) + " bytes, expected at least " +
           std::to_string(kInfoSizeRead);
  if (!isPlainToken(info->name, kMaxNameLength))
    return "plugin name missing or not a plain word (letters, digits, _ - .; at most 64)";
  c.name = info->name;
  if (info->description != nullptr)
    c.description.assign(info->description, strnlen(info->description, kMaxDescriptionLength));
  if (info->extensions == nullptr || info->extensions[0] == nullptr) return "no file extensions listed";
  for (std::size_t i = 0; info->extensions[i] != nullptr; ++i) {
    if (i == kMaxExtensions) return "more than 32 file extensions listed (is the list NULL-terminated?)";
    const char* e = info->extensions[i];
    if (e[0] == '.') ++e;
    if (!isPlainToken(e, kMaxExtensionLength)) return "file extension #" + std::to_string(i + 1) + " is not a plain word";
    c.extensions.push_back(lower(e));
  }
  if (info->load == nullptr) return "load function is NULL";
  return {};
}

}  // namespace

OpenedPlugin openPlugin(const std::string& path) {
  OpenedPlugin out;
  out.candidate.path = path;
  dlerror();  // clear any stale message
  void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (handle == nullptr) {
    const char* why = dlerror();
    out.candidate.reason = std::string("not loadable: ") + (why != nullptr ? why : "dlopen failed");
    return out;
  }
  void* symbol = dlsym(handle, PRISM_PLUGIN_ENTRY_SYMBOL);
  if (symbol == nullptr) {
    out.candidate.reason = std::string("missing symbol ") + PRISM_PLUGIN_ENTRY_SYMBOL +
                           " (not a prism plugin, or built for another ABI version)";
    dlclose(handle);
    return out;
  }
  PrismPluginEntryFn entry;
  static_assert(sizeof(entry) == sizeof(symbol), "function and data pointers differ in size");
  std::memcpy(&entry, &symbol, sizeof(entry));  // dlsym returns void*; POSIX allows this conversion
  const PrismPluginInfo* info = entry();
  std::string reason = readInfo(info, out.candidate);
  if (!reason.empty()) {
    out.candidate.reason = reason;
    out.candidate.extensions.clear();
    dlclose(handle);
    return out;
  }
  out.candidate.accepted = true;
  out.info = info;
  out.handle = handle;
  return out;
}

}  // namespace prism
