#include "build/model_library.h"

#include <dlfcn.h>

#include "support/diagnostic.h"

namespace sylva::build {

ModelLibrary::ModelLibrary(const std::string& path) {
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

}  // namespace sylva::build
