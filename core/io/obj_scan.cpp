#include "core/io/obj_scan.h"

#include "core/io/scene_text.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <functional>
#include <optional>
#include <stdexcept>
#include <utility>

namespace prism {

namespace {

constexpr std::size_t kMaxDiagnostics = 50;

struct TooManyErrors {};

// One line cut into words, each with its column. The scan and the copy
// tinyobjloader reads (normalise*ForTinyObj) both cut the text with this
// reader, so they see the same lines and words:
// - a line ends at "\n", "\r" or "\r\n", as tinyobjloader's safeGetline ends
//   it, so that both number lines alike;
// - words are separated by isSpace (also \v and \f, as in Prism's other
//   readers); the copy separates them by single spaces, which tinyobjloader's
//   IS_SPACE (' ' and '\t' only) reads the same way;
// - `#` starts a comment anywhere (for tinyobjloader only at the start of a
//   line; the copy has none);
// - a UTF-8 byte-order mark is skipped, and never copied.
// A statement never spans lines: Prism does not support the rare `\`
// continuation, and neither does tinyobjloader.
struct Line {
  int number = 0;
  std::vector<Token> words;
  bool ended = false; // by a line break; the last line may end with the text
};

class LineReader {
public:
  explicit LineReader(std::string_view text) : text_(text) {
    if (text_.substr(0, 3) == "\xEF\xBB\xBF") offset_ = 3;
  }

  bool next(Line& line) {
    if (offset_ >= text_.size()) return false;
    const std::size_t start = offset_;
    const std::size_t end = std::min(text_.find_first_of("\r\n", start), text_.size());
    line.ended = end < text_.size();
    offset_ = end + (text_.compare(end, 2, "\r\n") == 0 ? 2 : 1);
    line.number = ++number_;
    line.words.clear();
    std::size_t i = start;
    while (i < end) {
      while (i < end && isSpace(text_[i]))
        ++i;
      if (i >= end || text_[i] == '#') break;
      const std::size_t wordStart = i;
      while (i < end && !isSpace(text_[i]) && text_[i] != '#')
        ++i;
      line.words.push_back(
          {text_.substr(wordStart, i - wordStart), number_, int(wordStart - start + 1)});
    }
    return true;
  }

  // Where the next line starts: everything before it has been read.
  std::size_t offset() const { return std::min(offset_, text_.size()); }

private:
  std::string_view text_;
  std::size_t offset_ = 0;
  int number_ = 0;
};

// Whether tinyobjloader's number parser reads `text` (a finite number to
// parseNumber) as the scan does. It knows plain decimals only ([sign] digits
// [. digits] [e [sign] digits]; "0x1p0" is 0 to it) and computes mantissa *
// 5^e * 2^e: with at most 64 characters and |e| <= 300 as written, no step
// overflows or underflows ("0e500" is NaN to it, 400 zeros after the point
// drop the digit after them), so it reads the value to a few ulps.
bool tinyObjReadsAlike(std::string_view text) {
  constexpr std::size_t kMaxCharacters = 64;
  constexpr long long kMaxExponent = 300;
  if (text.size() > kMaxCharacters) return false;
  std::size_t i = 0;
  const auto sign = [&] {
    if (i < text.size() && (text[i] == '+' || text[i] == '-')) ++i;
  };
  const auto digits = [&] {
    long long value = 0;
    std::size_t count = 0;
    for (; i < text.size() && text[i] >= '0' && text[i] <= '9'; ++i, ++count)
      value = std::min(value * 10 + (text[i] - '0'), kMaxExponent + 1);
    return std::pair{count, value};
  };
  sign();
  std::size_t mantissaDigits = digits().first;
  if (i < text.size() && text[i] == '.') {
    ++i;
    mantissaDigits += digits().first;
  }
  if (mantissaDigits == 0) return false;
  if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
    ++i;
    sign();
    const auto [count, exponent] = digits();
    if (count == 0 || exponent > kMaxExponent) return false;
  }
  return i == text.size();
}

class Scanner {
public:
  Scanner(ObjScan& scan, const std::string& name) : scan_(scan), name_(name) {}

