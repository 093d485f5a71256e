#include "support/plugin_library.h"

#include <dlfcn.h>

#include <filesystem>
#include <system_error>
#include <vector>

#include "support/diagnostic.h"

namespace sylva {

namespace {

// The program's own folder first, so that a copied or installed program takes
// the plugins copied beside it; then the build tree's, for the tests.
std::vector<std::filesystem::path> plugin_folders() {
  std::vector<std::filesystem::path> folders;
  std::error_code error;
  const std::filesystem::path program = std::filesystem::read_symlink("/proc/self/exe", error);
  if (!error) folders.push_back(program.parent_path());
  const std::filesystem::path build_tree = SYLVA_PLUGIN_DIR;
  if (folders.empty() || !std::filesystem::equivalent(folders.front(), build_tree, error))
    folders.push_back(build_tree);
  return folders;
}

}  // namespace

void* plugin_symbol(const std::string& file_name, const char* symbol, const std::string& purpose) {
  const std::string cannot = "cannot open " + file_name + ", which " + purpose + ": ";
  std::string looked_in;
  for (const std::filesystem::path& folder : plugin_folders()) {
    const std::filesystem::path path = folder / file_name;
    std::error_code error;
    if (!std::filesystem::exists(path, error)) {
      looked_in += (looked_in.empty() ? "" : ", ") + folder.string();
      continue;
    }
    // Never closed: its object lives as long as the program.
    void* library = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!library) throw ModelError(cannot + dlerror());
    void* address = dlsym(library, symbol);
    if (!address) throw ModelError(cannot + path.string() + " has no " + symbol);
    return address;
  }
  throw ModelError(cannot + "not found in " + looked_in);
}

}  // namespace sylva
