// Prism's curved primitives inside Embree: user geometry whose callbacks call
// Prism's own test (intersectPrimitive), so that Embree and Prism run the same
// arithmetic per primitive and the comparison measures the hierarchies.
#pragma once

#include "core/scene/scene.h"

#include <embree3/rtcore.h>

namespace prism::bench {

// What the callbacks of one user geometry need: every primitive of one kind.
// Must outlive the Embree scene.
struct UserPrimitives {
  const Scene* scene = nullptr;
  PrimitiveKind kind{};
};

// A committed user geometry of `count` primitives of `primitives.kind`.
RTCGeometry makeUserGeometry(RTCDevice device, const UserPrimitives& primitives,
                             unsigned int count);

} // namespace prism::bench
