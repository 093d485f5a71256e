// Running a program and collecting what it printed.
#pragma once

#include <string>
#include <vector>

namespace sylva {

struct ProcessResult {
  int exit_code = -1;  // -1 if it could not be started or was killed
  bool timed_out = false;
  std::string out;
  std::string err;
};

// Runs argv[0] (searched in PATH) with the given arguments and waits for it.
// The program runs in a process group of its own, which an interrupted run
// stops (support/interruption.h) and which is killed whole when it runs past
// `timeout_seconds` (0: no limit), so a compiler's own children go with it.
ProcessResult run_process(const std::vector<std::string>& argv, double timeout_seconds = 0);

}  // namespace sylva
