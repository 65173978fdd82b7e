// Facts about the machine and the process that statistics report (docs/statistics.md).
#pragma once

#include <string>

namespace prism {

// "Intel(R) Xeon(R) ... (x86_64)": the CPU model and the architecture.
std::string machineDescription();

// User + system CPU time of the whole process (all threads) so far.
double processCpuSeconds();

} // namespace prism
