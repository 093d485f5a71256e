// The statements of a preprocessed cpfg L-system file, as cpfg's lexer
// (lsys_input.l) splits them. Internal to the cpfg front end.
#pragma once

#include <string>
#include <vector>

#include "lang/cpfg_expr.h"

namespace sylva::lang::cpfg {

// Splits `preprocessed` (the C preprocessor's output, with line markers) into
// logical lines. A newline ends a statement unless
//  - the line after it starts with a tab (cpfg's "\n\t": the statement goes
//    on; a line that starts with spaces begins a new one), or
//  - it falls inside a { } block of an expression part (a Start: block, a
//    production's pre- or post-condition statements, define:), where cpfg
//    reads across lines.
// The preprocessor turns leading tabs into spaces, so whether a line starts
// with a tab is read from the source file its line marker names; where that
// file cannot be read, from the preprocessed line itself.
// `files` receives the file names (main_file first); positions index it.
std::vector<Line> read_logical_lines(const std::string& preprocessed, std::vector<std::string>& files,
                                     const std::string& main_file);

}  // namespace sylva::lang::cpfg
