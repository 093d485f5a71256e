#include "lang/translator.h"

#include <filesystem>
#include <optional>
#include <set>
#include <sstream>

#include "lang/cpfg_parser.h"
#include "lang/cpp_generator.h"
#include "lang/lc_parser.h"
#include "lang/token.h"
#include "support/diagnostic.h"
#include "support/line_marker.h"
#include "support/preprocessor_errors.h"
#include "support/subprocess.h"
#include "support/whole_file.h"

namespace sylva::lang {
namespace fs = std::filesystem;

namespace {

std::string read_model_file(const std::string& path) {
  std::error_code ec;
  if (!fs::exists(path, ec)) throw ModelError(SourceLocation{path, 0, 0}, "no such file");
  WholeFile file = read_whole_file(path);
  if (file.failure == WholeFile::Failure::IsFolder)
    throw ModelError(SourceLocation{path, 0, 0}, "is a directory, not a model file");
  if (!file) throw ModelError(SourceLocation{path, 0, 0}, "cannot be read");
  return std::move(file.bytes);
}

// The preprocessor's first error at its file, line and column; its whole
// output where none is located.
[[noreturn]] void preprocessor_failed(const std::string& path, const ProcessResult& r) {
  if (std::optional<ModelError> error = first_preprocessor_error(r.err, path, path)) throw *error;
  std::string message = r.err.empty() ? "the C preprocessor failed" : r.err;
  while (!message.empty() && message.back() == '\n') message.pop_back();
  throw ModelError(message.find(path) != std::string::npos ? message : path + ": error: " + message);
}

// The files named by the preprocessor's line markers.
std::vector<std::string> marker_files(const std::string& text) {
  std::vector<std::string> files;
  std::set<std::string> seen;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    std::optional<LineMarker> marker = parse_line_marker(line);
    if (!marker || marker->file.empty() || marker->file[0] == '<') continue;
    if (seen.insert(marker->file).second) files.push_back(marker->file);
  }
  return files;
}

ParsedModel parse_cpfg_file(const std::string& model_path, const TranslatorOptions& options) {
  // cpfg models go through the C preprocessor (#define, #include) on their own.
  // cpfg's preprocessor (vlabcpp) passes a line whose `#` starts no directive
  // through as text (`#` is also a turtle symbol: `	#(0.1) F`), as does the
  // C preprocessor in its assembler mode; in C mode it is an error.
  std::vector<std::string> argv = {options.compiler, "-E", "-x", "assembler-with-cpp", "-D__SYLVA__=1",
                                   "-D__CPFG__=1"};
  for (const std::string& d : options.defines) argv.push_back("-D" + d);
  std::string dir = fs::path(model_path).parent_path().string();
  argv.push_back("-I");
  argv.push_back(dir.empty() ? "." : dir);
  for (const std::string& d : options.include_dirs) argv.insert(argv.end(), {"-I", d});
  argv.push_back(model_path);
  ProcessResult pre = run_process(argv);
  if (pre.exit_code != 0) preprocessor_failed(model_path, pre);
  return ParsedModel{parse_cpfg(pre.out, model_path), marker_files(pre.out)};
}

Translation translate_cpfg(const std::string& model_path, const TranslatorOptions& options) {
  ParsedModel parsed = parse_cpfg_file(model_path, options);
  // The generated C++ needs the runtime: lpfgall.h and cpfg's helpers,
  // preprocessed in front of it.
  std::vector<std::string> rt = {options.compiler, "-E", "-x", "c++", "-std=gnu++20", "-D__SYLVA__=1",
                                 "-isystem", options.runtime_include_dir, "-include", "lpfgall.h",
                                 "-include", "sylva/runtime/cpfg_helpers.h", "/dev/null"};
  ProcessResult runtime = run_process(rt);
  if (runtime.exit_code != 0) preprocessor_failed(model_path, runtime);

  Translation result;
  result.cpp = runtime.out + "\n" + generate_cpp(parsed.model);
  result.dependencies = std::move(parsed.dependencies);
  result.warnings = parsed.model.warnings;
  for (const std::string& f : marker_files(runtime.out))
    if (f != "/dev/null") result.dependencies.push_back(f);
  return result;
}

}  // namespace

