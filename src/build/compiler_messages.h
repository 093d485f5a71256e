// What the C++ compiler says about a model, made about the model: its
// messages name the model's lines already (the generated code carries line
// markers); lines that only name generated functions are dropped, and a
// column past the end of the model's line (inside generated code) is moved
// back onto the line.
#pragma once

#include <functional>
#include <optional>
#include <string>

namespace sylva::build {

// The text of `line` (from 1) of `file`, or nullopt where it cannot be read.
using SourceLines = std::function<std::optional<std::string>(const std::string& file, int line)>;

// The compiler's standard error as the user should see it; `lines` reads
// the files its messages point into.
std::string compiler_messages(const std::string& err, const SourceLines& lines);

// The same, reading the files from disk.
std::string compiler_messages(const std::string& err);

}  // namespace sylva::build
