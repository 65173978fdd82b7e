#include "sweep_distributed.h"

#include "core/sweep/sweep_table.h"

#include <span>
#include <stdexcept>
#include <string>

namespace prism {

DistributedSweep runSweepOverGroup(ProcessGroup& group, const Scene& scene, const Accel& accel,
                                   const SweepGrid& grid, const ReferencePicture& reference,
                                   Executor& executor,
                                   const ProcessGroup::DistributeProgress& progress) {
  const std::vector<SweepSetting> settings = grid.settings();
  // An item is a whole group, not a setting: its settings share their pass 1
  // (sweep_runner.h), which a setting handed out alone would trace again on
  // every process that got one of them.
  const auto groups = passOneGroups(settings);
  const int count = int(groups.size());
  // Deepest groups first: they cost the most (the grid runs them last), and
  // handing the longest items out first leaves the short ones to even out
  // the end of the job.
  auto groupOf = [&](int item) { return groups[std::size_t(count - 1 - item)]; };

  DistributedSweep result;
  // Each result is the group's rows as sweep.csv text (formatSweepCsv): every
  // field of a row, numbers in their shortest exact form and an infinite
  // PSNR as "inf", so the rows rebuilt on rank 0 are the rows rendered.
  const std::vector<std::string> texts = group.distribute(
      count,
      [&](int item) {
        const auto [first, last] = groupOf(item);
        ++result.groupsHere;
        return formatSweepCsv(runSweepGroup(scene, accel,
                                            std::span(settings).subspan(first, last - first),
                                            reference, executor, {}, grid.minTimedSeconds));
      },
      progress);
  if (texts.empty()) return result; // not rank 0

  result.rows.resize(settings.size());
  for (int item = 0; item < count; ++item) {
    const auto [first, last] = groupOf(item);
    const std::vector<SweepRow> rows = parseSweepCsv(texts[std::size_t(item)]);
    if (rows.size() != last - first)
      throw std::logic_error("distributed sweep: a group came back with " +
                             std::to_string(rows.size()) + " rows instead of " +
                             std::to_string(last - first));
    for (std::size_t i = 0; i < rows.size(); ++i) {
      SweepRow& row = result.rows[first + i];
      row = rows[i];
      if (settingOptions(row.setting) != settingOptions(settings[first + i]))
        throw std::logic_error("distributed sweep: a group came back with the rows of " +
                               settingOptions(row.setting) + " for " +
                               settingOptions(settings[first + i]));
      // As the grid made it: a --no-aa setting's unused threshold and jitter
      // are not in the table.
      row.setting = settings[first + i];
    }
  }
  return result;
}

} // namespace prism
