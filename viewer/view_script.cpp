#include "view_script.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

namespace prism {

namespace {

struct Token {
  std::string text;
  int column = 1; // 1-based
};

std::vector<Token> split(const std::string& line) {
  std::vector<Token> tokens;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && std::isspace((unsigned char)line[i]))
      ++i;
    if (i >= line.size()) break;
    const std::size_t start = i;
    while (i < line.size() && !std::isspace((unsigned char)line[i]))
      ++i;
    tokens.push_back({line.substr(start, i - start), int(start) + 1});
  }
  return tokens;
}

// The text after the keyword, trimmed: paths and echo text may hold spaces.
std::string restOfLine(const std::string& line, const Token& keyword) {
  std::size_t start = std::size_t(keyword.column - 1) + keyword.text.size();
  while (start < line.size() && std::isspace((unsigned char)line[start]))
    ++start;
  std::size_t end = line.size();
  while (end > start && std::isspace((unsigned char)line[end - 1]))
    --end;
  return line.substr(start, end - start);
}

bool toNumber(const std::string& text, double& value) {
  errno = 0;
  char* end = nullptr;
  value = std::strtod(text.c_str(), &end);
  return end != text.c_str() && *end == '\0' && errno == 0 && std::isfinite(value);
}

// One line's parse: fills `action` or records why not.
class LineParser {
public:
  LineParser(const std::string& name, int line, std::vector<Diagnostic>& errors)
      : name_(name), line_(line), errors_(errors) {}

  void error(const Token& at, const std::string& message) {
    errors_.push_back({name_, line_, at.column, message});
    ok_ = false;
  }
  bool ok() const { return ok_; }

  // Expects exactly `count` arguments after the keyword.
  bool arity(const std::vector<Token>& t, std::size_t count, const std::string& usage) {
    if (t.size() == count + 1) return true;
    error(t.size() > count + 1 ? t[count + 1] : t[0], t[0].text + ": expected " + usage + ", got " +
                                                          std::to_string(t.size() - 1) +
                                                          " argument" + (t.size() == 2 ? "" : "s"));
    return false;
  }

  double number(const Token& t, const std::string& what, double min, double max) {
    double value = 0.0;
    if (!toNumber(t.text, value)) {
      error(t, what + ": expected a number, got '" + t.text + "'");
    } else if (value < min || value > max) {
      std::ostringstream range;
      range << what << " must be in [" << min << ", " << max << "], got " << t.text;
      error(t, range.str());
    }
    return value;
  }

  int integer(const Token& t, const std::string& what, int min, int max) {
    const double value = number(t, what, min, max);
    if (ok_ && value != std::floor(value)) error(t, what + ": expected an integer, got " + t.text);
    return ok_ ? int(value) : 0;
  }

  double onOff(const Token& t) {
    if (t.text == "on") return 1.0;
    if (t.text == "off") return 0.0;
    error(t, "expected on or off, got '" + t.text + "'");
    return 0.0;
  }

private:
  const std::string& name_;
  int line_;
  std::vector<Diagnostic>& errors_;
  bool ok_ = true;
};

const std::map<std::string, ScriptOp>& keywords() {
  static const std::map<std::string, ScriptOp> table{
      {"wait", ScriptOp::Wait},
      {"frames", ScriptOp::Frames},
      {"timeout", ScriptOp::Timeout},
      {"depth", ScriptOp::Depth},
      {"thresh", ScriptOp::Thresh},
      {"jitter", ScriptOp::Jitter},
      {"no-aa", ScriptOp::NoAa},
      {"ambient", ScriptOp::Ambient},
      {"fog", ScriptOp::Fog},
      {"light", ScriptOp::Light},
      {"intensity", ScriptOp::Intensity},
      {"texture", ScriptOp::Texture},
      {"orbit", ScriptOp::Orbit},
      {"pan", ScriptOp::Pan},
      {"zoom", ScriptOp::Zoom},
      {"reset", ScriptOp::Reset},
      {"overlay", ScriptOp::Overlay},
      {"markers", ScriptOp::Markers},
      {"exposure", ScriptOp::Exposure},
      {"ev", ScriptOp::Ev},
      {"picture", ScriptOp::Picture},
      {"inspect", ScriptOp::Inspect},
      {"pin", ScriptOp::Pin},
      {"compare", ScriptOp::Compare},
      {"reload", ScriptOp::Reload},
      {"save", ScriptOp::Save},
      {"screenshot", ScriptOp::Screenshot},
      {"echo", ScriptOp::Echo},
      {"print", ScriptOp::Print},
      {"quit", ScriptOp::Quit},
  };
  return table;
}

const std::map<std::string, WaitFor>& waitTargets() {
  static const std::map<std::string, WaitFor> table{{"coarse", WaitFor::Coarse},
                                                    {"pass1", WaitFor::Pass1},
                                                    {"done", WaitFor::Done},
                                                    {"reload", WaitFor::Reload},
                                                    {"error", WaitFor::Error}};
  return table;
}

