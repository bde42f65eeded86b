// The one view every picture of a model uses: an orthographic camera from the front (+z), a
// little to the right and above, so a tube shows its front and its top.
#pragma once

#include <cmath>

#include "mesh/stitch_mesh.hpp"

namespace skein {

struct ViewPoint {
  double x, y;   // on the picture, y down
  double depth;  // larger is nearer the viewer
};

inline ViewPoint project(Vec3 p) {
  constexpr double yaw = 0.35, pitch = 0.3;
  double x = p.x * std::cos(yaw) - p.z * std::sin(yaw);
  double z = p.x * std::sin(yaw) + p.z * std::cos(yaw);
  double y = p.y * std::cos(pitch) - z * std::sin(pitch);
  double depth = p.y * std::sin(pitch) + z * std::cos(pitch);
  return {x, -y, depth};
}

}  // namespace skein
