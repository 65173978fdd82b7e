// NFF (Standard Procedural Databases). One command per keyword:
//   v  from/at/up/angle/hither/resolution   the view
//   b R G B                                  background
//   l X Y Z [R G B]                          point light
//   f R G B Kd Ks Shine T ior                current material
//   c BX BY BZ BR  AX AY AZ AR               open cone or cylinder
//   s X Y Z R                                sphere
//   p N  then N vertices                     polygon
//   pp N then N vertices each with a normal  polygon patch (smooth)
// `#` starts a comment. The reader works like the .sc one (both are a
// ReaderBase, core/io/reader_base.h): tokens with line and column, every
// problem reported at its token, the rest of a broken command skipped,
// reading continued (up to 50 errors).
#include "core/io/nff_reader.h"

#include "core/io/import_common.h"
#include "core/io/reader_base.h"
#include "core/io/scene_text.h"
#include "core/math/model_range.h"
#include "core/scene/scene_builder.h"
#include "core/shapes/shape_kinds.h"
#include "core/shapes/triangulate.h"

#include <array>
#include <cmath>
#include <optional>

namespace prism {

namespace {

constexpr std::size_t kMaxWarnings = 20;

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

class NffReader : public ReaderBase {
public:
  NffReader(std::string_view text, const std::string& name) : name_(name), lexer_(text) {
    readFrom(lexer_, name_);
  }

