// The MPI plugin (experiment/mpi_session.h): run numbers from rank 0 to the
// other ranks, results (text) back. Messages are polled with short sleeps
// rather than waited for in MPI, whose waits spin on a core the runs need.
// The C API only: OpenMPI's and MPICH's C++ bindings would need their own library.
#define OMPI_SKIP_MPICXX 1
#define MPICH_SKIP_MPICXX 1
#include <mpi.h>

#include <chrono>
#include <thread>

#include "experiment/mpi_session.h"
#include "support/plugin_library.h"

namespace sylva::experiment {
namespace {

constexpr int kRunTag = 1;     // rank 0 → rank: a run's number, or -1: no more
constexpr int kResultTag = 2;  // rank → rank 0: the run's result

class Session : public MpiSession {
 public:
  Session() {
    int initialised = 0;
    MPI_Initialized(&initialised);
    if (!initialised) MPI_Init(nullptr, nullptr);
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
  }
  ~Session() override { MPI_Finalize(); }
  int rank() const override { return rank_; }
  int size() const override { return size_; }
  bool agree(bool go) override {
    int value = go ? 1 : 0;
    MPI_Bcast(&value, 1, MPI_INT, 0, MPI_COMM_WORLD);
    return value != 0;
  }
  void send_run(int rank, long number) override { MPI_Send(&number, 1, MPI_LONG, rank, kRunTag, MPI_COMM_WORLD); }
  bool poll_result(int& rank, std::string& text) override {
    int arrived = 0;
    MPI_Status status;
    MPI_Iprobe(MPI_ANY_SOURCE, kResultTag, MPI_COMM_WORLD, &arrived, &status);
    if (!arrived) return false;
    int length = 0;
    MPI_Get_count(&status, MPI_CHAR, &length);
    text.assign(static_cast<std::size_t>(length), '\0');
    MPI_Recv(text.data(), length, MPI_CHAR, status.MPI_SOURCE, kResultTag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    rank = status.MPI_SOURCE;
    return true;
  }
  void serve(const std::function<std::string(long)>& run) override {
    for (;;) {
      int arrived = 0;
      MPI_Iprobe(0, kRunTag, MPI_COMM_WORLD, &arrived, MPI_STATUS_IGNORE);
      if (!arrived) {
        std::this_thread::sleep_for(std::chrono::microseconds(200));
        continue;
      }
      long number = 0;
      MPI_Recv(&number, 1, MPI_LONG, 0, kRunTag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      if (number < 0) return;
      const std::string text = run(number);
      MPI_Send(text.data(), static_cast<int>(text.size()), MPI_CHAR, 0, kResultTag, MPI_COMM_WORLD);
    }
  }

 private:
  int rank_ = 0, size_ = 1;
};

}  // namespace
}  // namespace sylva::experiment

extern "C" SYLVA_PLUGIN_EXPORT sylva::experiment::MpiSession* sylva_mpi_session() {
  return new sylva::experiment::Session();
}
