// The text layer shared by every scene reader (.sc, NFF): numbers in C
// syntax read independently of the locale, integer literals, white-space
// separated tokens with `#` comments and their line and column, tokens quoted
// safely inside messages, and whole files read with a size limit.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace prism {

// The largest scene text read (a single file, and for .sc everything read
// through includes): keeps hostile input from exhausting memory.
inline constexpr std::size_t kMaxSceneBytes = std::size_t(256) << 20;

enum class NumberKind { NotANumber, Finite, NonFinite };

// Parses a whole token in C floating-point syntax (decimal or hexadecimal,
// optional sign; "inf" and "nan" recognised so that they can be rejected by
// name). A number too small for a double becomes 0, as with strtod.
NumberKind parseNumber(std::string_view text, double& value);
bool isNumber(std::string_view text);

// An integer literal: digits with an optional '+'. Saturates at 2^62.
std::optional<std::uint64_t> parseInteger(std::string_view text);

// Text as it may appear inside a message: control bytes and bytes that are
// not well-formed UTF-8 escaped as \xHH, everything else unchanged.
std::string printable(std::string_view text);

// A token as it may appear inside a message: quoted, printable, long tokens
// shortened.
std::string quoted(std::string_view text);

bool isSpace(char c);

struct Token {
  std::string_view text; // empty only at the end of the file
  int line = 0;
  int column = 0;

  bool atEnd() const { return text.empty(); }
};

// Splits one file's text into white-space separated tokens, dropping comments,
// with one token of lookahead.
class Lexer {
public:
  explicit Lexer(std::string_view text) : text_(text) {
    // Some editors start UTF-8 files with a byte order mark; columns count after it.
    if (text_.substr(0, 3) == "\xEF\xBB\xBF") position_.offset = position_.lineStart = 3;
  }

  const Token& peek() {
    if (!peeked_) {
      beforePeek_ = position_;
      peeked_ = scan(false);
    }
    return *peeked_;
  }

  Token next() {
    const Token token = peek();
    peeked_.reset();
    return token;
  }

  // The PATH of `include`: the next token, or a double-quoted string on one line
  // that may contain white space and '#'. An unterminated quote yields a token
  // that starts with '"' and does not end with one.
  Token nextPath() {
    if (peeked_) { // scanned the plain way: scan it again
      position_ = beforePeek_;
      peeked_.reset();
    }
    return scan(true);
  }

private:
  struct Position {
    std::size_t offset = 0;
    std::size_t lineStart = 0;
    int line = 1;
  };

  void skipSpaceAndComments() {
    while (position_.offset < text_.size()) {
      const char c = text_[position_.offset];
      if (c == '#') {
        const std::size_t newline = text_.find('\n', position_.offset);
        position_.offset = newline == std::string_view::npos ? text_.size() : newline;
      } else if (isSpace(c)) {
        ++position_.offset;
        if (c == '\n') {
          ++position_.line;
          position_.lineStart = position_.offset;
        }
      } else {
        return;
      }
    }
  }

  Token scan(bool path) {
    skipSpaceAndComments();
    Token token;
    token.line = position_.line;
    token.column = int(position_.offset - position_.lineStart + 1);
    const std::size_t start = position_.offset;
    std::size_t end = start;
    if (path && start < text_.size() && text_[start] == '"') {
      const std::size_t close = text_.find_first_of("\"\n", start + 1);
      end = close == std::string_view::npos ? text_.size()
                                            : (text_[close] == '"' ? close + 1 : close);
    } else {
      while (end < text_.size() && !isSpace(text_[end]) && text_[end] != '#') {
        ++end;
      }
    }
    token.text = text_.substr(start, end - start);
    position_.offset = end;
    return token;
  }

  std::string_view text_;
  Position position_;
  Position beforePeek_;
  std::optional<Token> peeked_;
};

// Reads a whole file into `out`. Refuses more than `maxBytes`, so that a device
// such as /dev/zero cannot exhaust memory, and (with regularOnly) anything but a
// regular file, so that a FIFO cannot block. Returns the reason on failure.
std::optional<std::string> readFile(const std::filesystem::path& path, bool regularOnly,
                                    std::string& out, std::size_t maxBytes = kMaxSceneBytes);

// The same file reached by different spellings of its path gets one identity, for
// include-cycle detection, the contents cache and Scene::files.
std::filesystem::path identityOf(const std::filesystem::path& path);

} // namespace prism
