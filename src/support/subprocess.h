// Running a program and collecting what it printed.
#pragma once

#include <string>
#include <vector>

namespace sylva {

struct ProcessResult {
  int exit_code = -1;  // -1 if it could not be started or was killed
  std::string out;
  std::string err;
};

// Runs argv[0] (searched in PATH) with the given arguments and waits for it.
ProcessResult run_process(const std::vector<std::string>& argv);

}  // namespace sylva
