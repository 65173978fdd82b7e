#include "core/scene/scene.h"

#include <filesystem>
#include <sstream>
#include <string>

namespace prism {

Aabb Scene::bounds(PrimitiveRef ref) const {
  return visit(ref, [&](const auto& shape) { return boundsOf(shape, arrays()); });
}

std::uint32_t Scene::materialIndex(PrimitiveRef ref) const {
  return visit(ref, [](const auto& shape) { return shape.material; });
}

Vec2 Scene::imageCoordinates(PrimitiveRef ref, const Vec3& point) const {
  const Vec2 uv = visit(ref, [&](const auto& shape) { return uvAt(shape, arrays(), point); });
  if (ref.kind != kindOf<Triangle> || ref.index >= triangleUvs.size()) return uv;
  // A triangle's uvAt is the point's barycentric weights of vertices 1 and 2.
  const std::array<Vec2, 3>& at = triangleUvs[ref.index];
  return (1.0 - uv.x - uv.y) * at[0] + uv.x * at[1] + uv.y * at[2];
}

Origin Scene::origin(PrimitiveRef ref) const {
  return visit(ref, [](const auto& shape) { return shape.origin; });
}

namespace {

// A kind's name in the plural: its kPlural where it has one (tori), else its
// name and "s".
template <class Kind> std::string plural() {
  if constexpr (requires { Kind::kPlural; })
    return Kind::kPlural;
  else
    return std::string(Kind::kName) + "s";
}

} // namespace

std::string Scene::kindCounts() const {
  std::string kinds;
  std::apply(
      [&]<class... Kinds>(const std::vector<Kinds>&... all) {
        ((kinds += all.empty() ? ""
                               : (kinds.empty() ? "" : ", ") + std::to_string(all.size()) + " " +
                                     (all.size() == 1 ? Kinds::kName : plural<Kinds>())),
         ...);
      },
      storage.vectors);
  return kinds;
}

std::string Scene::describe(PrimitiveRef ref) const {
  std::ostringstream text;
  text << kindName(ref.kind) << " #" << ref.index << placeOf(origin(ref));
  return text.str();
}

std::string Scene::placeOf(Origin o) const {
  if (o.file >= files.size()) return "";
  return " (" + std::filesystem::path(files[o.file]).filename().string() + ":" +
         std::to_string(o.line) + ")";
}

std::vector<PrimitiveRef> Scene::allPrimitives() const {
  std::vector<PrimitiveRef> refs;
  refs.reserve(primitiveCount());
  const auto addAll = [&]<class Kind>(const std::vector<Kind>& shapesOfKind) {
    for (std::uint32_t i = 0; i < shapesOfKind.size(); ++i)
      refs.push_back({kindOf<Kind>, i});
  };
  std::apply([&](const auto&... v) { (addAll(v), ...); }, storage.vectors);
  return refs;
}

} // namespace prism