  void error(const Token& at, std::string message) {
    if (scan_.errors.size() >= kMaxDiagnostics) {
      scan_.errors.push_back({name_, at.line, at.column, "too many errors; giving up"});
      throw TooManyErrors{};
    }
    scan_.errors.push_back({name_, at.line, at.column, std::move(message)});
  }

  // tinyobjloader reads a line as a C string, so a NUL byte would end the
  // statement for it and not for the scan. Comments may hold them.
  bool noNulByte(const Line& line) {
    for (const Token& w : line.words) {
      const std::size_t at = w.text.find('\0');
      if (at != std::string_view::npos) {
        error({w.text.substr(at, 1), w.line, w.column + int(at)}, "unexpected NUL byte");
        return false;
      }
    }
    return true;
  }

  // Checks that words[first, first + count) are finite numbers that
  // tinyobjloader reads alike; `names` label them in messages. Reports a
  // missing one at the statement keyword.
  bool numbers(const Line& line, std::size_t first, std::size_t count, const char* const* names,
               double* values = nullptr) {
    const std::string keyword(line.words[0].text);
    for (std::size_t i = 0; i < count; ++i) {
      if (first + i >= line.words.size()) {
        error(line.words[0],
              keyword + ": expected " + names[i] + " (a number) at the end of the line");
        return false;
      }
      const Token& w = line.words[first + i];
      double value = 0.0;
      const NumberKind kind = parseNumber(w.text, value);
      if (kind == NumberKind::NotANumber) {
        error(w, keyword + ": expected " + names[i] + " (a number) but found " + quoted(w.text));
        return false;
      }
      if (kind == NumberKind::NonFinite) {
        error(w, keyword + ": " + names[i] + " is not a finite number (" + quoted(w.text) + ")");
        return false;
      }
      if (!tinyObjReadsAlike(w.text)) {
        error(w, keyword + ": " + names[i] +
                     " must be a plain decimal number (at most 64 characters, an exponent from "
                     "-300 to 300), found " +
                     quoted(w.text));
        return false;
      }
      if (values != nullptr) values[i] = value;
    }
    return true;
  }

