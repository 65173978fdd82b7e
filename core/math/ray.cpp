#include "core/math/ray.h"

namespace prism {

const char* rayKindName(RayKind kind) {
  switch (kind) {
  case RayKind::Eye: return "eye";
  case RayKind::Shadow: return "shadow";
  case RayKind::Reflected: return "reflected";
  case RayKind::Transmitted: return "transmitted";
  }
  return "?";
}

} // namespace prism
