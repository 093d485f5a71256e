// How a .e file's "executable:" line becomes a Field.
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "env/field.h"

namespace sylva::env {

// The "executable:" command line, split into words as a shell would (quotes
// honoured), with the folder relative paths are resolved against (the folder
// of the .e file, which is the model's folder in a Virtual Laboratory object).
struct ProgramInvocation {
  std::string program;                 // first word, e.g. "honda81" or "./my_env"
  std::vector<std::string> arguments;  // the remaining words
  std::filesystem::path directory;
  std::string e_file;                  // the .e file's path, for error messages
  int e_file_line = 0;                 // line of the executable: command

  // The arguments that are not options: parameter files. The Virtual
  // Laboratory programs accept "-e commfile.e" (and a few single-letter flags)
  // before their parameter file; those are skipped here.
  std::vector<std::string> positional_arguments() const;
  // An argument resolved against `directory`.
  std::filesystem::path resolve(const std::string& argument) const;
};

}  // namespace sylva::env
