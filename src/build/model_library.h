// A compiled model loaded into the process.
#pragma once

#include <string>

#include "sylva/abi.h"

namespace sylva::build {

class ModelLibrary {
 public:
  // Throws ModelError if the library cannot be loaded or is not a model.
  explicit ModelLibrary(const std::string& path);
  ~ModelLibrary();
  ModelLibrary(const ModelLibrary&) = delete;
  ModelLibrary& operator=(const ModelLibrary&) = delete;

  const abi::ModelDescriptor& descriptor() const { return *descriptor_; }

 private:
  void* handle_ = nullptr;
  const abi::ModelDescriptor* descriptor_ = nullptr;
};

}  // namespace sylva::build