// The actions that take one number in a range: what the number is called in
// the usage message, the range, and whether it is a whole number (kept in
// ScriptAction::index) or not (ScriptAction::values).
struct OneNumber {
  const char* usage;
  double min, max;
  bool whole;
};

const std::map<ScriptOp, OneNumber>& oneNumberActions() {
  static const std::map<ScriptOp, OneNumber> table{
      {ScriptOp::Frames, {"N", 0, 1000000, true}},
      {ScriptOp::Timeout, {"SECONDS", 0.001, 1e6, false}},
      {ScriptOp::Depth, {"D", 1, 1000, true}},
      {ScriptOp::Thresh, {"T", 0.0, 1.0, false}},
      {ScriptOp::Zoom, {"FACTOR", 1e-6, 1e6, false}},
      {ScriptOp::Ev, {"STOPS", -5.0, 5.0, false}},
  };
  return table;
}

void parseArguments(const std::string& line, const std::vector<Token>& t, LineParser& p,
                    ScriptAction& a) {
  constexpr double kHuge = 1e30;
  if (const auto it = oneNumberActions().find(a.op); it != oneNumberActions().end()) {
    const OneNumber& n = it->second;
    if (!p.arity(t, 1, n.usage)) return;
    if (n.whole)
      a.index = p.integer(t[1], t[0].text, int(n.min), int(n.max));
    else
      a.values.push_back(p.number(t[1], t[0].text, n.min, n.max));
    return;
  }
  // Arguments first..last (by default to the end of the line), each at least `min`.
  auto numbers = [&](std::size_t first, const char* what, double min,
                     std::size_t last = std::size_t(-1)) {
    for (std::size_t i = first; i < t.size() && i <= last; ++i)
      a.values.push_back(p.number(t[i], what, min, kHuge));
  };
  switch (a.op) {
  case ScriptOp::Wait:
    if (!p.arity(t, 1, "coarse, pass1, done, reload or error")) return;
    if (const auto it = waitTargets().find(t[1].text); it != waitTargets().end()) {
      a.waitFor = it->second;
    } else {
      p.error(t[1], "wait: expected coarse, pass1, done, reload or error, got '" + t[1].text + "'");
    }
    return;
  case ScriptOp::Jitter:
  case ScriptOp::NoAa:
  case ScriptOp::Overlay:
  case ScriptOp::Markers:
    if (p.arity(t, 1, "on or off")) a.values.push_back(p.onOff(t[1]));
    return;
  case ScriptOp::Ambient:
    if (p.arity(t, 3, "R G B")) numbers(1, "ambient", 0.0);
    return;
  case ScriptOp::Fog: // as the scene language's `fog`: every number >= 0
    if (!p.arity(t, 4, "R G B DENSITY")) return;
    numbers(1, "fog colour", 0.0, 3);
    numbers(4, "fog density", 0.0);
    return;
  case ScriptOp::Light:
    if (!p.arity(t, 4, "N X Y Z")) return;
    a.index = p.integer(t[1], "light number", 1, 1000000);
    numbers(2, "light position", -kHuge);
    return;
  case ScriptOp::Intensity:
    if (!p.arity(t, 4, "N R G B")) return;
    a.index = p.integer(t[1], "light number", 1, 1000000);
    numbers(2, "intensity", 0.0);
    return;
  case ScriptOp::Texture: { // as the scene language's `texture` and `surface`
    if (t.size() != 6 && t.size() != 9) {
      p.error(t.size() > 9 ? t[9] : t[0], "texture: expected N SCALE R G B [R0 G0 B0], got " +
                                              std::to_string(t.size() - 1) + " arguments");
      return;
    }
    a.index = p.integer(t[1], "texture number", 1, 1000000);
    a.values.push_back(p.number(t[2], "texture scale", 0.0, kHuge));
    if (double zero = 1.0; toNumber(t[2].text, zero) && zero == 0.0)
      p.error(t[2], "texture scale must be positive, got " + t[2].text);
    numbers(3, "texture colour", 0.0, 5);
    numbers(6, "surface colour", 0.0);
    return;
  }
  case ScriptOp::Orbit:
    if (p.arity(t, 2, "YAW PITCH (degrees)")) numbers(1, "orbit", -kHuge);
    return;
  case ScriptOp::Pan:
    if (p.arity(t, 2, "DX DY (pixels)")) numbers(1, "pan", -kHuge);
    return;
  case ScriptOp::Save:
  case ScriptOp::Screenshot:
    if (t.size() < 2) p.error(t[0], t[0].text + ": expected PATH");
    a.path = restOfLine(line, t[0]);
    return;
  case ScriptOp::Echo: a.path = restOfLine(line, t[0]); return;
  case ScriptOp::Print:
    if (!p.arity(t, 1, "sweep")) return;
    if (t[1].text != "sweep") p.error(t[1], "print: expected sweep, got '" + t[1].text + "'");
    a.path = t[1].text;
    return;
  case ScriptOp::Exposure:
    if (!p.arity(t, 1, "auto or lock")) return;
    if (t[1].text != "auto" && t[1].text != "lock")
      p.error(t[1], "exposure: expected auto or lock, got '" + t[1].text + "'");
    a.values.push_back(t[1].text == "lock" ? 1.0 : 0.0);
    return;
  case ScriptOp::Picture:
    if (!p.arity(t, 1, "fit or PERCENT")) return;
    a.values.push_back(t[1].text == "fit" ? 0.0 : p.number(t[1], "picture", 6.25, 6400.0));
    return;
  case ScriptOp::Inspect:
    if (!p.arity(t, 2, "X Y")) return;
    a.values.push_back(p.integer(t[1], "inspect", 0, 1 << 20));
    a.values.push_back(p.integer(t[2], "inspect", 0, 1 << 20));
    return;
  case ScriptOp::Compare:
    if (t.size() < 2 || t.size() > 3) {
      p.error(t[0], "compare: expected off, flip or split [FRACTION]");
      return;
    }
    if (t[1].text == "off")
      a.index = 0;
    else if (t[1].text == "flip")
      a.index = 1;
    else if (t[1].text == "split")
      a.index = 2;
    else
      p.error(t[1], "compare: expected off, flip or split, got '" + t[1].text + "'");
    a.values.push_back(t.size() == 3 ? p.number(t[2], "compare", 0.0, 1.0) : 0.5);
    return;
  case ScriptOp::Reset:
  case ScriptOp::Reload:
  case ScriptOp::Pin:
  case ScriptOp::Quit: p.arity(t, 0, "no arguments"); return;
  case ScriptOp::Frames:
  case ScriptOp::Timeout:
  case ScriptOp::Depth:
  case ScriptOp::Thresh:
  case ScriptOp::Zoom:
  case ScriptOp::Ev: return; // oneNumberActions, above
  }
}

} // namespace

