// The C preprocessor that view files go through (LPFG manual 8.1): the
// system compiler's -E, with its line markers followed back to the file and
// line each line was written on.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "inputs/input_text.h"

namespace sylva::io {

struct PreprocessedLine {
  std::string file;  // as the line markers name it (#included files by their path)
  int line = 0;
  std::string text;
};

// The lines of `path` after `compiler -E`, blank ones left out. A
// preprocessor error is a ModelError at its file, line and column.
std::vector<PreprocessedLine> preprocess_file(const std::string& path, const std::string& compiler);

// The text as written, to report a word's column there: comments and macros
// move words within a preprocessed line.
class OriginalColumns {
 public:
  // Moves `word` (of `file`'s line `line`) to where its text stands in the
  // original line, the occurrence nearest its preprocessed column; leaves it
  // where it is if the text is not there (a macro's expansion).
  void restore(Word& word, const std::string& file, int line);

 private:
  const std::string* line_of(const std::string& file, int line);
  std::map<std::string, std::vector<std::string>> files_;
};

}  // namespace sylva::io
