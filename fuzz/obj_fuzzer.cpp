// The OBJ/MTL reader (core/io/obj_reader.h: Prism's scan, then tinyobjloader) on
// arbitrary text, then the hierarchy and a few traced rays over every scene it
// accepts. The reader takes a path: the input is written to the sandbox as
// a.obj, and what follows a line `#mtl` as a.mtl, so that `mtllib a.mtl` lets
// the fuzzer reach the material reader too.
#include "core/io/obj_reader.h"
#include "fuzz/fuzz_check.h"

using namespace prism;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text = fuzz::asText(data, size);
  if (fuzz::mtllibLeavesSandbox(text)) return -1; // not kept in the corpus
  std::vector<Diagnostic> warnings;
  return fuzz::checkReader(text, [&] { return loadObj(fuzz::stageObj(text), &warnings); });
}
