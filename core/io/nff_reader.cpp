// NFF (Standard Procedural Databases). One command per keyword:
//   v  from/at/up/angle/hither/resolution   the view
//   b R G B                                  background
//   l X Y Z [R G B]                          point light
//   f R G B Kd Ks Shine T ior                current material
//   c BX BY BZ BR  AX AY AZ AR               open cone or cylinder
//   s X Y Z R                                sphere
//   p N  then N vertices                     polygon
//   pp N then N vertices each with a normal  polygon patch (smooth)
// `#` starts a comment. The reader works like the .sc one: tokens with line
// and column, every problem reported at its token, the rest of a broken
// command skipped, reading continued (up to 50 errors).
#include "core/io/nff_reader.h"

#include "core/io/import_common.h"
#include "core/io/scene_text.h"
#include "core/math/model_range.h"
#include "core/scene/scene_builder.h"
#include "core/shapes/shape_kinds.h"
#include "core/shapes/triangulate.h"

#include <array>
#include <cmath>
#include <limits>
#include <optional>

namespace prism {

namespace {

constexpr std::size_t kMaxDiagnostics = 50;
constexpr std::size_t kMaxWarnings = 20;
constexpr int kMaxResolution = 32768;
constexpr std::uint64_t kMaxPolygonVertices = std::numeric_limits<std::uint32_t>::max();

struct TooManyErrors {};

struct Arg {
  double value = 0.0;
  Token token;
};

Vec3 vec(const Arg* a) { return Vec3(a[0].value, a[1].value, a[2].value); }

bool isCommand(std::string_view word) {
  for (const char* k : {"v", "b", "l", "f", "c", "s", "p", "pp"}) {
    if (word == k) return true;
  }
  return false;
}

bool isViewWord(std::string_view word) {
  for (const char* k : {"from", "at", "up", "angle", "hither", "resolution"}) {
    if (word == k) return true;
  }
  return false;
}

class NffReader {
public:
  NffReader(std::string_view text, const std::string& name) : name_(name), lexer_(text) {}

  Scene run(std::vector<Diagnostic>* warnings);

private:
  // Diagnostics and recovery.
  void report(const Token& at, std::string message);
  void warn(const Token& at, std::string message);
  void resync();
  void skipNumbers();

  // Arguments: false when missing (reported, input resynchronised).
  bool token(const char* command, const char* name, const char* kind, Token& out);
  bool number(const char* command, const char* name, Arg& out, bool& valid);
  template <std::size_t N>
  bool numbers(const char* command, const char* const (&names)[N], Arg (&out)[N], bool& valid) {
    for (std::size_t i = 0; i < N; ++i) {
      if (!number(command, names[i], out[i], valid)) return false;
    }
    return true;
  }
  void nonNegative(const char* command, const Arg& a, const char* name, bool& valid);

  void command(const Token& keyword);
  void view(const Token& keyword);
  void background(const Token& keyword);
  void light(const Token& keyword);
  void fill(const Token& keyword);
  void cone(const Token& keyword);
  void sphere(const Token& keyword);
  void polygon(const Token& keyword, bool patch);
  void finish();

  Origin origin(const Token& keyword) const { return {0, std::uint32_t(keyword.line)}; }

  std::string name_;
  Lexer lexer_;
  Scene scene_;
  SceneBuilder build_{scene_}; // the current material (`f`) too
  std::vector<Diagnostic> errors_, warnings_;
  std::size_t droppedWarnings_ = 0;

