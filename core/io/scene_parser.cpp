// The .sc scene language (documented for users in docs/scene-language.md).
//
// A hand-written lexer over the whole file text and a recursive-descent parser,
// one small member function per command. Errors never stop the parse early: each
// is recorded with its position, the rest of the broken command is skipped, and
// parsing continues so that one run reports every problem (up to a cap). How
// arguments are read and errors reported is shared with the NFF reader
// (ReaderBase); what a command adds goes through the SceneBuilder.
#include "core/io/scene_parser.h"

#include "core/io/oiio_module.h"
#include "core/io/reader_base.h"
#include "core/io/scene_text.h"
#include "core/io/shape_text/shape_text.h"
#include "core/math/model_range.h"
#include "core/math/transform.h"
#include "core/scene/scene_builder.h"
#include "core/shapes/blob.h"
#include "core/shapes/box.h"
#include "core/shapes/capped_cone.h"
#include "core/shapes/cone.h"
#include "core/shapes/disc.h"
#include "core/shapes/mesh_closure.h"
#include "core/shapes/quadric_surface.h"
#include "core/shapes/shape_kinds.h"
#include "core/shapes/torus.h"
#include "core/shapes/triangle.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <unordered_map>
#include <variant>

namespace prism {

namespace fs = std::filesystem;

namespace {

// ---------------------------------------------------------------------------
// Limits that keep hostile input from exhausting time or memory.

constexpr std::size_t kMaxIncludeDepth = 64; // files open at once, the main file included
// kMaxSceneBytes (core/io/scene_text.h) bounds the text parsed, counting every
// inclusion of a file: a few lines that include a file twice, which includes
// another twice, ... would otherwise expand exponentially. Also the largest
// single file read.
constexpr const char* kMaxSceneBytesText = "256 MiB";
constexpr int kMinResolution = 1;
// Groups open at once. Each costs a saved material and transform (about 400
// bytes), so without a limit a file of nothing but `push` would need 80 times
// its size in memory.
constexpr std::size_t kMaxGroupDepth = 100000;
// CSG blocks open at once: a node's tree is walked recursively for every ray.
constexpr std::size_t kMaxCsgDepth = 1000;

// ---------------------------------------------------------------------------
// Parser

// True when the transform turns space inside out, so counterclockwise vertex order
// becomes clockwise. The sign of the determinant of the unit-length columns: the
// determinant itself can underflow to zero for tiny scales.
bool mirrors(const Transform& t) {
  Mat3 m = t.linear();
  for (int i = 0; i < 3; ++i) {
    m[i] /= glm::length(m[i]);
  }
  return glm::determinant(m) < 0.0;
}

template <int N> bool allFinite(const glm::mat<N, N, double>& m) {
  for (int i = 0; i < N; ++i) {
    for (int j = 0; j < N; ++j) {
      if (!std::isfinite(m[i][j])) return false;
    }
  }
  return true;
}

// The map a shape placed in its own frame is written back through (see
// Parser::addPlaced).
const Mat3& placedMap(const Ellipsoid& e) { return e.objectToWorld; }
const Mat3& placedMap(const Cone& c) { return c.objectToWorld; }
const Mat3& placedMap(const CappedCone& c) { return c.side.objectToWorld; }
const Mat3& placedMap(const Box& b) { return b.frame.objectToWorld; }
const Mat3& placedMap(const Disc& d) { return d.frame.objectToWorld; }
const Mat3& placedMap(const Torus& t) { return t.objectToWorld; }
const Mat3& placedMap(const Quadric& q) { return q.frame.objectToWorld; }
const Mat3& placedMap(const Blob& b) { return b.frame.objectToWorld; }

class Parser : public ReaderBase {
public:
  Scene run(std::string_view text, const std::string& name);

private:
  using Handler = void (Parser::*)(Command&);
  struct Keyword {
    std::string_view name;
    Handler handler;
  };
  static const std::array<Keyword, 38> kKeywords;
  static Handler handlerFor(std::string_view name);

  // One file being parsed; they nest through `include`.
  struct SourceFile {
    std::string name; // as the user named it, for diagnostics
    fs::path identity;
    std::uint32_t index = 0; // into Scene::files
    Lexer lexer;
    std::size_t savedAtEntry = 0; // saved_.size() when the file began
  };

  // What `push` saves and `pop` restores, besides the group and material
  // the builder saves.
  // A `csg` or `mesh` block saves them too (its operation or flag says so),
  // and `end` restores them.
  struct Saved {
    Transform transform;
    Location pushedAt;
    std::optional<CsgOp> csg;     // a csg block rather than a push
    bool mesh = false;            // a mesh block rather than a push
    bool inMesh = false;          // a push inside a mesh block: the builder has no group for it
    std::size_t errorsBefore = 0; // diagnosticCount() at a csg block's start
  };

  // An open `mesh` block: its triangles, placed, kept until `end` checks that
  // they bound a solid.
  struct MeshFace {
    std::array<Vec3, 3> v;
    std::optional<std::array<Vec3, 3>> normals;
    std::optional<std::array<Vec2, 3>> uvs; // triangle_uv, ptriangle_uv (not in csg)
    Location at;                            // where errors about the triangle point
    Origin origin;
  };
  struct OpenMesh {
    Location at;
    Origin origin;
    std::size_t errorsBefore = 0; // diagnosticCount() at `mesh`
    std::vector<MeshFace> faces;
  };

  void parseFile(std::string_view text, const std::string& name, const fs::path& identity,
                 std::uint32_t index);
  void command();
  void closeOpenPushes();
  void checkCamera();

  bool startsCommand(std::string_view word) const override { return handlerFor(word) != nullptr; }

