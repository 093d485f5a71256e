#include "build/model_library.h"

#include <dlfcn.h>

#include <filesystem>

#include "build/model_cache.h"
#include "support/diagnostic.h"

namespace sylva::build {

ModelLibrary::ModelLibrary(const std::string& path, const std::string& checksum) {
  // Mapping a truncated file would fault (SIGBUS) at the first page past its end.
  if (file_checksum(path) != checksum)
    throw ModelError("the compiled model " + path + " is damaged: its bytes are not those it was compiled into");
  handle_ = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle_) throw ModelError(std::string("cannot load compiled model: ") + dlerror());
  auto entry = reinterpret_cast<abi::ModelEntryPoint>(dlsym(handle_, abi::kEntryPointName));
  if (!entry) {
    dlclose(handle_);
    throw ModelError(path + " is not a compiled Sylva model");
  }
  descriptor_ = entry();
  if (!descriptor_ || descriptor_->abi_version != abi::kAbiVersion) {
    dlclose(handle_);
    throw ModelError(path + " was compiled for another version of Sylva");
  }
}

ModelLibrary::~ModelLibrary() {
  if (handle_) dlclose(handle_);
}

LoadedModel load_model(const std::string& model_path, const BuildOptions& options) {
  BuiltModel built = build_model(model_path, options);
  try {
    auto library = std::make_unique<ModelLibrary>(built.library_path, built.library_checksum);
    return LoadedModel{std::move(built), std::move(library)};
  } catch (const ModelError&) {
    if (built.compiled_now) throw;
  }
  // Damaged on the disk, or removed by a run pruning the cache: compile it again.
  const std::filesystem::path library = built.library_path;
  const ModelCache cache(library.parent_path());
  const std::string key = library.stem().string();
  {
    const ModelCache::Lock lock = cache.lock(key);
    // Another run may have compiled it again meanwhile.
    if (cache.recorded_checksum(key) == built.library_checksum) cache.discard_library(key);
  }
  BuiltModel rebuilt = build_model(model_path, options);
  try {
    auto loaded = std::make_unique<ModelLibrary>(rebuilt.library_path, rebuilt.library_checksum);
    return LoadedModel{std::move(rebuilt), std::move(loaded)};
  } catch (const ModelError& e) {
    throw ModelError(std::string(e.what()) + " (the model was compiled again, once, and still does not load)");
  }
}

}  // namespace sylva::build