std::vector<ScriptAction> parseScript(const std::string& text, const std::string& name) {
  std::vector<ScriptAction> actions;
  std::vector<Diagnostic> errors;
  std::istringstream in(text);
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    if (const std::size_t hash = line.find('#'); hash != std::string::npos) line.erase(hash);
    const std::vector<Token> tokens = split(line);
    if (tokens.empty()) continue;
    LineParser p(name, number, errors);
    const auto it = keywords().find(tokens[0].text);
    if (it == keywords().end()) {
      p.error(tokens[0], "unknown action '" + tokens[0].text + "'");
      continue;
    }
    ScriptAction action;
    action.op = it->second;
    action.line = number;
    action.text = restOfLine(line, Token{"", 1});
    parseArguments(line, tokens, p, action);
    if (p.ok()) actions.push_back(std::move(action));
  }
  if (!errors.empty()) throw SceneError(std::move(errors));
  return actions;
}

std::vector<ScriptAction> loadScript(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw SceneError({Diagnostic{path, 1, 1, "cannot read the script"}});
  std::ostringstream text;
  text << in.rdbuf();
  return parseScript(text.str(), path);
}

TextureEdit textureEditOf(const ScriptAction& a, const FileValues& file, const UserEdits& edits) {
  const std::size_t count = file.textures.size();
  if (a.index < 1 || std::size_t(a.index) > count)
    throw std::runtime_error("there is no texture " + std::to_string(a.index) + " (the scene has " +
                             std::to_string(count) + ")");
  const std::size_t i = std::size_t(a.index - 1);
  const bool imageOnly = file.textures[i].group.imageOnly();
  if (imageOnly && a.values.size() == 7)
    throw std::runtime_error("texture " + std::to_string(a.index) +
                             " is an image: give SCALE R G B (its size and the surface colour)");
  TextureValues values = edits.textureOver(file, i);
  const auto colour = [&](std::size_t first) {
    return Color(a.values[first], a.values[first + 1], a.values[first + 2]);
  };
  values.scale = a.values[0];
  if (imageOnly) {
    values.base = colour(1);
  } else {
    values.color = colour(1);
    if (a.values.size() == 7) values.base = colour(4);
  }
  return {i, values};
}

bool ScriptRunner::step(ScriptHost& host, Clock::time_point now) {
  while (next_ < actions_.size()) {
    const ScriptAction& action = actions_[next_];
    auto fail = [&](const std::string& why) {
      throw std::runtime_error("script line " + std::to_string(action.line) + " (" + action.text +
                               "): " + why);
    };
    try {
      if (!started_) {
        if (action.op == ScriptOp::Timeout) timeoutSeconds_ = action.values[0];
        host.start(action);
        started_ = true;
        startedAt_ = now;
      }
      if (!host.finished(action)) {
        if (std::chrono::duration<double>(now - startedAt_).count() > timeoutSeconds_) {
          std::ostringstream why;
          why << "did not complete within " << timeoutSeconds_ << " s";
          fail(why.str());
        }
        return true; // try again next frame
      }
    } catch (const std::runtime_error& error) {
      if (std::string(error.what()).rfind("script line ", 0) == 0) throw;
      fail(error.what());
    }
    started_ = false;
    ++next_;
    if (action.op == ScriptOp::Quit) next_ = actions_.size(); // nothing runs after quit
  }
  return false;
}

} // namespace prism
