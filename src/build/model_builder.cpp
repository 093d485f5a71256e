#include "build/model_builder.h"

#include <pwd.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "build/cache_maintenance.h"
#include "build/cache_manifest.h"
#include "build/compiler_messages.h"
#include "build/model_cache.h"
#include "lang/translator.h"
#include "support/content_hash.h"
#include "support/default_compiler.h"
#include "support/diagnostic.h"
#include "support/interruption.h"
#include "support/subprocess.h"
#include "support/whole_file.h"

#ifndef SYLVA_RUNTIME_INCLUDE_DIR
#define SYLVA_RUNTIME_INCLUDE_DIR ""
#endif
#ifndef SYLVA_RUNTIME_PCH
#define SYLVA_RUNTIME_PCH ""
#define SYLVA_RUNTIME_PCH_COMPILER ""
#endif

namespace sylva::build {
namespace fs = std::filesystem;

namespace {

constexpr double kDefaultCompileTimeout = 600;

// How a model's code is generated: the same for the compile, for the
// preprocessing that takes the precompiled runtime header and for that header.
const std::vector<std::string> kCodeFlags = {
    "-std=gnu++20", "-O2", "-fPIC", "-fvisibility=hidden", "-fno-gnu-unique",
    // Plain IEEE arithmetic as the reference implementation does it: no fused
    // multiply-add, so float results match to the last bit.
    "-ffp-contract=off"};
const std::vector<std::string> kLinkFlags = {"-shared", "-w"};
// The translator's own definitions for L+C models (lang/translator.cpp), which
// the precompiled header must be made with to be taken.
const std::vector<std::string> kModelDefines = {"-D__SYLVA__=1", "-DLINUX=1"};

std::string env_or(const char* name, const std::string& fallback) {
  const char* value = std::getenv(name);
  return value && *value ? value : fallback;
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
  std::string runtime;
  std::vector<std::string> defines;
  std::vector<std::string> include_dirs;
  std::string language;
  // lpfgall.h precompiled by this program's build, or empty: the build's
  // SYLVA_RUNTIME_PCH when the runtime and the compiler are the ones it was
  // made for and it was made (an empty file where that compiler could not).
  std::string runtime_pch;
};

std::string runtime_pch(const std::string& runtime, const std::string& compiler) {
  std::error_code ec;
  if (runtime != SYLVA_RUNTIME_INCLUDE_DIR || compiler != SYLVA_RUNTIME_PCH_COMPILER ||
      fs::file_size(SYLVA_RUNTIME_PCH, ec) == 0 || ec)
    return "";
  return SYLVA_RUNTIME_PCH;
}

ResolvedOptions resolve(const BuildOptions& options) {
  ResolvedOptions r;
  r.compiler = compiler_or_default(options.compiler);
  r.runtime = options.runtime_include_dir.empty() ? default_runtime_include_dir() : options.runtime_include_dir;
  r.defines = options.defines;
  r.include_dirs = options.include_dirs;
  r.language = options.language;
  r.runtime_pch = runtime_pch(r.runtime, r.compiler);
  return r;
}

lang::TranslatorOptions translator_options(const ResolvedOptions& r) {
  return lang::TranslatorOptions{r.compiler, r.runtime, r.defines, r.include_dirs,
                                 r.language.empty() ? "auto" : r.language, {}};
}

// The translator's options for a model about to be compiled: with the
// precompiled runtime header when there is one. The compiler checks that it
// was made by the same compiler with the same flags and definitions, and
// reads lpfgall.h itself otherwise; a model with its own lpfgall.h beside it
// still finds that first. The C++ then names the header in a pragma instead
// of holding the runtime's text, and the compile reads it again.
lang::TranslatorOptions compile_translator_options(const ResolvedOptions& r) {
  lang::TranslatorOptions options = translator_options(r);
  if (r.runtime_pch.empty()) return options;
  options.preprocessor_flags = kCodeFlags;
  options.preprocessor_flags.insert(options.preprocessor_flags.end(),
                                    {"-fpch-preprocess", "-isystem", fs::path(r.runtime_pch).parent_path().string()});
  return options;
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
  h.add(r.runtime_pch.empty() ? "no pch" : file_stamp(r.runtime_pch));
  return h.hex();
}

// The manifest, if it is whole, written for this lookup, and no file the
// model read has changed since.
std::optional<Manifest> still_valid_manifest(const ModelCache& cache, const std::string& lookup_key) {
  const WholeFile text = read_whole_file(cache.file(lookup_key + ".manifest").string());
  if (!text) return std::nullopt;
  std::optional<Manifest> manifest = read_manifest(text.bytes, lookup_key);
  if (!manifest) return std::nullopt;
  for (const Manifest::Dependency& dep : manifest->dependencies)
    if (file_stamp(dep.path) != dep.stamp) return std::nullopt;
  return manifest;
}

}  // namespace

std::string default_cache_dir() {
  if (const char* dir = std::getenv("SYLVA_CACHE_DIR"); dir && *dir) return dir;
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg == '/') return std::string(xdg) + "/sylva";
  if (const char* home = std::getenv("HOME"); home && *home) return std::string(home) + "/.cache/sylva";
  if (const passwd* user = getpwuid(getuid()); user && user->pw_dir && *user->pw_dir)
    return std::string(user->pw_dir) + "/.cache/sylva";
  // A folder every user can write in would let another plant code for this one to run.
  throw ModelError("no home folder to keep compiled models in: set SYLVA_CACHE_DIR or give --cache-dir");
}

