// Facts about the machine and the process that statistics report (docs/statistics.md).
#pragma once

#include <string>
#include <string_view>

namespace prism {

// "Intel(R) Xeon(R) ... (x86_64)": the CPU model and the architecture, from
// /proc/cpuinfo and uname (describeCpu).
std::string machineDescription();

// The CPU described from the text of a /proc/cpuinfo and the architecture
// `arch` (uname's machine), "MODEL (ARCH)". MODEL is the first `model name`
// (x86 and some 32-bit ARM kernels); else, on arm64, each distinct `CPU
// implementer` and `CPU part` named ("ARM Neoverse-N1", "ARM implementer 0x41
// part 0xd99" for a part it does not know, "ARM Cortex-A55 + ARM Cortex-A76"
// for mixed cores); else `Processor`, `cpu model`, `cpu`, `uarch` or
// `vendor_id`. The board (`Model`, else `Hardware`, as Raspberry Pi kernels
// give) follows after a comma. "unknown CPU" only when none of these is there.
std::string describeCpu(std::string_view cpuinfo, std::string_view arch);

// This host's name (gethostname), "unknown" if it has none.
std::string hostName();

// User + system CPU time of the whole process (all threads) so far.
double processCpuSeconds();

} // namespace prism