  bool noMoreThan(const Line& line, std::size_t count) {
    if (line.words.size() <= count) return true;
    const Token& extra = line.words[count];
    error(extra, std::string(line.words[0].text) + ": unexpected " + quoted(extra.text) +
                     " after the statement's arguments");
    return false;
  }

private:
  ObjScan& scan_;
  const std::string& name_;
};

// An `f` corner's vertex, texture coordinate and normal index as written,
// empty where absent ("1", "1/2", "1//3", "1/2/3", also "1/" and "1//");
// nothing when it has more than two '/'.
std::optional<std::array<std::string_view, 3>> cornerParts(std::string_view corner) {
  std::array<std::string_view, 3> parts;
  for (std::size_t part = 0;; ++part) {
    const std::size_t slash = corner.find('/');
    if (part == parts.size()) return std::nullopt;
    parts[part] = corner.substr(0, slash);
    if (slash == std::string_view::npos) return parts;
    corner.remove_prefix(slash + 1);
  }
}

// One index of a corner: a non-zero integer, negative counting back from the
// latest of the `count` statements so far. Returns the problem, if any.
std::optional<std::string> checkIndex(std::string_view text, std::size_t part, long long count) {
  static constexpr const char* kWhat[] = {"vertex", "texture coordinate", "normal"};
  static constexpr const char* kStatement[] = {"v", "vt", "vn"};
  std::string_view digits = text;
  if (!digits.empty() && (digits[0] == '-' || digits[0] == '+')) digits.remove_prefix(1);
  const std::optional<std::uint64_t> value = parseInteger(digits);
  if (!value || digits.empty() || digits[0] == '+') {
    return std::string("expected a ") + kWhat[part] + " index (an integer) but found " +
           quoted(text);
  }
  if (*value == 0) return std::string(kWhat[part]) + " index 0 (indices count from 1)";
  if (*value > std::uint64_t(count)) {
    // As written: parseInteger saturates, and a huge index is best recognised.
    return std::string(kWhat[part]) + " index " + quoted(text) + " is out of range (" +
           std::to_string(count) + " '" + kStatement[part] + "' statements before this face)";
  }
  return std::nullopt;
}

// One `f` corner: v, v/t, v//n or v/t/n; `counts` are the v, vt and vn
// statements so far. Returns the problem, if any.
std::optional<std::string> checkCorner(std::string_view corner,
                                       const std::array<long long, 3>& counts) {
  const std::optional<std::array<std::string_view, 3>> parts = cornerParts(corner);
  if (!parts) return "too many '/' in " + quoted(corner);
  if ((*parts)[0].empty()) {
    return "expected a vertex index (an integer) but found " + quoted(corner);
  }
  for (std::size_t part = 0; part < 3; ++part) {
    if ((*parts)[part].empty()) continue;
    if (std::optional<std::string> problem = checkIndex((*parts)[part], part, counts[part])) {
      return problem;
    }
  }
  return std::nullopt;
}

bool ignoredObjStatement(std::string_view k) {
  // Grouping, smoothing, lines and points, and the free-form geometry Prism
  // does not render.
  static constexpr std::string_view kIgnored[] = {
      "o",     "g",        "s",        "l",    "p",          "vp",        "cstype",
      "deg",   "bmat",     "step",     "curv", "curv2",      "surf",      "parm",
      "trim",  "hole",     "scrv",     "sp",   "end",        "con",       "mg",
      "bevel", "c_interp", "d_interp", "lod",  "shadow_obj", "trace_obj", "ctech",
      "stech", "maplib",   "usemap",   "call", "csh",        "vw",        "t"};
  for (const std::string_view i : kIgnored) {
    if (k == i) return true;
  }
  return false;
}

// The text of `words` from the first to the last, with what separates them.
std::string_view span(const std::vector<Token>& words, std::size_t first) {
  const Token& last = words.back();
  return {words[first].text.data(),
          std::size_t(last.text.data() + last.text.size() - words[first].text.data())};
}

// Writes a text over itself, front to back: each statement of the copy is at
// most as long as the line it comes from (single spaces where the line had at
// least one separator, corners only shortened, a comment or CRLF at most
// dropped), so nothing is overwritten before it is read. Checked all the same:
// a mistake would be an exception, not a garbled copy.
class InPlaceWriter {
public:
  explicit InPlaceWriter(std::string& text) : text_(text) {}

  // `s` is a literal or lies in the text at or after the writing position.
  void put(std::string_view s) {
    if (s.empty()) return; // (memmove must not be given a null pointer)
    const std::less<const char*> before;
    const char* const at = text_.data() + at_;
    if (!before(s.data(), text_.data()) && before(s.data(), at)) overtaken();
    std::memmove(text_.data() + at_, s.data(), s.size());
    at_ += s.size();
  }

  void putWords(const std::vector<Token>& words, std::size_t count) {
    for (std::size_t i = 0; i < count && i < words.size(); ++i) {
      if (i > 0) put(" ");
      put(words[i].text);
    }
  }

  // Ends a line; `readUpTo` is where the reader's next line starts.
  void endLine(bool lineBreak, std::size_t readUpTo) {
    if (lineBreak) put("\n");
    if (at_ > readUpTo) overtaken();
  }

  void finish() { text_.resize(at_); }

private:
  [[noreturn]] static void overtaken() {
    throw std::logic_error("normalising for tinyobjloader overtook the text being read");
  }

