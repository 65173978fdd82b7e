// tree: a binary tree of cones with a sphere at every joint, and leaves, on a
// ground square. The trunk (level 0) forks into two branches, each of those
// into two, down to level L: 2^(L+1) - 1 branches, each an open cone and the
// sphere at its tip (a green leaf at the last level), so 2^(L+2) - 1
// primitives with the ground. Branches shrink by a fixed ratio, so the tree
// keeps its size and only fills in as the level grows.
#include "core/math/hash.h"

#include "scene_parts.h"
#include "spd_kinds.h"

namespace prism::spd {
namespace {

constexpr double kLength = 2.0, kRadius = 0.16;
constexpr double kLengthRatio = 0.78, kRadiusRatio = 0.68;
constexpr double kGolden = 137.50776405; // degrees: consecutive forks turn by it

long primitives(int level) { return (4L << level) - 1; }

class Tree {
public:
  Tree(ScWriter& out, int levels) : out_(out), levels_(levels), rng_(0x74726565) {}

  void branch(V3 base, V3 dir, double len, double radius, double turn, int level) {
    const V3 tip = base + len * dir;
    const double tipRadius = radius * kRadiusRatio;
    const bool leaf = level == levels_;
    out_.push(); // the branch and all that grows from it; pop restores the bark
    out_.cone(base, radius, tip, tipRadius);
    if (leaf) {
      // A leaf is much larger than the twig's tip, so the crown fills; its
      // size follows the last branch length so it shrinks as levels are added.
      out_.surface(plastic(0.25, 0.6, 0.2, 0.25, 30));
      out_.sphere(tip, 0.45 * len + tipRadius);
    } else {
      out_.sphere(tip, tipRadius);
      // Two children in a plane turned from the parent's fork by the golden
      // angle, spread 32 to 50 degrees from the parent and bent upwards a little.
      const Frame f = frameAround(dir);
      for (int k = 0; k < 2; ++k) {
        const double spread = rng_.uniform(32, 50);
        V3 d = direction(f, radians(spread), radians(turn + 180.0 * k));
        d = normalize(d + V3{0, 0.12, 0});
        branch(tip, d, len * kLengthRatio * rng_.uniform(0.9, 1.05), tipRadius, turn + kGolden,
               level + 1);
      }
    }
    out_.pop();
  }

private:
  ScWriter& out_;
  int levels_;
  SplitMix64 rng_;
};

void write(ScWriter& out, int level) {
  out.stage({.eye = {2, 3.8, 14},
             .lookat = {0, 3.6, 0},
             .fov = 45,
             .lights = {{{10, 16, 10}, 600}, {{-12, 6, 8}, 160}},
             .background = {0.45, 0.6, 0.85},
             .ambient = 0.12});
  out.surface(metal(0.45, 0.5, 0.4, 0.3));
  groundSquare(out, 20);
  out.surface(plastic(0.45, 0.32, 0.2, 0.05, 8)); // bark
  Tree(out, level).branch({0, 0, 0}, {0, 1, 0}, kLength, kRadius, 0, 0);
}

} // namespace

SpdKind treeKind() {
  return {"tree",
          "a binary tree of cones and spheres with leaves, on a ground square",
          "forks from trunk to leaves (2^(L+2) - 1 primitives)",
          0,
          18,
          primitives,
          write};
}

} // namespace prism::spd
