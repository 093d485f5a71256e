#include "env/environment.h"

#include <dlfcn.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "env/external_program.h"
#include "env/programs/programs.h"
#include "support/diagnostic.h"

namespace sylva::env {
namespace {

namespace fs = std::filesystem;

using BuiltinFactory = std::unique_ptr<Field> (*)(const ProgramInvocation&);

struct Builtin {
  const char* name;
  BuiltinFactory make;
};

constexpr Builtin kBuiltins[] = {
    {"honda81", make_honda81}, {"ecosystem", make_ecosystem}, {"arvo", make_arvo},     {"density", make_density},
    {"clover", make_clover},   {"chiba", make_chiba},         {"takenaka", make_takenaka},
};

// Words as a POSIX shell splits them: blanks separate, '...' and "..." quote,
// a backslash escapes the next character (outside single quotes).
std::vector<std::string> split_command_line(const std::string& line, bool* unterminated) {
  std::vector<std::string> words;
  std::string word;
  bool in_word = false;
  char quote = 0;
  for (std::size_t k = 0; k < line.size(); ++k) {
    const char c = line[k];
    if (quote == '\'') {
      if (c == '\'') quote = 0;
      else word.push_back(c);
    } else if (quote == '"') {
      if (c == '"') quote = 0;
      else if (c == '\\' && k + 1 < line.size() && (line[k + 1] == '"' || line[k + 1] == '\\')) word.push_back(line[++k]);
      else word.push_back(c);
    } else if (c == ' ' || c == '\t') {
      if (in_word) words.push_back(word);
      word.clear();
      in_word = false;
    } else {
      in_word = true;
      if (c == '\'' || c == '"') quote = c;
      else if (c == '\\' && k + 1 < line.size()) word.push_back(line[++k]);
      else word.push_back(c);
    }
  }
  if (in_word) words.push_back(word);
  *unterminated = quote != 0;
  return words;
}

bool is_executable_file(const fs::path& path) {
  std::error_code error;
  return fs::is_regular_file(path, error) && ::access(path.c_str(), X_OK) == 0;
}

bool ends_with(const std::string& text, const std::string& suffix) {
  return text.size() >= suffix.size() && text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// A plugin's Field, keeping its library loaded while the Field lives.
class PluginField : public Field {
 public:
  PluginField(void* library, Field* field) : library_(library), field_(field) {}
  ~PluginField() override {
    delete field_;
    ::dlclose(library_);
  }
  void answer(std::span<const Query> queries, std::span<Answer> answers, int step) override {
    field_->answer(queries, answers, step);
  }
  void finish() override { field_->finish(); }

 private:
  void* library_;
  Field* field_;
};

std::unique_ptr<Field> load_plugin(const ProgramInvocation& invocation, const SourceLocation& where) {
  const fs::path path = invocation.resolve(invocation.program);
  std::error_code error;
  if (!fs::is_regular_file(path, error))
    throw ModelError(where, "environment plugin '" + invocation.program + "' not found (looked for " + path.string() +
                                ")");
  void* library = ::dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!library)
    throw ModelError(where, "cannot load environment plugin '" + invocation.program + "': " + ::dlerror());
  auto factory = reinterpret_cast<PluginFactory>(::dlsym(library, kPluginFactoryName));
  if (!factory) {
    ::dlclose(library);
    throw ModelError(where, "environment plugin '" + invocation.program + "' does not export extern \"C\" " +
                                kPluginFactoryName + "(int, const char* const*, const char*)");
  }
  std::vector<std::string> words{invocation.program};
  words.insert(words.end(), invocation.arguments.begin(), invocation.arguments.end());
  std::vector<const char*> argv;
  for (const std::string& w : words) argv.push_back(w.c_str());
  argv.push_back(nullptr);
  const std::string directory = invocation.directory.string();
  Field* field = nullptr;
  try {
    field = factory(static_cast<int>(words.size()), argv.data(), directory.c_str());
  } catch (...) {
    ::dlclose(library);
    throw;
  }
  if (!field) {
    ::dlclose(library);
    throw ModelError(where, "environment plugin '" + invocation.program + "' could not start (its " +
                                kPluginFactoryName + " returned null)");
  }
  return std::make_unique<PluginField>(library, field);
}

// The program file an external program's name stands for, or empty.
fs::path find_program(const ProgramInvocation& invocation) {
  const std::string& name = invocation.program;
  if (name.find('/') != std::string::npos) {
    const fs::path path = invocation.resolve(name);
    return is_executable_file(path) ? path : fs::path();
  }
  if (const char* path_variable = std::getenv("PATH")) {
    std::string paths = path_variable;
    std::size_t start = 0;
    while (start <= paths.size()) {
      std::size_t colon = paths.find(':', start);
      if (colon == std::string::npos) colon = paths.size();
      const std::string folder = paths.substr(start, colon - start);
      const fs::path candidate = fs::path(folder.empty() ? "." : folder) / name;
      if (is_executable_file(candidate)) return candidate;
      start = colon + 1;
    }
  }
  const fs::path beside = invocation.directory / name;
  return is_executable_file(beside) ? beside : fs::path();
}

}  // namespace

ProgramInvocation invocation_of(const CommSpec& spec) {
  const SourceLocation where{spec.path, spec.executable_line, spec.executable_column};
  bool unterminated = false;
  std::vector<std::string> words = split_command_line(spec.executable, &unterminated);
  if (unterminated) throw ModelError(where, "the command line has an unterminated quote");
  if (words.empty()) throw ModelError(where, "expected the command line of the environmental program");
  ProgramInvocation invocation;
  invocation.program = words.front();
  invocation.arguments.assign(words.begin() + 1, words.end());
  invocation.directory = fs::path(spec.path).parent_path();
  if (invocation.directory.empty()) invocation.directory = ".";
  invocation.e_file = spec.path;
  invocation.e_file_line = spec.executable_line;
  return invocation;
}

namespace {

std::unique_ptr<Field> start_external_program(const CommSpec& spec, const ProgramInvocation& invocation,
                                              const FieldOptions& options) {
  const SourceLocation where{spec.path, spec.executable_line, spec.executable_column};
  const fs::path program = find_program(invocation);
  if (program.empty()) {
    std::string builtins;
    for (const Builtin& b : kBuiltins) builtins += std::string(builtins.empty() ? "" : ", ") + b.name;
    const std::string looked = invocation.program.find('/') != std::string::npos
                                   ? "no executable file " + invocation.resolve(invocation.program).string()
                                   : "not a built-in program (" + builtins + "), not on PATH and not in " +
                                         invocation.directory.string();
    throw ProgramNotStarted(where, "environmental program '" + invocation.program + "' not found: " + looked);
  }
  return std::make_unique<ExternalProgramField>(fs::absolute(program).string(), invocation, spec,
                                                options.timeout_seconds);
}

// "file:line:column: warning: message".
std::string warning_at(const SourceLocation& at, const std::string& message) {
  std::string text = at.file;
  if (at.line > 0) text += ":" + std::to_string(at.line);
  if (at.column > 0) text += ":" + std::to_string(at.column);
  return text + ": warning: " + message;
}

}  // namespace

std::unique_ptr<Field> make_field(const CommSpec& spec, const FieldOptions& options) {
  // The reader has warned that no program is named.
  if (spec.executable.empty()) return std::make_unique<IgnoredEnvironment>();
  const SourceLocation where{spec.path, spec.executable_line, spec.executable_column};
  const ProgramInvocation invocation = invocation_of(spec);
  const std::string base = fs::path(invocation.program).filename().string();
  for (const Builtin& builtin : kBuiltins)
    if (base == builtin.name) return through_comm_library(builtin.make(invocation), spec, options.master, options.warn);
  if (ends_with(invocation.program, ".so")) return load_plugin(invocation, where);
  try {
    return start_external_program(spec, invocation, options);
  } catch (const ProgramNotStarted& not_started) {
    const std::string text = warning_at(not_started.where(), not_started.message()) +
                             "; the environment is ignored, as lpfg and cpfg ignore a program they cannot start\n";
    if (options.warn) options.warn(text);
    else std::fputs(text.c_str(), stderr);
    return std::make_unique<IgnoredEnvironment>();
  }
}

}  // namespace sylva::env
