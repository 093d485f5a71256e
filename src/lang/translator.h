// From a model file to the C++ of its compiled model: preprocess, recognise
// the language, build the Model IR, generate C++.
#pragma once

#include <string>
#include <vector>

#include "lang/model_ir.h"

namespace sylva::lang {

struct TranslatorOptions {
  std::string compiler = "g++";           // its preprocessor is used
  std::string runtime_include_dir;         // where lpfgall.h lives
  std::vector<std::string> defines;        // -D for the preprocessor
  std::vector<std::string> include_dirs;   // -I after the model's folder
  // "auto" (or empty): cpfg if the file has `Lsystem:` ... `endlsystem` lines,
  // L+C otherwise; "cpfg" or "lc" to say which.
  std::string language = "auto";
  // L+C models: flags for the preprocessor before all others; model_builder's
  // let it take lpfgall.h from a precompiled header.
  std::vector<std::string> preprocessor_flags;
};

// Whether a model's text is cpfg (an `Lsystem:` line and an `endlsystem`
// line, outside comments).
bool looks_like_cpfg(const std::string& source);

struct Translation {
  std::string cpp;                          // preprocessed C++ (compile as .ii)
  std::vector<std::string> dependencies;    // every file the preprocessor read
  std::vector<std::string> warnings;        // "file:line:column: warning: ..."
};

// Throws ModelError for a missing file, a preprocessor error or an L+C error.
Translation translate_file(const std::string& model_path, const TranslatorOptions& options);

// The Model IR of a model file, preprocessed (without a precompiled
// runtime) and parsed in its language, and the files the preprocessor read:
// translate_file's first half, for those that read the IR itself.
struct ParsedModel {
  Model model;
  std::vector<std::string> dependencies;
};
ParsedModel parse_model_file(const std::string& model_path, const TranslatorOptions& options);

}  // namespace sylva::lang
