// From a model file to the C++ of its compiled model: preprocess, recognise
// the language, build the Model IR, generate C++.
#pragma once

#include <string>
#include <vector>

namespace sylva::lang {

struct TranslatorOptions {
  std::string compiler = "g++";           // its preprocessor is used
  std::string runtime_include_dir;         // where lpfgall.h lives
  std::vector<std::string> defines;        // -D for the preprocessor
};

struct Translation {
  std::string cpp;                          // preprocessed C++ (compile as .ii)
  std::vector<std::string> dependencies;    // every file the preprocessor read
};

// Throws ModelError for a missing file, a preprocessor error or an L+C error.
Translation translate_file(const std::string& model_path, const TranslatorOptions& options);

}  // namespace sylva::lang
