#include "core/scene/scene.h"

#include <filesystem>
#include <sstream>
#include <string_view>

namespace prism {

Aabb Scene::bounds(PrimitiveRef ref) const {
  return visit(ref, [&](const auto& shape) { return boundsOf(shape, arrays()); });
}

std::uint32_t Scene::materialIndex(PrimitiveRef ref) const {
  return visit(ref, [](const auto& shape) { return shape.material; });
}

Origin Scene::origin(PrimitiveRef ref) const {
  return visit(ref, [](const auto& shape) { return shape.origin; });
}

namespace {

// "2 spheres", "1 box", "3 boxes".
std::string counted(std::size_t count, std::string_view name) {
  std::string text = std::to_string(count) + " " + std::string(name);
  if (count != 1) text += name.ends_with('x') ? "es" : "s";
  return text;
}

} // namespace

std::string Scene::kindCounts() const {
  std::string kinds;
  std::apply(
      [&]<class... Kinds>(const std::vector<Kinds>&... all) {
        ((kinds +=
          all.empty() ? "" : (kinds.empty() ? "" : ", ") + counted(all.size(), Kinds::kName)),
         ...);
      },
      storage.vectors);
  return kinds;
}

std::string Scene::describe(PrimitiveRef ref) const {
  std::ostringstream text;
  text << kindName(ref.kind) << " #" << ref.index;
  const Origin o = origin(ref);
  if (o.file < files.size())
    text << " (" << std::filesystem::path(files[o.file]).filename().string() << ":" << o.line
         << ")";
  return text.str();
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
