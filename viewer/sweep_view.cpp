#include "sweep_view.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace prism {

namespace {

std::string psnrText(double psnr) {
  if (std::isinf(psnr) && psnr > 0.0) return "inf dB (the reference itself)";
  char text[48];
  std::snprintf(text, sizeof text, "%.2f dB", psnr);
  return text;
}

std::string secondsText(double seconds) {
  char text[48];
  std::snprintf(text, sizeof text, "%.3g s", seconds);
  return text;
}

std::string percentText(double share) {
  char text[48];
  std::snprintf(text, sizeof text, "%.2f%%", 100.0 * share);
  return text;
}

} // namespace

std::string sweepPathBeside(const std::string& scenePath) {
  const std::filesystem::path scene(scenePath);
  return (scene.parent_path() / (scene.stem().string() + ".sweep.csv")).string();
}

LoadedSweep loadSweep(const std::string& path, bool mustExist) {
  LoadedSweep sweep;
  std::error_code error;
  const bool exists = std::filesystem::exists(path, error);
  if (!exists && !mustExist) return sweep; // no sweep of this scene
  sweep.path = path;
  try {
    if (!exists) throw std::runtime_error("no such file");
    if (std::filesystem::is_directory(path, error)) throw std::runtime_error("a directory");
    const std::uintmax_t size = std::filesystem::file_size(path, error);
    if (!error && size > kMaxSweepBytes)
      throw std::runtime_error("too large for a sweep table (" + std::to_string(size) + " bytes)");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error("cannot read it");
    std::ostringstream text;
    text << in.rdbuf();
    if (in.bad()) throw std::runtime_error("cannot read it");
    sweep.rows = parseSweepCsv(text.str());
    markParetoFront(sweep.rows); // of the rows there are, whatever the file says
  } catch (const SweepCsvError& e) {
    sweep.rows.clear();
    sweep.error = path + ":" + e.what();
  } catch (const std::exception& e) { // the file, or out of memory
    sweep.rows.clear();
    sweep.error = path + ": " + e.what();
  }
  return sweep;
}

SweepSetting sweepSettingOf(const RenderSettings& s) {
  SweepSetting setting;
  setting.antialias = !s.noAa;
  setting.depth = s.maxDepth;
  setting.jitter = !s.noAa && s.jitter;
  setting.bailout = s.bailout;
  setting.thresh = s.thresh;
  const float asFloat = float(s.thresh);
  if (double(asFloat) == s.thresh) { // the slider's: read it as the decimal it shows
    char text[32];
    const auto written = std::to_chars(text, text + sizeof text, asFloat);
    double decimal = 0.0;
    if (written.ec == std::errc() && std::from_chars(text, written.ptr, decimal).ec == std::errc())
      setting.thresh = decimal;
  }
  return setting;
}

SweepStatus sweepStatus(const LoadedSweep& sweep, const RenderSettings& settings) {
  SweepStatus status;
  if (!sweep.present()) return status;
  status.visible = true;
  const std::string name = std::filesystem::path(sweep.path).filename().string();
  if (!sweep.error.empty()) {
    status.error = sweep.error;
    status.lines = {"The sweep table cannot be read:", sweep.error};
    return status;
  }
  status.setting = sweepSettingOf(settings);
  auto& lines = status.lines;
  lines.push_back(name + ": " + std::to_string(sweep.rows.size()) + " settings measured");
  lines.push_back("these settings: " + settingOptions(status.setting));
  const SweepRow* current = findSetting(sweep.rows, status.setting);
  if (!current) {
    lines.push_back("not in the sweep");
    return status;
  }
  status.current = *current;
  const ImageError& e = current->error;
  lines.push_back("expected PSNR " + psnrText(e.psnr));
  lines.push_back("pixels more than 2 levels off: " + percentText(e.over2));
  lines.push_back("worst pixel: " + std::to_string(e.worstLevels) + " levels off, at (" +
                  std::to_string(e.worstX) + ", " + std::to_string(e.worstY) + ")");
  lines.push_back("CPU time in the sweep: " + secondsText(current->cpuSeconds));
  if (const SweepRow* best = bestWithinCost(sweep.rows, current->cpuSeconds)) status.best = *best;
  if (status.currentOnFront()) {
    lines.push_back("on the Pareto front: no setting of the sweep is as cheap and more accurate");
  } else if (status.best) {
    lines.push_back("Pareto-optimal at the same cost: " + settingOptions(status.best->setting) +
                    ", " + psnrText(status.best->error.psnr) + ", " +
                    secondsText(status.best->cpuSeconds));
  } else {
    lines.push_back("no setting on the Pareto front costs this little");
  }
  return status;
}

} // namespace prism
