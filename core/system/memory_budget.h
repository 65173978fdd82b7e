// How much memory a render needs, and how much this process may still take,
// so that a render too large for the machine is refused with a message before
// any work is done instead of dying of std::bad_alloc (or being killed) after
// minutes of work.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace prism {

// Bytes per pixel of a headless render: the film (pass-1 centre and final
// radiance, 3 floats each, and a supersampled flag) and the exposed 8-bit
// picture handed to the image writer.
inline constexpr std::uint64_t kRenderBytesPerPixel = 2 * 12 + 1 + 3;
// Bytes per pixel of a previewer session: the render's film, the display
// buffers the window reads (its copy of the radiance, the sample level per
// pixel, the supersampled flags), the float texture and its upload, and a
// second film while a restart replaces the first.
inline constexpr std::uint64_t kPreviewBytesPerPixel = 2 * (2 * 12 + 1 + 12 + 1) + 12 + 1 + 2 * 12;

std::uint64_t imageBytes(int width, int height, std::uint64_t bytesPerPixel);

struct MemoryAvailable {
  std::uint64_t bytes = 0;
  std::string source; // what sets the limit, for messages ("ulimit -v", ...)
};

// The smallest of: the PRISM_MEMORY_LIMIT environment variable (bytes, or
// with a K, M, G, T or P suffix for powers of 1024), the system's available
// memory (MemAvailable), the room left under this process's cgroup limit, and
// under its address-space and data limits (ulimit -v, -d). Nothing when none
// of them is known.
std::optional<MemoryAvailable> availableMemory();

// "4096", "512K", "8G": a byte count with an optional binary suffix.
std::optional<std::uint64_t> parseByteCount(std::string_view text);

// "27.9 GiB", "512.0 MiB", ...: a size for messages.
std::string formatBytes(std::uint64_t bytes);

// Why a render of `bytes` cannot fit in what is available, or nothing if it
// can (or if nothing is known about the available memory).
std::optional<std::string> memoryProblem(std::uint64_t bytes, const std::string& what);

} // namespace prism