std::string default_runtime_include_dir() { return env_or("SYLVA_RUNTIME_DIR", SYLVA_RUNTIME_INCLUDE_DIR); }

double default_compile_timeout() {
  const char* text = std::getenv("SYLVA_COMPILE_TIMEOUT");
  if (!text || !*text) return kDefaultCompileTimeout;
  char* end = nullptr;
  const double seconds = std::strtod(text, &end);
  if (*end != '\0' || !std::isfinite(seconds) || seconds <= 0)
    throw ModelError(std::string("SYLVA_COMPILE_TIMEOUT: expected a positive number of seconds, not '") + text + "'");
  return seconds;
}

std::string translate_model(const std::string& model_path, const BuildOptions& options) {
  return lang::translate_file(model_path, translator_options(resolve(options))).cpp;
}

lang::ParsedModel parse_model(const std::string& model_path, const BuildOptions& options) {
  return lang::parse_model_file(model_path, translator_options(resolve(options)));
}

namespace {

void tell_waiting() { std::fprintf(stderr, "sylva: waiting for another run compiling this model\n"); }

// Compiles KEY's library from `cpp` into the cache; returns its checksum.
// Nothing is left behind but the library: not the C++ (it is large and
// `sylva translate` prints it), not the compiler's output if it fails.
std::string compile_library(const ModelCache& cache, const std::string& key, const std::string& cpp,
                            const std::string& model_path, const ResolvedOptions& r, const BuildOptions& options) {
  const double timeout = options.compile_timeout_seconds > 0 ? options.compile_timeout_seconds : default_compile_timeout();
  fs::path source = temporary_path(cache.file(key));
  source += ".ii";
  const fs::path output = temporary_path(cache.library(key));
  const interruption::TemporaryFile registered_source(source.string()), registered_output(output.string());
  std::ofstream source_file(source, std::ios::binary);
  source_file << cpp;
  source_file.close();
  if (!source_file) {
    std::error_code ignored;
    fs::remove(source, ignored);
    throw ModelError("cannot write " + source.string());
  }
  std::vector<std::string> argv = {r.compiler};
  argv.insert(argv.end(), kCodeFlags.begin(), kCodeFlags.end());
  argv.insert(argv.end(), kLinkFlags.begin(), kLinkFlags.end());
  argv.insert(argv.end(), {"-o", output.string(), source.string()});
  if (options.verbose) fprintf(stderr, "sylva: compiling %s\n", model_path.c_str());
  const ProcessResult result = run_process(argv, timeout);
  std::error_code ec;
  fs::remove(source, ec);
  if (result.timed_out || result.exit_code != 0) {
    fs::remove(output, ec);
    if (result.timed_out) {
      char limit[32];
      std::snprintf(limit, sizeof limit, "%g", timeout);
      throw ModelError(SourceLocation{model_path, 0, 0},
                       std::string("compiling the model took longer than the limit of ") + limit +
                           " seconds, and the compiler was stopped (--compile-timeout SECONDS or "
                           "SYLVA_COMPILE_TIMEOUT allow more)");
    }
    std::string messages = compiler_messages(result.err);
    if (messages.empty()) messages = model_path + ": error: the C++ compiler (" + r.compiler + ") failed";
    throw ModelError(messages);
  }
  return cache.install_library(output, key);
}

}  // namespace

