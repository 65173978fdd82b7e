// tree_gen: writes the tree of scenes/tree.sc and the forest of scenes/forest.sc
// in Prism's scene language (docs/scene-language.md), and the same tree built
// from closed solids, scenes/tree-solid.sc.
//
//   tree_gen [SCENES_DIR]    (default: the current directory) writes
//     SCENES_DIR/parts/tree_body.sc  the tree itself, over 100,000 primitives
//     SCENES_DIR/tree.sc             camera, lights, ground and the tree
//     SCENES_DIR/forest.sc           the same ground under ten trees (over a
//                                    million primitives), for the previewer
//     SCENES_DIR/parts/tree_solid_body.sc  the same tree (the same seed, so
//                                    the same branches, bends and twigs) with
//                                    solid branches, see below
//     SCENES_DIR/tree-solid.sc       tree.sc's setting around that tree
//
// The tree is built recursively. Every branch is one push/pop group holding its
// own segments and, nested inside, the groups of all its sub-branches, so the
// scene's hierarchy follows the tree: a ray that misses a branch's bounding box
// skips everything that grows from it. Branches are placed with relative
// transforms (each in its parent's frame, +y along the branch), which keeps the
// numbers short. Geometry comes from small part files included many times:
//   parts/branch.sc  an octagonal frustum (8 polygons), one per branch segment,
//   parts/twigN.sc   three twig variants: a stalk and 10 to 14 folded leaves
//                    (21 to 29 primitives), the leaves in the surface written
//                    before the include: each variant's green or, on a third of
//                    the last-generation branches, an autumn tint,
// so the files stay small while the primitive count is large. A sphere covers
// every joint between segments. The bark is a marble texture whose veins are
// dark furrows along the branches, a furrow every quarter of a branch's
// radius. The forest includes the one tree ten times, each turned, scaled and
// placed differently.
//
// The solid tree writes every segment as a `capped_cone` (the frustum itself,
// round and closed, instead of eight polygons), a sphere of the segment's end
// radius (plus 1%, so that no rim of a flat cap shows) at every bend and at
// the tip of each last-generation branch, and at every fork a `blob` that
// merges the branch ends into a smooth collar: one component inside the
// parent's end and two along each child's axis. Its branches are written at
// their size, so each branch group gives its bark texture a spacing of its
// own (0.4 of its radius at its base). Both trees draw the same random
// numbers in the same order: the solid one differs only in what it writes.
//
// Deterministic: a fixed seed and our own generator (splitmix64), no
// std::*_distribution (whose output differs between standard libraries), and
// numbers printed with %.4g (which also hides last-bit differences between
// maths libraries). Uses only the C++ standard library and the header-only
// core/math/hash.h.

#include "core/math/hash.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

