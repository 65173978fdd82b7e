#include "core/io/scene_text.h"

#include <array>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>

namespace prism {

namespace fs = std::filesystem;

// ---------------------------------------------------------------------------
// Numbers

// from_chars reports overflow and underflow alike as out of range. Which one it
// was follows from the order of magnitude: where the first significant digit sits
// relative to the radix point, plus the exponent. `body` has no sign or "0x".
namespace {

bool overflows(std::string_view body, bool hex) {
  const char exponentChar = hex ? 'p' : 'e';
  long long order = 0; // the magnitude is about base^(order - 1)
  bool afterPoint = false, significant = false;
  std::size_t i = 0;
  for (; i < body.size(); ++i) {
    const char c = char(body[i] | 0x20); // lower case for letters
    if (c == exponentChar) break;
    if (body[i] == '.') {
      afterPoint = true;
    } else if (!significant && body[i] == '0') {
      if (afterPoint) --order;
    } else {
      significant = true;
      if (!afterPoint) ++order;
    }
  }
  long long exponent = 0;
  bool negativeExponent = false;
  if (++i < body.size() && (body[i] == '+' || body[i] == '-')) negativeExponent = body[i++] == '-';
  for (; i < body.size(); ++i) {
    exponent = std::min(exponent * 10 + (body[i] - '0'), 1'000'000'000'000LL);
  }
  if (negativeExponent) exponent = -exponent;
  const long long digitScale = hex ? 4 : 1; // hex digits are 4 binary orders, 'p' counts in 2s
  return (order - 1) * digitScale + exponent > 0;
}

} // namespace

// Parses a whole token in C floating-point syntax (decimal or hexadecimal, optional
// sign, "inf" and "nan" recognised so that they can be rejected by name). Independent
// of the C locale, unlike strtod.
NumberKind parseNumber(std::string_view text, double& value) {
  std::string_view body = text;
  bool negative = false;
  if (!body.empty() && (body[0] == '+' || body[0] == '-')) {
    negative = body[0] == '-';
    body.remove_prefix(1);
  }
  auto format = std::chars_format::general;
  if (body.size() > 2 && body[0] == '0' && (body[1] == 'x' || body[1] == 'X')) {
    body.remove_prefix(2);
    format = std::chars_format::hex;
  }
  // from_chars takes its own '-' (which would let "--1" and "0x-1" through) and no '+'.
  if (body.empty() || body[0] == '+' || body[0] == '-') return NumberKind::NotANumber;
  const char* end = body.data() + body.size();
  const auto [ptr, ec] = std::from_chars(body.data(), end, value, format);
  if (ptr != end || ec == std::errc::invalid_argument) return NumberKind::NotANumber;
  if (ec == std::errc::result_out_of_range) {
    if (overflows(body, format == std::chars_format::hex)) return NumberKind::NonFinite;
    value = 0.0; // too small for a double: rounds to zero, as strtod does
  }
  if (negative) value = -value;
  return std::isfinite(value) ? NumberKind::Finite : NumberKind::NonFinite;
}

bool isNumber(std::string_view text) {
  double ignored = 0.0;
  return parseNumber(text, ignored) != NumberKind::NotANumber;
}

// An integer literal: digits with an optional '+'. Saturates instead of wrapping
// (every caller has a much smaller upper bound).
std::optional<std::uint64_t> parseInteger(std::string_view text) {
  if (!text.empty() && text[0] == '+') text.remove_prefix(1);
  if (text.empty()) return std::nullopt;
  constexpr std::uint64_t kSaturated = std::uint64_t(1) << 62;
  std::uint64_t value = 0;
  for (const char c : text) {
    if (c < '0' || c > '9') return std::nullopt;
    value = std::min(value * 10 + std::uint64_t(c - '0'), kSaturated);
  }
  return value;
}

namespace {

// The length of the well-formed UTF-8 sequence at the start of `text`
// (Unicode's table 3-7: no overlong forms, no surrogates, nothing above
// U+10FFFF), or 0 if it does not start with one.
std::size_t utf8SequenceLength(std::string_view text) {
  const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(text[i]); };
  const unsigned char lead = byte(0);
  std::size_t length = 0;
  unsigned char secondLo = 0x80, secondHi = 0xBF;
  if (lead >= 0xC2 && lead <= 0xDF) {
    length = 2;
  } else if (lead >= 0xE0 && lead <= 0xEF) {
    length = 3;
    if (lead == 0xE0) secondLo = 0xA0; // overlong below U+0800
    if (lead == 0xED) secondHi = 0x9F; // surrogates
  } else if (lead >= 0xF0 && lead <= 0xF4) {
    length = 4;
    if (lead == 0xF0) secondLo = 0x90; // overlong below U+10000
    if (lead == 0xF4) secondHi = 0x8F; // above U+10FFFF
  } else {
    return 0;
  }
  if (text.size() < length || byte(1) < secondLo || byte(1) > secondHi) return 0;
  for (std::size_t i = 2; i < length; ++i)
    if (byte(i) < 0x80 || byte(i) > 0xBF) return 0;
  return length;
}

} // namespace

// Control bytes and bytes that are not part of well-formed UTF-8 become \xHH,
// so that a message never carries raw binary input to the terminal.
std::string printable(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size();) {
    const auto byte = static_cast<unsigned char>(text[i]);
    if (byte >= 0x80) {
      if (const std::size_t n = utf8SequenceLength(text.substr(i))) {
        out.append(text.substr(i, n));
        i += n;
        continue;
      }
    } else if (byte >= 0x20 && byte != 0x7F) {
      out += text[i++];
      continue;
    }
    static constexpr char kHex[] = "0123456789abcdef";
    out += "\\x";
    out += kHex[byte >> 4];
    out += kHex[byte & 0xF];
    ++i;
  }
  return out;
}

// A token as it may appear inside a message: quoted, made printable and
// shortened (hostile input can hold megabyte-long "tokens").
std::string quoted(std::string_view text) {
  constexpr std::size_t kMaxShown = 40;
  bool shortened = false;
  if (text.size() > kMaxShown) {
    std::size_t cut = kMaxShown;
    while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80) {
      --cut; // not inside a UTF-8 sequence
    }
    text = text.substr(0, cut);
    shortened = true;
  }
  return "'" + printable(text) + (shortened ? "...'" : "'");
}

bool isSpace(char c) {
  return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f';
}

// ---------------------------------------------------------------------------
// Files

std::optional<std::string> readFile(const fs::path& path, bool regularOnly, std::string& out,
                                    std::size_t maxBytes) {
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (regularOnly && !ec && fs::exists(status) && !fs::is_regular_file(status)) {
    return fs::is_directory(status) ? std::strerror(EISDIR) : "not a regular file";
  }
  errno = 0;
  const std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "rb"),
                                                             &std::fclose);
  if (!file) return std::strerror(errno != 0 ? errno : ENOENT);
  std::array<char, 1 << 16> buffer;
  while (const std::size_t n = std::fread(buffer.data(), 1, buffer.size(), file.get())) {
    if (out.size() + n > maxBytes) return "larger than " + std::to_string(maxBytes >> 20) + " MiB";
    out.append(buffer.data(), n);
  }
  if (std::ferror(file.get())) return std::strerror(errno != 0 ? errno : EIO);
  return std::nullopt;
}

fs::path identityOf(const fs::path& path) {
  std::error_code ec;
  fs::path canonical = fs::weakly_canonical(path, ec);
  if (!ec) return canonical;
  canonical = fs::absolute(path, ec);
  return ec ? path.lexically_normal() : canonical.lexically_normal();
}

} // namespace prism