BuiltModel build_model(const std::string& model_path, const BuildOptions& options) {
  ResolvedOptions r = resolve(options);
  std::error_code ec;
  if (!fs::is_regular_file(model_path, ec)) {
    const char* why = fs::is_directory(model_path, ec) ? "is a directory, not a model file"
                      : fs::exists(model_path, ec)     ? "is not a regular file"
                                                       : "no such file";
    throw ModelError(SourceLocation{model_path, 0, 0}, why);
  }
  const ModelCache cache(options.cache_dir.empty() ? default_cache_dir() : options.cache_dir);

  std::string source = read_whole_file(model_path).bytes;
  const std::string lookup_key = direct_key(model_path, source, r);
  if (const std::optional<Manifest> manifest = still_valid_manifest(cache, lookup_key)) {
    const std::string key = fs::path(manifest->library).stem().string();
    if (const std::optional<std::string> checksum = cache.recorded_checksum(key)) {
      cache.mark_used(key);
      return BuiltModel{cache.library(key).string(), *checksum, false, manifest->warnings};
    }
  }

  lang::Translation translation = lang::translate_file(model_path, compile_translator_options(r));
  ContentHash h;
  h.add(kCacheFormat);
  h.add(r.compiler);
  for (const std::string& flag : kCodeFlags) h.add(flag);
  for (const std::string& flag : kLinkFlags) h.add(flag);
  // The C++ names the precompiled header, whose content it depends on.
  h.add(r.runtime_pch.empty() ? "no pch" : file_stamp(r.runtime_pch));
  h.add(translation.cpp);
  const std::string key = h.hex();
  BuiltModel built{cache.library(key).string(), {}, false, translation.warnings};
  {
    const ModelCache::Lock lock = cache.lock(key, options.verbose ? tell_waiting : nullptr);
    if (const std::optional<std::string> checksum = cache.verified_checksum(key)) {
      built.library_checksum = *checksum;
      cache.mark_used(key);
    } else {
      built.library_checksum = compile_library(cache, key, translation.cpp, model_path, r, options);
      built.compiled_now = true;
    }
  }

  Manifest manifest{lookup_key, cache.library(key).filename().string(), translation.warnings, {}};
  for (const std::string& dep : translation.dependencies) {
    std::string path = fs::absolute(dep, ec).string();
    manifest.dependencies.push_back({file_stamp(path), path});
  }
  cache.write_file(lookup_key + ".manifest", manifest_text(manifest));
  if (built.compiled_now) prune_cache_if_full(cache, key, lookup_key + ".manifest");
  return built;
}

void precompile_runtime(const std::string& output, const std::string& runtime_include_dir,
                        const std::string& compiler) {
  std::vector<std::string> argv = {compiler, "-x", "c++-header"};
  argv.insert(argv.end(), kCodeFlags.begin(), kCodeFlags.end());
  argv.insert(argv.end(), kModelDefines.begin(), kModelDefines.end());
  argv.insert(argv.end(), {"-w", "-isystem", runtime_include_dir, (fs::path(runtime_include_dir) / "lpfgall.h").string(),
                           "-o", output});
  const ProcessResult result = run_process(argv, default_compile_timeout());
  if (result.timed_out || result.exit_code != 0)
    throw ModelError("cannot precompile " + runtime_include_dir + "/lpfgall.h with " + compiler + ": " + result.err);
}

}  // namespace sylva::build
