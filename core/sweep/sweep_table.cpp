#include "sweep_table.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numeric>
#include <optional>

namespace prism {

namespace {

// The columns, in the order formatSweepCsv writes them.
enum Column {
  Antialias,
  Thresh,
  Depth,
  Jitter,
  Bailout,
  Options,
  CpuS,
  WallS,
  EyeRpp,
  ShadowRpp,
  ReflectedRpp,
  TransmittedRpp,
  PilotRpp,
  TotalRpp,
  Supersampled,
  Rmse,
  PsnrDb,
  WorstLevels,
  WorstX,
  WorstY,
  Over2,
  Pareto,
  kColumns
};

constexpr std::array<std::string_view, kColumns> kNames{
    "antialias", "thresh",    "depth",        "jitter",     "bailout",       "options",
    "cpu_s",     "wall_s",    "eye_rpp",      "shadow_rpp", "reflected_rpp", "transmitted_rpp",
    "pilot_rpp", "total_rpp", "supersampled", "rmse",       "psnr_db",       "worst_levels",
    "worst_x",   "worst_y",   "over2",        "pareto"};

// Derived from the others (settingOptions, RaysPerPixel::total): written for
// people, not needed to read a row back.
bool derived(int column) { return column == Options || column == TotalRpp; }

// Shortest text that reads back as exactly `value`.
std::string number(double value) {
  char text[64];
  const auto [end, error] = std::to_chars(text, text + sizeof text, value);
  return error == std::errc() ? std::string(text, end) : std::string("nan");
}

std::string number(int value) { return std::to_string(value); }

bool sameWithin(double a, double b) { return std::abs(a - b) <= 1e-9; }

// The error text shows at most this much of a field.
std::string shown(std::string_view field) {
  constexpr std::size_t kShown = 40;
  std::string text(field.substr(0, kShown));
  if (field.size() > kShown) text += "...";
  for (char& c : text)
    if ((unsigned char)c < 0x20 || (unsigned char)c == 0x7f) c = '?';
  return text;
}

struct Field {
  std::string_view text;
  int column = 1; // 1-based character column of its first character
};

class Reader {
public:
  explicit Reader(int line) : line_(line) {}

  [[noreturn]] void fail(int column, const std::string& what) const {
    throw SweepCsvError(std::to_string(line_) + ":" + std::to_string(column) + ": " + what);
  }

  double real(const Field& f, std::string_view name, bool infinityAllowed = false) const {
    double value = 0.0;
    const char* first = f.text.data();
    const char* last = first + f.text.size();
    if (infinityAllowed && f.text == "inf") return std::numeric_limits<double>::infinity();
    const auto [end, error] = std::from_chars(first, last, value);
    if (f.text.empty() || error != std::errc() || end != last || !std::isfinite(value))
      fail(f.column, std::string(name) + ": expected a number, got '" + shown(f.text) + "'");
    return value;
  }

  double nonNegative(const Field& f, std::string_view name) const {
    const double value = real(f, name);
    if (value < 0.0) fail(f.column, std::string(name) + ": negative, got " + shown(f.text));
    return value;
  }

  int integer(const Field& f, std::string_view name, int min) const {
    int value = 0;
    const char* first = f.text.data();
    const char* last = first + f.text.size();
    const auto [end, error] = std::from_chars(first, last, value);
    if (f.text.empty() || error != std::errc() || end != last)
      fail(f.column, std::string(name) + ": expected an integer, got '" + shown(f.text) + "'");
    if (value < min)
      fail(f.column, std::string(name) + ": must be at least " + std::to_string(min) + ", got " +
                         shown(f.text));
    return value;
  }

