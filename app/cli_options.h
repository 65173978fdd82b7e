// Option shapes the commands share, so each command's option list reads as
// a list of what it takes.
#pragma once

#include <CLI/CLI.hpp>

#include <cmath>
#include <string>
#include <type_traits>

namespace prism {

// An option whose value must lie in [min, max], its default shown in --help.
// Not a number is outside every range: CLI::Range alone lets "nan" through,
// since every comparison with NaN is false.
template <class T, class Bound>
CLI::Option* addRangedOption(CLI::App& command, const std::string& name, T& value,
                             const std::string& help, Bound min, Bound max) {
  CLI::Option* option =
      command.add_option(name, value, help)->capture_default_str()->check(CLI::Range(min, max));
  if constexpr (std::is_floating_point_v<T>)
    option->check(CLI::Validator(
        [](std::string& text) {
          T parsed{};
          return CLI::detail::lexical_cast(text, parsed) && std::isnan(parsed)
                     ? "Value " + text + " is not a number"
                     : std::string();
        },
        ""));
  return option;
}

// The scene file every rendering command takes first. `orStdin`: "-" is
// also accepted (the scene read from standard input).
inline CLI::Option* addSceneArgument(CLI::App& command, std::string& scene, bool orStdin = false) {
  if (!orStdin)
    return command.add_option("scene", scene, "Scene file (.sc, .nff or .obj)")
        ->required()
        ->check(CLI::ExistingFile);
  return command
      .add_option("scene", scene, "Scene file (.sc, .nff or .obj), or - for .sc text on stdin")
      ->required()
      ->check(CLI::Validator(
          [](std::string& name) {
            std::string copy = name;
            return name == "-" ? std::string() : CLI::ExistingFile(copy);
          },
          "FILE or -"));
}

} // namespace prism