  Token keyword_;             // of the command being read
  std::optional<Token> view_; // where `v` was given
  std::optional<Token> background_;
  double angle_ = 0.0; // NFF's angle between pixel centres
  struct RawLight {
    Vec3 position;
    Color color;
    Token keyword;
  };
  std::vector<RawLight> lights_;
};

Scene NffReader::run(std::vector<Diagnostic>* warnings) {
  build_.addFile(name_);
  try {
    while (!lexer_.peek().atEnd())
      command(lexer_.next());
    finish();
  } catch (const TooManyErrors&) {
  }
  if (!errors_.empty()) throw SceneError(std::move(errors_));
  if (droppedWarnings_ > 0) {
    warnings_.push_back(
        {name_, 1, 1, "and " + std::to_string(droppedWarnings_) + " more warnings like these"});
  }
  if (warnings != nullptr) {
    warnings->insert(warnings->end(), warnings_.begin(), warnings_.end());
  }
  return std::move(scene_);
}

void NffReader::report(const Token& at, std::string message) {
  if (errors_.size() >= kMaxDiagnostics) {
    errors_.push_back({name_, at.line, at.column, "too many errors; giving up"});
    throw TooManyErrors{};
  }
  errors_.push_back({name_, at.line, at.column, std::move(message)});
}

void NffReader::warn(const Token& at, std::string message) {
  if (warnings_.size() >= kMaxWarnings) {
    ++droppedWarnings_;
    return;
  }
  warnings_.push_back({name_, at.line, at.column, std::move(message)});
}

// After a missing or malformed argument: drop the offending token unless it
// starts the next command, then the numbers that belonged to the broken one.
void NffReader::resync() {
  const Token& next = lexer_.peek();
  if (!next.atEnd() && !isCommand(next.text) && !isViewWord(next.text)) lexer_.next();
  skipNumbers();
}

void NffReader::skipNumbers() {
  while (!lexer_.peek().atEnd() && isNumber(lexer_.peek().text))
    lexer_.next();
}

bool NffReader::token(const char* command, const char* name, const char* kind, Token& out) {
  out = lexer_.peek();
  if (out.atEnd()) { // reported at the command, as the .sc reader does
    report(keyword_,
           std::string(command) + ": expected " + name + " but reached the end of the file");
    return false;
  }
  if (!isNumber(out.text)) {
    report(out, std::string(command) + ": expected " + name + " (" + kind + ") but found " +
                    quoted(out.text));
    resync();
    return false;
  }
  lexer_.next();
  return true;
}

bool NffReader::number(const char* command, const char* name, Arg& out, bool& valid) {
  if (!token(command, name, "a number", out.token)) return false;
  if (parseNumber(out.token.text, out.value) == NumberKind::NonFinite) {
    report(out.token, std::string(command) + ": " + name + " is not a finite number (" +
                          quoted(out.token.text) + ")");
    out.value = std::numeric_limits<double>::quiet_NaN();
    valid = false;
  }
  return true;
}

void NffReader::nonNegative(const char* command, const Arg& a, const char* name, bool& valid) {
  if (a.value < 0.0) {
    report(a.token, std::string(command) + ": " + name + " must not be negative, found " +
                        quoted(a.token.text));
    valid = false;
  }
}

void NffReader::command(const Token& keyword) {
  keyword_ = keyword;
  const std::string_view k = keyword.text;
  if (k == "v") return view(keyword);
  if (k == "b") return background(keyword);
  if (k == "l") return light(keyword);
  if (k == "f") return fill(keyword);
  if (k == "c") return cone(keyword);
  if (k == "s") return sphere(keyword);
  if (k == "p") return polygon(keyword, false);
  if (k == "pp") return polygon(keyword, true);
  if (isNumber(k)) {
    report(keyword, "expected a command but found the number " + quoted(k) +
                        " (too many numbers for the command before it?)");
  } else if (isViewWord(k)) {
    report(keyword, quoted(k) + " belongs to a view: it may only follow 'v'");
  } else {
    report(keyword, "unknown command " + quoted(k));
  }
  skipNumbers();
}

// v, then from/at/up/angle/hither/resolution (in the order the format gives
// them, though any order is accepted), each once.
void NffReader::view(const Token& keyword) {
  if (view_) {
    report(keyword, "duplicate 'v' (first given at " + name_ + ":" + std::to_string(view_->line) +
                        ":" + std::to_string(view_->column) + ")");
  } else {
    view_ = keyword;
  }
  bool seen[6] = {};
  static constexpr const char* kWords[] = {"from", "at", "up", "angle", "hither", "resolution"};
  while (isViewWord(lexer_.peek().text)) {
    const Token word = lexer_.next();
    keyword_ = word; // arguments missing at the end of the file are reported here
    int which = 0;
    while (word.text != kWords[which])
      ++which;
    if (seen[which]) report(word, "v: duplicate " + quoted(word.text));
    seen[which] = true;
    bool valid = true;
    CameraSpec& camera = scene_.camera;
    if (which <= 2) {
      Arg a[3];
      if (!numbers(kWords[which], {"X", "Y", "Z"}, a, valid) || !valid) continue;
      if (which <= 1 && !withinModelRange(vec(a))) {
        report(a[0].token,
               std::string(kWords[which]) + ": the point must be within +-" + kMaxCoordinateText);
        continue;
      }
      (which == 0 ? camera.eye : which == 1 ? camera.lookat : camera.up) = vec(a);
    } else if (which == 3) {
      Arg a;
      if (!number("angle", "DEGREES", a, valid) || !valid) continue;
      if (!(a.value > 0.0 && a.value < 180.0)) {
        report(a.token, "angle: DEGREES must be greater than 0 and less than 180, found " +
                            quoted(a.token.text));
        continue;
      }
      angle_ = a.value;
    } else if (which == 4) {
      Arg a; // Prism clips nothing: the hither distance is read and ignored.
      number("hither", "DISTANCE", a, valid);
    } else {
      static constexpr const char* kNames[] = {"XRES", "YRES"};
      int size[2] = {0, 0};
      for (int i = 0; i < 2; ++i) {
        Token t;
        if (!token("resolution", kNames[i], "an integer", t)) break;
        const std::optional<std::uint64_t> value = parseInteger(t.text);
        if (!value || *value < 1 || *value > std::uint64_t(kMaxResolution)) {
          report(t, std::string("resolution: ") + kNames[i] + " must be an integer from 1 to " +
                        std::to_string(kMaxResolution) + ", found " + quoted(t.text));
        } else {
          size[i] = int(*value);
        }
      }
      if (size[0] > 0 && size[1] > 0) {
        scene_.width = size[0];
        scene_.height = size[1];
      }
    }
  }
  static constexpr int kRequired[] = {0, 1, 2, 3, 5};
  for (const int i : kRequired) {
    if (!seen[i]) report(keyword, std::string("v: missing '") + kWords[i] + "'");
  }
}

void NffReader::background(const Token& keyword) {
  if (background_) {
    report(keyword, "duplicate 'b' (first given at " + name_ + ":" +
                        std::to_string(background_->line) + ":" +
                        std::to_string(background_->column) + ")");
  }
  background_ = keyword;
  bool valid = true;
  Arg a[3];
  if (!numbers("b", {"R", "G", "B"}, a, valid)) return;
  static constexpr const char* kNames[] = {"R", "G", "B"};
  for (int i = 0; i < 3; ++i)
    nonNegative("b", a[i], kNames[i], valid);
  if (valid) scene_.background = vec(a);
}

// l X Y Z [R G B]: the colour is optional (white without it).
void NffReader::light(const Token& keyword) {
  bool valid = true;
  Arg position[3];
  if (!numbers("l", {"X", "Y", "Z"}, position, valid)) return;
  Color color(1.0);
  if (!lexer_.peek().atEnd() && isNumber(lexer_.peek().text)) {
    static constexpr const char* kNames[] = {"R", "G", "B"};
    Arg rgb[3];
    if (!numbers("l", kNames, rgb, valid)) return;
    for (int i = 0; i < 3; ++i)
      nonNegative("l", rgb[i], kNames[i], valid);
    color = vec(rgb);
  }
  if (valid && !withinModelRange(vec(position))) {
    report(keyword, outsideModelRangeMessage("l"));
    return;
  }
  if (valid) lights_.push_back({vec(position), color, keyword});
}

// f R G B Kd Ks Shine T ior: the same model as Prism's surface, argument for
// argument.
void NffReader::fill(const Token& keyword) {
  (void)keyword;
  static constexpr const char* kNames[] = {"R", "G", "B", "KD", "KS", "SHINE", "T", "IOR"};
  bool valid = true;
  Arg a[8];
  if (!numbers("f", kNames, a, valid)) return;
  for (int i = 0; i < 8; ++i)
    nonNegative("f", a[i], kNames[i], valid);
  if (!valid) return;
  // SPD files write ior 0 for opaque materials, where it plays no part.
  double ir = a[7].value;
  if (ir == 0.0) {
    if (a[6].value > 0.0) {
      report(a[7].token, "f: IOR must be positive for a transmitting material (T > 0), found " +
                             quoted(a[7].token.text));
      return;
    }
    ir = 1.0;
  }
  build_.setMaterial(Material{vec(a), a[3].value, a[4].value, a[6].value, a[5].value, ir});
}

// c: base centre and radius, apex centre and radius, open at both ends. NFF
// gives both radii negative to say only the inside is seen; Prism's surfaces
// are two-sided, so the sign is dropped.
void NffReader::cone(const Token& keyword) {
  static constexpr const char* kNames[] = {"BASE_X", "BASE_Y", "BASE_Z", "BASE_RADIUS",
                                           "APEX_X", "APEX_Y", "APEX_Z", "APEX_RADIUS"};
  bool valid = true;
  Arg a[8];
  if (!numbers("c", kNames, a, valid) || !valid) return;
  double rb = a[3].value, ra = a[7].value;
  if (rb < 0.0 && ra < 0.0) {
    rb = -rb;
    ra = -ra;
  } else if (rb < 0.0 || ra < 0.0) {
    const Arg& bad = rb < 0.0 ? a[3] : a[7];
    report(bad.token, "c: negative radius " + quoted(bad.token.text) +
                          " (only both radii may be negative, meaning seen from inside)");
    return;
  }
  if (const std::optional<std::string> problem = coneProblem(vec(a), rb, vec(a + 4), ra)) {
    report(keyword, "c: " + *problem);
    return;
  }
  Cone c = makeCone(vec(a), rb, vec(a + 4), ra);
  if (!withinModelRange(c.bounds)) {
    report(keyword, outsideModelRangeMessage("c"));
    return;
  }
  c.material = build_.currentMaterial();
  c.origin = origin(keyword);
  build_.add(c);
}

void NffReader::sphere(const Token& keyword) {
  bool valid = true;
  Arg a[4];
  if (!numbers("s", {"X", "Y", "Z", "RADIUS"}, a, valid) || !valid) return;
  if (!(a[3].value > 0.0)) {
    report(a[3].token, "s: RADIUS must be positive, found " + quoted(a[3].token.text));
    return;
  }
  const Sphere sphere{vec(a), a[3].value, build_.currentMaterial(), origin(keyword)};
  if (!withinModelRange(boundsOf(sphere))) {
    report(keyword, outsideModelRangeMessage("s"));
    return;
  }
  build_.add(sphere);
}

// p N, then N vertices: a flat polygon, exactly like the .sc `polygon`.
// pp N, then N vertices each followed by its normal: a polygon patch, split
// into smooth triangles. Vertices are read as they come, never reserved from
// N, so a hostile N costs nothing until the numbers are there.
void NffReader::polygon(const Token& keyword, bool patch) {
  const char* name = patch ? "pp" : "p";
  Token countToken;
  if (!token(name, "N", "an integer", countToken)) return;
  const std::optional<std::uint64_t> count = parseInteger(countToken.text);
  if (!count || *count < 3 || *count > kMaxPolygonVertices) {
    report(countToken, std::string(name) + ": N must be an integer from 3 to " +
                           std::to_string(kMaxPolygonVertices) + ", found " +
                           quoted(countToken.text));
    skipNumbers();
    return;
  }
  const std::uint64_t perVertex = patch ? 6 : 3;
  const std::uint64_t wanted = perVertex * *count;
  std::vector<Vec3> points, normals;
  Vec3 value3(0.0);
  bool valid = true;
  for (std::uint64_t found = 0; found < wanted; ++found) {
    const Token t = lexer_.peek();
    double value = 0.0;
    const NumberKind kind = t.atEnd() ? NumberKind::NotANumber : parseNumber(t.text, value);
    if (kind == NumberKind::NotANumber) {
      const std::string expected = std::string(name) + ": expected " + std::to_string(wanted) +
                                   " numbers for " + std::to_string(*count) + " vertices, found " +
                                   std::to_string(found);
      if (t.atEnd()) {
        report(keyword, expected + " before the end of the file");
      } else {
        report(t, expected + " before " + quoted(t.text));
        resync();
      }
      return;
    }
    lexer_.next();
    const std::uint64_t slot = found % perVertex;
    if (kind == NumberKind::NonFinite) {
      const std::string axis = (slot >= 3 ? "N" : "") + std::string(1, "XYZ"[slot % 3]) +
                               std::to_string(found / perVertex + 1);
      report(t,
             std::string(name) + ": " + axis + " is not a finite number (" + quoted(t.text) + ")");
      valid = false;
    }
    value3[int(slot % 3)] = value;
    if (slot == 2) points.push_back(value3);
    if (slot == 5) {
      if (value3 == Vec3(0.0)) {
        report(t, std::string(name) + ": the normal of vertex " +
                      std::to_string(found / perVertex + 1) + " must not be the zero vector");
        valid = false;
      }
      normals.push_back(glm::normalize(value3 / maxAbsComponent(value3)));
    }
  }
  if (!valid) return;
  for (const Vec3& point : points) {
    if (!withinModelRange(point)) {
      report(keyword, outsideModelRangeMessage(name));
      return;
    }
  }
  if (!patch) {
    if (const std::optional<std::string> problem = polygonProblem(points)) {
      if (problem->starts_with("degenerate")) {
        warn(keyword, "p: " + *problem + "; dropped");
      } else {
        report(keyword, "p: " + *problem);
      }
      return;
    }
    build_.polygon(points, build_.currentMaterial(), origin(keyword));
    return;
  }
  const auto firstVertex = std::uint32_t(scene_.meshVertices.size());
  const auto firstNormal = std::uint32_t(scene_.meshNormals.size());
  scene_.meshVertices.insert(scene_.meshVertices.end(), points.begin(), points.end());
  scene_.meshNormals.insert(scene_.meshNormals.end(), normals.begin(), normals.end());
  std::size_t dropped = 0;
  const Triangulation triangulation = triangulatePolygon(points);
  for (const std::array<std::uint32_t, 3>& tri : triangulation.triangles) {
    const std::array<std::uint32_t, 3> v{firstVertex + tri[0], firstVertex + tri[1],
                                         firstVertex + tri[2]};
    const std::array<std::uint32_t, 3> n{firstNormal + tri[0], firstNormal + tri[1],
                                         firstNormal + tri[2]};
    if (!build_.meshTriangle(v, &n, build_.currentMaterial(), origin(keyword))) ++dropped;
  }
  // A patch of zero area is not simple either; it is reported as dropped.
  if (!triangulation.simple && dropped < triangulation.triangles.size())
    warn(keyword, "pp: " + notSimpleWarning(1, "patch"));
  if (dropped > 0) {
    warn(keyword, "pp: " + std::to_string(dropped) +
                      (dropped == 1 ? " triangle has" : " triangles have") + " zero area; dropped");
  }
}

// Once the whole file is read: the camera, and the lights' intensities.
void NffReader::finish() {
  const Token start{"", 1, 1};
  if (!view_) warn(start, "no view ('v'): using the default camera of .sc scenes");
  const CameraSpec& camera = scene_.camera;
  const Token& at = view_ ? *view_ : start;
  const Vec3 direction = camera.lookat - camera.eye;
  const Vec3 forward = glm::normalize(direction);
  if (direction == Vec3(0.0) || !isFinite(forward)) {
    report(at, "v: 'from' and 'at' must be distinct points");
    return;
  }
  const double upLength = maxAbsComponent(camera.up);
  if (upLength == 0.0) {
    report(at, "v: 'up' must not be the zero vector");
    return;
  }
  const Vec3 unitUp = glm::normalize(camera.up / upLength);
  if (glm::length(glm::cross(forward, unitUp)) < 1e-9) {
    report(at, "v: 'up' is parallel to the view direction (from 'from' to 'at')");
    return;
  }
  // NFF's angle spans the centres of the top and bottom pixel rows; Prism's
  // fov spans the image's edges, half a pixel further out on each side.
  if (angle_ > 0.0) {
    const double h = scene_.height;
    const double halfTan = std::tan(glm::radians(angle_) / 2.0) * (h > 1.0 ? h / (h - 1.0) : 1.0);
    scene_.camera.fov = glm::degrees(2.0 * std::atan(halfTan));
  }
  // NFF lights do not fall off. Each light is made to deliver its NFF
  // intensity at the point the view looks at, so the balance between lights
  // there is the one the file intends; the overall scale is the automatic
  // exposure's business.
  const double floor = 1e-3 * glm::length(direction);
  for (const RawLight& l : lights_) {
    const double distance = std::max(glm::length(l.position - camera.lookat), floor);
    const Color intensity = falloffCompensated(l.color, distance);
    if (!isFinite(intensity)) {
      report(l.keyword, "l: the colour times the squared distance to the view's 'at' point (the "
                        "1/r^2 compensation) is too large for a double");
      continue;
    }
    build_.addLight({l.position, intensity});
  }
}

} // namespace

Scene parseNff(std::string_view text, const std::string& name, std::vector<Diagnostic>* warnings) {
  return NffReader(text, name).run(warnings);
}

Scene loadNff(const std::filesystem::path& path, std::vector<Diagnostic>* warnings) {
  const std::string name = path.string();
  std::string text;
  if (const std::optional<std::string> problem = readFile(path, false, text)) {
    throw SceneError({Diagnostic{name, 1, 1, "cannot read file: " + *problem}});
  }
  return parseNff(text, name, warnings);
}

} // namespace prism
