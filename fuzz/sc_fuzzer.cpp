// The .sc reader (core/io/scene_parser.h) on arbitrary text, then the hierarchy
// and a few traced rays over every scene it accepts. The text is read as the
// file main.sc of the sandbox, which holds a few parts it may include by name
// (see fuzz_check.cpp).
#include "core/io/scene_parser.h"
#include "fuzz/fuzz_check.h"

using namespace prism;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text = fuzz::asText(data, size);
  if (fuzz::includeLeavesSandbox(text)) return -1; // not kept in the corpus
  return fuzz::checkReader(
      text, [&] { return parseScene(text, (fuzz::sandbox() / "main.sc").string()); });
}
