#include "bench/embree/isa.h"

#include <utility>
#include <vector>

namespace prism::bench {

namespace {

struct Target {
  const char* name;     // as Embree's CMake option and its verbose output name it
  const char* isaValue; // as the device configuration's "isa=" names it
  bool compiled;
  bool supported; // by this CPU
};

// Embree's AVX512 kernels are its SKX target: F, CD, BW, DQ and VL.
bool cpuHasSkx() {
  return __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512cd") &&
         __builtin_cpu_supports("avx512bw") && __builtin_cpu_supports("avx512dq") &&
         __builtin_cpu_supports("avx512vl");
}

std::vector<Target> targets() {
  return {
      {"SSE2", "sse2", PRISM_EMBREE_ISA_SSE2, bool(__builtin_cpu_supports("sse2"))},
      {"SSE4.2", "sse4.2", PRISM_EMBREE_ISA_SSE42, bool(__builtin_cpu_supports("sse4.2"))},
      {"AVX", "avx", PRISM_EMBREE_ISA_AVX, bool(__builtin_cpu_supports("avx"))},
      {"AVX2", "avx2", PRISM_EMBREE_ISA_AVX2,
       __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma") &&
           __builtin_cpu_supports("bmi2")},
      {"AVX512", "avx512", PRISM_EMBREE_ISA_AVX512, cpuHasSkx()},
  };
}

// The value of "isa=" in a device configuration ("threads=1,isa=avx2"), or "".
std::string forcedIsa(const std::string& config) {
  const std::size_t at = config.find("isa=");
  if (at == std::string::npos) return "";
  const std::size_t start = at + 4;
  return config.substr(start, config.find(',', start) - start);
}

} // namespace

IsaReport embreeIsa(RTCDevice device, const std::string& deviceConfig) {
  IsaReport r;
  // __builtin_cpu_supports takes only literals.
  const std::pair<const char*, bool> flags[] = {{"sse4.2", __builtin_cpu_supports("sse4.2")},
                                                {"avx", __builtin_cpu_supports("avx")},
                                                {"avx2", __builtin_cpu_supports("avx2")},
                                                {"fma", __builtin_cpu_supports("fma")},
                                                {"avx512f", __builtin_cpu_supports("avx512f")},
                                                {"avx512cd", __builtin_cpu_supports("avx512cd")},
                                                {"avx512bw", __builtin_cpu_supports("avx512bw")},
                                                {"avx512dq", __builtin_cpu_supports("avx512dq")},
                                                {"avx512vl", __builtin_cpu_supports("avx512vl")}};
  for (const auto& [flag, present] : flags)
    if (present) r.cpuFlags += (r.cpuFlags.empty() ? "" : " ") + std::string(flag);

  const std::string forced = forcedIsa(deviceConfig);
  bool capped = false;
  for (const Target& t : targets()) {
    if (t.compiled) r.compiled += (r.compiled.empty() ? "" : " ") + std::string(t.name);
    if (!capped && t.compiled && t.supported) r.selected = t.name;
    // A forced ISA ("isa=avx2") caps the choice.
    if (forced == t.isaValue) capped = true;
  }

  for (auto [property, width] : {std::pair{RTC_DEVICE_PROPERTY_NATIVE_RAY4_SUPPORTED, "4"},
                                 std::pair{RTC_DEVICE_PROPERTY_NATIVE_RAY8_SUPPORTED, "8"},
                                 std::pair{RTC_DEVICE_PROPERTY_NATIVE_RAY16_SUPPORTED, "16"}})
    if (rtcGetDeviceProperty(device, property) != 0)
      r.nativePackets += (r.nativePackets.empty() ? "" : " ") + std::string(width);
  return r;
}

} // namespace prism::bench
