// What every fuzz target does once a reader has produced a scene, and the small
// pieces of plumbing they share. See docs/fuzzing.md.
#pragma once

#include "core/io/scene_parser.h"
#include "core/scene/scene.h"

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace prism::fuzz {

// A broken promise: prints `what` (and the input, escaped, when given) to
// stderr and aborts, which libFuzzer reports as a crash with a stack trace and
// saves the input. Used for checks the sanitizers cannot make themselves.
[[noreturn]] void fail(const std::string& what, std::string_view input = {});

// Builds the BVH and the push/pop group hierarchy over `scene` and traces a
// 4x4 image at depth 4, and one ray through the image's centre, through each
// (one ray at a time and as one bundle), so
// that eye, shadow, reflected and transmitted rays all run. Fails when a
// colour is NaN or when the two hierarchies, or the single and bundled rays,
// disagree (core/accel/accel.h promises the very same hits). The image is small
// whatever the scene's resolution: an execution must stay cheap.
void renderChecks(const Scene& scene);

// One execution of a reader target: `load()` reads the input into a Scene.
// A rejection must come with at least one located diagnostic; an accepted
// scene goes through renderChecks.
template <class Load> int checkReader(std::string_view input, Load load) {
  Scene scene;
  try {
    scene = load();
  } catch (const SceneError& e) {
    if (e.diagnostics().empty()) fail("SceneError without a diagnostic", input);
    return 0;
  }
  renderChecks(scene);
  return 0;
}

// A private, empty-at-start directory for this process (TMPDIR/prism-fuzz-PID-
// XXXXXX), removed at exit, and by the next process if this one crashes. Readers that take paths
// (OBJ) or follow includes (.sc) get their files here, so a run never depends on what else is on
// the disk.
const std::filesystem::path& sandbox();

// Writes `bytes` to `path` (replacing it); removes it when `bytes` is null.
void writeFile(const std::filesystem::path& path, const std::string_view* bytes);

// True when `text` could make a reader open a file outside the sandbox: a
// path with a '/' in it after `include` or `image` anywhere (.sc paths may
// follow on a later line) or after `mtllib` or `map_Kd` on the same line
// (OBJ, MTL). Such inputs are
// skipped, not read: what they find depends on the machine, and a 200 MB
// library read as a scene only measures the disk.
bool includeLeavesSandbox(std::string_view scText);
bool mtllibLeavesSandbox(std::string_view objText);

// The input as text: `#!FORMAT` on the first line selects a reader in the
// round-trip target; the OBJ targets split the text at kMtlMarker.
inline std::string_view asText(const std::uint8_t* data, std::size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

// Everything after this line is the MTL file `a.mtl` beside `a.obj`. A comment
// in OBJ, so that a seed still reads as an OBJ file on its own.
inline constexpr std::string_view kMtlMarker = "\n#mtl\n";

// Writes the OBJ part of `text` to sandbox()/a.obj and the MTL part, if any, to
// sandbox()/a.mtl (removing a stale one) and returns the OBJ file's path.
std::filesystem::path stageObj(std::string_view text);

} // namespace prism::fuzz
