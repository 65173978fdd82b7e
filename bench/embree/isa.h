// Which instruction set Embree traces with on this host: the widest of the
// kernels it was compiled with (CMake reports them, see CMakeLists.txt) that
// the CPU supports, unless the device configuration names one ("isa=avx2").
#pragma once

#include <embree3/rtcore.h>

#include <string>

namespace prism::bench {

struct IsaReport {
  std::string cpuFlags; // the vector extensions the CPU has, e.g. "sse4.2 avx avx2 avx512f ..."
  std::string compiled; // Embree's compiled kernels, e.g. "SSE2 SSE4.2 AVX AVX2 AVX512"
  std::string selected; // what it runs here, e.g. "AVX512"
  std::string nativePackets; // the ray packet widths it runs natively, e.g. "4 8 16"
};

IsaReport embreeIsa(RTCDevice device, const std::string& deviceConfig);

} // namespace prism::bench
