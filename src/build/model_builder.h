// Turns a model file into a loadable shared library, through a cache keyed by
// content: an unchanged model (and unchanged files it includes) is never
// translated or compiled again.
#pragma once

#include <string>
#include <vector>

namespace sylva::build {

struct BuildOptions {
  std::string compiler;             // empty: $SYLVA_CXX, $CXX, then g++
  std::string cache_dir;            // empty: $SYLVA_CACHE_DIR or ~/.cache/sylva
  std::string runtime_include_dir;  // empty: the runtime this program was built with
  std::vector<std::string> defines;
  // Searched for included files after the model's own folder (a copy of a
  // model kept elsewhere still finds the files beside the original).
  std::vector<std::string> include_dirs;
  bool verbose = false;             // say what is being done on stderr
  std::string language;             // empty or "auto": recognised; "cpfg" or "lc"
};

struct BuiltModel {
  std::string library_path;
  bool compiled_now = false;  // false: taken from the cache
  // The translator's warnings (kept with the cached library, so a cached
  // model warns as it did when it was built).
  std::vector<std::string> warnings;
};

// Throws ModelError with the model's file and line for translation errors and
// for C++ errors in the model's code.
BuiltModel build_model(const std::string& model_path, const BuildOptions& options);

// The C++ the model translates to (what `sylva translate` prints).
std::string translate_model(const std::string& model_path, const BuildOptions& options);

// Defaults resolved from the environment (the compiler: support/default_compiler.h).
std::string default_cache_dir();
std::string default_runtime_include_dir();

}  // namespace sylva::build
