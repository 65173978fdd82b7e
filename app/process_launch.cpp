#include "process_launch.h"

#include "core/system/shared_module.h"
#include "mpi/mpi_module.h"

#include <dlfcn.h>

#include <cstdlib>
#include <iostream>
#include <sstream>

namespace prism {

bool startedByMpiLauncher() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK"})
    if (std::getenv(name) != nullptr) return true;
  return false;
}

std::optional<std::string> srunWithoutMpiProblem() {
  const char* tasks = std::getenv("SLURM_STEP_NUM_TASKS");
  if (startedByMpiLauncher() || !tasks || std::atoi(tasks) <= 1) return std::nullopt;
  return std::string("started by srun as one of ") + tasks +
         " tasks without an MPI process manager: every task would do the whole job "
         "and write the same files; run `srun --mpi=pmix ...` or `mpirun ...` inside the "
         "allocation "
         "(docs/distributed.md)";
}

std::unique_ptr<ProcessGroup> joinProcessGroup(std::string& error) {
  const SharedModule module = loadSharedModule("libprism_mpi.so");
  if (!module.handle) {
    error = "started by an MPI launcher, but the MPI module is missing (a build without MPI?): " +
            module.error;
    return nullptr;
  }
  const auto start = reinterpret_cast<PrismMpiStartFn>(dlsym(module.handle, "prism_mpi_start"));
  if (!start) {
    error = "the MPI module has no entry 'prism_mpi_start'";
    return nullptr;
  }
  char message[512] = "";
  std::unique_ptr<ProcessGroup> group(start(message, sizeof message));
  if (!group) error = std::string("MPI did not start: ") + message;
  return group;
}

struct QuietStderr::Impl {
  std::ostringstream captured;
  std::streambuf* saved = nullptr;
};

QuietStderr::QuietStderr(bool quiet) : impl_(std::make_unique<Impl>()) {
  if (quiet) impl_->saved = std::cerr.rdbuf(impl_->captured.rdbuf());
}

QuietStderr::~QuietStderr() {
  if (impl_->saved) std::cerr.rdbuf(impl_->saved);
}

std::string QuietStderr::text() const { return impl_->captured.str(); }

bool agreeOnSuccess(ProcessGroup* group, bool ok, const QuietStderr& quiet) {
  if (!group) return ok;
  const std::optional<ProcessGroup::Failure> failure = group->firstFailure(ok, quiet.text());
  if (failure && group->rank() == 0 && failure->rank != 0)
    std::cerr << "prism: error: on rank " << failure->rank << ":\n" << failure->message;
  return !failure;
}

} // namespace prism
