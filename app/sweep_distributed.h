// The settings of `prism sweep` spread over the processes of an MPI job
// (docs/choosing-settings.md#sweeps-over-mpi): each process renders whole
// groups of settings that share a pass 1 and measures them against its own
// copy of the reference; rank 0 gathers the rows.
#pragma once

#include "core/accel/accel.h"
#include "core/render/executor.h"
#include "core/render/process_group.h"
#include "core/sweep/reference.h"
#include "core/sweep/sweep_runner.h"

#include <vector>

namespace prism {

struct DistributedSweep {
  std::vector<SweepRow> rows; // on rank 0, every setting's in SweepGrid::settings() order
  int groupsHere = 0;         // the groups this process rendered
};

// Collective: every process of `group` calls it with the same scene, grid
// and reference. Each group of settings of one depth and bailout (what
// runSweepGroup renders) is one item of ProcessGroup::distribute, rendered
// on `executor` (this process's threads). `progress(done, total)`, on rank 0,
// hears how many groups the job has finished. Rows as runSweep's: the
// Pareto front not yet marked; empty on the other ranks.
DistributedSweep runSweepOverGroup(ProcessGroup& group, const Scene& scene, const Accel& accel,
                                   const SweepGrid& grid, const ReferencePicture& reference,
                                   Executor& executor,
                                   const ProcessGroup::DistributeProgress& progress = {});

} // namespace prism