  std::string& text_;
  std::size_t at_ = 0;
};

void writeObjStatement(const Line& line, InPlaceWriter& out) {
  const std::string_view k = line.words[0].text;
  if (k == "v" || k == "vn" || ((k == "o" || k == "g") && line.words.size() > 1)) {
    out.putWords(line.words, line.words.size());
  } else if (k == "vt") {
    out.putWords(line.words, 3); // U and V (0 when absent, for both); W is not used
  } else if (k == "f") {
    out.put(k);
    for (std::size_t i = 1; i < line.words.size(); ++i) {
      const std::array<std::string_view, 3> parts =
          cornerParts(line.words[i].text).value_or(std::array<std::string_view, 3>{});
      out.put(" ");
      out.put(parts[0]);
      if (!parts[1].empty() || !parts[2].empty()) out.put("/");
      out.put(parts[1]);
      if (!parts[2].empty()) {
        out.put("/");
        out.put(parts[2]);
      }
    }
  }
}

void writeMtlStatement(const Line& line, InPlaceWriter& out) {
  const std::string_view k = line.words[0].text;
  if (k == "newmtl" && line.words.size() > 1) {
    // tinyobjloader names a material by the rest of its line.
    out.put("newmtl ");
    out.put(span(line.words, 1));
  } else if (k == "Kd" || k == "Ks") {
    out.putWords(line.words, 4);
  } else if (k == "Ns" || k == "Ni" || k == "d" || k == "Tr" || k == "illum") {
    out.putWords(line.words, 2);
  }
  // The rest has no counterpart in Prism's model: tinyobjloader need not see
  // it (nor parse its texture options).
}

template <typename WriteStatement>
void normalise(std::string& text, WriteStatement writeStatement) {
  InPlaceWriter out(text);
  LineReader reader(text);
  Line line;
  while (reader.next(line)) {
    if (!line.words.empty()) writeStatement(line, out);
    out.endLine(line.ended, reader.offset());
  }
  out.finish();
}

void normaliseMtlForTinyObj(std::string& text) { normalise(text, writeMtlStatement); }

// A file named in an OBJ or MTL file, relative to that file's `directory`.
// Exporters on Windows write folders with backslashes (`maps\wood.png`). A
// backslash is a legal character of a name here, so such a name is read with
// each backslash as a folder separator only where that file exists and the
// name as written does not; a message about a missing file quotes the name
// as written.
std::filesystem::path referencedFile(const std::filesystem::path& directory,
                                     std::string_view written) {
  const std::filesystem::path asWritten = (directory / std::string(written)).lexically_normal();
  if (written.find('\\') == std::string_view::npos) return asWritten;
  std::error_code ec;
  if (std::filesystem::exists(asWritten, ec)) return asWritten;
  std::string separated(written);
  std::replace(separated.begin(), separated.end(), '\\', '/');
  const std::filesystem::path slashed = (directory / separated).lexically_normal();
  return std::filesystem::exists(slashed, ec) ? slashed : asWritten;
}

// `map_Kd [OPTIONS] FILE` of MTL file `name`: the options Prism maps (-s, -o,
// -clamp) taken, the others' arguments checked and skipped, FILE (the rest of
// the line, so it may hold spaces) resolved against the file's directory.
// Nothing after reporting a problem.
std::optional<DiffuseMap> diffuseMap(const Line& line, const std::string& name, Scanner& s) {
  const std::string k(line.words[0].text);
  DiffuseMap map;
  std::size_t i = 1;
  // The options that take 1 to 3 numbers (-o, -s, -t), 1 (-bm, -boost,
  // -texres), 2 (-mm) or one word (on/off, a channel, a map type).
  struct Option {
    std::string_view name;
    std::size_t minNumbers, maxNumbers; // both 0: one word
  };
  static constexpr Option kOptions[] = {
      {"-o", 1, 3},      {"-s", 1, 3},       {"-t", 1, 3},      {"-bm", 1, 1},     {"-boost", 1, 1},
      {"-texres", 1, 1}, {"-mm", 2, 2},      {"-blendu", 0, 0}, {"-blendv", 0, 0}, {"-cc", 0, 0},
      {"-clamp", 0, 0},  {"-imfchan", 0, 0}, {"-type", 0, 0}};
  static constexpr const char* kUvw[] = {"U", "V", "W"};
  static constexpr const char* kValue[] = {"VALUE"};
  static constexpr const char* kBaseGain[] = {"BASE", "GAIN"};
  while (i < line.words.size() && line.words[i].text.starts_with('-') &&
         !isNumber(line.words[i].text)) {
    const Token& word = line.words[i];
    const Option* option = nullptr;
    for (const Option& o : kOptions)
      if (o.name == word.text) option = &o;
    if (option == nullptr) {
      s.error(word, k + ": unknown option " + quoted(word.text));
      return std::nullopt;
    }
    ++i;
    if (option->maxNumbers == 0) {
      if (i >= line.words.size()) {
        s.error(word, k + ": " + std::string(word.text) + " expects a value, found nothing");
        return std::nullopt;
      }
      const Token& value = line.words[i++];
      if (word.text == "-clamp" || word.text == "-blendu" || word.text == "-blendv" ||
          word.text == "-cc") {
        if (value.text != "on" && value.text != "off") {
          s.error(value, k + ": " + std::string(word.text) + " expects on or off, found " +
                             quoted(value.text));
          return std::nullopt;
        }
        if (word.text == "-clamp") map.clamp = value.text == "on";
      }
      continue;
    }
    std::size_t count = option->minNumbers;
    while (count < option->maxNumbers && i + count < line.words.size() &&
           isNumber(line.words[i + count].text))
      ++count;
    double values[3] = {0.0, 0.0, 0.0};
    const char* const* names = option->maxNumbers == 3   ? kUvw
                               : option->maxNumbers == 2 ? kBaseGain
                                                         : kValue;
    // Checked as a statement of their own, named "map_Kd -s" in messages.
    const std::string named = k + " " + std::string(word.text);
    Line part;
    part.words.push_back({named, word.line, word.column});
    part.words.insert(part.words.end(), line.words.begin() + std::ptrdiff_t(i),
                      line.words.begin() + std::ptrdiff_t(std::min(i + count, line.words.size())));
    if (!s.numbers(part, 1, count, names, values)) return std::nullopt;
    if (word.text == "-s") {
      for (std::size_t c = 0; c < 2 && c < count; ++c) {
        if (values[c] == 0.0) {
          s.error(line.words[i + c], k + ": -s " + kUvw[c] + " must not be 0");
          return std::nullopt;
        }
      }
      map.scale = Vec2(values[0], count > 1 ? values[1] : 1.0);
    } else if (word.text == "-o") {
      map.offset = Vec2(values[0], count > 1 ? values[1] : 0.0);
    }
    i += count;
  }
  if (i >= line.words.size()) {
    s.error(line.words[0], k + ": expected a FILE");
    return std::nullopt;
  }
  const Token& file = line.words[i];
  map.path =
      referencedFile(std::filesystem::path(name).parent_path(), span(line.words, i)).string();
  map.library = name;
  map.line = file.line;
  map.column = file.column;
  return map;
}

// Reads, checks and normalises the material library at `path`, once.
void scanLibrary(const std::filesystem::path& path, const Token& at, Scanner& s, ObjScan& scan) {
  const std::string resolved = path.string();
  for (const MaterialLibrary& library : scan.libraries) {
    if (library.path == resolved) return;
  }
  std::string mtl;
  if (const std::optional<std::string> problem = readFile(path, true, mtl)) {
    s.error(at, "mtllib: cannot read '" + resolved + "': " + *problem);
    return;
  }
  scanMtl(mtl, resolved, scan);
  normaliseMtlForTinyObj(mtl);
  scan.libraries.push_back({resolved, std::move(mtl)});
  if (scan.errors.size() > kMaxDiagnostics) throw TooManyErrors{};
}

} // namespace

