#include "config_file.h"

#include <fstream>
#include <sstream>

namespace prism {

namespace {

constexpr const char* kConfigOption = "--config";

// One `key = value` line of the file, where it is.
struct Setting {
  std::string section; // the command, "" outside any section
  std::string key;     // the option's long name without "--"
  int line = 0;
  int column = 0; // of the key, 1-based
};

std::optional<std::string> configFileIn(const std::vector<const char*>& args) {
  const std::string prefix = std::string(kConfigOption) + "=";
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string arg = args[i];
    if (arg == kConfigOption && i + 1 < args.size()) return std::string(args[i + 1]);
    if (arg.rfind(prefix, 0) == 0) return arg.substr(prefix.size());
  }
  return std::nullopt;
}

std::string trimmed(const std::string& s) {
  const std::size_t begin = s.find_first_not_of(" \t\r");
  if (begin == std::string::npos) return "";
  return s.substr(begin, s.find_last_not_of(" \t\r") - begin + 1);
}

// The sections and keys of the file, as CLI11 reads them: `[name]` opens a
// section, `name.key = ...` is key in section name, `#` and `;` start
// comments. Values are CLI11's business.
std::vector<Setting> scanSettings(std::istream& in) {
  std::vector<Setting> settings;
  std::string section;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    const std::string text = trimmed(line);
    if (text.empty() || text[0] == '#' || text[0] == ';') continue;
    if (text[0] == '[') {
      section = trimmed(text.substr(1, text.find(']') - 1));
      continue;
    }
    const std::size_t equals = text.find('=');
    std::string key = trimmed(text.substr(0, equals));
    std::string inSection = section;
    if (const std::size_t dot = key.find('.'); dot != std::string::npos && section.empty()) {
      inSection = key.substr(0, dot);
      key = key.substr(dot + 1);
    }
    settings.push_back({inSection, key, number, int(line.find_first_not_of(" \t")) + 1});
  }
  return settings;
}

std::string place(const std::string& file, const Setting& s) {
  return file + ":" + std::to_string(s.line) + ":" + std::to_string(s.column) + ": error: ";
}

const CLI::App* commandNamed(const CLI::App& app, const std::string& name) {
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; }))
    if (sub->check_name(name)) return sub;
  return nullptr;
}

} // namespace

void addConfigOption(CLI::App& app) {
  app.set_config(kConfigOption, "",
                 "Read the command's settings from FILE, a [render] (or [view], [sweep], ...) "
                 "section of `option = value` lines; the command line overrides them");
  app.allow_config_extras(CLI::config_extras_mode::error);
  app.fallthrough(); // `prism render SCENE --config FILE`: the commands pass it on
}

std::vector<std::string> configFileProblems(const CLI::App& app,
                                            const std::vector<const char*>& args) {
  const std::optional<std::string> file = configFileIn(args);
  if (!file) return {};
  std::ifstream in(*file);
  if (!in) return {*file + ": error: cannot read the settings file"};
  std::vector<std::string> problems;
  for (const Setting& s : scanSettings(in)) {
    if (s.section.empty()) {
      problems.push_back(place(*file, s) + "`" + s.key +
                         "` is outside a section: settings go under the command they are for, "
                         "e.g. [render]");
      continue;
    }
    const CLI::App* command = commandNamed(app, s.section);
    if (!command) {
      problems.push_back(place(*file, s) + "[" + s.section + "] is not a command of prism");
      continue;
    }
    const CLI::Option* option = command->get_option_no_throw("--" + s.key);
    if (!option || s.key == "help")
      problems.push_back(place(*file, s) + "prism " + command->get_name() + " has no option --" +
                         s.key);
  }
  return problems;
}

std::optional<std::string> locateConfigError(const std::vector<const char*>& args,
                                             const std::string& message) {
  const std::optional<std::string> file = configFileIn(args);
  if (!file) return std::nullopt;
  std::ifstream in(*file);
  for (const Setting& s : scanSettings(in)) {
    const std::string option = "--" + s.key;
    bool onCommandLine = false; // then the file's value was not used
    for (const char* arg : args)
      onCommandLine = onCommandLine || std::string(arg) == option ||
                      std::string(arg).rfind(option + "=", 0) == 0;
    const std::size_t at = message.find(option);
    const bool named =
        at != std::string::npos && (at + option.size() == message.size() ||
                                    !(std::isalnum((unsigned char)message[at + option.size()]) ||
                                      message[at + option.size()] == '-'));
    if (named && !onCommandLine) return place(*file, s) + message;
  }
  return std::nullopt;
}

} // namespace prism