  bool flag(const Field& f, std::string_view name) const {
    if (f.text == "0") return false;
    if (f.text == "1") return true;
    fail(f.column, std::string(name) + ": expected 0 or 1, got '" + shown(f.text) + "'");
  }

private:
  int line_;
};

std::vector<Field> splitFields(std::string_view line) {
  std::vector<Field> fields;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = line.find(',', start);
    const std::size_t end = comma == std::string_view::npos ? line.size() : comma;
    fields.push_back({line.substr(start, end - start), int(start) + 1});
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  return fields;
}

} // namespace

std::string settingOptions(const SweepSetting& s) {
  std::string text = "--depth " + number(s.depth);
  if (s.antialias) {
    text += " --thresh " + number(s.thresh);
    if (s.jitter) text += " --jitter";
  } else {
    text += " --no-aa";
  }
  if (s.bailout != 0.0) text += " --bailout " + number(s.bailout);
  return text;
}

// Sorted by cost, then by PSNR from the best: a row is on the front when its
// PSNR is the best of its cost and better than that of every cheaper row.
// O(n log n), so that no table, however long, takes long.
void markParetoFront(std::vector<SweepRow>& rows) {
  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    rows[i].pareto = false;
    // A row without a cost or an accuracy is not comparable: never on the front, and
    // it beats nothing.
    if (!std::isnan(rows[i].cpuSeconds) && !std::isnan(rows[i].error.psnr)) order.push_back(i);
  }
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    if (rows[a].cpuSeconds != rows[b].cpuSeconds) return rows[a].cpuSeconds < rows[b].cpuSeconds;
    return rows[a].error.psnr > rows[b].error.psnr;
  });
  bool anyCheaper = false;
  double bestCheaper = 0.0; // the best PSNR of the rows cheaper than the current group
  for (std::size_t g = 0; g < order.size();) {
    const double cost = rows[order[g]].cpuSeconds;
    const double best = rows[order[g]].error.psnr; // of this cost
    std::size_t end = g;
    while (end < order.size() && rows[order[end]].cpuSeconds == cost)
      ++end;
    if (!anyCheaper || best > bestCheaper) {
      for (std::size_t k = g; k < end && rows[order[k]].error.psnr == best; ++k)
        rows[order[k]].pareto = true; // equal rows are all on the front
    }
    if (!anyCheaper || best > bestCheaper) bestCheaper = best;
    anyCheaper = true;
    g = end;
  }
}

std::string formatSweepCsv(const std::vector<SweepRow>& rows) {
  std::string text;
  for (std::size_t c = 0; c < kNames.size(); ++c)
    text += std::string(c ? "," : "") + std::string(kNames[c]);
  text += "\n";
  for (const SweepRow& r : rows) {
    const SweepSetting& s = r.setting;
    const std::array<std::string, kColumns> fields{
        s.antialias ? "1" : "0",
        s.antialias ? number(s.thresh) : "",
        number(s.depth),
        s.antialias && s.jitter ? "1" : "0",
        number(s.bailout),
        settingOptions(s),
        number(r.cpuSeconds),
        number(r.wallSeconds),
        number(r.rays.eye),
        number(r.rays.shadow),
        number(r.rays.reflected),
        number(r.rays.transmitted),
        number(r.rays.pilot),
        number(r.rays.total()),
        number(r.supersampled),
        number(r.error.rmse),
        number(r.error.psnr), // to_chars writes +infinity as "inf"
        number(r.error.worstLevels),
        number(r.error.worstX),
        number(r.error.worstY),
        number(r.error.over2),
        r.pareto ? "1" : "0",
    };
    for (std::size_t c = 0; c < fields.size(); ++c)
      text += (c ? "," : "") + fields[c];
    text += "\n";
  }
  return text;
}

