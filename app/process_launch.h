// Joining the process group of an MPI job (docs/distributed.md). `prism` does
// not link MPI: when an MPI launcher (mpirun, mpiexec, srun with PMI) started
// it, it loads libprism_mpi.so and initialises MPI through it; otherwise it
// runs as the one process of its job and pays nothing for MPI.
#pragma once

#include "core/render/process_group.h"

#include <memory>
#include <optional>
#include <string>

namespace prism {

// True when the environment says an MPI launcher started this process
// (Open MPI's OMPI_COMM_WORLD_SIZE, PMI's PMI_SIZE, PMIx's PMIX_RANK).
bool startedByMpiLauncher();

// When Slurm's srun started this process as one of several tasks but with no
// MPI process manager (no --mpi=pmix): every task would do the whole job and
// write the same files, so render and sweep refuse, saying why.
std::optional<std::string> srunWithoutMpiProblem();

// The job's process group: null, with `error` saying why, when the MPI module
// is missing (a build without MPI) or MPI does not start.
std::unique_ptr<ProcessGroup> joinProcessGroup(std::string& error);

// While alive, this process's std::cerr goes nowhere: ranks other than 0
// keep quiet (rank 0 speaks for the job); their failures reach rank 0
// through ProcessGroup::firstFailure, or stderr directly where the job ends.
class QuietStderr {
public:
  explicit QuietStderr(bool quiet);
  ~QuietStderr();
  QuietStderr(const QuietStderr&) = delete;
  QuietStderr& operator=(const QuietStderr&) = delete;
  // What was written to std::cerr meanwhile.
  std::string text() const;

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Where one process of a job could fail alone (a scene file it cannot read,
// a folder rank 0 cannot write), the processes agree before going on, so
// that none waits for one that has left. Collective under MPI: true when
// `ok` on every process; otherwise rank 0 prints the first failing rank's
// captured stderr (its own it printed already). Without a group: `ok`.
bool agreeOnSuccess(ProcessGroup* group, bool ok, const QuietStderr& quiet);

} // namespace prism
