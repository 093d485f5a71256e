#include "build/model_builder.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "build/compiler_messages.h"
#include "lang/translator.h"
#include "support/content_hash.h"
#include "support/default_compiler.h"
#include "support/diagnostic.h"
#include "support/subprocess.h"
#include "support/whole_file.h"

#ifndef SYLVA_RUNTIME_INCLUDE_DIR
#define SYLVA_RUNTIME_INCLUDE_DIR ""
#endif

namespace sylva::build {
namespace fs = std::filesystem;

namespace {

// Bumped whenever generated code or the runtime's contract changes.
constexpr const char* kCacheFormat = "sylva-model-cache-19";

const std::vector<std::string> kCompileFlags = {
    "-std=gnu++20", "-O2", "-fPIC", "-shared", "-fvisibility=hidden", "-fno-gnu-unique",
    // Plain IEEE arithmetic as the reference implementation does it: no fused
    // multiply-add, so float results match to the last bit.
    "-ffp-contract=off", "-w"};

std::string env_or(const char* name, const std::string& fallback) {
  const char* value = std::getenv(name);
  return value && *value ? value : fallback;
}

// Whole or not at all, so a build running beside this one never reads half a file.
void write_cache_file(const fs::path& path, const std::string& content) {
  if (write_file_atomically(path.string(), content) != 0) throw ModelError("cannot write " + path.string());
}

// Size and modification time: enough to notice an edited file.
std::string file_stamp(const std::string& path) {
  struct stat st;
  if (stat(path.c_str(), &st) != 0) return "missing";
  return std::to_string(st.st_size) + ":" + std::to_string(st.st_mtim.tv_sec) + "." +
         std::to_string(st.st_mtim.tv_nsec);
}

std::string find_in_path(const std::string& program) {
  if (program.find('/') != std::string::npos) return program;
  std::stringstream dirs(env_or("PATH", "/usr/bin:/bin"));
  std::string dir;
  while (std::getline(dirs, dir, ':')) {
    fs::path candidate = fs::path(dir) / program;
    if (access(candidate.c_str(), X_OK) == 0) return candidate.string();
  }
  return program;
}

struct ResolvedOptions {
  std::string compiler;
  fs::path cache_dir;
  std::string runtime;
  std::vector<std::string> defines;
  std::vector<std::string> include_dirs;
  std::string language;
};

ResolvedOptions resolve(const BuildOptions& options) {
  ResolvedOptions r;
  r.compiler = options.compiler.empty() ? default_compiler() : options.compiler;
  r.cache_dir = options.cache_dir.empty() ? default_cache_dir() : options.cache_dir;
  r.runtime = options.runtime_include_dir.empty() ? default_runtime_include_dir() : options.runtime_include_dir;
  r.defines = options.defines;
  r.include_dirs = options.include_dirs;
  r.language = options.language;
  return r;
}

lang::TranslatorOptions translator_options(const ResolvedOptions& r) {
  return lang::TranslatorOptions{r.compiler, r.runtime, r.defines, r.include_dirs,
                                 r.language.empty() ? "auto" : r.language};
}

// The key of the direct lookup: the model file itself and the tools.
std::string direct_key(const std::string& model_path, const std::string& source, const ResolvedOptions& r) {
  ContentHash h;
  h.add(kCacheFormat);
  h.add(fs::absolute(model_path).string());
  h.add(source);
  h.add(r.compiler);
  h.add(file_stamp(find_in_path(r.compiler)));
  h.add(r.runtime);
  for (const std::string& d : r.defines) h.add(d);
  for (const std::string& d : r.include_dirs) h.add("-I" + d);
  h.add("language=" + r.language);
  return h.hex();
}

// A manifest records which library a model built into and the files it read.
bool manifest_still_valid(const fs::path& manifest, std::string* library, std::vector<std::string>* warnings) {
  std::ifstream in(manifest);
  if (!in) return false;
  std::string line;
  bool have_library = false;
  while (std::getline(in, line)) {
    if (line.rfind("library ", 0) == 0) {
      *library = line.substr(8);
      have_library = true;
    } else if (line.rfind("warning ", 0) == 0) {
      warnings->push_back(line.substr(8));
    } else if (line.rfind("dep ", 0) == 0) {
      std::size_t space = line.find(' ', 4);
      if (space == std::string::npos) return false;
      if (file_stamp(line.substr(space + 1)) != line.substr(4, space - 4)) return false;
    }
  }
  return have_library && fs::exists(*library);
}

}  // namespace

std::string default_cache_dir() {
  if (const char* dir = std::getenv("SYLVA_CACHE_DIR"); dir && *dir) return dir;
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) return std::string(xdg) + "/sylva";
  if (const char* home = std::getenv("HOME"); home && *home) return std::string(home) + "/.cache/sylva";
  return (fs::temp_directory_path() / "sylva-cache").string();
}

