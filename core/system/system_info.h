// Facts about the machine and the process that statistics report (docs/statistics.md).
#pragma once

#include <string>

namespace prism {

// "Intel(R) Xeon(R) ... (x86_64)": the CPU model and the architecture.
std::string machineDescription();

// This host's name (gethostname), "unknown" if it has none.
std::string hostName();

// User + system CPU time of the whole process (all threads) so far.
double processCpuSeconds();

} // namespace prism
