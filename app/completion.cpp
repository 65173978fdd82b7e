#include "completion.h"

#include <algorithm>
#include <cctype>
#include <iostream>
#include <sstream>
#include <vector>

namespace prism {

namespace {

// What the words after an option are.
enum class ValueKind { none, files, choices };

struct OptionShape {
  std::vector<std::string> names; // -o, --output
  int values = 0;                 // words taken after it (0: a flag)
  ValueKind kind = ValueKind::none;
  std::vector<std::string> choices;
};

struct CommandShape {
  std::string key;                  // "" for the program, "render", "bench.x" below
  std::vector<std::string> names;   // the name and its aliases
  std::vector<OptionShape> options; // hidden ones left out
  bool positionals = false;         // takes file arguments
  std::vector<const CLI::App*> subcommands;
};

bool hidden(const std::string& group) { return group.empty(); }

// Words that can go into the script unquoted.
bool plainWord(const std::string& word) {
  if (word.empty()) return false;
  for (const char c : word)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_' && c != '.' &&
        c != '+')
      return false;
  return true;
}

// The values of a check against a set: CLI11 describes IsMember as
// "{a,b,c}" and CheckedTransformer as "value in {a->x,b->y}" in the type name.
std::vector<std::string> choicesIn(const std::string& typeName) {
  std::vector<std::string> out;
  const std::size_t open = typeName.find('{');
  const std::size_t close = typeName.find('}', open);
  if (open == std::string::npos || close == std::string::npos) return out;
  std::stringstream list(typeName.substr(open + 1, close - open - 1));
  for (std::string item; std::getline(list, item, ',');) {
    item = item.substr(0, item.find("->"));
    while (!item.empty() && item.front() == ' ')
      item.erase(item.begin());
    while (!item.empty() && item.back() == ' ')
      item.pop_back();
    if (plainWord(item)) out.push_back(item);
  }
  return out;
}

OptionShape shapeOf(const CLI::Option& option) {
  OptionShape s;
  for (const std::string& n : option.get_snames())
    s.names.push_back("-" + n);
  for (const std::string& n : option.get_lnames())
    s.names.push_back("--" + n);
  // A flag takes nothing; an option with a fixed count (--size W H) that
  // many words; a list of any length (or an optional value) one.
  s.values =
      option.get_items_expected_max() == 0 ? 0 : std::max(1, option.get_items_expected_min());
  const std::string type = option.get_type_name();
  s.choices = choicesIn(type);
  if (!s.choices.empty())
    s.kind = ValueKind::choices;
  else if (type.rfind("TEXT", 0) == 0 || type.find("FILE") != std::string::npos ||
           type.find("PATH") != std::string::npos || type.find("DIR") != std::string::npos)
    s.kind = ValueKind::files;
  return s;
}

void collect(const CLI::App& app, const std::string& key, std::vector<CommandShape>& out) {
  CommandShape c;
  c.key = key;
  c.names.push_back(app.get_name());
  for (const std::string& alias : app.get_aliases())
    c.names.push_back(alias);
  for (const CLI::Option* option : app.get_options()) {
    if (hidden(option->get_group())) continue;
    if (option->nonpositional())
      c.options.push_back(shapeOf(*option));
    else
      c.positionals = true;
  }
  c.subcommands = app.get_subcommands(
      [](const CLI::App* sub) { return !sub->get_name().empty() && !hidden(sub->get_group()); });
  out.push_back(c);
  for (const CLI::App* sub : c.subcommands)
    collect(*sub, key.empty() ? sub->get_name() : key + "." + sub->get_name(), out);
}

std::string joined(const std::vector<std::string>& words, const std::string& between) {
  std::string s;
  for (const std::string& w : words)
    s += (s.empty() ? "" : between) + w;
  return s;
}

// Case patterns `KEY:WORD|KEY:WORD2` for one command's key and several words.
std::string patterns(const std::string& key, const std::vector<std::string>& words) {
  std::vector<std::string> p;
  for (const std::string& w : words)
    p.push_back(key + ":" + w);
  return joined(p, "|");
}

} // namespace

