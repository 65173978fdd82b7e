#include "core/obj_scan.h"

#include "core/scene_text.h"

#include <array>
#include <optional>

namespace prism {

namespace {

constexpr std::size_t kMaxDiagnostics = 50;

struct TooManyErrors {};

// One line cut into white-space separated words, each with its column; `#`
// starts a comment. OBJ and MTL are line-oriented: a statement never spans
// lines (Prism does not support the rare `\` continuation).
struct Line {
  int number = 0;
  std::vector<Token> words;
};

class LineReader {
public:
  explicit LineReader(std::string_view text) : text_(text) {
    if (text_.substr(0, 3) == "\xEF\xBB\xBF") offset_ = 3;
  }

  bool next(Line& line) {
    if (offset_ >= text_.size()) return false;
    const std::size_t start = offset_;
    std::size_t end = text_.find('\n', start);
    if (end == std::string_view::npos) end = text_.size();
    offset_ = end + 1;
    line.number = ++number_;
    line.words.clear();
    std::size_t i = start;
    const std::size_t columnBase = start == 3 && number_ == 1 ? 3 : start;
    while (i < end) {
      while (i < end && isSpace(text_[i]))
        ++i;
      if (i >= end || text_[i] == '#') break;
      const std::size_t wordStart = i;
      while (i < end && !isSpace(text_[i]) && text_[i] != '#')
        ++i;
      line.words.push_back(
          {text_.substr(wordStart, i - wordStart), number_, int(wordStart - columnBase + 1)});
    }
    return true;
  }

private:
  std::string_view text_;
  std::size_t offset_ = 0;
  int number_ = 0;
};

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

  // Checks that words[first, first + count) are finite numbers; `names` label
  // them in messages. Reports a missing one at the statement keyword.
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

// One `f` corner: v, v/t, v//n or v/t/n, each a non-zero integer, negative
// counting back from the latest. Returns the problem, if any.
std::optional<std::string> checkCorner(std::string_view corner,
                                       const std::array<long long, 3>& counts) {
  static constexpr const char* kWhat[] = {"vertex", "texture coordinate", "normal"};
  static constexpr const char* kStatement[] = {"v", "vt", "vn"};
  std::size_t part = 0;
  std::size_t start = 0;
  while (true) {
    const std::size_t slash = corner.find('/', start);
    const std::string_view text = corner.substr(
        start, slash == std::string_view::npos ? std::string_view::npos : slash - start);
    if (part > 2) return "too many '/' in " + quoted(corner);
    if (!text.empty() || part == 0) {
      bool negative = false;
      std::string_view digits = text;
      if (!digits.empty() && (digits[0] == '-' || digits[0] == '+')) {
        negative = digits[0] == '-';
        digits.remove_prefix(1);
      }
      const std::optional<std::uint64_t> value = parseInteger(digits);
      if (!value || digits.empty() || digits[0] == '+') {
        return std::string("expected a ") + kWhat[part] + " index (an integer) but found " +
               quoted(text.empty() ? corner : text);
      }
      const long long count = counts[part];
      if (*value == 0) return std::string(kWhat[part]) + " index 0 (indices count from 1)";
      if (*value > std::uint64_t(count)) {
        return std::string(kWhat[part]) + " index " + (negative ? "-" : "") +
               std::to_string(*value) + " is out of range (" + std::to_string(count) + " '" +
               kStatement[part] + "' statements before this face)";
      }
    }
    if (slash == std::string_view::npos) break;
    start = slash + 1;
    ++part;
  }
  return std::nullopt;
}

bool ignoredObjStatement(std::string_view k) {
  // Grouping, smoothing, texture coordinates, lines and points, and the
  // free-form geometry Prism does not render.
  static constexpr std::string_view kIgnored[] = {
      "o",        "g",    "s",          "vt",        "l",     "p",     "vp",     "cstype",
      "deg",      "bmat", "step",       "curv",      "curv2", "surf",  "parm",   "trim",
      "hole",     "scrv", "sp",         "end",       "con",   "mg",    "bevel",  "c_interp",
      "d_interp", "lod",  "shadow_obj", "trace_obj", "ctech", "stech", "maplib", "usemap",
      "call",     "csh",  "vw",         "t"};
  for (const std::string_view i : kIgnored) {
    if (k == i) return true;
  }
  return false;
}

} // namespace

void scanMtl(std::string_view text, const std::string& name, ObjScan& scan) {
  Scanner s(scan, name);
  LineReader reader(text);
  Line line;
  std::string current;
  bool any = false;
  try {
    while (reader.next(line)) {
      if (line.words.empty()) continue;
      const std::string_view k = line.words[0].text;
      if (k == "newmtl") {
        if (line.words.size() < 2) {
          s.error(line.words[0], "newmtl: expected a NAME");
          continue;
        }
        // tinyobjloader names the material by the rest of the line.
        const Token& first = line.words[1];
        const Token& last = line.words.back();
        current = std::string(first.text.data(), last.text.data() + last.text.size());
        scan.materials.try_emplace(current, false);
        any = true;
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
      } else if (k == "illum") {
        const Token* w = line.words.size() > 1 ? &line.words[1] : nullptr;
        const std::optional<std::uint64_t> v = w ? parseInteger(w->text) : std::nullopt;
        if (!v || *v > 10) {
          s.error(w ? *w : line.words[0],
                  "illum: expected an illumination model from 0 to 10, found " +
                      (w ? quoted(w->text) : std::string("nothing")));
        } else if (any) {
          scan.materials[current] = true;
        }
      }
      // Everything else (Ka, Ke, Tf, texture maps, PBR extensions) has no
      // counterpart in Prism's model and is ignored.
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
  static constexpr const char* kXyz[] = {"X", "Y", "Z", "W"};
  try {
    while (reader.next(line)) {
      if (line.words.empty()) continue;
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
        scan.faceLines.push_back(std::uint32_t(line.number));
        scan.triangles += corners - 2;
      } else if (k == "usemtl") {
        if (line.words.size() < 2) {
          s.error(keyword, "usemtl: expected a material NAME");
          continue;
        }
        uses.push_back({line.words[1], std::string(line.words[1].text)});
      } else if (k == "mtllib") {
        if (line.words.size() < 2) {
          s.error(keyword, "mtllib: expected a FILE");
          continue;
        }
        for (std::size_t i = 1; i < line.words.size(); ++i) {
          const std::filesystem::path path =
              (directory / std::filesystem::path(std::string(line.words[i].text)))
                  .lexically_normal();
          std::string mtl;
          if (const std::optional<std::string> problem = readFile(path, true, mtl)) {
            s.error(line.words[i], "mtllib: cannot read '" + path.string() + "': " + *problem);
            continue;
          }
          scan.materialLibraries.push_back(path.string());
          scanMtl(mtl, path.string(), scan);
          if (scan.errors.size() > kMaxDiagnostics) throw TooManyErrors{};
        }
      } else if (!ignoredObjStatement(k)) {
        s.error(keyword, "unknown statement " + quoted(k));
      }
    }
    for (const Use& use : uses) {
      if (scan.materials.count(use.name) == 0) {
        s.error(use.at,
                "usemtl: no material " + prism::quoted(use.name) +
                    (scan.materialLibraries.empty() ? std::string(" (no 'mtllib' was given)")
                                                    : " in the material libraries"));
      }
    }
  } catch (const TooManyErrors&) {
  }
  return scan;
}

} // namespace prism
