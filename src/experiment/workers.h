// Where runs go: a narrow interface the scheduler hands runs to and
// collects results from, whatever carries them — processes of this machine
// (experiment/local_processes.h), the ranks of an MPI job (the MPI plugin),
// or a fake in tests.
#pragma once

#include <functional>
#include <vector>

#include "experiment/run_one.h"
#include "experiment/runs.h"

namespace sylva::experiment {

class Workers {
 public:
  virtual ~Workers() = default;
  // How many runs it takes at once.
  virtual int capacity() const = 0;
  // How many it has now.
  virtual int busy() const = 0;
  // Starts `run` (busy() < capacity()).
  virtual void start(const RunSpec& run) = 0;
  // The runs finished since the last call, waiting up to `timeout_ms` for one.
  virtual std::vector<RunResult> collect(int timeout_ms) = 0;
};

// Hands out `runs` in order to whichever workers are free (so slow runs do
// not hold up the others) until all are done, calling `finished` with each
// result as it comes. Returns the results by run number.
std::vector<RunResult> schedule(const std::vector<RunSpec>& runs, const std::vector<Workers*>& workers,
                                const std::function<void(const RunResult&)>& finished = {});

}  // namespace sylva::experiment
