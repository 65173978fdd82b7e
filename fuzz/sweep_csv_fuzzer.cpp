// The sweep table's reader (core/sweep/sweep_table.h), which the previewer runs
// on whatever file lies beside a scene as NAME.sweep.csv, on arbitrary text:
// it may reject the text (SweepCsvError) but never crash; what it accepts
// must write back (formatSweepCsv) to text that reads as the same rows, and
// the previewer's look-ups must run on it.
#include "core/sweep/sweep_table.h"
#include "fuzz/fuzz_check.h"

#include <cstdlib>

using namespace prism;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text = fuzz::asText(data, size);
  std::vector<SweepRow> rows;
  try {
    rows = parseSweepCsv(text);
  } catch (const SweepCsvError&) {
    return 0; // rejected with a message: fine
  }
  const std::vector<SweepRow> again = parseSweepCsv(formatSweepCsv(rows));
  // The reader accepts no NaN, so rows compare with ==.
  if (again != rows) std::abort();
  markParetoFront(rows);
  for (const SweepRow& row : rows) {
    if (findSetting(rows, row.setting) == nullptr) std::abort();
    (void)bestWithinCost(rows, row.cpuSeconds);
  }
  return 0;
}
