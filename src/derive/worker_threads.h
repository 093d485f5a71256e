// Runs the tasks of one pass on a few threads: task k's result goes to slot
// k, so the order the threads take tasks in never shows in the result. Each
// thread checks the run's limits (RunBudget) and reports faults in model
// code as the calling thread does.
#pragma once

#include <cstddef>
#include <exception>
#include <functional>
#include <vector>

namespace sylva::derive {

// Calls task(k) for k in [0, count) on up to `threads` threads, the calling
// one included, and waits for all. The helper threads are kept from call to
// call; a call made while another has them starts threads of its own. An
// exception from a task is rethrown here, the one of the lowest k (as a
// serial loop would have met first).
void run_tasks(int threads, std::size_t count, const std::function<void(std::size_t)>& task);

}  // namespace sylva::derive
