// The sweep table's reader (core/sweep/sweep_table.h), which the previewer runs
// on whatever file lies beside a scene as NAME.sweep.csv, on arbitrary text:
// it may reject the text (SweepCsvError) but never crash; what it accepts
// must write back (formatSweepCsv) to text that reads as the same rows, and
// the previewer's look-ups must run on it.
#include "core/sweep/sweep_table.h"
#include "fuzz/fuzz_check.h"

#include <cmath>
#include <cstdlib>

using namespace prism;

namespace {

bool same(double a, double b) { return a == b || (std::isnan(a) && std::isnan(b)); }

bool sameRow(const SweepRow& a, const SweepRow& b) {
  return a.setting == b.setting && same(a.cpuSeconds, b.cpuSeconds) &&
         same(a.wallSeconds, b.wallSeconds) && same(a.rays.eye, b.rays.eye) &&
         same(a.rays.shadow, b.rays.shadow) && same(a.rays.reflected, b.rays.reflected) &&
         same(a.rays.transmitted, b.rays.transmitted) && same(a.rays.pilot, b.rays.pilot) &&
         same(a.supersampled, b.supersampled) && same(a.error.rmse, b.error.rmse) &&
         same(a.error.psnr, b.error.psnr) && a.error.worstLevels == b.error.worstLevels &&
         a.error.worstX == b.error.worstX && a.error.worstY == b.error.worstY &&
         same(a.error.over2, b.error.over2) && a.pareto == b.pareto;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text = fuzz::asText(data, size);
  std::vector<SweepRow> rows;
  try {
    rows = parseSweepCsv(text);
  } catch (const SweepCsvError&) {
    return 0; // rejected with a message: fine
  }
  const std::vector<SweepRow> again = parseSweepCsv(formatSweepCsv(rows));
  if (again.size() != rows.size()) std::abort();
  for (std::size_t i = 0; i < rows.size(); ++i)
    if (!sameRow(rows[i], again[i])) std::abort();
  markParetoFront(rows);
  for (const SweepRow& row : rows) {
    if (findSetting(rows, row.setting) == nullptr) std::abort();
    (void)bestWithinCost(rows, row.cpuSeconds);
  }
  return 0;
}
