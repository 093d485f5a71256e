#include <chrono>
#include <stdexcept>
#include <thread>

#include "experiment/workers.h"

namespace sylva::experiment {

std::vector<RunResult> schedule(const std::vector<RunSpec>& runs, const std::vector<Workers*>& workers,
                                const std::function<void(const RunResult&)>& finished) {
  int capacity = 0;
  for (const Workers* w : workers) capacity += w->capacity();
  if (capacity <= 0 && !runs.empty()) throw std::logic_error("experiment: no workers to run on");
  std::vector<RunResult> results(runs.size());
  std::size_t next = 0, done = 0;
  while (done < runs.size()) {
    for (Workers* w : workers)
      while (next < runs.size() && w->busy() < w->capacity()) w->start(runs[next++]);
    // One kind of workers is waited for; several are polled in turn, with a
    // short sleep when none had anything, so none holds up the others.
    const int timeout = workers.size() == 1 ? 1000 : 0;
    std::size_t arrived = 0;
    for (Workers* w : workers) {
      for (RunResult& result : w->collect(timeout)) {
        ++arrived;
        const long number = result.number;
        if (number < 0 || static_cast<std::size_t>(number) >= runs.size())
          throw std::runtime_error("experiment: a worker returned run " + std::to_string(number) + ", which is not one");
        if (finished) finished(result);
        results[number] = std::move(result);
        ++done;
      }
    }
    if (workers.size() > 1 && arrived == 0) std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
  return results;
}

}  // namespace sylva::experiment