void scanMtl(std::string_view text, const std::string& name, ObjScan& scan) {
  Scanner s(scan, name);
  LineReader reader(text);
  Line line;
  std::string current;
  // tinyobjloader keeps the first definition of a name (its map's insert):
  // `illum` counts only in that one, and not before any `newmtl`.
  bool firstDefinition = false;
  try {
    while (reader.next(line)) {
      if (line.words.empty() || !s.noNulByte(line)) continue;
      const std::string_view k = line.words[0].text;
      if (k == "newmtl") {
        if (line.words.size() < 2) {
          s.error(line.words[0], "newmtl: expected a NAME");
          continue;
        }
        current = std::string(span(line.words, 1));
        firstDefinition = scan.materials.try_emplace(current, false).second;
      } else if (k == "Kd" || k == "Ks") {
        static constexpr const char* kNames[] = {"R", "G", "B"};
        double rgb[3];
        if (line.words.size() > 1 && !isNumber(line.words[1].text)) {
          s.error(line.words[1], std::string(k) + ": only R G B colours are supported, found " +
                                     quoted(line.words[1].text));
          continue;
        }
        if (!s.numbers(line, 1, 3, kNames, rgb) || !s.noMoreThan(line, 4)) continue;
        for (int i = 0; i < 3; ++i) {
          if (rgb[i] < 0.0) {
            s.error(line.words[std::size_t(i) + 1],
                    std::string(k) + ": " + kNames[i] + " must not be negative, found " +
                        quoted(line.words[std::size_t(i) + 1].text));
          }
        }
      } else if (k == "Ns" || k == "Ni" || k == "d" || k == "Tr") {
        static constexpr const char* kName[] = {"VALUE"};
        double v = 0.0;
        if (!s.numbers(line, 1, 1, kName, &v)) continue;
        const Token& w = line.words[1];
        if (k == "Ns" && v < 0.0) {
          s.error(w, "Ns: the exponent must not be negative, found " + quoted(w.text));
        } else if (k == "Ni" && !(v > 0.0)) {
          s.error(w, "Ni: the index of refraction must be positive, found " + quoted(w.text));
        } else if ((k == "d" || k == "Tr") && !(v >= 0.0 && v <= 1.0)) {
          s.error(w, std::string(k) + ": must be from 0 to 1, found " + quoted(w.text));
        }
      } else if (k == "map_Kd") {
        std::optional<DiffuseMap> map = diffuseMap(line, name, s);
        // tinyobjloader's rule for the other statements: the first
        // definition of a name counts.
        if (map && firstDefinition) scan.diffuseMaps[current] = std::move(*map);
      } else if (k == "illum") {
        const Token* w = line.words.size() > 1 ? &line.words[1] : nullptr;
        const std::optional<std::uint64_t> v = w ? parseInteger(w->text) : std::nullopt;
        if (!v || *v > 10) {
          s.error(w ? *w : line.words[0],
                  "illum: expected an illumination model from 0 to 10, found " +
                      (w ? quoted(w->text) : std::string("nothing")));
        } else if (firstDefinition) {
          scan.materials[current] = true;
        }
      }
      // Everything else (Ka, Ke, Tf, the other texture maps, PBR extensions)
      // has no counterpart in Prism's model and is ignored
      // (docs/importing.md says why for map_Ks and map_d).
    }
  } catch (const TooManyErrors&) {
  }
}

