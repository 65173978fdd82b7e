// The table `prism sweep` writes and the previewer reads: its CSV reads back
// exactly what was written (infinite PSNR and rows without antialiasing
// included), finds its columns by name, and says where a malformed file is
// wrong; the Pareto front and the look-ups, on hand-made rows.
#include "core/sweep/sweep_table.h"

#include <gtest/gtest.h>

#include <limits>
#include <string>

namespace prism {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

SweepRow row(double cpu, double psnr, SweepSetting setting = {}) {
  SweepRow r;
  r.setting = setting;
  r.cpuSeconds = cpu;
  r.error.psnr = psnr;
  return r;
}

SweepSetting aa(int depth, double thresh, bool jitter = false, double bailout = 0.0) {
  return {
      .antialias = true, .thresh = thresh, .depth = depth, .jitter = jitter, .bailout = bailout};
}

SweepSetting noAa(int depth, double bailout = 0.0) {
  return {.antialias = false, .depth = depth, .bailout = bailout};
}

// Every field of a row, so that a mismatch says which.
void expectSameRow(const SweepRow& got, const SweepRow& want) {
  EXPECT_EQ(got.setting, want.setting);
  EXPECT_EQ(got.cpuSeconds, want.cpuSeconds);
  EXPECT_EQ(got.wallSeconds, want.wallSeconds);
  EXPECT_EQ(got.rays.eye, want.rays.eye);
  EXPECT_EQ(got.rays.shadow, want.rays.shadow);
  EXPECT_EQ(got.rays.reflected, want.rays.reflected);
  EXPECT_EQ(got.rays.transmitted, want.rays.transmitted);
  EXPECT_EQ(got.rays.pilot, want.rays.pilot);
  EXPECT_EQ(got.supersampled, want.supersampled);
  EXPECT_EQ(got.error.rmse, want.error.rmse);
  EXPECT_EQ(got.error.psnr, want.error.psnr);
  EXPECT_EQ(got.error.worstLevels, want.error.worstLevels);
  EXPECT_EQ(got.error.worstX, want.error.worstX);
  EXPECT_EQ(got.error.worstY, want.error.worstY);
  EXPECT_EQ(got.error.over2, want.error.over2);
  EXPECT_EQ(got.pareto, want.pareto);
}

std::vector<SweepRow> sampleRows() {
  SweepRow a = row(1.0 / 3.0, 41.234567890123456, aa(5, 0.1, true, 0.5));
  a.wallSeconds = 0.1234567890123;
  a.rays = {.eye = 4.0625, .shadow = 7.1, .reflected = 1e-300, .transmitted = 0.3, .pilot = 0.7};
  a.supersampled = 0.123;
  a.error = {.rmse = 2.5e-7,
             .psnr = 41.234567890123456,
             .worstLevels = 17,
             .worstX = 3,
             .worstY = 159,
             .over2 = 0.001};
  a.pareto = true;
  SweepRow exact = row(12.75, kInf, aa(8, 0.0)); // the reference's own setting
  exact.pareto = true;
  SweepRow plain = row(0.02, 25.5, noAa(3, 2.0));
  plain.rays.eye = 1.0;
  plain.error.worstLevels = 255;
  return {a, exact, plain};
}

TEST(SweepSettingOptions, ShortestNumbers) {
  EXPECT_EQ(settingOptions(aa(5, 0.1)), "--depth 5 --thresh 0.1");
  EXPECT_EQ(settingOptions(aa(5, 0.1, true, 0.5)), "--depth 5 --thresh 0.1 --jitter --bailout 0.5");
  EXPECT_EQ(settingOptions(aa(8, 0.0)), "--depth 8 --thresh 0");
  EXPECT_EQ(settingOptions(aa(2, 1.0, false, 2.0)), "--depth 2 --thresh 1 --bailout 2");
  EXPECT_EQ(settingOptions(noAa(3)), "--depth 3 --no-aa");
  // Threshold and jitter do not apply without antialiasing.
  EXPECT_EQ(settingOptions(
                {.antialias = false, .thresh = 0.3, .depth = 1, .jitter = true, .bailout = 0.5}),
            "--depth 1 --no-aa --bailout 0.5");
}

TEST(SweepCsv, RoundTripsEveryFieldExactly) {
  const std::vector<SweepRow> rows = sampleRows();
  const std::string text = formatSweepCsv(rows);
  EXPECT_EQ(text.substr(0, text.find('\n')),
            "antialias,thresh,depth,jitter,bailout,options,cpu_s,wall_s,eye_rpp,shadow_rpp,"
            "reflected_rpp,transmitted_rpp,pilot_rpp,total_rpp,supersampled,rmse,psnr_db,"
            "worst_levels,worst_x,worst_y,over2,pareto");
  // The infinite PSNR is "inf"; a row without antialiasing has no threshold.
  EXPECT_NE(text.find(",inf,"), std::string::npos) << text;
  EXPECT_NE(text.find("\n0,,3,0,2,--depth 3 --no-aa --bailout 2,0.02,"), std::string::npos) << text;
  EXPECT_NE(text.find(",--depth 5 --thresh 0.1 --jitter --bailout 0.5,"), std::string::npos);
  const std::vector<SweepRow> back = parseSweepCsv(text);
  ASSERT_EQ(back.size(), rows.size());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    SCOPED_TRACE(i);
    expectSameRow(back[i], rows[i]);
  }
  EXPECT_EQ(formatSweepCsv(back), text);
  // An empty table is its header.
  EXPECT_TRUE(parseSweepCsv(formatSweepCsv({})).empty());
}

