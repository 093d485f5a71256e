// The command lines of lpfg and cpfg, read as those programs read them, so
// that the line an object's `specifications` gives runs unchanged:
//   lpfg: files in any order, each recognised by its extension, and lpfg's
//         options (-b, -a, -out FILE, -w W H, -cleanEA20, ...);
//   cpfg: options that name the file after them (-m map, -m2 map2, -M mat,
//         -e env), then the L-system, the view file and the animation file
//         in that order, whatever their names end in.
// Sylva's own options are left where they are for the command line's parser;
// see docs/reference-dialects.md for every reference option and what it does here.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "inputs/input_files.h"

namespace sylva {

struct ReferenceCommandLine {
  std::string model;                   // empty: no L-system among the files
  std::vector<io::InputFile> inputs;   // in command-line order, .e files included
  std::vector<std::string> outputs;    // lpfg's -out and cpfg's -obj/-png/-ps FILE
  std::string string_path;             // lpfg's -out FILE.str, cpfg's -str FILE
  bool interpreted_string = false;     // cpfg's -h: the string is written after homomorphism
  bool clean_ea20 = false;             // lpfg's -cleanEA20
  bool compile_only = false;           // lpfg's -c
  std::optional<int> width, height;    // the window's size (-w W H): the size of pictures
  // One line for each option accepted but without effect in a run without
  // a window ("-a: the animation mode ...; ignored").
  std::vector<std::string> notes;
  // The arguments that are Sylva's own, in order, for its option parser.
  std::vector<std::string> sylva_arguments;
};

// How many values a Sylva option takes: nullopt when `name` ("-o",
// "--string") is not one of Sylva's options.
using SylvaOptionArity = std::function<std::optional<int>(const std::string& name)>;

// Splits `arguments` (what follows `sylva run`) into the reference programs'
// files and options and Sylva's own. Where the two disagree on a spelling
// Sylva's meaning is kept (-o FILE is an output, not lpfg's library) and
// documented. Throws ModelError for a reference option without its value
// ("-m" as the last argument).
ReferenceCommandLine read_reference_command_line(const std::vector<std::string>& arguments,
                                                 const SylvaOptionArity& sylva_option);

}  // namespace sylva
