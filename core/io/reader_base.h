// What the .sc parser and the NFF reader share: reading a command's numeric
// and integer arguments with their checks, reporting each problem at its
// token as FILE:LINE:COLUMN (Diagnostic), skipping the rest of a broken
// command, and giving up after kMaxDiagnostics errors. The two formats differ
// in their commands, not in how an argument is read or a mistake reported, so
// the messages agree word for word between them.
#pragma once

#include "core/io/diagnostic.h"
#include "core/io/scene_text.h"
#include "core/math/math.h"
#include "core/scene/camera.h"

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace prism {

// Unwinds a reader once the diagnostic cap is reached, or after an error
// that would bury the rest under follow-up errors.
struct StopReading {};

// A place in a scene file, kept for messages about it later.
struct Location {
  std::string file;
  int line = 1;
  int column = 1;

  std::string text() const; // "FILE:LINE:COLUMN"
};

// A numeric argument and the token it was read from (for messages).
struct Arg {
  double value = 0.0;
  Token token;
};

inline Vec3 vec(const Arg* a) { return Vec3(a[0].value, a[1].value, a[2].value); }

// One command being read.
struct Command {
  Token keyword;     // errors about the whole command are reported here
  std::string name;  // how messages name it: "sphere", NFF's "s" or "from"
  bool valid = true; // false once an argument broke a constraint: not applied
};

// The largest width or height a scene file may ask for (`resolution`).
inline constexpr int kMaxResolution = 32768;
// The largest N of a polygon: vertices are counted in 32 bits.
inline constexpr std::uint64_t kMaxPolygonVertices = std::numeric_limits<std::uint32_t>::max();

class ReaderBase {
public:
  static constexpr std::size_t kMaxDiagnostics = 50;

  virtual ~ReaderBase() = default;

protected:
  // Runs `read`, then throws what it reported as a SceneError, if anything.
  template <class Read> void readAll(Read&& read) {
    try {
      read();
    } catch (const StopReading&) {
    }
    if (!diagnostics_.empty()) throw SceneError(std::move(diagnostics_));
  }

  // The file being read (the .sc parser switches files at includes).
  void readFrom(Lexer& lexer, const std::string& file) {
    lexer_ = &lexer;
    file_ = &file;
  }
  Lexer& lexer() { return *lexer_; }
  const std::string& fileName() const { return *file_; }

  // Whether `word` starts a command: where skipping a broken one stops.
  virtual bool startsCommand(std::string_view word) const = 0;

  // --- Diagnostics and recovery

  // Records an error; throws StopReading past the cap.
  void report(Location at, std::string message);
  void error(const Token& at, std::string message) {
    report({fileName(), at.line, at.column}, std::move(message));
  }
  // An error in an argument of `c`: "NAME: message"; `c` is not applied.
  void invalid(Command& c, const Token& at, const std::string& message);
  // The errors recorded so far (a block can tell whether any fell inside it).
  std::size_t diagnosticCount() const { return diagnostics_.size(); }
  // After a missing or malformed argument: drops the offending token unless
  // it starts the next command, then the numbers that belonged to the broken
  // command.
  void resync();
  void skipNumbers();

  // Commands that may be given once (camera and image settings): false, and
  // an error, for a repeat. Where each was first given stays known.
  bool once(Command& c);
  const Location* firstGiven(const std::string& name) const;
  // "duplicate 'NAME' (first given at FILE:LINE:COLUMN)"
  static std::string duplicateMessage(const std::string& name, const Location& first);

  // --- Arguments. Each returns false when the argument is missing (already
  // reported and the input resynchronised); the command must then stop
  // reading.

  // The next token, which must be a number (`kind` says what kind, for the
  // message).
  bool argumentToken(Command& c, const char* name, const char* kind, Token& out);
  // A number; a non-finite one is reported, and reads as NaN.
  bool number(Command& c, const char* name, Arg& out);
  template <std::size_t N> bool numbers(Command& c, const char* const (&names)[N], Arg (&out)[N]) {
    for (std::size_t i = 0; i < N; ++i) {
      if (!number(c, names[i], out[i])) return false;
    }
    return true;
  }
  // An integer from lo to hi; `out` is empty when the token is not one
  // (reported, the command invalid).
  bool integer(Command& c, const char* name, std::uint64_t lo, std::uint64_t hi,
               std::optional<std::uint64_t>& out);
  void requireNonNegative(Command& c, const Arg& a, const char* name);
  void requireColor(Command& c, const Arg* rgb); // R G B, each non-negative

  // A polygon's N, from 3 to kMaxPolygonVertices; nothing when missing or
  // out of range (reported, the command's numbers skipped).
  std::optional<std::uint64_t> vertexCount(Command& c);
  // Reads `count` vertices of `perVertex` numbers each (a point, then for 6
  // a normal), calling take(i, value, token) with the i-th number as it
  // comes, so that a hostile N costs nothing until the numbers are there.
  // Non-finite numbers are reported (X1, NY2, ...) and the command made
  // invalid. False when the numbers run out (reported).
  template <class Take>
  bool vertexNumbers(Command& c, std::uint64_t count, std::uint64_t perVertex, Take&& take) {
    const std::uint64_t wanted = perVertex * count;
    for (std::uint64_t found = 0; found < wanted; ++found) {
      const Token token = lexer().peek();
      double value = 0.0;
      const NumberKind kind =
          token.atEnd() ? NumberKind::NotANumber : parseNumber(token.text, value);
      if (kind == NumberKind::NotANumber) {
        missingVertexNumber(c, count, wanted, found, token);
        return false;
      }
      lexer().next();
      if (kind == NumberKind::NonFinite) nonFiniteVertexNumber(c, found, perVertex, token);
      take(found, value, token);
    }
    return true;
  }

private:
  void missingVertexNumber(Command& c, std::uint64_t count, std::uint64_t wanted,
                           std::uint64_t found, const Token& token);
  void nonFiniteVertexNumber(Command& c, std::uint64_t found, std::uint64_t perVertex,
                             const Token& token);

  std::vector<Diagnostic> diagnostics_;
  std::map<std::string, Location> firstGiven_; // commands allowed once, by name
  Lexer* lexer_ = nullptr;
  const std::string* file_ = nullptr;
};

// The whole text of a scene file `path` (at most maxBytes); a SceneError
// "cannot read file: ..." at its first line when that fails.
std::string readSceneText(const std::filesystem::path& path, std::size_t maxBytes = kMaxSceneBytes);

} // namespace prism