TEST(SweepCsv, ToleratesCrlfAndAMissingOrExtraTrailingNewline) {
  const std::vector<SweepRow> rows = sampleRows();
  std::string text = formatSweepCsv(rows);
  std::string crlf;
  for (char c : text)
    crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
  EXPECT_EQ(parseSweepCsv(crlf).size(), 3u);
  EXPECT_EQ(parseSweepCsv(text.substr(0, text.size() - 1)).size(), 3u);
  EXPECT_EQ(parseSweepCsv(text + "\n\r\n").size(), 3u);
  EXPECT_EQ(parseSweepCsv("\xEF\xBB\xBF" + text).size(), 3u); // a byte order mark
}

// Splits a CSV text into lines of fields.
std::vector<std::vector<std::string>> cells(const std::string& text) {
  std::vector<std::vector<std::string>> table;
  std::size_t start = 0;
  while (start < text.size()) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    const std::string line = text.substr(start, end - start);
    start = end + 1;
    std::vector<std::string> fields;
    std::size_t from = 0;
    for (std::size_t comma; (comma = line.find(',', from)) != std::string::npos; from = comma + 1)
      fields.push_back(line.substr(from, comma - from));
    fields.push_back(line.substr(from));
    table.push_back(fields);
  }
  return table;
}

std::string joined(const std::vector<std::vector<std::string>>& table) {
  std::string text;
  for (const auto& fields : table) {
    for (std::size_t i = 0; i < fields.size(); ++i)
      text += (i ? "," : "") + fields[i];
    text += "\n";
  }
  return text;
}

TEST(SweepCsv, FindsColumnsByNameIgnoringUnknownOnes) {
  const std::vector<SweepRow> rows = sampleRows();
  auto table = cells(formatSweepCsv(rows));
  // Columns in reverse order, and a column of a later version in the middle.
  for (auto& fields : table) {
    std::reverse(fields.begin(), fields.end());
    fields.insert(fields.begin() + 5, &fields == &table.front() ? "gpu_s" : "9.5");
  }
  std::vector<SweepRow> back = parseSweepCsv(joined(table));
  ASSERT_EQ(back.size(), rows.size());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    SCOPED_TRACE(i);
    expectSameRow(back[i], rows[i]);
  }
  // The derived columns (options, total_rpp) may be left out.
  table = cells(formatSweepCsv(rows));
  for (auto& fields : table) {
    fields.erase(fields.begin() + 13); // total_rpp
    fields.erase(fields.begin() + 5);  // options
  }
  back = parseSweepCsv(joined(table));
  ASSERT_EQ(back.size(), rows.size());
  expectSameRow(back[0], rows[0]);
}

std::string errorOf(const std::string& text) {
  try {
    parseSweepCsv(text);
  } catch (const SweepCsvError& error) {
    return error.what();
  }
  return "(parsed)";
}

