// The C entry of libprism_mpi.so, the module that holds every use of MPI
// (docs/distributed.md). The program loads it only when an MPI launcher
// started it (app/process_launch.h).
#pragma once

#include <cstddef>

namespace prism {
class ProcessGroup;
}

extern "C" {
// Initialises MPI (MPI_THREAD_FUNNELED: only the calling thread makes MPI
// calls) and returns the job's process group, to be deleted (which finalises
// MPI) by the caller; or null with the reason in `error`.
using PrismMpiStartFn = prism::ProcessGroup* (*)(char* error, std::size_t errorSize);
}
