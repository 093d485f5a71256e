// Turns a model file into a loadable shared library, through a cache keyed by
// content: an unchanged model (and unchanged files it includes) is never
// translated or compiled again.
#pragma once

#include <string>
#include <vector>

namespace sylva::lang {
struct ParsedModel;  // lang/translator.h
}

namespace sylva::build {

struct BuildOptions {
  std::string compiler;             // empty: $SYLVA_CXX, $CXX, then g++
  std::string cache_dir;            // empty: default_cache_dir()
  std::string runtime_include_dir;  // empty: the runtime this program was built with
  std::vector<std::string> defines;
  // Searched for included files after the model's own folder (a copy of a
  // model kept elsewhere still finds the files beside the original).
  std::vector<std::string> include_dirs;
  bool verbose = false;             // say what is being done on stderr
  std::string language;             // empty or "auto": recognised; "cpfg" or "lc"
  double compile_timeout_seconds = 0;  // 0: default_compile_timeout()
};

struct BuiltModel {
  std::string library_path;      // inside the cache
  std::string library_checksum;  // of its bytes when it was compiled
  bool compiled_now = false;  // false: taken from the cache
  // The translator's warnings (kept with the cached library, so a cached
  // model warns as it did when it was built).
  std::vector<std::string> warnings;
};

// Throws ModelError with the model's file and line for translation errors and
// for C++ errors in the model's code, and when the compile runs past its time
// limit. Concurrent runs of one model compile it once.
BuiltModel build_model(const std::string& model_path, const BuildOptions& options);

// The C++ the model translates to (what `sylva translate` prints).
std::string translate_model(const std::string& model_path, const BuildOptions& options);
// The model's IR (lang/model_ir.h), as translate_model reads it.
lang::ParsedModel parse_model(const std::string& model_path, const BuildOptions& options);

// Defaults resolved from the environment (the compiler: support/default_compiler.h).
// The cache: $SYLVA_CACHE_DIR, $XDG_CACHE_HOME/sylva, then ~/.cache/sylva in
// the home folder ($HOME, else the user's entry in the password database);
// never a folder shared with other users, so ModelError if there is no home.
std::string default_cache_dir();
std::string default_runtime_include_dir();
// $SYLVA_COMPILE_TIMEOUT, else 600 seconds.
double default_compile_timeout();

// Precompiles the runtime's lpfgall.h into `output`, a GCC precompiled header
// made as models are compiled, which translating and compiling a model take
// in place of the header's text (once per build of this program: parsing the
// runtime is most of a model's compile). Throws ModelError when the compiler
// fails.
void precompile_runtime(const std::string& output, const std::string& runtime_include_dir,
                        const std::string& compiler);

}  // namespace sylva::build