TEST(SweepCsv, MalformedFilesSayWhereByLineAndColumn) {
  const std::string good = formatSweepCsv(sampleRows());
  const std::size_t headerEnd = good.find('\n') + 1;
  const std::string header = good.substr(0, headerEnd);
  const std::string row1 = good.substr(headerEnd, good.find('\n', headerEnd) + 1 - headerEnd);
  auto with = [&](std::size_t column, const std::string& value) {
    auto table = cells(row1.substr(0, row1.size() - 1));
    table[0][column] = value;
    return header + row1 + joined(table);
  };
  // The row is line 3; the field's first character is the column.
  const std::string line3 = joined(cells(row1.substr(0, row1.size() - 1)));
  const std::size_t cpuColumn = [&] {
    std::size_t at = 0;
    for (int commas = 0; commas < 6; ++commas)
      at = line3.find(',', at) + 1;
    return at + 1;
  }();
  EXPECT_EQ(errorOf(with(6, "fast")),
            "3:" + std::to_string(cpuColumn) + ": cpu_s: expected a number, got 'fast'");
  EXPECT_EQ(errorOf(with(6, "")),
            "3:" + std::to_string(cpuColumn) + ": cpu_s: expected a number, got ''");
  const std::string cpuAt = "3:" + std::to_string(cpuColumn) + ": ";
  EXPECT_EQ(errorOf(with(6, "1.5s")), cpuAt + "cpu_s: expected a number, got '1.5s'");
  EXPECT_EQ(errorOf(with(6, "nan")), cpuAt + "cpu_s: expected a number, got 'nan'");
  EXPECT_EQ(errorOf(with(6, "inf")), cpuAt + "cpu_s: expected a number, got 'inf'");
  EXPECT_EQ(errorOf(with(6, "-1")), cpuAt + "cpu_s: negative, got -1");
  EXPECT_EQ(errorOf(with(0, "yes")), "3:1: antialias: expected 0 or 1, got 'yes'");
  EXPECT_EQ(errorOf(with(2, "0")),
            "3:" + std::to_string(line3.find(",5,") + 2) + ": depth: must be at least 1, got 0");
  EXPECT_EQ(errorOf(with(2, "2.5")), "3:" + std::to_string(line3.find(",5,") + 2) +
                                         ": depth: expected an integer, got '2.5'");
  EXPECT_NE(errorOf(with(2, "99999999999999999999")).find("depth: expected an integer"),
            std::string::npos);
  EXPECT_NE(errorOf(with(16, "-inf")).find("psnr_db: expected a number, got '-inf'"),
            std::string::npos);
  // An antialiased row needs its threshold.
  EXPECT_EQ(errorOf(with(1, "")), "3:3: thresh: expected a number, got ''");

  // Too many fields: where the first extra one starts; too few: the line's end.
  EXPECT_EQ(errorOf(header + row1.substr(0, row1.size() - 1) + ",extra\n"),
            "2:" + std::to_string(row1.size() + 1) +
                ": expected 22 fields as in the header, got 23");
  EXPECT_EQ(errorOf(header + "1,0.1,5\n"), "2:8: expected 22 fields as in the header, got 3");
  // A header without a column the rows need, or with one twice.
  EXPECT_EQ(errorOf("antialias,thresh\n"), "1:17: the header has no column 'depth'");
  EXPECT_EQ(errorOf(header.substr(10)),
            "1:" + std::to_string(header.size() - 10) + ": the header has no column 'antialias'");
  EXPECT_EQ(errorOf(header.substr(0, header.size() - 1) + ",depth\n"),
            "1:" + std::to_string(header.size() + 1) + ": column 'depth' appears twice");
  EXPECT_EQ(errorOf(""), "1:1: no header line: the file is empty");
  EXPECT_EQ(errorOf("\r\n\n"), "1:1: no header line: the file is empty");
  // Blank lines count: the error's line is the file's.
  EXPECT_EQ(errorOf(header + "\n\n" + "x\n").substr(0, 2), "4:");
  // Garbage is shown shortened, without control characters.
  EXPECT_EQ(errorOf(with(0, std::string(100, 'z') + "\x01")),
            "3:1: antialias: expected 0 or 1, got '" + std::string(40, 'z') + "...'");
}

TEST(SweepCsv, GarbageNeverCrashes) {
  const std::string good = formatSweepCsv(sampleRows());
  unsigned state = 12345;
  const auto next = [&] { return state = state * 1103515245u + 12345u; };
  for (int trial = 0; trial < 3000; ++trial) {
    std::string text = good;
    const int edits = 1 + int(next() % 8);
    for (int e = 0; e < edits; ++e) {
      const std::size_t at = next() % text.size();
      switch (next() % 3) {
      case 0: text[at] = char(next() % 256); break;
      case 1: text.erase(at, next() % 20); break;
      default: text.insert(at, std::string(1 + next() % 3, ",\n\r0.e-9"[next() % 8]));
      }
      if (text.empty()) text = ",";
    }
    try {
      const std::vector<SweepRow> rows = parseSweepCsv(text);
      EXPECT_LE(rows.size(), 10u);
    } catch (const SweepCsvError& error) {
      const std::string what = error.what();
      EXPECT_NE(what.find(':'), std::string::npos) << what;
    }
  }
}

TEST(SweepParetoFront, MarksWhatNothingBeats) {
  std::vector<SweepRow> rows{
      row(1.0, 30.0), // cheapest: on the front
      row(2.0, 29.0), // dearer and worse than row 0: dominated
      row(2.0, 35.0), // on the front
      row(3.0, 35.0), // as good as row 2 but dearer: dominated
      row(4.0, kInf), // exact: on the front
      row(5.0, 40.0), // dearer and worse than row 4: dominated
      row(0.5, 20.0), // cheapest of all: on the front
  };
  rows[1].pareto = true; // whatever the rows said before
  markParetoFront(rows);
  const std::vector<bool> want{true, false, true, false, true, false, true};
  for (std::size_t i = 0; i < rows.size(); ++i)
    EXPECT_EQ(rows[i].pareto, want[i]) << "row " << i;
}

