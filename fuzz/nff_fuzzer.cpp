// The NFF reader (core/io/nff_reader.h) on arbitrary text, then the hierarchy and
// a few traced rays over every scene it accepts.
#include "core/io/nff_reader.h"
#include "fuzz/fuzz_check.h"

using namespace prism;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text = fuzz::asText(data, size);
  std::vector<Diagnostic> warnings;
  return fuzz::checkReader(text, [&] { return parseNff(text, "fuzz.nff", &warnings); });
}
