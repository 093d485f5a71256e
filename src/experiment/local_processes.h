// Runs on this machine, each in a process of its own forked for it: a model's
// global variables start fresh in every run (so results do not depend on
// which runs a process did before), and a run that crashes or hangs costs
// only its own row.
#pragma once

#include <functional>
#include <map>
#include <string>

#include "experiment/workers.h"

namespace sylva::experiment {

class LocalProcesses : public Workers {
 public:
  // `run` is what the forked process does with a RunSpec: its result as
  // encode_result() writes it. `timeout_seconds` (0: none) ends a run that
  // takes longer.
  using RunFunction = std::function<std::string(const RunSpec&)>;
  LocalProcesses(int capacity, RunFunction run, double timeout_seconds = 0);
  ~LocalProcesses() override;

  int capacity() const override { return capacity_; }
  int busy() const override { return static_cast<int>(children_.size()); }
  void start(const RunSpec& run) override;
  std::vector<RunResult> collect(int timeout_ms) override;

 private:
  struct Child {
    long number = 0;
    int pid = 0;
    std::string output;
    double started = 0;
  };
  RunResult ended(int fd, Child& child);

  int capacity_;
  RunFunction run_;
  double timeout_seconds_;
  std::map<int, Child> children_;  // by the read end of the child's pipe
};

}  // namespace sylva::experiment
