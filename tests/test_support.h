// Helpers shared by the tests: running models through the public API or the
// sylva program, and reading test data.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "support/subprocess.h"

namespace sylva::test {

// tests/ in the source tree, and examples/.
std::string data_path(const std::string& relative);
std::string example_path(const std::string& relative);

std::string read_text(const std::string& path);

// The final string of `model` after `steps` steps (the model's own
// derivation length if negative), in the text format, without the newline.
// The model is built into the tests' own cache.
std::string derive_string(const std::string& model, int steps = -1);

// Runs the sylva program with `args` in `working_dir` (the tests' cache is set).
ProcessResult run_sylva(const std::vector<std::string>& args, const std::string& working_dir = ".");

// The folders directly under `dir` that hold a model (lsystem.l), sorted.
std::vector<std::filesystem::path> model_folders(const std::string& dir);

// A fresh empty directory under the system's temporary directory.
std::string make_temp_dir(const std::string& name);

// Writes `text` as `file_name` in a fresh temporary directory named after
// `folder`; returns the file's path.
std::string write_temp_file(const std::string& folder, const std::string& file_name, const std::string& text);

// Whether this kernel faults in a stretch of pages with one call
// (MADV_POPULATE_WRITE, Linux 5.14): without it pages fault in one by one.
bool kernel_populates_pages();

}  // namespace sylva::test