ObjScan scanObj(std::string_view text, const std::string& name,
                const std::filesystem::path& directory) {
  ObjScan scan;
  Scanner s(scan, name);
  LineReader reader(text);
  Line line;
  std::array<long long, 3> counts{0, 0, 0}; // v, vt, vn so far
  struct Use {
    Token at;
    std::string name;
  };
  std::vector<Use> uses;
  std::map<std::string, std::uint32_t, std::less<>> usedIds;
  std::uint32_t material = kNoMaterial;
  static constexpr const char* kXyz[] = {"X", "Y", "Z", "W"};
  try {
    while (reader.next(line)) {
      if (line.words.empty() || !s.noNulByte(line)) continue;
      const Token& keyword = line.words[0];
      const std::string_view k = keyword.text;
      if (k == "v") {
        // x y z, optionally w, or x y z r g b (a common vertex-colour extension).
        static constexpr const char* kNames[] = {"X", "Y", "Z", "R", "G", "B"};
        const std::size_t n = line.words.size() - 1;
        const std::size_t want = n <= 3 ? 3 : n == 4 ? 4 : 6;
        if (!s.numbers(line, 1, want, want == 4 ? kXyz : kNames) || !s.noMoreThan(line, want + 1))
          continue;
        ++counts[0];
      } else if (k == "vn") {
        if (!s.numbers(line, 1, 3, kXyz) || !s.noMoreThan(line, 4)) continue;
        ++counts[2];
      } else if (k == "vt") {
        // u, optionally v (0 when absent) and w (not used).
        static constexpr const char* kNames[] = {"U", "V", "W"};
        const std::size_t n = std::clamp<std::size_t>(line.words.size() - 1, 1, 3);
        double uvw[3] = {0.0, 0.0, 0.0};
        if (!s.numbers(line, 1, n, kNames, uvw) || !s.noMoreThan(line, n + 1)) continue;
        scan.texcoords.emplace_back(uvw[0], uvw[1]);
        ++counts[1];
      } else if (k == "f") {
        const std::size_t corners = line.words.size() - 1;
        if (corners < 3) {
          s.error(keyword, "f: a face needs at least 3 vertices, found " + std::to_string(corners));
          continue;
        }
        bool ok = true;
        for (std::size_t i = 1; i < line.words.size(); ++i) {
          if (const std::optional<std::string> problem = checkCorner(line.words[i].text, counts)) {
            s.error(line.words[i], "f: " + *problem);
            ok = false;
          }
        }
        if (!ok) continue;
        scan.faces.push_back({std::uint32_t(line.number), std::uint32_t(corners), material});
        scan.triangles += corners - 2;
      } else if (k == "usemtl") {
        if (line.words.size() < 2) {
          s.error(keyword, "usemtl: expected a material NAME");
          continue;
        }
        const std::string_view used = line.words[1].text;
        auto it = usedIds.find(used);
        if (it == usedIds.end()) {
          it = usedIds.emplace(std::string(used), std::uint32_t(scan.usedMaterials.size())).first;
          scan.usedMaterials.emplace_back(used);
          uses.push_back({line.words[1], std::string(used)});
        }
        material = it->second;
      } else if (k == "mtllib") {
        if (line.words.size() < 2) {
          s.error(keyword, "mtllib: expected a FILE");
          continue;
        }
        for (std::size_t i = 1; i < line.words.size(); ++i) {
          scanLibrary(referencedFile(directory, line.words[i].text), line.words[i], s, scan);
        }
      } else if (!ignoredObjStatement(k)) {
        s.error(keyword, "unknown statement " + quoted(k));
      }
    }
    // A material may be used before the `mtllib` that defines it.
    for (const Use& use : uses) {
      if (scan.materials.count(use.name) == 0) {
        s.error(use.at, "usemtl: no material " + prism::quoted(use.name) +
                            (scan.libraries.empty() ? std::string(" (no 'mtllib' was given)")
                                                    : " in the material libraries"));
      }
    }
  } catch (const TooManyErrors&) {
  }
  return scan;
}

void normaliseObjForTinyObj(std::string& text) { normalise(text, writeObjStatement); }

} // namespace prism
