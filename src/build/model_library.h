// A compiled model loaded into the process.
#pragma once

#include <memory>
#include <string>

#include "build/model_builder.h"
#include "sylva/abi.h"

namespace sylva::build {

class ModelLibrary {
 public:
  // Loads the library only if its bytes are those it was compiled into
  // (`checksum`): a damaged file is never mapped into the process. Throws
  // ModelError if they are not, or if it cannot be loaded or is not a model.
  ModelLibrary(const std::string& path, const std::string& checksum);
  ~ModelLibrary();
  ModelLibrary(const ModelLibrary&) = delete;
  ModelLibrary& operator=(const ModelLibrary&) = delete;

  const abi::ModelDescriptor& descriptor() const { return *descriptor_; }

 private:
  void* handle_ = nullptr;
  const abi::ModelDescriptor* descriptor_ = nullptr;
};

struct LoadedModel {
  BuiltModel built;
  std::unique_ptr<ModelLibrary> library;
};

// Builds the model (or takes it from the cache) and loads it. A library from
// the cache that is damaged or does not load is compiled again, once; if
// that does not load either, ModelError says so.
LoadedModel load_model(const std::string& model_path, const BuildOptions& options);

}  // namespace sylva::build
