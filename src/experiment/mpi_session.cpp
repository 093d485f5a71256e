#include "experiment/mpi_session.h"

#include <chrono>
#include <cstdlib>
#include <stdexcept>
#include <thread>

#include "experiment/workers.h"
#include "support/plugin_library.h"

namespace sylva::experiment {
namespace {

// Each rank is sent up to kQueued runs, so that it starts its next run as
// soon as one ends instead of waiting for rank 0 to hear of it; it runs them
// one at a time.
constexpr int kQueued = 2;

class OtherRanks : public Workers {
 public:
  explicit OtherRanks(MpiSession& session) : session_(session), busy_(static_cast<std::size_t>(session.size()), 0) {}
  ~OtherRanks() override {
    for (int rank = 1; rank < session_.size(); ++rank) session_.send_run(rank, -1);
  }
  int capacity() const override { return kQueued * (session_.size() - 1); }
  int busy() const override { return count_; }
  void start(const RunSpec& run) override {
    // The least loaded rank.
    int chosen = 0;
    for (int rank = 1; rank < session_.size(); ++rank)
      if (busy_[rank] < kQueued && (chosen == 0 || busy_[rank] < busy_[chosen])) chosen = rank;
    if (chosen == 0) throw std::logic_error("MPI: no free rank");
    session_.send_run(chosen, run.number);
    ++busy_[chosen];
    ++count_;
  }
  std::vector<RunResult> collect(int timeout_ms) override {
    std::vector<RunResult> results;
    const auto until = std::chrono::steady_clock::now() + std::chrono::milliseconds(timeout_ms);
    int rank = 0;
    std::string text;
    while (count_ > 0) {
      if (session_.poll_result(rank, text)) {
        --busy_[rank];
        --count_;
        results.push_back(decode_result(text));
        continue;
      }
      if (!results.empty() || std::chrono::steady_clock::now() >= until) break;
      // Polled with short sleeps: waiting in MPI would spin on a core the runs need.
      std::this_thread::sleep_for(std::chrono::microseconds(500));
    }
    return results;
  }

 private:
  MpiSession& session_;
  std::vector<int> busy_;  // runs sent and not back, by rank; rank 0's entry unused
  int count_ = 0;
};

}  // namespace

std::unique_ptr<Workers> other_ranks(MpiSession& session) { return std::make_unique<OtherRanks>(session); }

bool launched_by_mpi() {
  for (const char* variable : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK", "MPI_LOCALNRANKS"})
    if (std::getenv(variable)) return true;
  return false;
}

std::unique_ptr<MpiSession> open_mpi_session() {
  auto* factory = reinterpret_cast<MpiSession* (*)()>(
      plugin_symbol("libsylva_mpi.so", "sylva_mpi_session", "runs experiments under MPI (it is built where OpenMPI is found)"));
  return std::unique_ptr<MpiSession>(factory());
}

}  // namespace sylva::experiment
