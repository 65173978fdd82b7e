// describeCpu: the machine as statistics name it, from /proc/cpuinfo texts of
// x86, arm64 servers (implementer and part only) and Raspberry Pi boards.
#include <gtest/gtest.h>

#include "core/system/system_info.h"

namespace {

using prism::describeCpu;

TEST(DescribeCpu, X86TakesTheFirstModelName) {
  const char* cpuinfo = "processor\t: 0\n"
                        "vendor_id\t: AuthenticAMD\n"
                        "cpu family\t: 23\n"
                        "model\t\t: 49\n"
                        "model name\t: AMD EPYC 7B12\n"
                        "cpu MHz\t\t: 2249.998\n"
                        "\n"
                        "processor\t: 1\n"
                        "model name\t: AMD EPYC 7B12\n";
  EXPECT_EQ(describeCpu(cpuinfo, "x86_64"), "AMD EPYC 7B12 (x86_64)");
}

// An AWS Graviton2 (Neoverse-N1): no model name, no Hardware line.
TEST(DescribeCpu, Arm64WithOnlyImplementerAndPart) {
  const char* cpuinfo = "processor\t: 0\n"
                        "BogoMIPS\t: 243.75\n"
                        "Features\t: fp asimd evtstrm aes pmull sha1 sha2 crc32 atomics\n"
                        "CPU implementer\t: 0x41\n"
                        "CPU architecture: 8\n"
                        "CPU variant\t: 0x3\n"
                        "CPU part\t: 0xd0c\n"
                        "CPU revision\t: 1\n"
                        "\n"
                        "processor\t: 1\n"
                        "CPU implementer\t: 0x41\n"
                        "CPU part\t: 0xd0c\n";
  EXPECT_EQ(describeCpu(cpuinfo, "aarch64"), "ARM Neoverse-N1 (aarch64)");
  // A part not in the table is named by its codes, never "unknown".
  EXPECT_EQ(describeCpu("CPU implementer\t: 0x41\nCPU part\t: 0xd99\n", "aarch64"),
            "ARM implementer 0x41 part 0xd99 (aarch64)");
  EXPECT_EQ(describeCpu("CPU implementer\t: 0x51\nCPU part\t: 0x802\n", "aarch64"),
            "Qualcomm implementer 0x51 part 0x802 (aarch64)");
  EXPECT_EQ(describeCpu("CPU implementer\t: 0x99\nCPU part\t: 0x001\n", "aarch64"),
            "implementer 0x99 part 0x001 (aarch64)");
}

// Big and little cores: each kind once, in order.
TEST(DescribeCpu, MixedArmCoresAreEachNamedOnce) {
  const char* cpuinfo = "processor\t: 0\nCPU implementer\t: 0x41\nCPU part\t: 0xd05\n\n"
                        "processor\t: 1\nCPU implementer\t: 0x41\nCPU part\t: 0xd05\n\n"
                        "processor\t: 2\nCPU implementer\t: 0x41\nCPU part\t: 0xd0b\n";
  EXPECT_EQ(describeCpu(cpuinfo, "aarch64"), "ARM Cortex-A55 + ARM Cortex-A76 (aarch64)");
}

// A Raspberry Pi 4 on a 64-bit kernel: the cores, then the board's Model.
TEST(DescribeCpu, RaspberryPiNamesTheCoresAndTheBoard) {
  const char* pi64 = "processor\t: 0\n"
                     "BogoMIPS\t: 108.00\n"
                     "CPU implementer\t: 0x41\n"
                     "CPU part\t: 0xd08\n"
                     "CPU revision\t: 3\n"
                     "\n"
                     "Revision\t: c03114\n"
                     "Serial\t\t: 10000000abcdef01\n"
                     "Model\t\t: Raspberry Pi 4 Model B Rev 1.4\n";
  EXPECT_EQ(describeCpu(pi64, "aarch64"),
            "ARM Cortex-A72, Raspberry Pi 4 Model B Rev 1.4 (aarch64)");
  // An older 32-bit kernel: "Processor" and "Hardware", no Model.
  const char* pi32 = "Processor\t: ARMv6-compatible processor rev 7 (v6l)\n"
                     "BogoMIPS\t: 697.95\n"
                     "Features\t: swp half thumb fastmult vfp edsp java tls\n"
                     "\n"
                     "Hardware\t: BCM2708\n"
                     "Revision\t: 000e\n";
  EXPECT_EQ(describeCpu(pi32, "armv6l"),
            "ARMv6-compatible processor rev 7 (v6l), BCM2708 (armv6l)");
  EXPECT_EQ(describeCpu("Hardware\t: BCM2835\n", "armv7l"), "BCM2835 (armv7l)");
}

TEST(DescribeCpu, UnknownOnlyWhenTheKernelSaysNothing) {
  EXPECT_EQ(describeCpu("", "riscv64"), "unknown CPU (riscv64)");
  EXPECT_EQ(
      describeCpu("processor\t: 0\nisa\t\t: rv64imafdc\nuarch\t\t: sifive,u74-mc\n", "riscv64"),
      "sifive,u74-mc (riscv64)");
  EXPECT_EQ(describeCpu("model name : X\n", ""), "X (unknown architecture)");
}

TEST(DescribeCpu, ThisMachineIsDescribed) {
  const std::string machine = prism::machineDescription();
  EXPECT_EQ(machine.find("unknown CPU"), std::string::npos) << machine;
  EXPECT_EQ(machine.back(), ')') << machine;
}

} // namespace