TEST(SweepParetoFront, EqualRowsAreBothOnTheFront) {
  std::vector<SweepRow> rows{row(1.0, 30.0), row(2.0, 35.0), row(2.0, 35.0), row(2.0, 34.0),
                             row(4.0, kInf), row(4.0, kInf), row(1.0, 30.0)};
  markParetoFront(rows);
  const std::vector<bool> want{true, true, true, false, true, true, true};
  for (std::size_t i = 0; i < rows.size(); ++i)
    EXPECT_EQ(rows[i].pareto, want[i]) << "row " << i;

  // One row, no rows, and a row without a measure (never on the front, beats nothing).
  std::vector<SweepRow> one{row(7.0, 12.0)};
  markParetoFront(one);
  EXPECT_TRUE(one[0].pareto);
  std::vector<SweepRow> none;
  markParetoFront(none);
  std::vector<SweepRow> nan{row(0.1, std::nan("")), row(1.0, 20.0)};
  markParetoFront(nan);
  EXPECT_FALSE(nan[0].pareto);
  EXPECT_TRUE(nan[1].pareto);
}

TEST(SweepLookups, FindSettingComparesNumbersWithinATolerance) {
  const std::vector<SweepRow> rows{row(1, 30, aa(5, 0.1)), row(2, 31, aa(5, 0.1, true)),
                                   row(3, 32, aa(5, 0.1, false, 0.5)), row(4, 33, noAa(5)),
                                   row(5, 34, aa(5, 0.3))};
  EXPECT_EQ(findSetting(rows, aa(5, 0.1)), &rows[0]);
  EXPECT_EQ(findSetting(rows, aa(5, 0.1 + 5e-10)), &rows[0]);
  EXPECT_EQ(findSetting(rows, aa(5, 0.1 + 1e-8)), nullptr);
  EXPECT_EQ(findSetting(rows, aa(5, float(0.3))), nullptr) << "a float's 0.3 is 1e-8 off";
  EXPECT_EQ(findSetting(rows, aa(5, 0.1, true)), &rows[1]);
  EXPECT_EQ(findSetting(rows, aa(5, 0.1, false, 0.5 - 1e-10)), &rows[2]);
  EXPECT_EQ(findSetting(rows, aa(5, 0.1, false, 2.0)), nullptr);
  EXPECT_EQ(findSetting(rows, aa(4, 0.1)), nullptr);
  // Without antialiasing, threshold and jitter do not matter.
  EXPECT_EQ(findSetting(rows, noAa(5)), &rows[3]);
  EXPECT_EQ(findSetting(rows, {.antialias = false, .thresh = 0.9, .depth = 5, .jitter = true}),
            &rows[3]);
  EXPECT_EQ(findSetting(rows, noAa(5, 0.5)), nullptr);
  EXPECT_EQ(findSetting({}, aa(5, 0.1)), nullptr);
}

TEST(SweepLookups, BestWithinCostIsTheMostAccurateAffordableFrontRow) {
  std::vector<SweepRow> rows{row(0.5, 20.0, noAa(1)),          row(1.0, 30.0, aa(1, 0.3)),
                             row(2.0, 29.0, aa(2, 0.3)),       row(2.0, 35.0, aa(3, 0.1)),
                             row(2.0, 35.0, aa(3, 0.1, true)), row(4.0, kInf, aa(8, 0.0))};
  markParetoFront(rows);
  EXPECT_EQ(bestWithinCost(rows, 0.4), nullptr);
  EXPECT_EQ(bestWithinCost(rows, 0.5), &rows[0]);
  EXPECT_EQ(bestWithinCost(rows, 1.99), &rows[1]);
  EXPECT_EQ(bestWithinCost(rows, 2.0), &rows[3]) << "of equal rows, the first";
  EXPECT_EQ(bestWithinCost(rows, 3.9), &rows[3]);
  EXPECT_EQ(bestWithinCost(rows, 4.0), &rows[5]);
  EXPECT_EQ(bestWithinCost(rows, kInf), &rows[5]);
  EXPECT_EQ(bestWithinCost(rows, std::nan("")), nullptr);
  // Only rows marked on the front count.
  for (SweepRow& r : rows)
    r.pareto = false;
  EXPECT_EQ(bestWithinCost(rows, 10.0), nullptr);
}

} // namespace
} // namespace prism