namespace {

// The seed was picked by rendering the trees of seeds 1 to 6 and keeping the
// best-looking one; any other value gives another tree of the same kind.
constexpr std::uint64_t kSeed = 4;
constexpr double kPi = 3.14159265358979323846;
// The spacing of the bark's furrows over a branch's radius: about eight
// across a branch's visible side. In the unit frustum of parts/branch.sc,
// stretched along each segment (2.5 times on the trunk, more on thinner
// branches), the marble's swirl runs along the branch too; the solid
// branches are written at their size, where the swirl is round and breaks
// such fine furrows into speckles: wider ones there (by eye, the closest to
// tree.sc's bark).
constexpr double kBarkFurrows = 0.25;
constexpr double kSolidBarkFurrows = 0.4;
// Primitives in parts/twig1.sc, twig2.sc, twig3.sc.
constexpr long kTwigPrims[3] = {25, 21, 29};

// The leaves' colours, written before each twig's include (the twig parts
// take the current surface for their leaves). Each variant has its green; a
// last-generation branch that has turned gives all its twigs one autumn tint,
// mixed 3:1 with each variant's green so the variants stay apart. Drawn from
// a generator of their own (kTintSeed), so the branches draw the numbers
// they drew before there were tints: the same tree.
// Colours and not a `texture`: in the leaves' object space (parts/leaf.sc)
// every leaf would show the same pattern, and each leaf's own map would make
// a stored material of it (40,000 per tree, some 250 MB more for forest.sc);
// pinned to the world (texture_space) the pattern would stay behind when the
// tree is placed by a transform, as forest.sc places it.
constexpr double kLeafGreens[3][3] = {{0.22, 0.5, 0.12}, {0.32, 0.56, 0.14}, {0.17, 0.42, 0.1}};
struct Tint {
  double share; // of the last-generation branches
  double rgb[3];
};
constexpr Tint kTints[] = {
    {0.12, {0.5, 0.58, 0.1}},   // yellow-green
    {0.10, {0.88, 0.64, 0.1}},  // gold
    {0.08, {0.84, 0.36, 0.06}}, // orange
    {0.05, {0.64, 0.14, 0.05}}, // red
};
constexpr std::uint64_t kTintSeed = 0x7ea5;

// splitmix64 (core/math/hash.h): tiny, fast, and the same on every platform.
using Rng = prism::SplitMix64;

struct Vec {
  double x = 0, y = 0, z = 0;
};
Vec operator*(double s, Vec v) { return {s * v.x, s * v.y, s * v.z}; }
Vec operator+(Vec a, Vec b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
double dot(Vec a, Vec b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
Vec cross(Vec a, Vec b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
double length(Vec v) { return std::sqrt(dot(v, v)); }

// A rotation as a 3x3 matrix (rows), mapping local to world directions. The
// generator tracks each branch's orientation only to bend it toward the sky.
struct Rot {
  std::array<std::array<double, 3>, 3> m{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};

  // Rotation about unit axis a by angle (radians), right-handed.
  static Rot axisAngle(Vec a, double angle) {
    const double c = std::cos(angle), s = std::sin(angle), t = 1 - c;
    Rot r;
    r.m = {{{t * a.x * a.x + c, t * a.x * a.y - s * a.z, t * a.x * a.z + s * a.y},
            {t * a.x * a.y + s * a.z, t * a.y * a.y + c, t * a.y * a.z - s * a.x},
            {t * a.x * a.z - s * a.y, t * a.y * a.z + s * a.x, t * a.z * a.z + c}}};
    return r;
  }
  Rot operator*(const Rot& b) const {
    Rot r;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        r.m[i][j] = 0;
        for (int k = 0; k < 3; ++k)
          r.m[i][j] += m[i][k] * b.m[k][j];
      }
    return r;
  }
  // World direction -> local direction (the transpose).
  Vec toLocal(Vec w) const {
    return {m[0][0] * w.x + m[1][0] * w.y + m[2][0] * w.z,
            m[0][1] * w.x + m[1][1] * w.y + m[2][1] * w.z,
            m[0][2] * w.x + m[1][2] * w.y + m[2][2] * w.z};
  }
};

// Tuning of the tree's shape.
// How the branches are made: octagonal frustums of polygons (tree.sc) or
// closed solids with blobs at the forks (tree-solid.sc).
enum class Style { Polygons, Solids };

struct Params {
  int levels = 5;            // branch generations below the trunk
  double trunkLength = 4.2;  // from the ground to the first fork
  double trunkRadius = 0.42; // at the ground
  double lengthRatio = 0.72; // child length / parent length
  double taper = 0.85;       // radius factor per segment (must match parts/branch.sc)
  double tropism = 0.12;     // fraction of the angle to vertical removed per segment
  double twigLength = 1.15;  // twig (stalk + leaves) length
};

class TreeWriter {
public:
  TreeWriter(std::FILE* out, Params p, Style style = Style::Polygons)
      : out_(out), p_(p), style_(style), rng_(kSeed), tintRng_(kTintSeed) {}

  // Writes the tree (roots and branches; no ground, no camera) as one group and
  // returns its number of primitives.
  long write() {
    if (solid())
      std::fprintf(out_,
                   "# tree_solid_body.sc -- the tree of tree-solid.sc, for Prism: the tree\n"
                   "# of tree_body.sc with closed solids for branches and blobs at the forks.\n"
                   "# GENERATED by tools/tree_gen.cpp; do not edit by hand, change the\n"
                   "# generator and run:  build/tools/tree_gen scenes\n"
                   "#\n"
                   "# Every push/pop below is a branch and everything growing from it; each\n"
                   "# twig of leaves is a group too. A branch segment is a capped_cone;\n"
                   "# each fork's blob follows the groups of the branches it joins.\n\n"
                   "push\n");
    else
      std::fprintf(out_, "# tree_body.sc -- the tree of tree.sc and forest.sc, for Prism.\n"
                         "# GENERATED by tools/tree_gen.cpp; do not edit by hand, change the\n"
                         "# generator and run:  build/tools/tree_gen scenes\n"
                         "#\n"
                         "# Every push/pop below is a branch and everything growing from it; each\n"
                         "# twig of leaves is a group too.\n\n"
                         "push\n");
    std::fprintf(out_, "surface 0.42 0.33 0.24  0.9 0 0  1 1   # bark: matte grey-brown\n");
    // parts/branch.sc and the roots are of radius 1 in their object space,
    // where the texture is evaluated: the furrows follow the branch's
    // thickness by themselves.
    barkTexture(kBarkFurrows, solid() ? "the roots' furrows" : "furrows along every branch");
    roots();
    branch(0, p_.trunkLength, p_.trunkRadius, Rot{}, 0, false);
    std::fprintf(out_, "pop\n");
    const char* name = solid() ? "tree_gen (solid)" : "tree_gen";
    if (solid()) {
      const long prims = segments_ + joints_ + forks_ + twigPrims_;
      std::fprintf(stderr,
                   "%s: %ld branch segments, %ld joint, tip and root spheres, %ld fork blobs (%ld "
                   "components), %ld twigs\n",
                   name, segments_, joints_, forks_, forkComponents_, twigs_);
      std::fprintf(stderr, "%s: %ld primitives in the tree\n", name, prims);
      std::fprintf(out_,
                   "# %ld primitives: %ld branch segments (capped cones), %ld joint, tip and root\n"
                   "# spheres, %ld fork blobs (%ld components in all),\n",
                   prims, segments_, joints_, forks_, forkComponents_);
      std::fprintf(out_, "# %ld twigs (%ld primitives), %ld of them in autumn colours.\n", twigs_,
                   twigPrims_, turnedTwigs_);
      return prims;
    }
    const long prims = segments_ * 8 + joints_ + twigPrims_;
    std::fprintf(stderr, "%s: %ld branch segments, %ld joint and root spheres, %ld twigs\n", name,
                 segments_, joints_, twigs_);
    std::fprintf(stderr, "%s: %ld primitives in the tree\n", name, prims);
    std::fprintf(
        out_,
        "# %ld primitives: %ld branch segments (8 polygons each), %ld joint and root spheres,\n",
        prims, segments_, joints_);
    std::fprintf(out_, "# %ld twigs (%ld primitives), %ld of them in autumn colours.\n", twigs_,
                 twigPrims_, turnedTwigs_);
    return prims;
  }

private:
  // Root buttresses: flattened ellipsoids half sunk into the ground around the
  // trunk's foot.
  void roots() {
    std::fprintf(out_, "push # roots\n");
    const int n = 5;
    for (int k = 0; k < n; ++k) {
      const double azimuth = 360.0 * k / n + rng_.uniform(-20, 20);
      const double len = p_.trunkRadius * rng_.uniform(1.8, 2.4);
      std::fprintf(out_,
                   " push rotate 0 1 0 %.4g translate %.4g 0 0 rotate 0 0 1 -12 scale %.4g %.4g "
                   "%.4g sphere 0 0 0 1 pop\n",
                   azimuth, 0.6 * p_.trunkRadius, len, 0.55 * p_.trunkRadius,
                   0.45 * p_.trunkRadius);
      ++joints_;
    }
    std::fprintf(out_, "pop\n");
  }

  // Writes a branch of generation `level` in the current frame (base at the
  // origin, growing along +y). `orient` maps this frame's directions to world.
  // `forked`: it grows from its parent's end, where the solid tree's fork blob
  // covers its base (no sphere there).
  void branch(int level, double len, double radius, Rot orient, int depth, bool forked) {
    const int segments = level == 0 ? 4 : (level <= 2 ? 3 : 2);
    const double segLength = len / segments;
    double r = radius;
    std::string pad(static_cast<std::size_t>(depth), ' ');
    std::fprintf(out_, "%spush # level %d\n", pad.c_str(), level);
    if (level == p_.levels) tint_ = drawTint();
    // The solid branches are written at their size: the furrows are scaled
    // to each one's radius at its base (its forks, bends and tip share them).
    if (solid()) {
      std::fprintf(out_, "%s ", pad.c_str());
      barkTexture(kSolidBarkFurrows * r, nullptr);
    }
    for (int s = 0; s < segments; ++s) {
      if (solid() ? s > 0 || (level > 0 && !forked) : s > 0 || level > 0) {
        // Just inside the octagon's faces (inradius cos 22.5 = 0.924) so it
        // fills the gap on the outside of a bend without bulging out; round
        // segments' rims lie on the sphere of their radius, so it is 1% over.
        std::fprintf(out_, "%s sphere 0 0 0 %.4g\n", pad.c_str(), (solid() ? 1.01 : 0.92) * r);
        ++joints_;
      }
      if (solid())
        std::fprintf(out_, "%s capped_cone 0 0 0 %.4g  0 %.4g 0 %.4g\n", pad.c_str(), r, segLength,
                     p_.taper * r);
      else
        std::fprintf(out_, "%s push scale %.4g %.4g %.4g include branch.sc pop\n", pad.c_str(), r,
                     segLength, r);
      ++segments_;
      std::fprintf(out_, "%s translate 0 %.4g 0\n", pad.c_str(), segLength);
      r *= p_.taper;
      const bool last = s == segments - 1;

      // Bend: a little random wobble plus a pull toward the vertical.
      if (!last) {
        Vec upLocal = orient.toLocal({0, 1, 0});
        Vec axis = cross({0, 1, 0}, upLocal);
        double toUp = std::asin(std::fmin(1.0, length(axis)));
        if (upLocal.y < 0) toUp = kPi - toUp;
        Vec wobble{rng_.uniform(-1, 1), 0, rng_.uniform(-1, 1)};
        Vec bendAxis = (level == 0 ? 0.0 : p_.tropism * toUp) * unit(axis) +
                       (level == 0 ? 0.04 : 0.12) * wobble;
        double angle = length(bendAxis);
        if (angle > 1e-4) {
          Vec a = (1.0 / angle) * bendAxis;
          std::fprintf(out_, "%s rotate %.4g %.4g %.4g %.4g\n", pad.c_str(), a.x, a.y, a.z,
                       angle * 180 / kPi);
          orient = orient * Rot::axisAngle(a, angle);
        }
      }

      // Side branches along the way (not on the trunk's lower part).
      if (!last && level < p_.levels && (level > 0 || s >= 2) && rng_.uniform() < 0.5) {
        child(level + 1, len * p_.lengthRatio * 0.8, r * 0.6, orient, depth, rng_.uniform(0, 360),
              rng_.uniform(45, 65), false);
      }
      if (!last && level == p_.levels) twig(depth, rng_.uniform(0, 360), rng_.uniform(50, 75), 0.8);
    }
    // The crown of this branch: forks, or twigs at the last generation.
    if (level < p_.levels) {
      const int forks = level == 0 ? 4 : 3;
      const double phase = rng_.uniform(0, 360);
      std::vector<Fork> children;
      for (int k = 0; k < forks; ++k) {
        const bool leader = k == 0 && level > 0;
        const double azimuth = phase + 360.0 * k / forks + rng_.uniform(-20, 20);
        const double tilt = leader ? rng_.uniform(5, 15) : rng_.uniform(35, 55);
        const double childRadius = r * (leader ? 0.95 : 0.75);
        child(level + 1, len * p_.lengthRatio * rng_.uniform(0.85, 1.1), childRadius, orient, depth,
              azimuth, tilt, true);
        children.push_back({azimuth, tilt, childRadius});
      }
      if (solid()) forkBlob(depth, r, children);
    } else {
      if (solid()) {
        // The rounded tip the twigs grow from.
        std::fprintf(out_, "%s sphere 0 0 0 %.4g\n", pad.c_str(), 1.01 * r);
        ++joints_;
      }
      for (int k = 0; k < 3; ++k)
        twig(depth, 120.0 * k + rng_.uniform(0, 60), rng_.uniform(20, 55), 1.0);
    }
    std::fprintf(out_, "%spop\n", pad.c_str());
  }

  // Bark: the matte grey-brown of the current surface, dark in furrows that
  // run along +y (the marble's veins, the planes x = const, swirled), one
  // every `spacing` object units; with a comment if one is given.
  void barkTexture(double spacing, const char* comment) {
    std::fprintf(out_, "texture marble %.4g  0.08 0.06 0.04  0.9 0 0  1", spacing);
    if (comment != nullptr) std::fprintf(out_, "   # %s", comment);
    std::fputc('\n', out_);
  }

  // A sub-branch turned `azimuth` degrees about the parent's axis and tilted
  // `tilt` degrees away from it.
  void child(int level, double len, double radius, const Rot& orient, int depth, double azimuth,
             double tilt, bool forked) {
    std::string pad(static_cast<std::size_t>(depth + 1), ' ');
    std::fprintf(out_, "%spush rotate 0 1 0 %.4g rotate 0 0 1 %.4g\n", pad.c_str(), azimuth, tilt);
    Rot o = orient * Rot::axisAngle({0, 1, 0}, azimuth * kPi / 180) *
            Rot::axisAngle({0, 0, 1}, tilt * kPi / 180);
    branch(level, len, radius, o, depth + 1, forked);
    std::fprintf(out_, "%spop\n", pad.c_str());
  }

  void twig(int depth, double azimuth, double tilt, double size) {
    const double s = p_.twigLength * size * rng_.uniform(0.8, 1.15);
    const int variant = static_cast<int>(rng_.next() % 3);
    std::string pad(static_cast<std::size_t>(depth + 1), ' ');
    const double* green = kLeafGreens[variant];
    double rgb[3];
    for (int c = 0; c < 3; ++c)
      rgb[c] = tint_ == nullptr ? green[c] : 0.25 * green[c] + 0.75 * tint_->rgb[c];
    std::fprintf(out_,
                 "%spush rotate 0 1 0 %.4g rotate 0 0 1 %.4g scale %.4g %.4g %.4g "
                 "surface %.3g %.3g %.3g  0.9 0.08 0  12 1 include twig%d.sc pop\n",
                 pad.c_str(), azimuth, tilt, s, s, s, rgb[0], rgb[1], rgb[2], variant + 1);
    ++twigs_;
    turnedTwigs_ += tint_ != nullptr;
    twigPrims_ += kTwigPrims[variant];
  }

  // The tint of a last-generation branch's twigs, or null: still green.
  const Tint* drawTint() {
    double u = tintRng_.uniform();
    for (const Tint& t : kTints) {
      if (u < t.share) return &t;
      u -= t.share;
    }
    return nullptr;
  }

  // A child at a fork: its turn and tilt (as child() takes them) and radius.
  struct Fork {
    double azimuth, tilt, radius;
  };

  // The solid tree's fork, at the parent's end (the current frame's origin,
  // the parent along -y, radius r there): one blob of a component 0.6 r
  // inside the parent and two along each child's axis, at 0.5 and 1.2 of its
  // radius; each component's radius of influence is 1.7 times the radius of
  // its branch, strength 1, threshold 0.5. Alone such a component is the
  // ball of 1.7 sqrt(1 - sqrt(0.5)) = 0.92 times the branch's radius, so the
  // chain along a child stays near its capped cone while the components
  // near the fork fuse into a collar over every rim there.
  void forkBlob(int depth, double r, const std::vector<Fork>& children) {
    constexpr double kInfluence = 1.7;
    std::string pad(static_cast<std::size_t>(depth), ' ');
    const int count = 1 + 2 * static_cast<int>(children.size());
    std::fprintf(out_, "%s blob 0.5 %d  0 %.4g 0 %.4g 1\n", pad.c_str(), count, -0.6 * r,
                 kInfluence * r);
    for (const Fork& f : children) {
      // The child's axis: +y tilted about z, then turned about y.
      const double t = f.tilt * kPi / 180, a = f.azimuth * kPi / 180;
      const Vec axis{-std::sin(t) * std::cos(a), std::cos(t), std::sin(t) * std::sin(a)};
      for (const double along : {0.5, 1.2}) {
        const Vec c = (along * f.radius) * axis;
        std::fprintf(out_, "%s  %.4g %.4g %.4g %.4g 1\n", pad.c_str(), c.x, c.y, c.z,
                     kInfluence * f.radius);
      }
    }
    ++forks_;
    forkComponents_ += count;
  }

  bool solid() const { return style_ == Style::Solids; }

  static Vec unit(Vec v) {
    const double l = length(v);
    return l > 1e-12 ? (1.0 / l) * v : Vec{1, 0, 0};
  }

  std::FILE* out_;
  Params p_;
  Style style_;
  Rng rng_;
  Rng tintRng_;
  const Tint* tint_ = nullptr; // of the current last-generation branch
  long turnedTwigs_ = 0;
  long segments_ = 0, joints_ = 0, twigs_ = 0, twigPrims_ = 0, forks_ = 0, forkComponents_ = 0;
};

// Camera, lights and ground, shared by tree.sc and forest.sc.
void writeSetting(std::FILE* out, const char* eye, const char* lookat, const char* fov,
                  const char* fillLight) {
  std::fprintf(out,
               "resolution 512 512\n"
               "eye %s\n"
               "lookat %s\n"
               "up 0 1 0\n"
               "fov %s\n"
               "background 0.36 0.52 0.8   # sky\n"
               "ambient 0.3 0.3 0.33\n"
               "\n"
               "# A warm sun to the upper right and a weaker cool fill light near the camera.\n"
               "light 50 45 45  7500 7000 6000\n"
               "light %s\n"
               "\n"
               "# Ground: a large grassy square.\n"
               "push\n"
               "surface 0.35 0.45 0.18  0.9 0 0  1 1\n"
               "polygon 4  -200 0 200  200 0 200  200 0 -200  -200 0 -200\n"
               "pop\n\n",
               eye, lookat, fov, fillLight);
}

void writeTreeScene(std::FILE* out, long treePrims) {
  std::fprintf(out, "# tree.sc -- a tree of high complexity, for Prism (see docs/scenes.md).\n"
                    "# GENERATED by tools/tree_gen.cpp; do not edit by hand, change the\n"
                    "# generator and run:  build/tools/tree_gen scenes\n"
                    "#\n"
                    "# Tests: many thousands of primitives rendered fast thanks to the push/pop\n"
                    "# hierarchy (each branch is a group holding its sub-branches; each twig of\n"
                    "# leaves is a group), shadows of the leaves on the ground and on each other,\n"
                    "# includes with transforms (parts/tree_body.sc includes parts/branch.sc,\n"
                    "# parts/twig1-3.sc and parts/leaf.sc), and a texture in the object space of\n"
                    "# an included part: the bark's furrows follow each segment's scale.\n\n");
  writeSetting(out, "0 3.5 28", "0 6.6 0", "40", "-25 12 30  180 200 260");
  std::fprintf(out, "# The tree: %ld primitives.\ninclude parts/tree_body.sc\n", treePrims);
}

// tree.sc's camera, lights and ground around the solid tree.
void writeSolidTreeScene(std::FILE* out, long treePrims) {
  std::fprintf(out, "# tree-solid.sc -- the tree of tree.sc built from closed solids, for Prism\n"
                    "# (see docs/scenes.md).\n"
                    "# GENERATED by tools/tree_gen.cpp; do not edit by hand, change the\n"
                    "# generator and run:  build/tools/tree_gen scenes\n"
                    "#\n"
                    "# The same branches, bends, twigs and leaves as tree.sc, from the same\n"
                    "# seed, but each branch segment is one round capped cone instead of eight\n"
                    "# polygons, a sphere rounds each bend and each twig-bearing tip, and at\n"
                    "# every fork a blob (metaballs) merges the ends of the parent and its\n"
                    "# children into one smooth collar. Look at the trunk's fork and the big\n"
                    "# boughs: round silhouettes and smooth shading where tree.sc shows facets.\n"
                    "# Tests: thousands of blobs and capped cones among tens of thousands of\n"
                    "# polygons, in the same push/pop hierarchy (parts/tree_solid_body.sc\n"
                    "# includes parts/twig1-3.sc and parts/leaf.sc).\n\n");
  writeSetting(out, "0 3.5 28", "0 6.6 0", "40", "-25 12 30  180 200 260");
  std::fprintf(out, "# The tree: %ld primitives.\ninclude parts/tree_solid_body.sc\n", treePrims);
}

// Ten copies of the tree in two staggered rows, each turned, scaled and moved
// a little by our generator, seen from farther back.
void writeForestScene(std::FILE* out, long treePrims) {
  constexpr int kTrees = 10;
  std::fprintf(out, "# forest.sc -- ten trees of tree.sc: over a million primitives, to show the\n"
                    "# previewer on a large scene (see docs/performance.md).\n"
                    "# GENERATED by tools/tree_gen.cpp; do not edit by hand, change the\n"
                    "# generator and run:  build/tools/tree_gen scenes\n\n");
  writeSetting(out, "0 12 52", "0 4 -4", "45", "-40 40 90  1100 1200 1600");
  Rng rng(kSeed + 1);
  for (int k = 0; k < kTrees; ++k) {
    const bool front = k < 4;
    const double x = front ? -27.0 + 18.0 * k : -37.5 + 15.0 * (k - 4);
    const double z = front ? 6.0 : -12.0;
    const double s = rng.uniform(0.8, 1.15);
    std::fprintf(out,
                 "push translate %.4g 0 %.4g rotate 0 1 0 %.4g scale %.4g %.4g %.4g "
                 "include parts/tree_body.sc pop\n",
                 x + rng.uniform(-2.5, 2.5), z + rng.uniform(-2.5, 2.5), rng.uniform(0, 360), s, s,
                 s);
  }
  std::fprintf(out, "\n# %ld primitives: %d trees of %ld, 1 for the ground.\n",
               kTrees * treePrims + 1, kTrees, treePrims);
}

} // namespace

int main(int argc, char** argv) {
  if (argc > 2) {
    std::fprintf(stderr, "usage: tree_gen [SCENES_DIR]\n");
    return 2;
  }
  const std::string dir = argc == 2 ? argv[1] : ".";
  // Writes one file with `write`; false (after a message) if that fails.
  auto writeFile = [](const std::string& path, const auto& write) {
    std::FILE* f = std::fopen(path.c_str(), "w");
    if (!f) {
      std::perror(path.c_str());
      return false;
    }
    write(f);
    if (std::ferror(f) != 0 || std::fclose(f) != 0) {
      std::perror(path.c_str());
      return false;
    }
    return true;
  };
  long treePrims = 0, solidPrims = 0;
  const bool ok =
      writeFile(dir + "/parts/tree_body.sc",
                [&](std::FILE* f) { treePrims = TreeWriter(f, Params{}).write(); }) &&
      writeFile(dir + "/tree.sc", [&](std::FILE* f) { writeTreeScene(f, treePrims); }) &&
      writeFile(dir + "/forest.sc", [&](std::FILE* f) { writeForestScene(f, treePrims); }) &&
      writeFile(
          dir + "/parts/tree_solid_body.sc",
          [&](std::FILE* f) { solidPrims = TreeWriter(f, Params{}, Style::Solids).write(); }) &&
      writeFile(dir + "/tree-solid.sc", [&](std::FILE* f) { writeSolidTreeScene(f, solidPrims); });
  return ok ? 0 : 1;
}