  // Commands: the camera and the picture.
  void eye(Command& c) { cameraPoint(c, scene_.camera.eye, true); }
  void lookat(Command& c) { cameraPoint(c, scene_.camera.lookat, true); }
  void up(Command& c) { cameraPoint(c, scene_.camera.up, false); }
  void cameraPoint(Command& c, Vec3& target, bool isPoint);
  void fov(Command& c);
  void resolution(Command& c);
  // Light and materials.
  void background(Command& c) { globalColor(c, scene_.background); }
  void ambient(Command& c) { globalColor(c, scene_.ambient); }
  void globalColor(Command& c, Color& target);
  void fog(Command& c);
  void absorption(Command& c);
  void texture(Command& c);
  void textureSpace(Command& c);
  void image(Command& c);
  // The next token, for the words after an image's PATH. Out of line: the
  // lexer's peek is inlined where numbers are read, and more call sites
  // make the compiler stop inlining it there, which slows reading.
  [[gnu::noinline]] Token peekOption() { return file().lexer.peek(); }
  void uv(Command& c);
  void light(Command& c);
  void surface(Command& c);
  // Shapes.
  void sphere(Command& c);
  void polygon(Command& c);
  void cone(Command& c);
  void torus(Command& c);
  void cylinder(Command& c);
  void box(Command& c);
  void disc(Command& c);
  void quadric(Command& c);
  void blob(Command& c);
  // The cone between two end circles under the current transform, for
  // `cone`, `capped_cone` and `cylinder`, or nothing after an error.
  std::optional<Cone> placedCone(Command& c, const Vec3& base, double baseRadius, const Vec3& apex,
                                 double apexRadius);
  // The checks of a radius that must be positive.
  void requirePositiveRadius(Command& c, const Arg& radius);
  // `triangle`, `ptriangle`, `triangle_uv` and `ptriangle_uv`, told apart by
  // the command's name.
  void triangle(Command& c);
  void addTriangle(Command& c, std::array<Vec3, 3> v, const std::array<Vec3, 3>* normals,
                   std::array<Vec2, 3>* uvs);
  // Adds a shape placed by its own affine map (an ellipsoid, a cone, ...) after
  // the checks they share: within the model range, and, when the map is
  // what `prism convert` writes back, not stretched too unevenly for that.
  template <class Shape> void addPlaced(Command& c, Shape shape, const char* name, bool mapWritten);
  // The checks of addPlaced: false after reporting a problem.
  template <class Shape>
  bool placedFits(Command& c, const Shape& shape, const char* name, bool mapWritten);
  // Transforms, groups and other files.
  void push(Command& c);
  void pop(Command& c);
  // CSG blocks: `csg OPERATION` ... `end`.
  void csg(Command& c);
  void end(Command& c);
  // An open shape inside a csg block: reported, its numbers skipped.
  bool openInCsg(Command& c);
  // Mesh blocks: `mesh` ... `end`, triangles that bound a solid.
  void mesh(Command& c);
  void endMesh();
  // A command other than triangles, transforms and include inside a mesh
  // block: reported, its numbers skipped.
  bool notInMesh(const Token& keyword);
  // The innermost push or csg block open in this file, or null.
  const Saved* innermostInFile() const {
    return saved_.size() > files_.back()->savedAtEntry ? &saved_.back() : nullptr;
  }
  void translate(Command& c);
  void scale(Command& c);
  void rotate(Command& c);
  void include(Command& c);

  // State.
  SourceFile& file() { return *files_.back(); }
  // A path written in the current file (`include`, `image`): relative to
  // that file's folder.
  fs::path besideCurrentFile(std::string_view written) {
    return (fs::path(file().name).parent_path() / fs::path(written)).lexically_normal();
  }
  Origin origin(const Command& c) { return {file().index, std::uint32_t(c.keyword.line)}; }
  void compose(Command& c, const Transform& t);
  // The one way transform_ changes: textures follow it (SceneBuilder::setObjectSpace).
  void setTransform(const Transform& t) {
    transform_ = t;
    build_.setObjectSpace(Mat3(t.inverse()), Vec3(t.inverse()[3]));
  }
  std::optional<std::string> readInclude(const fs::path& path, const fs::path& identity,
                                         const std::string*& text);
  std::uint32_t fileIndex(const fs::path& identity, const std::string& name);
  struct ResolvedInclude {
    fs::path path;     // relative to the including file's folder, normalised
    std::string name;  // path as a string, for messages and Scene::files
    fs::path identity; // identityOf(path)
  };
  const ResolvedInclude& resolveInclude(std::string_view raw);
  // The PATH argument of `include` and `image`, unquoted; nothing (after
  // reporting why) when it is missing, unclosed or empty.
  std::optional<std::string_view> pathArgument(Command& c, const Token& token);

  Scene scene_;
  SceneBuilder build_{scene_}; // the current material and group too

  Transform transform_;
  std::vector<Saved> saved_; // in step with build_'s pushes

  std::vector<std::unique_ptr<SourceFile>> files_;            // the include stack, main file first
  std::map<fs::path, std::string> contents_;                  // every included file, read once
  std::unordered_map<std::string, ResolvedInclude> includes_; // by including file and PATH
  std::map<fs::path, std::uint32_t> fileIndices_;
  std::size_t parsedBytes_ = 0;