std::string default_runtime_include_dir() { return env_or("SYLVA_RUNTIME_DIR", SYLVA_RUNTIME_INCLUDE_DIR); }

std::string translate_model(const std::string& model_path, const BuildOptions& options) {
  return lang::translate_file(model_path, translator_options(resolve(options))).cpp;
}

BuiltModel build_model(const std::string& model_path, const BuildOptions& options) {
  ResolvedOptions r = resolve(options);
  std::error_code ec;
  if (!fs::is_regular_file(model_path, ec)) {
    const char* why = fs::is_directory(model_path, ec) ? "is a directory, not a model file"
                      : fs::exists(model_path, ec)     ? "is not a regular file"
                                                       : "no such file";
    throw ModelError(SourceLocation{model_path, 0, 0}, why);
  }
  fs::create_directories(r.cache_dir, ec);
  if (ec) throw ModelError("cannot create the model cache " + r.cache_dir.string() + ": " + ec.message());

  std::string source = read_whole_file(model_path).bytes;
  fs::path manifest = r.cache_dir / (direct_key(model_path, source, r) + ".manifest");
  std::string library;
  std::vector<std::string> cached_warnings;
  if (manifest_still_valid(manifest, &library, &cached_warnings)) return BuiltModel{library, false, cached_warnings};

  lang::Translation translation = lang::translate_file(model_path, translator_options(r));
  ContentHash h;
  h.add(kCacheFormat);
  h.add(r.compiler);
  for (const std::string& flag : kCompileFlags) h.add(flag);
  h.add(translation.cpp);
  std::string key = h.hex();
  fs::path so = r.cache_dir / (key + ".so");
  BuiltModel built{so.string(), false, translation.warnings};

  if (!fs::exists(so)) {
    fs::path ii = r.cache_dir / (key + ".ii");
    write_cache_file(ii, translation.cpp);
    fs::path tmp = so;
    tmp += ".tmp" + std::to_string(getpid());
    std::vector<std::string> argv = {r.compiler};
    argv.insert(argv.end(), kCompileFlags.begin(), kCompileFlags.end());
    argv.insert(argv.end(), {"-o", tmp.string(), ii.string()});
    if (options.verbose) fprintf(stderr, "sylva: compiling %s\n", model_path.c_str());
    ProcessResult result = run_process(argv);
    if (result.exit_code != 0) {
      fs::remove(tmp, ec);
      std::string messages = compiler_messages(result.err);
      if (messages.empty()) messages = model_path + ": error: the C++ compiler (" + r.compiler + ") failed";
      throw ModelError(messages);
    }
    fs::rename(tmp, so);
    built.compiled_now = true;
  }

  std::string manifest_text = "library " + so.string() + "\n";
  for (const std::string& warning : translation.warnings)
    if (warning.find('\n') == std::string::npos) manifest_text += "warning " + warning + "\n";
  for (const std::string& dep : translation.dependencies) {
    std::string path = fs::absolute(dep, ec).string();
    manifest_text += "dep " + file_stamp(path) + " " + path + "\n";
  }
  write_cache_file(manifest, manifest_text);
  return built;
}

}  // namespace sylva::build