bool looks_like_cpfg(const std::string& source) {
  // Comments out, then look for the two lines.
  std::string text;
  text.reserve(source.size());
  for (std::size_t i = 0; i < source.size();) {
    if (source.compare(i, 2, "/*") == 0) {
      std::size_t e = source.find("*/", i + 2);
      for (std::size_t k = i; k < (e == std::string::npos ? source.size() : e + 2); ++k)
        if (source[k] == '\n') text += '\n';
      i = e == std::string::npos ? source.size() : e + 2;
    } else if (source.compare(i, 2, "//") == 0) {
      while (i < source.size() && source[i] != '\n') ++i;
    } else {
      text += source[i++];
    }
  }
  bool lsystem = false, end = false;
  std::istringstream in(text);
  std::string line;
  auto lower = [](std::string s) {
    for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return s;
  };
  while (std::getline(in, line)) {
    std::size_t b = line.find_first_not_of(" \t\r");
    if (b == std::string::npos) continue;
    std::string l = lower(line.substr(b));
    if (l.rfind("lsystem", 0) == 0) {
      std::size_t c = l.find_first_not_of(" \t", 7);
      if (c != std::string::npos && l[c] == ':') lsystem = true;
    }
    if (l.rfind("endlsystem", 0) == 0) end = true;
  }
  return lsystem && end;
}

namespace {

bool is_cpfg(const std::string& source, const std::string& language) {
  if (language == "cpfg" || ((language.empty() || language == "auto") && looks_like_cpfg(source))) return true;
  if (!language.empty() && language != "auto" && language != "lc")
    throw ModelError("unknown model language '" + language + "' (expected cpfg or lc)");
  return false;
}

ParsedModel parse_lc_file(const std::string& model_path, const std::string& source, const TranslatorOptions& options) {
  // lpfg preprocesses models on Linux with LINUX defined: models test it.
  std::vector<std::string> argv = {options.compiler, "-E", "-x", "c++", "-std=gnu++20", "-D__SYLVA__=1", "-DLINUX=1"};
  argv.insert(argv.end(), options.preprocessor_flags.begin(), options.preprocessor_flags.end());
  for (const std::string& d : options.defines) argv.push_back("-D" + d);
  argv.push_back("-isystem");
  argv.push_back(options.runtime_include_dir);
  std::string dir = fs::path(model_path).parent_path().string();
  argv.push_back("-I");
  argv.push_back(dir.empty() ? "." : dir);
  for (const std::string& d : options.include_dirs) argv.insert(argv.end(), {"-I", d});
  // Models that do not include lpfgall.h get it first, as if they had.
  if (source.find("lpfgall.h") == std::string::npos) {
    argv.push_back("-include");
    argv.push_back("lpfgall.h");
  }
  argv.push_back(model_path);
  ProcessResult pre = run_process(argv);
  if (pre.exit_code != 0) preprocessor_failed(model_path, pre);

  TokenStream tokens = tokenize_preprocessed(pre.out);
  Model model = parse_lc(tokens, model_path);
  return ParsedModel{std::move(model), std::move(tokens.dependencies)};
}

}  // namespace

ParsedModel parse_model_file(const std::string& model_path, const TranslatorOptions& options) {
  const std::string source = read_model_file(model_path);
  return is_cpfg(source, options.language) ? parse_cpfg_file(model_path, options)
                                           : parse_lc_file(model_path, source, options);
}

Translation translate_file(const std::string& model_path, const TranslatorOptions& options) {
  const std::string source = read_model_file(model_path);
  if (is_cpfg(source, options.language)) return translate_cpfg(model_path, options);
  ParsedModel parsed = parse_lc_file(model_path, source, options);
  Translation result;
  result.cpp = generate_cpp(parsed.model);
  result.dependencies = std::move(parsed.dependencies);
  return result;
}

}  // namespace sylva::lang
