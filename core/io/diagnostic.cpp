#include "core/io/diagnostic.h"

#include "core/io/scene_text.h"

namespace prism {

// File names come from the command line and from `include` lines, and
// messages quote the input: both are made printable (invalid UTF-8 escaped).
std::string Diagnostic::format(const char* severity) const {
  return printable(file) + ":" + std::to_string(line) + ":" + std::to_string(column) + ": " +
         severity + ": " + printable(message);
}

namespace {

std::string formatAll(const std::vector<Diagnostic>& diagnostics) {
  std::string text;
  for (const Diagnostic& d : diagnostics) {
    if (!text.empty()) text += '\n';
    text += d.format();
  }
  return text;
}

} // namespace

SceneError::SceneError(std::vector<Diagnostic> diagnostics)
    : std::runtime_error(formatAll(diagnostics)), diagnostics_(std::move(diagnostics)) {}

} // namespace prism