  bool cameraBroken_ = false;             // an eye/lookat/up was rejected: skip the camera checks
  std::vector<Vec3> vertices_;            // scratch for polygon
  std::vector<BlobComponent> components_; // scratch for blob
  std::optional<OpenMesh> mesh_;          // the open mesh block, if any
};

const std::array<Parser::Keyword, 38> Parser::kKeywords = {{
    {"eye", &Parser::eye},
    {"lookat", &Parser::lookat},
    {"up", &Parser::up},
    {"fov", &Parser::fov},
    {"resolution", &Parser::resolution},
    {"background", &Parser::background},
    {"ambient", &Parser::ambient},
    {"light", &Parser::light},
    {"surface", &Parser::surface},
    {"absorption", &Parser::absorption},
    {"texture", &Parser::texture},
    {"texture_space", &Parser::textureSpace},
    {"fog", &Parser::fog},
    {"sphere", &Parser::sphere},
    {"polygon", &Parser::polygon},
    {"cone", &Parser::cone},
    {"torus", &Parser::torus},
    {"triangle", &Parser::triangle},
    {"ptriangle", &Parser::triangle},
    {"triangle_uv", &Parser::triangle},  // each vertex with its surface coordinates U V
    {"ptriangle_uv", &Parser::triangle}, // each vertex with its normal and U V
    {"box", &Parser::box},
    {"disc", &Parser::disc},
    {"cylinder", &Parser::cylinder},
    {"capped_cone", &Parser::cone}, // a cone closed by discs at both ends
    {"quadric", &Parser::quadric},
    {"blob", &Parser::blob},
    {"push", &Parser::push},
    {"pop", &Parser::pop},
    {"csg", &Parser::csg},
    {"end", &Parser::end},
    {"mesh", &Parser::mesh},
    {"translate", &Parser::translate},
    {"scale", &Parser::scale},
    {"rotate", &Parser::rotate},
    {"include", &Parser::include},
    // Last: the table is searched in order for every command, and these are
    // written once per surface at most.
    {"image", &Parser::image},
    {"uv", &Parser::uv},
}};

Parser::Handler Parser::handlerFor(std::string_view name) {
  for (const Keyword& k : kKeywords) {
    if (k.name == name) return k.handler;
  }
  return nullptr;
}

Scene Parser::run(std::string_view text, const std::string& name) {
  const fs::path identity = identityOf(name);
  readAll([&] {
    parsedBytes_ = text.size();
    parseFile(text, name, identity, fileIndex(identity, name));
    checkCamera();
  });
  return std::move(scene_);
}

void Parser::parseFile(std::string_view text, const std::string& name, const fs::path& identity,
                       std::uint32_t index) {
  files_.push_back(
      std::make_unique<SourceFile>(SourceFile{name, identity, index, Lexer(text), saved_.size()}));
  readFrom(file().lexer, file().name);
  while (!file().lexer.peek().atEnd()) {
    command();
  }
  closeOpenPushes();
  files_.pop_back();
  if (!files_.empty()) readFrom(file().lexer, file().name);
}

void Parser::command() {
  const Token token = file().lexer.next();
  if (const Handler handler = handlerFor(token.text)) {
    if (notInMesh(token)) return;
    Command c{token, std::string(token.text)};
    (this->*handler)(c);
    return;
  }
  if (isNumber(token.text)) {
    error(token, "expected a command but found the number " + quoted(token.text) +
                     " (too many numbers for the command before it?)");
  } else {
    std::string lower(token.text);
    for (char& ch : lower) {
      ch = char(std::tolower(static_cast<unsigned char>(ch)));
    }
    const bool caseOnly = handlerFor(lower) != nullptr;
    error(token, "unknown keyword " + quoted(token.text) +
                     (caseOnly ? " (keywords are lower case: '" + lower + "')" : ""));
  }
  skipNumbers();
}

// Each push still open when its file ends is an error; the state is restored to
// what it was before the outermost of them, so the including file continues
// with the material, transform and group it had.
void Parser::closeOpenPushes() {
  const std::size_t base = file().savedAtEntry;
  if (saved_.size() == base) return;
  for (std::size_t i = base; i < saved_.size(); ++i) {
    report(saved_[i].pushedAt, saved_[i].csg    ? "csg without matching end"
                               : saved_[i].mesh ? "mesh without matching end"
                                                : "push without matching pop");
  }
  setTransform(saved_[base].transform);
  while (saved_.size() > base) {
    if (saved_.back().csg)
      build_.endCsg();
    else if (saved_.back().mesh)
      mesh_.reset(); // reported: its triangles are dropped
    else if (!saved_.back().inMesh)
      build_.pop();
    saved_.pop_back();
  }
}

// ---------------------------------------------------------------------------
// Camera and global commands

void Parser::cameraPoint(Command& c, Vec3& target, bool isPoint) {
  const bool first = once(c);
  Arg a[3];
  if (!numbers(c, {"X", "Y", "Z"}, a)) {
    cameraBroken_ = cameraBroken_ || first;
    return;
  }
  if (c.valid && isPoint && !withinModelRange(vec(a))) {
    invalid(c, a[0].token, std::string("the point must be within +-") + kMaxCoordinateText);
  }
  if (c.valid) target = vec(a);
  if (first && !c.valid) cameraBroken_ = true;
}

void Parser::fov(Command& c) {
  once(c);
  Arg a;
  if (!number(c, "DEGREES", a)) return;
  if (c.valid && !(a.value > 0.0 && a.value < 180.0)) {
    invalid(c, a.token,
            "DEGREES must be greater than 0 and less than 180, found " + quoted(a.token.text));
  }
  if (c.valid) scene_.camera.fov = a.value;
}

void Parser::resolution(Command& c) {
  once(c);
  int size[2] = {0, 0};
  static constexpr const char* kNames[] = {"W", "H"};
  for (int i = 0; i < 2; ++i) {
    std::optional<std::uint64_t> value;
    if (!integer(c, kNames[i], kMinResolution, kMaxResolution, value)) return;
    if (value) size[i] = int(*value);
  }
  if (!c.valid) return;
  scene_.width = size[0];
  scene_.height = size[1];
}

void Parser::globalColor(Command& c, Color& target) {
  once(c);
  Arg a[3];
  if (!numbers(c, {"R", "G", "B"}, a)) return;
  requireColor(c, a);
  if (c.valid) target = vec(a);
}

void Parser::fog(Command& c) {
  once(c);
  Arg a[4];
  if (!numbers(c, {"R", "G", "B", "DENSITY"}, a)) return;
  requireColor(c, a);
  requireNonNegative(c, a[3], "DENSITY");
  if (c.valid) scene_.fog = Fog{vec(a), a[3].value};
}

void Parser::light(Command& c) {
  Arg a[6];
  if (!numbers(c, {"X", "Y", "Z", "R", "G", "B"}, a)) return;
  requireColor(c, a + 3);
  if (!c.valid) return;
  const Vec3 position = transform_.point(vec(a));
  if (!withinModelRange(position)) {
    error(c.keyword, outsideModelRangeMessage("light"));
    return;
  }
  build_.addLight({position, vec(a + 3)});
}

void Parser::surface(Command& c) {
  static constexpr const char* kNames[] = {"R", "G", "B", "KDR", "KSR", "KST", "E", "IR"};
  Arg a[8];
  if (!numbers(c, kNames, a)) return;
  for (int i = 0; i < 7; ++i) {
    requireNonNegative(c, a[i], kNames[i]);
  }
  if (a[7].value <= 0.0) {
    invalid(c, a[7].token, "IR must be positive, found " + quoted(a[7].token.text));
  }
  if (!c.valid) return;
  build_.setMaterial(Material{vec(a), a[3].value, a[4].value, a[5].value, a[6].value, a[7].value});
}

// Amends the current surface: the primitives after it absorb inside.
void Parser::absorption(Command& c) {
  Arg a[3];
  if (!numbers(c, {"R", "G", "B"}, a)) return;
  requireColor(c, a);
  if (!c.valid) return;
  Material m = build_.currentMaterialValue();
  m.absorption = vec(a);
  build_.setMaterial(m);
}

// Amends the current surface: a pattern blends its C, kdr, ksr, kst and e
// toward the numbers given (docs/scene-language.md#textures).
void Parser::texture(Command& c) {
  const Token word = file().lexer.peek();
  const std::optional<TextureKind> kind = word.atEnd() ? std::nullopt : textureKindNamed(word.text);
  if (!kind) {
    error(word.atEnd() ? c.keyword : word,
          "texture: expected a kind (" + std::string(kTextureKindList) + ") but " +
              (word.atEnd() ? std::string("reached the end of the file")
                            : "found " + quoted(word.text)));
    if (!word.atEnd() && !startsCommand(word.text)) file().lexer.next();
    skipNumbers();
    return;
  }
  file().lexer.next();
  static constexpr const char* kNames[] = {"SCALE", "R", "G", "B", "KDR", "KSR", "KST", "E"};
  Arg a[8];
  if (!numbers(c, kNames, a)) return;
  if (a[0].value <= 0.0)
    invalid(c, a[0].token, "SCALE must be positive, found " + quoted(a[0].token.text));
  for (int i = 1; i < 8; ++i)
    requireNonNegative(c, a[i], kNames[i]);
  if (!c.valid) return;
  Material m = build_.currentMaterialValue();
  m.texture =
      Texture{*kind, a[0].value, vec(a + 1), a[4].value, a[5].value, a[6].value, a[7].value};
  build_.setMaterial(m);
}

// Amends the current texture: its pattern is evaluated at M p, p the point in
// world coordinates, whatever the transform (what `prism convert` writes:
// the transform it writes a shape under is only that shape's).
void Parser::textureSpace(Command& c) {
  static constexpr const char* kNames[] = {"M11", "M12", "M13", "M14", "M21", "M22",
                                           "M23", "M24", "M31", "M32", "M33", "M34"};
  Arg a[12];
  if (!numbers(c, kNames, a) || !c.valid) return;
  Material m = build_.currentMaterialValue();
  if (!m.texture.active()) {
    error(c.keyword, "texture_space: the current surface has no texture (give 'texture' first)");
    return;
  }
  for (int row = 0; row < 3; ++row) {
    for (int column = 0; column < 3; ++column)
      m.texture.linear[column][row] = a[4 * row + column].value; // glm: [column][row]
    m.texture.offset[row] = a[4 * row + 3].value;
  }
  m.texture.fromWorld = true;
  build_.setMaterial(m);
}

// Amends the current surface: its colour is multiplied by an image's at the
// surface coordinates (docs/scene-language.md#image-textures). PATH is
// relative to the file that names it; words after it choose the wrap, the
// encoding and point sampling.
void Parser::image(Command& c) {
  const Token token = file().lexer.nextPath();
  const std::optional<std::string_view> raw = pathArgument(c, token);
  if (!raw) return;
  ImageMap map;
  ImageEncoding encoding = ImageEncoding::Auto;
  for (Token word = peekOption(); !word.atEnd(); word = peekOption()) {
    if (const std::optional<ImageWrap> wrap = imageWrapNamed(word.text)) {
      map.wrap = *wrap;
    } else if (const std::optional<ImageEncoding> e = imageEncodingNamed(word.text)) {
      encoding = *e;
    } else if (word.text == "unfiltered") {
      map.filtered = false;
    } else {
      break;
    }
    file().lexer.next();
  }
  const fs::path path = besideCurrentFile(*raw);
  const std::string name = path.string();
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) {
    error(token, "image: cannot read '" + name +
                     "': " + (fs::exists(path, ec) ? "not a regular file" : "no such file"));
    return;
  }
  std::variant<std::uint32_t, std::string> loaded;
  try {
    if (!scene_.images) scene_.images = std::make_shared<ImageLibrary>(oiioTextureBackend());
    loaded = scene_.images->load(name, encoding);
  } catch (const std::runtime_error& e) { // the OpenImageIO module is missing
    loaded = std::string(e.what());
  }
  if (const std::string* why = std::get_if<std::string>(&loaded)) {
    error(token, "image: cannot read '" + name + "': " + *why);
    return;
  }
  map.image = std::get<std::uint32_t>(loaded);
  map.peak = scene_.images->info(map.image).peak;
  Material m = build_.currentMaterialValue();
  m.image = map;
  build_.setMaterial(m);
}

// Amends the current image map: image coordinates are
// s = u SU + OU, t = v SV + OV.
void Parser::uv(Command& c) {
  Arg a[4];
  if (!numbers(c, {"SU", "SV", "OU", "OV"}, a) || !c.valid) return;
  for (int i = 0; i < 2; ++i)
    if (a[i].value == 0.0)
      invalid(c, a[i].token, std::string(i == 0 ? "SU" : "SV") + " must not be 0");
  if (!c.valid) return;
  Material m = build_.currentMaterialValue();
  if (!m.image.active()) {
    error(c.keyword, "uv: the current surface has no image (give 'image' first)");
    return;
  }
  m.image.scale = {a[0].value, a[1].value};
  m.image.offset = {a[2].value, a[3].value};
  build_.setMaterial(m);
}

// ---------------------------------------------------------------------------
// Primitives

void Parser::sphere(Command& c) {
  Arg a[4];
  if (!numbers(c, {"X", "Y", "Z", "RADIUS"}, a)) return;
  const Arg& r = a[3];
  requirePositiveRadius(c, r);
  if (!c.valid) return;

  const Vec3 center = transform_.point(vec(a));
  double s = 1.0;
  // A sphere's surface coordinates are in world axes; an image on a turned
  // (or mirrored) sphere must turn with it, so that one is an ellipsoid,
  // whose coordinates are its own.
  const bool turnsImage = build_.currentMaterialValue().image.active() &&
                          transform_.linear() != Mat3(transform_.linear()[0][0]);
  if (transform_.isSimilarity(&s) && !turnsImage) {
    const double radius = r.value * s;
    if (!(radius > 0.0)) {
      error(c.keyword, "sphere: too small after the current transform");
      return;
    }
    const Sphere sphere{center, radius, build_.currentMaterial(), origin(c)};
    if (!withinModelRange(boundsOf(sphere))) {
      error(c.keyword, outsideModelRangeMessage("sphere"));
      return;
    }
    build_.add(sphere);
    return;
  }
  // A non-uniform scale makes it the image of the unit sphere under x -> L (r x) + center.
  const Mat3 linear = transform_.linear() * r.value;
  if (!allFinite(linear)) {
    error(c.keyword, outsideModelRangeMessage("sphere"));
    return;
  }
  Ellipsoid e = makeEllipsoid(linear, center);
  if (!allFinite(e.worldToObject)) {
    error(c.keyword, "sphere: too small after the current transform");
    return;
  }
  addPlaced(c, e, "sphere", true);
}

template <class Shape>
bool Parser::placedFits(Command& c, const Shape& shape, const char* name, bool mapWritten) {
  if (!withinModelRange(boundsOf(shape, ShapeArrays{}))) {
    error(c.keyword, outsideModelRangeMessage(name));
    return false;
  }
  if (mapWritten && !(stretchRatioBound(placedMap(shape)) <= kMaxStretchRatio)) {
    error(c.keyword, tooUnevenMessage(name));
    return false;
  }
  return true;
}

template <class Shape>
void Parser::addPlaced(Command& c, Shape shape, const char* name, bool mapWritten) {
  if (!placedFits(c, shape, name, mapWritten)) return;
  shape.material = build_.currentMaterial();
  shape.origin = origin(c);
  build_.add(shape);
}

void Parser::polygon(Command& c) {
  if (openInCsg(c)) return;
  const std::optional<std::uint64_t> count = vertexCount(c);
  if (!count) return;
  vertices_.clear();
  Vec3 vertex(0.0);
  const auto take = [&](std::uint64_t found, double value, const Token&) {
    const int axis = int(found % 3);
    vertex[axis] = value;
    if (axis == 2) vertices_.push_back(transform_.point(vertex));
  };
  if (!vertexNumbers(c, *count, 3, take) || !c.valid) return;
  // A mirroring transform would turn the counterclockwise order, and with it the
  // outward normal, inside out.
  if (mirrors(transform_)) std::reverse(vertices_.begin(), vertices_.end());
  for (const Vec3& v : vertices_) {
    if (!withinModelRange(v)) {
      error(c.keyword, outsideModelRangeMessage("polygon"));
      return;
    }
  }
  if (const std::optional<std::string> problem = polygonProblem(vertices_)) {
    error(c.keyword, "polygon: " + *problem);
    return;
  }
  build_.polygon(vertices_, build_.currentMaterial(), origin(c));
}

void Parser::cone(Command& c) {
  static constexpr const char* kNames[] = {"BX", "BY", "BZ", "BR", "AX", "AY", "AZ", "AR"};
  Arg a[8];
  if (c.name == "cone" && openInCsg(c)) return;
  if (!numbers(c, kNames, a)) return;
  for (const int i : {3, 7}) {
    if (a[i].value < 0.0) invalid(c, a[i].token, "negative radius " + quoted(a[i].token.text));
  }
  if (!c.valid) return;
  const std::optional<Cone> cone = placedCone(c, vec(a), a[3].value, vec(a + 4), a[7].value);
  if (!cone) return;
  if (c.name == "cone") {
    // An elliptic cone is written back through its frame's map (see
    // core/io/shape_text/), which must stay well conditioned; a circular one
    // is written as its end circles.
    addPlaced(c, *cone, "cone", !isCircular(*cone));
    return;
  }
  CappedCone capped;
  capped.side = *cone;
  addPlaced(c, capped, c.name.c_str(), !isCircular(*cone));
}

void Parser::cylinder(Command& c) {
  static constexpr const char* kNames[] = {"BX", "BY", "BZ", "AX", "AY", "AZ", "R"};
  Arg a[7];
  if (!numbers(c, kNames, a)) return;
  requirePositiveRadius(c, a[6]);
  if (!c.valid) return;
  const std::optional<Cone> cone = placedCone(c, vec(a), a[6].value, vec(a + 3), a[6].value);
  if (!cone) return;
  CappedCone capped;
  capped.side = *cone;
  addPlaced(c, capped, "cylinder", !isCircular(*cone));
}

std::optional<Cone> Parser::placedCone(Command& c, const Vec3& base, double baseRadius,
                                       const Vec3& apex, double apexRadius) {
  if (const std::optional<std::string> problem = coneProblem(base, baseRadius, apex, apexRadius)) {
    error(c.keyword, c.name + ": " + *problem);
    return std::nullopt;
  }
  Cone cone = makeCone(base, baseRadius, apex, apexRadius, transform_.linear(),
                       transform_.point(Vec3(0.0)));
  if (!allFinite(cone.worldToObject) || !isFinite(cone.worldToObjectOffset)) {
    error(c.keyword, c.name + ": too large or too small after the current transform");
    return std::nullopt;
  }
  return cone;
}

void Parser::requirePositiveRadius(Command& c, const Arg& r) {
  if (r.value < 0.0) invalid(c, r.token, "negative radius " + quoted(r.token.text));
  if (r.value == 0.0) invalid(c, r.token, "radius must be positive, found " + quoted(r.token.text));
}

void Parser::box(Command& c) {
  static constexpr const char* kNames[] = {"X0", "Y0", "Z0", "X1", "Y1", "Z1"};
  Arg a[6];
  if (!numbers(c, kNames, a) || !c.valid) return;
  const Vec3 corner0 = vec(a), corner1 = vec(a + 3);
  if (const std::optional<std::string> problem = boxProblem(corner0, corner1)) {
    error(c.keyword, "box: " + *problem);
    return;
  }
  const Box box = makeBox(corner0, corner1, transform_.linear(), transform_.point(Vec3(0.0)));
  // A scale can round the corners together, or the map's inverse overflow.
  if (!allFinite(box.frame.worldToObject) || !isFinite(box.frame.worldToObjectOffset) ||
      !(box.lo.x < box.hi.x && box.lo.y < box.hi.y && box.lo.z < box.hi.z)) {
    error(c.keyword, "box: too large or too small after the current transform");
    return;
  }
  // A box without rotation or shear is stored and written as its corners;
  // any other through its frame's map.
  addPlaced(c, box, "box", !isWorldAligned(box));
}

void Parser::disc(Command& c) {
  if (openInCsg(c)) return;
  static constexpr const char* kNames[] = {"CX", "CY", "CZ", "NX", "NY", "NZ", "R"};
  Arg a[7];
  if (!numbers(c, kNames, a)) return;
  if (vec(a + 3) == Vec3(0.0)) invalid(c, a[3].token, "N (NX NY NZ) must not be the zero vector");
  requirePositiveRadius(c, a[6]);
  if (!c.valid) return;
  if (const std::optional<std::string> problem = discProblem(vec(a), vec(a + 3), a[6].value)) {
    error(c.keyword, "disc: " + *problem);
    return;
  }
  const Disc disc =
      makeDisc(vec(a), vec(a + 3), a[6].value, transform_.linear(), transform_.point(Vec3(0.0)));
  if (!allFinite(disc.frame.worldToObject) || !isFinite(disc.frame.worldToObjectOffset) ||
      !isFinite(disc.normal)) {
    error(c.keyword, "disc: too large or too small after the current transform");
    return;
  }
  addPlaced(c, disc, "disc", !isCircular(disc));
}

void Parser::quadric(Command& c) {
  if (openInCsg(c)) return; // an open surface (its clip box's faces are not part of it)
  static constexpr const char* kNames[] = {"A", "B", "C",  "D",  "E",  "F",  "G",  "H",
                                           "I", "J", "X0", "Y0", "Z0", "X1", "Y1", "Z1"};
  Arg a[16];
  if (!numbers(c, kNames, a) || !c.valid) return;
  std::array<double, 10> coef;
  for (int i = 0; i < 10; ++i)
    coef[i] = a[i].value;
  const Vec3 corner0 = vec(a + 10), corner1 = vec(a + 13);
  if (const std::optional<std::string> problem = quadricProblem(coef, corner0, corner1)) {
    error(c.keyword, "quadric: " + *problem);
    return;
  }
  const Quadric q =
      makeQuadric(coef, corner0, corner1, transform_.linear(), transform_.point(Vec3(0.0)));
  // The map's inverse can overflow, and the rescaled coefficients too.
  bool finite = allFinite(q.frame.worldToObject) && isFinite(q.frame.worldToObjectOffset);
  for (const double k : q.coef)
    finite = finite && std::isfinite(k);
  if (!finite) {
    error(c.keyword, "quadric: too large or too small after the current transform");
    return;
  }
  // Written back in its frame under the current transform's map (see
  // core/io/shape_text/), which must stay well conditioned.
  addPlaced(c, q, "quadric", !isUnplaced(q));
}

void Parser::torus(Command& c) {
  static constexpr const char* kNames[] = {"CX", "CY", "CZ", "AX", "AY", "AZ", "MAJOR", "MINOR"};
  Arg a[8];
  if (!numbers(c, kNames, a)) return;
  const Vec3 center = vec(a), axis = vec(a + 3);
  if (c.valid && axis == Vec3(0.0)) invalid(c, a[3].token, "the axis (AX AY AZ) must not be zero");
  for (const int i : {6, 7}) {
    if (c.valid && !(a[i].value > 0.0))
      invalid(c, a[i].token,
              std::string(kNames[i]) + " must be positive, found " + quoted(a[i].token.text));
  }
  if (c.valid && !(a[7].value < a[6].value)) {
    invalid(c, a[7].token,
            "MINOR must be less than MAJOR, found " + quoted(a[7].token.text) +
                " (horn and spindle tori are not supported)");
  }
  if (!c.valid) return;
  if (const std::optional<std::string> problem =
          torusProblem(center, axis, a[6].value, a[7].value)) {
    error(c.keyword, "torus: " + *problem);
    return;
  }
  Torus torus = makeTorus(center, axis, a[6].value, a[7].value, transform_.linear(),
                          transform_.point(Vec3(0.0)));
  if (!allFinite(torus.worldToObject) || !isFinite(torus.worldToObjectOffset)) {
    error(c.keyword, "torus: too large or too small after the current transform");
    return;
  }
  // A stretched torus is written back through its frame's map (see
  // core/io/shape_text/), which must stay well conditioned; a round one as
  // its centre, axis and radii.
  addPlaced(c, torus, "torus", !isRound(torus));
}

void Parser::blob(Command& c) {
  Arg threshold;
  if (!number(c, "THRESHOLD", threshold)) return;
  if (c.valid && !(threshold.value > 0.0))
    invalid(c, threshold.token,
            "THRESHOLD must be positive, found " + quoted(threshold.token.text));
  std::optional<std::uint64_t> count;
  if (!integer(c, "N", 1, kMaxBlobComponents, count)) return;
  if (!count) {
    skipNumbers();
    return;
  }
  // Read as they come, so a hostile N costs nothing until its numbers are
  // there.
  components_.clear();
  static constexpr const char* kSlots[] = {"X", "Y", "Z", "R", "S"};
  for (std::uint64_t i = 0; i < *count; ++i) {
    Arg a[5];
    for (int k = 0; k < 5; ++k) {
      const std::string name = kSlots[k] + std::to_string(i + 1);
      if (!number(c, name.c_str(), a[k])) return;
    }
    const std::string index = std::to_string(i + 1);
    if (a[3].value <= 0.0)
      invalid(c, a[3].token, "R" + index + " must be positive, found " + quoted(a[3].token.text));
    if (a[4].value == 0.0)
      invalid(c, a[4].token, "S" + index + " must not be zero, found " + quoted(a[4].token.text));
    components_.push_back({vec(a), a[3].value, a[4].value});
  }
  if (!c.valid) return;
  if (const std::optional<std::string> problem = blobProblem(components_, threshold.value)) {
    error(c.keyword, "blob: " + *problem);
    return;
  }
  PlacedBlob placed =
      makeBlob(components_, threshold.value, transform_.linear(), transform_.point(Vec3(0.0)));
  bool usable = allFinite(placed.blob.frame.worldToObject) &&
                isFinite(placed.blob.frame.worldToObjectOffset) && !placed.blob.bounds.empty();
  for (const BlobComponent& component : placed.components)
    usable = usable && isFinite(component.center) && component.radius > 0.0 &&
             std::isfinite(component.radius);
  if (!usable) {
    error(c.keyword, "blob: too large or too small after the current transform");
    return;
  }
  // A blob under a stretching transform is written back through its frame's
  // map (see core/io/shape_text/), which must stay well conditioned.
  if (!placedFits(c, placed.blob, "blob", placed.blob.placed)) return;
  placed.blob.material = build_.currentMaterial();
  placed.blob.origin = origin(c);
  build_.blob(placed);
}

// The four triangle forms: each vertex is X Y Z, then NX NY NZ for
// `ptriangle` and `ptriangle_uv`, then U V for `triangle_uv` and
// `ptriangle_uv`.
void Parser::triangle(Command& c) {
  if (!mesh_ && openInCsg(c)) return;
  const bool smooth = c.name.front() == 'p';
  const bool withUv = c.name.ends_with("_uv");
  if (withUv && mesh_ && build_.inCsg()) {
    // A mesh operand's triangles live in the closed meshes' arrays, which
    // keep no surface coordinates of their own.
    error(c.keyword, c.name + ": per-vertex uv is not supported in a mesh block inside csg (its "
                              "triangles get their barycentric coordinates; use triangle or "
                              "ptriangle there)");
    skipNumbers();
    return;
  }
  // Per vertex: 3 coordinates, 3 for the normal, 2 for uv.
  static constexpr const char* kNames[4][24] = {
      {"X1", "Y1", "Z1", "X2", "Y2", "Z2", "X3", "Y3", "Z3"},
      {"X1", "Y1", "Z1", "NX1", "NY1", "NZ1", "X2", "Y2", "Z2", "NX2", "NY2", "NZ2", "X3", "Y3",
       "Z3", "NX3", "NY3", "NZ3"},
      {"X1", "Y1", "Z1", "U1", "V1", "X2", "Y2", "Z2", "U2", "V2", "X3", "Y3", "Z3", "U3", "V3"},
      {"X1",  "Y1",  "Z1", "NX1", "NY1", "NZ1", "U1", "V1",  "X2",  "Y2",  "Z2", "NX2",
       "NY2", "NZ2", "U2", "V2",  "X3",  "Y3",  "Z3", "NX3", "NY3", "NZ3", "U3", "V3"}};
  const int perVertex = 3 + (smooth ? 3 : 0) + (withUv ? 2 : 0);
  const char* const* names = kNames[(withUv ? 2 : 0) + (smooth ? 1 : 0)];
  Arg a[24];
  for (int i = 0; i < 3 * perVertex; ++i)
    if (!number(c, names[i], a[i])) return;
  if (!c.valid) return;
  std::array<Vec3, 3> vertices, normals;
  std::array<Vec2, 3> uvs;
  for (int i = 0; i < 3; ++i) {
    const Arg* at = a + perVertex * i;
    vertices[i] = vec(at);
    if (smooth) {
      normals[i] = vec(at + 3);
      if (normals[i] == Vec3(0.0)) {
        const std::string k = std::to_string(i + 1);
        invalid(c, at[3].token,
                "N" + k + " (NX" + k + " NY" + k + " NZ" + k + ") must not be the zero vector");
      }
    }
    if (withUv) uvs[i] = Vec2(at[perVertex - 2].value, at[perVertex - 1].value);
  }
  if (!c.valid) return;
  addTriangle(c, vertices, smooth ? &normals : nullptr, withUv ? &uvs : nullptr);
}

// Places a triangle (and its vertex normals, if any) through the current
// transform and stores it in the scene's mesh arrays, with its per-vertex
// surface coordinates, if any (which no transform changes).
void Parser::addTriangle(Command& c, std::array<Vec3, 3> v, const std::array<Vec3, 3>* normals,
                         std::array<Vec2, 3>* uvs) {
  std::array<Vec3, 3> n;
  for (int i = 0; i < 3; ++i) {
    v[i] = transform_.point(v[i]);
    if (!withinModelRange(v[i])) {
      error(c.keyword, outsideModelRangeMessage(c.name));
      return;
    }
    if (normals != nullptr) {
      // Normals move by the inverse transpose; scaled before normalising so
      // that a tiny or huge one cannot under- or overflow.
      const Vec3 moved = transform_.normal((*normals)[i] / maxAbsComponent((*normals)[i]));
      n[i] = glm::normalize(moved / maxAbsComponent(moved));
      if (!isFinite(n[i])) {
        error(c.keyword, c.name + ": vertex normal is not finite after the current transform");
        return;
      }
    }
  }
  // A mirror turns the counterclockwise order inside out; the normals stay
  // outward by themselves (the inverse transpose mirrors them too). The
  // surface coordinates stay with their vertices.
  if (mirrors(transform_)) {
    std::swap(v[1], v[2]);
    std::swap(n[1], n[2]);
    if (uvs != nullptr) std::swap((*uvs)[1], (*uvs)[2]);
  }
  if (const std::optional<std::string> problem = triangleProblem(v[0], v[1], v[2])) {
    error(c.keyword, c.name + ": " + *problem);
    return;
  }
  if (mesh_) {
    std::optional<std::array<Vec3, 3>> kept;
    if (normals != nullptr) kept = n;
    std::optional<std::array<Vec2, 3>> keptUvs;
    if (uvs != nullptr) keptUvs = *uvs;
    mesh_->faces.push_back(
        {v, kept, keptUvs, Location{file().name, c.keyword.line, c.keyword.column}, origin(c)});
    return;
  }
  const PrimitiveRef ref =
      build_.triangle(v, normals != nullptr ? &n : nullptr, build_.currentMaterial(), origin(c));
  if (uvs != nullptr) build_.setTriangleUvs(ref.index, *uvs);
}

// ---------------------------------------------------------------------------
// Hierarchy and transforms

void Parser::push(Command& c) {
  if (saved_.size() >= kMaxGroupDepth) {
    // Every later pop would be reported as unmatched: stop here.
    error(c.keyword, "push: groups nested more than " + std::to_string(kMaxGroupDepth) + " deep");
    throw StopReading{};
  }
  const bool inMesh = mesh_.has_value();
  saved_.push_back({transform_, Location{file().name, c.keyword.line, c.keyword.column},
                    std::nullopt, false, inMesh});
  // In a mesh block a push scopes the transform only: no group, no material.
  if (!inMesh) build_.push(origin(c));
}

void Parser::pop(Command& c) {
  if (const Saved* open = innermostInFile(); open != nullptr && (open->csg || open->mesh)) {
    error(c.keyword, std::string("pop without matching push (a ") + (open->csg ? "csg" : "mesh") +
                         " block is open: close it with 'end' first)");
    return;
  }
  if (saved_.size() == file().savedAtEntry) {
    error(c.keyword, saved_.empty() ? "pop without matching push"
                                    : "pop without matching push in this file (push and pop "
                                      "must balance within each file)");
    return;
  }
  setTransform(saved_.back().transform);
  if (!saved_.back().inMesh) build_.pop();
  saved_.pop_back();
}

bool Parser::openInCsg(Command& c) {
  if (!build_.inCsg()) return false;
  error(c.keyword, c.name +
                       ": not a closed solid, so it cannot be an operand of csg (spheres, boxes, "
                       "cylinders, capped cones, tori, blobs, meshes and csg blocks can)");
  skipNumbers();
  return true;
}

bool Parser::notInMesh(const Token& keyword) {
  if (!mesh_) return false;
  static constexpr std::string_view kAllowed[] = {
      "triangle",  "ptriangle", "triangle_uv", "ptriangle_uv", "push", "pop",
      "translate", "scale",     "rotate",      "include",      "end"};
  if (std::find(std::begin(kAllowed), std::end(kAllowed), keyword.text) != std::end(kAllowed))
    return false;
  error(keyword, std::string(keyword.text) +
                     ": not allowed inside a mesh block (it holds triangle, ptriangle, "
                     "triangle_uv, ptriangle_uv, push, pop, translate, scale, rotate and "
                     "include)");
  skipNumbers();
  return true;
}

void Parser::mesh(Command& c) {
  saved_.push_back({transform_, Location{file().name, c.keyword.line, c.keyword.column},
                    std::nullopt, true, false});
  mesh_ = OpenMesh{saved_.back().pushedAt, origin(c), diagnosticCount(), {}};
}

// The mesh's triangles must bound a solid (mesh_closure.h): then, wound
// outward, they are the open csg block's next operand, or outside csg plain
// triangles. A mesh with an error inside is dropped (its errors say why).
void Parser::endMesh() {
  OpenMesh open = std::move(*mesh_);
  mesh_.reset();
  if (diagnosticCount() != open.errorsBefore) return;
  if (open.faces.empty()) {
    report(open.at, "mesh: has no triangles");
    return;
  }
  std::vector<std::array<Vec3, 3>> corners;
  corners.reserve(open.faces.size());
  for (const MeshFace& f : open.faces)
    corners.push_back(f.v);
  WeldedMesh welded = weld(corners);
  if (const std::optional<ClosureProblem> p = closureProblem(welded)) {
    const std::string edge = "the edge from (" + sc::vec(p->from) + ") to (" + sc::vec(p->to) + ")";
    report(open.faces[p->triangle].at,
           p->kind == ClosureProblem::Kind::Open
               ? "mesh: not closed: " + edge + " of this triangle is in no other triangle"
               : "mesh: not consistently oriented: this triangle runs " + edge +
                     " the same way as the triangle at " + open.faces[p->other].at.text() +
                     " (triangles sharing an edge must run it in opposite directions, and no "
                     "more than two may share it)");
    return;
  }
  const double volume = signedVolume6(welded);
  if (!(volume != 0.0)) {
    report(open.at, "mesh: encloses no volume");
    return;
  }
  // Wound inward: every triangle turned over, so the right-hand normals
  // point out (vertex normals are kept as given, and each vertex keeps its
  // surface coordinates).
  const bool flip = volume < 0.0;
  std::vector<std::optional<std::array<Vec3, 3>>> normals;
  normals.reserve(open.faces.size());
  for (std::size_t i = 0; i < open.faces.size(); ++i) {
    std::optional<std::array<Vec3, 3>> n = open.faces[i].normals;
    if (flip) {
      std::swap(welded.triangles[i][1], welded.triangles[i][2]);
      if (n) std::swap((*n)[1], (*n)[2]);
      if (std::optional<std::array<Vec2, 3>>& uv = open.faces[i].uvs) std::swap((*uv)[1], (*uv)[2]);
    }
    normals.push_back(n);
  }
  const std::uint32_t material = build_.currentMaterial();
  if (build_.inCsg()) {
    build_.solidMesh({welded.vertices, welded.triangles, normals, material, open.origin});
    return;
  }
  for (std::size_t i = 0; i < open.faces.size(); ++i) {
    const auto& t = welded.triangles[i];
    const PrimitiveRef ref =
        build_.triangle({welded.vertices[t[0]], welded.vertices[t[1]], welded.vertices[t[2]]},
                        normals[i] ? &*normals[i] : nullptr, material, open.faces[i].origin);
    if (open.faces[i].uvs) build_.setTriangleUvs(ref.index, *open.faces[i].uvs);
  }
}

void Parser::csg(Command& c) {
  const Token word = file().lexer.peek();
  std::optional<CsgOp> op;
  for (const CsgOp o : {CsgOp::Union, CsgOp::Intersection, CsgOp::Difference}) {
    if (word.text == csgOpName(o)) op = o;
  }
  if (!op) {
    // Still a block (a union), so its operands and `end` read as such.
    error(word.atEnd() ? c.keyword : word,
          "csg: expected union, intersection or difference but " +
              (word.atEnd() ? std::string("reached the end of the file")
                            : "found " + quoted(word.text)));
    if (!word.atEnd() && !startsCommand(word.text)) file().lexer.next();
    skipNumbers();
  } else {
    file().lexer.next();
  }
  if (build_.openCsgs() >= kMaxCsgDepth) {
    error(c.keyword, "csg: blocks nested more than " + std::to_string(kMaxCsgDepth) + " deep");
    throw StopReading{};
  }
  const CsgOp operation = op.value_or(CsgOp::Union);
  saved_.push_back({transform_, Location{file().name, c.keyword.line, c.keyword.column}, operation,
                    false, false, diagnosticCount()});
  build_.beginCsg(operation, origin(c));
}

void Parser::end(Command& c) {
  const Saved* open = innermostInFile();
  if (open == nullptr) {
    error(c.keyword, saved_.empty() || !(saved_.back().csg || saved_.back().mesh)
                         ? "end without matching csg or mesh"
                         : "end without matching csg or mesh in this file (blocks and their end "
                           "must balance within each file)");
    return;
  }
  if (open->mesh) {
    setTransform(open->transform);
    saved_.pop_back();
    endMesh();
    return;
  }
  if (!open->csg) {
    error(c.keyword,
          "end without matching csg or mesh (a push is open: close it with 'pop' first)");
    return;
  }
  const Location at = open->pushedAt;
  const CsgOp op = *open->csg;
  // An operand dropped for an error of its own is reported already.
  const bool operandsBroken = diagnosticCount() != open->errorsBefore;
  setTransform(open->transform);
  saved_.pop_back();
  const std::size_t count = build_.endCsg();
  if (count < 2 && !operandsBroken) {
    report(at, std::string("csg ") + csgOpName(op) + ": needs at least two operands, found " +
                   std::to_string(count));
  }
}

// Composes `t` onto the current transform unless the result is no longer usable
// (entries or inverse overflowing after many large or tiny scales).
void Parser::compose(Command& c, const Transform& t) {
  const Transform next = transform_ * t;
  if (!allFinite(next.matrix()) || !allFinite(next.inverse())) {
    error(c.keyword,
          c.name + ": the current transform would become degenerate (too large or too small)");
    return;
  }
  setTransform(next);
}

void Parser::translate(Command& c) {
  Arg a[3];
  if (!numbers(c, {"X", "Y", "Z"}, a) || !c.valid) return;
  compose(c, Transform::translate(vec(a)));
}

void Parser::scale(Command& c) {
  static constexpr const char* kNames[] = {"X", "Y", "Z"};
  Arg a[3];
  if (!numbers(c, kNames, a)) return;
  for (int i = 0; i < 3; ++i) {
    if (a[i].value == 0.0) {
      invalid(c, a[i].token,
              std::string(kNames[i]) + " must not be zero, found " + quoted(a[i].token.text));
    }
  }
  if (c.valid) compose(c, Transform::scale(vec(a)));
}

void Parser::rotate(Command& c) {
  Arg a[4];
  if (!numbers(c, {"AX", "AY", "AZ", "DEGREES"}, a)) return;
  const Vec3 axis = vec(a);
  if (c.valid && axis == Vec3(0.0)) invalid(c, a[0].token, "the axis (AX AY AZ) must not be zero");
  if (!c.valid) return;
  // Scaled first so that normalising a tiny or huge axis cannot under- or overflow.
  compose(c, Transform::rotate(axis / maxAbsComponent(axis), a[3].value));
}

// ---------------------------------------------------------------------------
// Include

std::uint32_t Parser::fileIndex(const fs::path& identity, const std::string& name) {
  const auto [it, inserted] =
      fileIndices_.try_emplace(identity, std::uint32_t(scene_.files.size()));
  if (inserted) build_.addFile(name);
  return it->second;
}

// Where an `include PATH` in the current file leads. identityOf costs several
// system calls (it resolves links) and path arithmetic is slow too; a part
// included 10^5 times (a leaf of a tree) is resolved once per scene, like its
// text is read once.
const Parser::ResolvedInclude& Parser::resolveInclude(std::string_view raw) {
  std::string key = file().name;
  key += '\0';
  key += raw;
  auto it = includes_.find(key);
  if (it == includes_.end()) {
    ResolvedInclude r;
    r.path = besideCurrentFile(raw);
    r.name = r.path.string();
    r.identity = identityOf(r.path);
    it = includes_.emplace(std::move(key), std::move(r)).first;
  }
  return it->second;
}

// The contents of an included file, read at most once per scene.
std::optional<std::string> Parser::readInclude(const fs::path& path, const fs::path& identity,
                                               const std::string*& text) {
  if (const auto it = contents_.find(identity); it != contents_.end()) {
    text = &it->second;
    return std::nullopt;
  }
  std::string contents;
  if (std::optional<std::string> problem = readFile(path, true, contents)) return problem;
  text = &contents_.emplace(identity, std::move(contents)).first->second;
  return std::nullopt;
}

std::optional<std::string_view> Parser::pathArgument(Command& c, const Token& token) {
  if (token.atEnd()) {
    error(c.keyword, c.name + ": expected PATH but reached the end of the file");
    return std::nullopt;
  }
  std::string_view raw = token.text;
  if (raw.front() == '"') {
    if (raw.size() < 2 || raw.back() != '"') {
      error(token, c.name + ": PATH has no closing '\"' on its line");
      skipNumbers();
      return std::nullopt;
    }
    raw = raw.substr(1, raw.size() - 2);
  }
  if (raw.empty()) {
    error(token, c.name + ": PATH is empty");
    skipNumbers();
    return std::nullopt;
  }
  return raw;
}

void Parser::include(Command& c) {
  const Token token = file().lexer.nextPath();
  const std::optional<std::string_view> raw = pathArgument(c, token);
  if (!raw) return;
  const ResolvedInclude& resolved = resolveInclude(*raw);
  const fs::path& path = resolved.path;
  const std::string& name = resolved.name;
  const fs::path& identity = resolved.identity;

  for (std::size_t i = 0; i < files_.size(); ++i) {
    if (files_[i]->identity != identity) continue;
    std::string cycle = "include cycle: ";
    for (std::size_t j = i; j < files_.size(); ++j) {
      cycle += files_[j]->name + " -> ";
    }
    error(token, cycle + name);
    skipNumbers();
    return;
  }
  if (files_.size() >= kMaxIncludeDepth) {
    error(token, "include: files nested more than " + std::to_string(kMaxIncludeDepth) + " deep");
    skipNumbers();
    return;
  }
  const std::string* text = nullptr;
  if (const std::optional<std::string> problem = readInclude(path, identity, text)) {
    error(token, "cannot read '" + name + "': " + *problem);
    skipNumbers();
    return;
  }
  if (parsedBytes_ + text->size() > kMaxSceneBytes) {
    error(token, std::string("include: the scene text, counting every inclusion, exceeds ") +
                     kMaxSceneBytesText);
    skipNumbers();
    return;
  }
  parsedBytes_ += text->size();
  parseFile(*text, name, identity, fileIndex(identity, name));
}

// ---------------------------------------------------------------------------
// Camera checks, once the whole scene is known

void Parser::checkCamera() {
  if (cameraBroken_) return;
  const Location mainStart{scene_.files[0], 1, 1};
  const auto given = [&](const char* name) { return firstGiven(name); };
  const Location* view = given("lookat") ? given("lookat") : given("eye");
  const Location& viewAt = view ? *view : mainStart;
  const Location& upAt = given("up") ? *given("up") : viewAt;

  switch (cameraProblem(scene_.camera)) {
  case CameraProblem::None: return;
  case CameraProblem::SamePoint:
    report(viewAt, "eye and lookat are the same point, so there is no view direction");
    return;
  case CameraProblem::NoDirection:
    report(viewAt, "eye and lookat are too close together or too far apart to give a view "
                   "direction");
    return;
  case CameraProblem::ZeroUp: report(upAt, "up must not be the zero vector"); return;
  case CameraProblem::ParallelUp:
    report(upAt, "up is parallel to the view direction (from eye to lookat)");
    return;
  case CameraProblem::ShortUp: report(upAt, "up is too short to give a direction"); return;
  }
}

} // namespace

Scene parseScene(std::string_view text, const std::string& name) {
  return Parser().run(text, name);
}

Scene loadScene(const std::filesystem::path& path) {
  return parseScene(readSceneText(path), path.string());
}

} // namespace prism
