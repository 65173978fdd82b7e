// `prism COMMAND ... --config FILE`: a command's settings kept in a file, in
// CLI11's TOML/INI format with one section per command, e.g.
//
//   [render]
//   depth = 3
//   thresh = 0.02
//   size = [1024, 768]
//   srgb = true
//
// The command line overrides the file (docs/command-line.md#settings-files).
// CLI11 reads the file; what it cannot say, where in the file a setting is
// wrong, is added here, so that mistakes read FILE:LINE:COLUMN like a scene's.
#pragma once

#include <CLI/CLI.hpp>

#include <optional>
#include <string>
#include <vector>

namespace prism {

// Adds --config to `app`; before the commands are added (they inherit the
// permission to pass it on to `app`, after their own options).
void addConfigOption(CLI::App& app);

// The problems of the file --config names in `args` (none without it): a
// file that cannot be read, a setting outside a section, a section that is
// no command, a setting the command does not have. One
// "FILE:LINE:COLUMN: error: ..." line each.
std::vector<std::string> configFileProblems(const CLI::App& app,
                                            const std::vector<const char*>& args);

// `message`, a CLI11 error about a setting's value ("Could not convert:
// --depth = x"), with the place of that setting in the file when it came
// from there; nothing when it did not.
std::optional<std::string> locateConfigError(const std::vector<const char*>& args,
                                             const std::string& message);

} // namespace prism