  Scene run(std::vector<Diagnostic>* warnings);

private:
  bool startsCommand(std::string_view word) const override {
    return isCommand(word) || isViewWord(word);
  }
  void warn(const Token& at, std::string message);

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
  std::vector<Diagnostic> warnings_;
  std::size_t droppedWarnings_ = 0;

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
  readAll([&] {
    while (!lexer_.peek().atEnd())
      command(lexer_.next());
    finish();
  });
  if (droppedWarnings_ > 0) {
    warnings_.push_back(
        {name_, 1, 1, "and " + std::to_string(droppedWarnings_) + " more warnings like these"});
  }
  if (warnings != nullptr) {
    warnings->insert(warnings->end(), warnings_.begin(), warnings_.end());
  }
  return std::move(scene_);
}

void NffReader::warn(const Token& at, std::string message) {
  if (warnings_.size() >= kMaxWarnings) {
    ++droppedWarnings_;
    return;
  }
  warnings_.push_back({name_, at.line, at.column, std::move(message)});
}

void NffReader::command(const Token& keyword) {
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
    error(keyword, "expected a command but found the number " + quoted(k) +
                       " (too many numbers for the command before it?)");
  } else if (isViewWord(k)) {
    error(keyword, quoted(k) + " belongs to a view: it may only follow 'v'");
  } else {
    error(keyword, "unknown command " + quoted(k));
  }
  skipNumbers();
}

// v, then from/at/up/angle/hither/resolution (in the order the format gives
// them, though any order is accepted), each once.
void NffReader::view(const Token& keyword) {
  Command v{keyword, "v"};
  if (once(v)) view_ = keyword;
  bool seen[6] = {};
  static constexpr const char* kWords[] = {"from", "at", "up", "angle", "hither", "resolution"};
  while (isViewWord(lexer_.peek().text)) {
    const Token word = lexer_.next();
    int which = 0;
    while (word.text != kWords[which])
      ++which;
    if (seen[which]) error(word, "v: duplicate " + quoted(word.text));
    seen[which] = true;
    // Arguments missing at the end of the file are reported at the word.
    Command c{word, kWords[which]};
    CameraSpec& camera = scene_.camera;
    if (which <= 2) {
      Arg a[3];
      if (!numbers(c, {"X", "Y", "Z"}, a) || !c.valid) continue;
      if (which <= 1 && !withinModelRange(vec(a))) {
        error(a[0].token,
              std::string(kWords[which]) + ": the point must be within +-" + kMaxCoordinateText);
        continue;
      }
      (which == 0 ? camera.eye : which == 1 ? camera.lookat : camera.up) = vec(a);
    } else if (which == 3) {
      Arg a;
      if (!number(c, "DEGREES", a) || !c.valid) continue;
      if (!(a.value > 0.0 && a.value < 180.0)) {
        error(a.token, "angle: DEGREES must be greater than 0 and less than 180, found " +
                           quoted(a.token.text));
        continue;
      }
      angle_ = a.value;
    } else if (which == 4) {
      Arg a; // Prism clips nothing: the hither distance is read and ignored.
      number(c, "DISTANCE", a);
    } else {
      static constexpr const char* kNames[] = {"XRES", "YRES"};
      int size[2] = {0, 0};
      for (int i = 0; i < 2; ++i) {
        std::optional<std::uint64_t> value;
        if (!integer(c, kNames[i], 1, kMaxResolution, value)) break;
        if (value) size[i] = int(*value);
      }
      if (size[0] > 0 && size[1] > 0) {
        scene_.width = size[0];
        scene_.height = size[1];
      }
    }
  }
  static constexpr int kRequired[] = {0, 1, 2, 3, 5};
  for (const int i : kRequired) {
    if (!seen[i]) error(keyword, std::string("v: missing '") + kWords[i] + "'");
  }
}

void NffReader::background(const Token& keyword) {
  // Unlike `v`, a repeated `b` is compared with the one just before it.
  if (background_) {
    error(keyword, duplicateMessage("b", {name_, background_->line, background_->column}));
  }
  background_ = keyword;
  Command c{keyword, "b"};
  Arg a[3];
  if (!numbers(c, {"R", "G", "B"}, a)) return;
  requireColor(c, a);
  if (c.valid) scene_.background = vec(a);
}

// l X Y Z [R G B]: the colour is optional (white without it).
void NffReader::light(const Token& keyword) {
  Command c{keyword, "l"};
  Arg position[3];
  if (!numbers(c, {"X", "Y", "Z"}, position)) return;
  Color color(1.0);
  if (!lexer_.peek().atEnd() && isNumber(lexer_.peek().text)) {
    Arg rgb[3];
    if (!numbers(c, {"R", "G", "B"}, rgb)) return;
    requireColor(c, rgb);
    color = vec(rgb);
  }
  if (c.valid && !withinModelRange(vec(position))) {
    error(keyword, outsideModelRangeMessage("l"));
    return;
  }
  if (c.valid) lights_.push_back({vec(position), color, keyword});
}

// f R G B Kd Ks Shine T ior: the same model as Prism's surface, argument for
// argument.
void NffReader::fill(const Token& keyword) {
  static constexpr const char* kNames[] = {"R", "G", "B", "KD", "KS", "SHINE", "T", "IOR"};
  Command c{keyword, "f"};
  Arg a[8];
  if (!numbers(c, kNames, a)) return;
  for (int i = 0; i < 8; ++i)
    requireNonNegative(c, a[i], kNames[i]);
  if (!c.valid) return;
  // SPD files write ior 0 for opaque materials, where it plays no part.
  double ir = a[7].value;
  if (ir == 0.0) {
    if (a[6].value > 0.0) {
      error(a[7].token, "f: IOR must be positive for a transmitting material (T > 0), found " +
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
  Command command{keyword, "c"};
  Arg a[8];
  if (!numbers(command, kNames, a) || !command.valid) return;
  double rb = a[3].value, ra = a[7].value;
  if (rb < 0.0 && ra < 0.0) {
    rb = -rb;
    ra = -ra;
  } else if (rb < 0.0 || ra < 0.0) {
    const Arg& bad = rb < 0.0 ? a[3] : a[7];
    error(bad.token, "c: negative radius " + quoted(bad.token.text) +
                         " (only both radii may be negative, meaning seen from inside)");
    return;
  }
  if (const std::optional<std::string> problem = coneProblem(vec(a), rb, vec(a + 4), ra)) {
    error(keyword, "c: " + *problem);
    return;
  }
  Cone c = makeCone(vec(a), rb, vec(a + 4), ra);
  if (!withinModelRange(c.bounds)) {
    error(keyword, outsideModelRangeMessage("c"));
    return;
  }
  c.material = build_.currentMaterial();
  c.origin = origin(keyword);
  build_.add(c);
}

void NffReader::sphere(const Token& keyword) {
  Command c{keyword, "s"};
  Arg a[4];
  if (!numbers(c, {"X", "Y", "Z", "RADIUS"}, a) || !c.valid) return;
  if (!(a[3].value > 0.0)) {
    error(a[3].token, "s: RADIUS must be positive, found " + quoted(a[3].token.text));
    return;
  }
  const Sphere sphere{vec(a), a[3].value, build_.currentMaterial(), origin(keyword)};
  if (!withinModelRange(boundsOf(sphere))) {
    error(keyword, outsideModelRangeMessage("s"));
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
  Command c{keyword, name};
  const std::optional<std::uint64_t> count = vertexCount(c);
  if (!count) return;
  const std::uint64_t perVertex = patch ? 6 : 3;
  std::vector<Vec3> points, normals;
  Vec3 value3(0.0);
  const auto take = [&](std::uint64_t found, double value, const Token& t) {
    const std::uint64_t slot = found % perVertex;
    value3[int(slot % 3)] = value;
    if (slot == 2) points.push_back(value3);
    if (slot == 5) {
      if (value3 == Vec3(0.0)) {
        invalid(c, t,
                "the normal of vertex " + std::to_string(found / perVertex + 1) +
                    " must not be the zero vector");
      }
      normals.push_back(glm::normalize(value3 / maxAbsComponent(value3)));
    }
  };
  if (!vertexNumbers(c, *count, perVertex, take) || !c.valid) return;
  for (const Vec3& point : points) {
    if (!withinModelRange(point)) {
      error(keyword, outsideModelRangeMessage(name));
      return;
    }
  }
  if (!patch) {
    if (const std::optional<std::string> problem = polygonProblem(points)) {
      if (problem->starts_with("degenerate")) {
        warn(keyword, "p: " + *problem + "; dropped");
      } else {
        error(keyword, "p: " + *problem);
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
  switch (cameraProblem(camera)) {
  case CameraProblem::SamePoint:
  case CameraProblem::NoDirection: error(at, "v: 'from' and 'at' must be distinct points"); return;
  case CameraProblem::ZeroUp: error(at, "v: 'up' must not be the zero vector"); return;
  case CameraProblem::ParallelUp:
    error(at, "v: 'up' is parallel to the view direction (from 'from' to 'at')");
    return;
  case CameraProblem::ShortUp:
    // NFF says nothing of up's length, so a tiny one is not the file's
    // mistake: scaled to a largest component of 1, the same direction gives
    // the camera a finite right vector (otherwise every eye ray is NaN).
    scene_.camera.up = camera.up / maxAbsComponent(camera.up);
    break;
  case CameraProblem::None: break;
  }
  const Vec3 direction = camera.lookat - camera.eye;
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
      error(l.keyword, "l: the colour times the squared distance to the view's 'at' point (the "
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
  return parseNff(readSceneText(path), path.string(), warnings);
}

} // namespace prism