std::vector<SweepRow> parseSweepCsv(std::string_view text) {
  if (text.starts_with("\xEF\xBB\xBF")) text.remove_prefix(3); // a UTF-8 byte order mark
  std::vector<SweepRow> rows;
  std::array<int, kColumns> at; // field index of each column
  at.fill(-1);
  std::size_t fieldCount = 0;
  bool header = true;
  int lineNumber = 0;
  for (std::size_t start = 0; start < text.size();) {
    ++lineNumber;
    const std::size_t newline = text.find('\n', start);
    const std::size_t end = newline == std::string_view::npos ? text.size() : newline;
    std::string_view line = text.substr(start, end - start);
    start = end + 1;
    if (line.ends_with('\r')) line.remove_suffix(1);
    if (line.empty()) continue; // blank lines (a trailing newline among them)
    const Reader read(lineNumber);
    const std::vector<Field> fields = splitFields(line);

    if (header) {
      header = false;
      fieldCount = fields.size();
      for (std::size_t i = 0; i < fields.size(); ++i) {
        const auto name = std::find(kNames.begin(), kNames.end(), fields[i].text);
        if (name == kNames.end()) continue; // a column of a later version
        int& index = at[std::size_t(name - kNames.begin())];
        if (index >= 0)
          read.fail(fields[i].column, "column '" + std::string(fields[i].text) + "' appears twice");
        index = int(i);
      }
      for (std::size_t c = 0; c < kNames.size(); ++c)
        if (at[c] < 0 && !derived(int(c)))
          read.fail(int(line.size()) + 1,
                    "the header has no column '" + std::string(kNames[c]) + "'");
      continue;
    }

    if (fields.size() != fieldCount) {
      const int column =
          fields.size() > fieldCount ? fields[fieldCount].column : int(line.size()) + 1;
      read.fail(column, "expected " + std::to_string(fieldCount) +
                            " fields as in the header, got " + std::to_string(fields.size()));
    }
    const auto field = [&](Column c) -> const Field& { return fields[std::size_t(at[c])]; };
    const auto name = [](Column c) { return kNames[c]; };
    SweepRow r;
    SweepSetting& s = r.setting;
    s.antialias = read.flag(field(Antialias), name(Antialias));
    const bool jitter = read.flag(field(Jitter), name(Jitter));
    if (s.antialias) {
      s.thresh = read.nonNegative(field(Thresh), name(Thresh));
      s.jitter = jitter;
    } else if (!field(Thresh).text.empty()) { // does not apply: the setting keeps its default
      read.real(field(Thresh), name(Thresh));
    }
    s.depth = read.integer(field(Depth), name(Depth), 1);
    s.bailout = read.nonNegative(field(Bailout), name(Bailout));
    r.cpuSeconds = read.nonNegative(field(CpuS), name(CpuS));
    r.wallSeconds = read.nonNegative(field(WallS), name(WallS));
    r.rays.eye = read.nonNegative(field(EyeRpp), name(EyeRpp));
    r.rays.shadow = read.nonNegative(field(ShadowRpp), name(ShadowRpp));
    r.rays.reflected = read.nonNegative(field(ReflectedRpp), name(ReflectedRpp));
    r.rays.transmitted = read.nonNegative(field(TransmittedRpp), name(TransmittedRpp));
    r.rays.pilot = read.nonNegative(field(PilotRpp), name(PilotRpp));
    if (at[TotalRpp] >= 0) read.real(field(TotalRpp), name(TotalRpp));
    r.supersampled = read.nonNegative(field(Supersampled), name(Supersampled));
    r.error.rmse = read.nonNegative(field(Rmse), name(Rmse));
    r.error.psnr = read.real(field(PsnrDb), name(PsnrDb), true);
    r.error.worstLevels = read.integer(field(WorstLevels), name(WorstLevels), 0);
    r.error.worstX = read.integer(field(WorstX), name(WorstX), 0);
    r.error.worstY = read.integer(field(WorstY), name(WorstY), 0);
    r.error.over2 = read.nonNegative(field(Over2), name(Over2));
    r.pareto = read.flag(field(Pareto), name(Pareto));
    rows.push_back(r);
  }
  if (header) throw SweepCsvError("1:1: no header line: the file is empty");
  return rows;
}

const SweepRow* findSetting(const std::vector<SweepRow>& rows, const SweepSetting& setting) {
  for (const SweepRow& r : rows) {
    const SweepSetting& s = r.setting;
    if (s.antialias != setting.antialias || s.depth != setting.depth ||
        !sameWithin(s.bailout, setting.bailout))
      continue;
    // Without antialiasing the threshold and jitter do not apply.
    if (s.antialias && (s.jitter != setting.jitter || !sameWithin(s.thresh, setting.thresh)))
      continue;
    return &r;
  }
  return nullptr;
}

const SweepRow* bestWithinCost(const std::vector<SweepRow>& rows, double cpuSeconds) {
  const SweepRow* best = nullptr;
  for (const SweepRow& r : rows) {
    if (!r.pareto || !(r.cpuSeconds <= cpuSeconds)) continue;
    // The most accurate; of equally accurate ones, the cheapest (then the first).
    if (!best || r.error.psnr > best->error.psnr ||
        (r.error.psnr == best->error.psnr && r.cpuSeconds < best->cpuSeconds))
      best = &r;
  }
  return best;
}

} // namespace prism
