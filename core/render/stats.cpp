#include "core/render/stats.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>

namespace prism {

namespace {
std::string line(const char* format, auto... args) {
  char buffer[512];
  std::snprintf(buffer, sizeof buffer, format, args...);
  return buffer;
}
} // namespace

std::string formatStatsText(const RenderStats& s) {
  const RayCounts& c = s.counts;
  std::string text;
  text += line("scene               %s\n", s.scene.c_str());
  text += line("machine             %s\n", s.machine.c_str());
  text += line("image               %d x %d = %lld pixels\n", s.width, s.height, s.pixels());
  text += line("max depth           %d\n", s.maxDepth);
  text += line("threshold           %g%s%s\n", s.thresh, s.jitter ? " (jittered sub-samples)" : "",
               s.noAa ? " (no antialiasing)" : "");
  text += line("bailout             %g levels%s\n", s.bailout, s.bailout > 0.0 ? "" : " (exact)");
  text += line("primitives          %zu (accel: %s)\n", s.primitives, s.accel.c_str());
  text += line("threads             %d\n", s.threads);
  text += line("load / build        %.3f s / %.3f s (wall)\n", s.loadSeconds, s.buildSeconds);
  text += line("render CPU time     %.3f s (user + system, all threads)\n", s.cpuSeconds);
  text += line("render wall time    %.3f s\n", s.wallSeconds);
  text += line("eye rays            %llu (pass 1: %llu, antialiasing: %llu)\n",
               (unsigned long long)c.eye(), (unsigned long long)c.eyePrimary,
               (unsigned long long)c.eyeAntialias);
  text += line("shadow rays         %llu\n", (unsigned long long)c.shadow);
  text += line("reflected rays      %llu\n", (unsigned long long)c.reflected);
  text += line("transmitted rays    %llu (total internal reflections: %llu)\n",
               (unsigned long long)c.transmitted, (unsigned long long)c.tirEvents);
  if (s.bailout > 0.0)
    text += line("bailout             %llu rays skipped (reflected: %llu, transmitted: %llu); "
                 "pilot rays: %llu\n",
                 (unsigned long long)(c.reflectedSkipped + c.transmittedSkipped),
                 (unsigned long long)c.reflectedSkipped, (unsigned long long)c.transmittedSkipped,
                 (unsigned long long)c.bailoutPilot);
  text += line("total rays          %llu\n", (unsigned long long)c.total());
  text += line("rays per pixel      %.3f\n", s.raysPerPixel());
  text += line("supersampled        %lld pixels (%.2f%%)\n", s.supersampledPixels,
               100.0 * s.supersampledShare());
  text += line("avgmax              %.6g\n", s.avgmax);
  if (!s.ranks.empty()) {
    text += line("ranks               %zu (load balance %.3f: mean CPU / busiest rank's)\n",
                 s.ranks.size(), s.loadBalance());
    text += line("  %4s  %-24s %7s %6s %14s %10s\n", "rank", "host", "threads", "tiles", "rays",
                 "CPU s");
    for (const RankStats& r : s.ranks)
      text += line("  %4d  %-24s %7d %6d %14llu %10.3f\n", r.rank, r.host.c_str(), r.threads,
                   r.tiles, (unsigned long long)r.rays, r.cpuSeconds);
  }
  return text;
}

double RenderStats::loadBalance() const {
  double sum = 0.0, busiest = 0.0;
  for (const RankStats& r : ranks) {
    sum += r.cpuSeconds;
    busiest = std::max(busiest, r.cpuSeconds);
  }
  return busiest > 0.0 ? sum / double(ranks.size()) / busiest : 0.0;
}

std::string formatStatsJson(const RenderStats& s) {
  const RayCounts& c = s.counts;
  nlohmann::ordered_json json = {
      {"scene", s.scene},
      {"machine", s.machine},
      {"width", s.width},
      {"height", s.height},
      {"pixels", s.pixels()},
      {"max_depth", s.maxDepth},
      {"thresh", s.thresh},
      {"jitter", s.jitter},
      {"no_aa", s.noAa},
      {"bailout", s.bailout},
      {"accel", s.accel},
      {"threads", s.threads},
      {"primitives", s.primitives},
      {"load_seconds", s.loadSeconds},
      {"build_seconds", s.buildSeconds},
      {"cpu_seconds", s.cpuSeconds},
      {"wall_seconds", s.wallSeconds},
      {"rays",
       {{"eye", c.eye()},
        {"eye_pass1", c.eyePrimary},
        {"eye_antialias", c.eyeAntialias},
        {"shadow", c.shadow},
        {"reflected", c.reflected},
        {"transmitted", c.transmitted},
        {"bailout_pilot", c.bailoutPilot},
        {"total", c.total()}}},
      {"tir_events", c.tirEvents},
      {"bailout_skipped",
       {{"reflected", c.reflectedSkipped}, {"transmitted", c.transmittedSkipped}}},
      {"rays_per_pixel", s.raysPerPixel()},
      {"supersampled_pixels", s.supersampledPixels},
      {"supersampled_share", s.supersampledShare()},
      {"avgmax", s.avgmax},
  };
  if (!s.ranks.empty()) {
    json["load_balance"] = s.loadBalance();
    nlohmann::ordered_json ranks = nlohmann::ordered_json::array();
    for (const RankStats& r : s.ranks)
      ranks.push_back({{"rank", r.rank},
                       {"host", r.host},
                       {"threads", r.threads},
                       {"tiles", r.tiles},
                       {"rays", r.rays},
                       {"cpu_seconds", r.cpuSeconds}});
    json["ranks"] = ranks;
  }
  return json.dump(2) + "\n";
}

} // namespace prism
