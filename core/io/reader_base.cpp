#include "core/io/reader_base.h"

namespace prism {

std::string Location::text() const {
  return file + ":" + std::to_string(line) + ":" + std::to_string(column);
}

void ReaderBase::report(Location at, std::string message) {
  if (diagnostics_.size() >= kMaxDiagnostics) {
    diagnostics_.push_back({std::move(at.file), at.line, at.column, "too many errors; giving up"});
    throw StopReading{};
  }
  diagnostics_.push_back({std::move(at.file), at.line, at.column, std::move(message)});
}

void ReaderBase::invalid(Command& c, const Token& at, const std::string& message) {
  c.valid = false;
  error(at, c.name + ": " + message);
}

void ReaderBase::resync() {
  const Token& token = lexer().peek();
  if (!token.atEnd() && !startsCommand(token.text)) lexer().next();
  skipNumbers();
}

void ReaderBase::skipNumbers() {
  while (!lexer().peek().atEnd() && isNumber(lexer().peek().text))
    lexer().next();
}

bool ReaderBase::once(Command& c) {
  const Location here{fileName(), c.keyword.line, c.keyword.column};
  const auto [first, inserted] = firstGiven_.try_emplace(c.name, here);
  if (!inserted) {
    c.valid = false;
    error(c.keyword, duplicateMessage(c.name, first->second));
  }
  return inserted;
}

const Location* ReaderBase::firstGiven(const std::string& name) const {
  const auto it = firstGiven_.find(name);
  return it == firstGiven_.end() ? nullptr : &it->second;
}

std::string ReaderBase::duplicateMessage(const std::string& name, const Location& first) {
  return "duplicate '" + name + "' (first given at " + first.text() + ")";
}

bool ReaderBase::argumentToken(Command& c, const char* name, const char* kind, Token& out) {
  out = lexer().peek();
  if (out.atEnd()) { // reported at the command: the end of the file has no place to show
    error(c.keyword, c.name + ": expected " + name + " but reached the end of the file");
    return false;
  }
  if (!isNumber(out.text)) {
    error(out, c.name + ": expected " + name + " (" + kind + ") but found " + quoted(out.text));
    resync();
    return false;
  }
  lexer().next();
  return true;
}

bool ReaderBase::number(Command& c, const char* name, Arg& out) {
  if (!argumentToken(c, name, "a number", out.token)) return false;
  if (parseNumber(out.token.text, out.value) == NumberKind::NonFinite) {
    invalid(c, out.token,
            std::string(name) + " is not a finite number (" + quoted(out.token.text) + ")");
    // NaN fails every later range check silently: one message per bad argument.
    out.value = std::numeric_limits<double>::quiet_NaN();
  }
  return true;
}

bool ReaderBase::integer(Command& c, const char* name, std::uint64_t lo, std::uint64_t hi,
                         std::optional<std::uint64_t>& out) {
  Token token;
  if (!argumentToken(c, name, "an integer", token)) return false;
  out = parseInteger(token.text);
  if (!out || *out < lo || *out > hi) {
    invalid(c, token,
            std::string(name) + " must be an integer from " + std::to_string(lo) + " to " +
                std::to_string(hi) + ", found " + quoted(token.text));
    out.reset();
  }
  return true;
}

void ReaderBase::requireNonNegative(Command& c, const Arg& a, const char* name) {
  if (a.value < 0.0) {
    invalid(c, a.token, std::string(name) + " must not be negative, found " + quoted(a.token.text));
  }
}

void ReaderBase::requireColor(Command& c, const Arg* rgb) {
  static constexpr const char* kNames[] = {"R", "G", "B"};
  for (int i = 0; i < 3; ++i) {
    requireNonNegative(c, rgb[i], kNames[i]);
  }
}

std::optional<std::uint64_t> ReaderBase::vertexCount(Command& c) {
  std::optional<std::uint64_t> count;
  if (!integer(c, "N", 3, kMaxPolygonVertices, count)) return std::nullopt;
  if (!count) skipNumbers();
  return count;
}

void ReaderBase::missingVertexNumber(Command& c, std::uint64_t count, std::uint64_t wanted,
                                     std::uint64_t found, const Token& token) {
  const std::string expected = c.name + ": expected " + std::to_string(wanted) + " numbers for " +
                               std::to_string(count) + " vertices, found " + std::to_string(found);
  if (token.atEnd()) {
    error(c.keyword, expected + " before the end of the file");
  } else {
    error(token, expected + " before " + quoted(token.text));
    resync();
  }
}

void ReaderBase::nonFiniteVertexNumber(Command& c, std::uint64_t found, std::uint64_t perVertex,
                                       const Token& token) {
  const std::uint64_t slot = found % perVertex; // 0-2 the point, 3-5 the normal
  const std::string name = (slot >= 3 ? "N" : "") + std::string(1, "XYZ"[slot % 3]) +
                           std::to_string(found / perVertex + 1);
  invalid(c, token, name + " is not a finite number (" + quoted(token.text) + ")");
}

std::string readSceneText(const std::filesystem::path& path, std::size_t maxBytes) {
  std::string text;
  if (const std::optional<std::string> problem = readFile(path, false, text, maxBytes)) {
    throw SceneError({Diagnostic{path.string(), 1, 1, "cannot read file: " + *problem}});
  }
  return text;
}

} // namespace prism
