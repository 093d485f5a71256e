#include "inputs/preprocessor.h"

#include "support/diagnostic.h"
#include "support/line_marker.h"
#include "support/preprocessor_errors.h"
#include "support/subprocess.h"

namespace sylva::io {

namespace {

[[noreturn]] void preprocessor_failed(const std::string& path, const std::string& argument, const std::string& compiler,
                                      const ProcessResult& result) {
  if (result.exit_code == -1 && result.err.starts_with("cannot run"))
    throw ModelError(SourceLocation{path, 0, 0}, "cannot run the C preprocessor: " + result.err);
  if (std::optional<ModelError> error = first_preprocessor_error(result.err, argument, path)) throw *error;
  std::string first = result.err.substr(0, result.err.find('\n'));
  throw ModelError(SourceLocation{path, 0, 0},
                   "the C preprocessor (" + compiler + " -E) failed" + (first.empty() ? std::string() : ": " + first));
}

}  // namespace

// Runs the preprocessor and follows its line markers ("# 12 \"file\" 2"), so
// every line knows the file and line it was written on.
std::vector<PreprocessedLine> preprocess_file(const std::string& path, const std::string& compiler) {
  // -std=c++17 rather than a GNU dialect: those predefine `linux` and `unix`,
  // words a view file may well hold.
  // A path starting with '-' would read as an option.
  std::string argument = path.starts_with("-") ? "./" + path : path;
  ProcessResult result = run_process({compiler, "-E", "-x", "c++", "-std=c++17", "-w", argument});
  if (result.exit_code != 0) preprocessor_failed(path, argument, compiler, result);
  std::vector<PreprocessedLine> lines;
  std::string file = path;
  int line_number = 1;
  std::size_t start = 0;
  const std::string& out = result.out;
  while (start < out.size()) {
    std::size_t end = out.find('\n', start);
    if (end == std::string::npos) end = out.size();
    std::string text = out.substr(start, end - start);
    start = end + 1;
    if (!text.empty() && text[0] == '#') {
      if (std::optional<LineMarker> marker = parse_line_marker(text)) {
        line_number = marker->line;
        file = marker->file == argument ? path : marker->file;
      }
      continue;  // a marker, or a #pragma the preprocessor kept
    }
    if (text.find_first_not_of(" \t\r") != std::string::npos) lines.push_back(PreprocessedLine{file, line_number, text});
    ++line_number;
  }
  return lines;
}

const std::string* OriginalColumns::line_of(const std::string& file, int line) {
  auto it = files_.find(file);
  if (it == files_.end()) {
    std::vector<std::string> lines;
    try {
      std::string text = read_input_file(file, "file");
      std::size_t start = 0;
      while (start <= text.size()) {
        std::size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        lines.push_back(text.substr(start, end - start));
        start = end + 1;
      }
    } catch (const ModelError&) {
      // <built-in> and the like: the preprocessed columns stay.
    }
    it = files_.emplace(file, std::move(lines)).first;
  }
  if (line < 1 || static_cast<std::size_t>(line) > it->second.size()) return nullptr;
  return &it->second[static_cast<std::size_t>(line - 1)];
}

void OriginalColumns::restore(Word& word, const std::string& file, int line) {
  const std::string* original = line_of(file, line);
  if (!original || word.text.empty()) return;
  int best = -1;
  for (std::size_t at = original->find(word.text); at != std::string::npos; at = original->find(word.text, at + 1)) {
    int column = static_cast<int>(at) + 1;
    if (best < 0 || std::abs(column - word.column) < std::abs(best - word.column)) best = column;
  }
  if (best > 0) word.column = best;
}

}  // namespace sylva::io
