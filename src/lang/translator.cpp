#include "lang/translator.h"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "lang/cpp_generator.h"
#include "lang/lc_parser.h"
#include "lang/token.h"
#include "support/diagnostic.h"
#include "support/subprocess.h"

namespace sylva::lang {
namespace fs = std::filesystem;

namespace {

std::string read_model_file(const std::string& path) {
  std::error_code ec;
  if (!fs::exists(path, ec)) throw ModelError(SourceLocation{path, 0, 0}, "no such file");
  if (fs::is_directory(path, ec)) throw ModelError(SourceLocation{path, 0, 0}, "is a directory, not a model file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ModelError(SourceLocation{path, 0, 0}, "cannot be read");
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// The preprocessor's complaints already carry file:line:column; keep them.
[[noreturn]] void preprocessor_failed(const std::string& path, const ProcessResult& r) {
  std::string message = r.err.empty() ? "the C preprocessor failed" : r.err;
  while (!message.empty() && message.back() == '\n') message.pop_back();
  throw ModelError(message.find(path) != std::string::npos ? message : path + ": error: " + message);
}

}  // namespace

Translation translate_file(const std::string& model_path, const TranslatorOptions& options) {
  std::string source = read_model_file(model_path);
  std::vector<std::string> argv = {options.compiler, "-E", "-x", "c++", "-std=gnu++20", "-D__SYLVA__=1"};
  for (const std::string& d : options.defines) argv.push_back("-D" + d);
  argv.push_back("-isystem");
  argv.push_back(options.runtime_include_dir);
  std::string dir = fs::path(model_path).parent_path().string();
  argv.push_back("-I");
  argv.push_back(dir.empty() ? "." : dir);
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
  Translation result;
  result.cpp = generate_cpp(model);
  result.dependencies = std::move(tokens.dependencies);
  return result;
}

}  // namespace sylva::lang