std::string bashCompletionScript(const CLI::App& app, const std::string& program, bool fileAtTop) {
  std::vector<CommandShape> commands;
  collect(app, "", commands);
  std::string function = "_";
  for (const char c : program)
    function += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';

  std::ostringstream s;
  s << "# Bash completion for " << program << ", written by `" << program
    << " --bash-completion` from its\n"
       "# command-line definitions. Source it, or install it as\n"
       "# share/bash-completion/completions/"
    << program << ".\n"
    << function << "() {\n"
    << "  local cur=${COMP_WORDS[COMP_CWORD]} cmd='' opt='' want=0 i w\n"
       "  COMPREPLY=()\n"
       "  # Which command the words name, and whether the word under the cursor\n"
       "  # is a value of an option before it (want > 0).\n"
       "  for ((i = 1; i < COMP_CWORD; i++)); do\n"
       "    w=${COMP_WORDS[i]}\n"
       "    if ((want > 0)); then\n"
       "      want=$((want - 1))\n"
       "      continue\n"
       "    fi\n"
       "    case \"$cmd:$w\" in\n";
  for (const CommandShape& c : commands) {
    for (const CLI::App* sub : c.subcommands) {
      std::vector<std::string> names{sub->get_name()};
      for (const std::string& alias : sub->get_aliases())
        names.push_back(alias);
      const std::string key = c.key.empty() ? sub->get_name() : c.key + "." + sub->get_name();
      s << "      " << patterns(c.key, names) << ") cmd=" << key << " ;;\n";
    }
    for (const OptionShape& o : c.options)
      if (o.values > 0)
        s << "      " << patterns(c.key, o.names) << ") opt=$w want=" << o.values << " ;;\n";
  }
  s << "    esac\n"
       "  done\n"
       "  if ((want > 0)); then\n"
       "    case \"$cmd:$opt\" in\n";
  for (const CommandShape& c : commands)
    for (const OptionShape& o : c.options) {
      if (o.values == 0 || o.kind == ValueKind::none) continue;
      s << "      " << patterns(c.key, o.names) << ")\n";
      if (o.kind == ValueKind::files)
        s << "        compopt -o filenames 2>/dev/null\n"
             "        mapfile -t COMPREPLY < <(compgen -f -- \"$cur\") ;;\n";
      else
        s << "        mapfile -t COMPREPLY < <(compgen -W '" << joined(o.choices, " ")
          << "' -- \"$cur\") ;;\n";
    }
  s << "    esac\n"
       "    return 0\n"
       "  fi\n"
       "  local words='' files=0\n"
       "  case $cmd in\n";
  for (const CommandShape& c : commands) {
    std::vector<std::string> words;
    for (const OptionShape& o : c.options)
      words.insert(words.end(), o.names.begin(), o.names.end());
    std::vector<std::string> subs;
    for (const CLI::App* sub : c.subcommands) {
      subs.push_back(sub->get_name());
      for (const std::string& alias : sub->get_aliases())
        subs.push_back(alias);
    }
    const bool files = c.positionals || (c.key.empty() && fileAtTop);
    s << "    " << (c.key.empty() ? "''" : c.key) << ")\n"
      << "      words='" << joined(words, " ") << "'\n";
    if (!subs.empty()) s << "      [[ $cur == -* ]] || words='" << joined(subs, " ") << "'\n";
    s << "      files=" << (files ? 1 : 0) << " ;;\n";
  }
  s << "  esac\n"
       "  mapfile -t COMPREPLY < <(compgen -W \"$words\" -- \"$cur\")\n"
       "  if ((files)) && [[ $cur != -* ]]; then\n"
       "    compopt -o filenames 2>/dev/null\n"
       "    mapfile -t -O ${#COMPREPLY[@]} COMPREPLY < <(compgen -f -- \"$cur\")\n"
       "  fi\n"
       "  return 0\n"
       "}\n"
       "complete -F "
    << function << " " << program << "\n";
  return s.str();
}

void addBashCompletionFlag(CLI::App& app, const std::string& program, bool fileAtTop) {
  app.add_flag_callback(
         "--bash-completion",
         [&app, program, fileAtTop] {
           std::cout << bashCompletionScript(app, program, fileAtTop);
           throw CLI::Success();
         },
         "Print a bash completion script")
      ->group("");
}

} // namespace prism
