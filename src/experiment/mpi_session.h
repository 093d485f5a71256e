// An experiment under MPI (`mpirun -n N sylva experiment PLAN`, `srun`):
// rank 0 reads the plan, compiles, schedules every run over its own
// processes and the other ranks, and writes the table; the other ranks run
// what it sends them. MPI itself lives in a plugin (libsylva_mpi.so) opened
// only under an MPI launcher, so that a run that is not one never loads it.
#pragma once

#include <functional>
#include <memory>
#include <string>

namespace sylva::experiment {

class Workers;

class MpiSession {
 public:
  virtual ~MpiSession() = default;
  virtual int rank() const = 0;
  virtual int size() const = 0;
  // Rank 0 tells the others whether the experiment goes ahead (false: the
  // plan or the model is wrong, rank 0 says why); every rank returns it.
  virtual bool agree(bool go) = 0;
  // Rank 0: sends run `number` to `rank` (-1: no more runs), and takes a
  // result that has arrived, if one has: which rank sent it, and its text.
  virtual void send_run(int rank, long number) = 0;
  virtual bool poll_result(int& rank, std::string& text) = 0;
  // The other ranks: run each number rank 0 sends with `run` (a result as
  // encode_result() writes it) until rank 0 has no more.
  virtual void serve(const std::function<std::string(long)>& run) = 0;
};

// Rank 0's view of the other ranks: workers taking one run at a time each.
std::unique_ptr<Workers> other_ranks(MpiSession& session);

// Whether this process was started by an MPI launcher (OpenMPI's mpirun, a
// PMI/PMIx launcher such as Slurm's srun with MPI).
bool launched_by_mpi();

// Opens the MPI plugin and initialises MPI. Throws ModelError when the
// plugin or MPI cannot be had.
std::unique_ptr<MpiSession> open_mpi_session();

}  // namespace sylva::experiment

// The MPI plugin's factory.
extern "C" __attribute__((visibility("default"))) sylva::experiment::MpiSession* sylva_mpi_session();
