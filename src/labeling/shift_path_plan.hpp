// Where each ring of coarse faces (a closed coarse row) starts its rounds: the coarse side edge
// its shift-path runs up (paper §3.1). Every separate path is a yarn piece (§4.2), so a path
// arriving at the top of a tube goes on into one ring above it, and each path goes on into a
// different ring: where tubes meet (a junction of several tubes knit towards it and several
// knit away), each incoming tube's path is placed so that it reaches a distinct outgoing tube.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "labeling/coarse_mesh.hpp"
#include "labeling/labeling.hpp"

namespace skein {

struct Ring {
  std::vector<CoarseFace> faces;        // left to right
  std::vector<std::uint8_t> can_start;  // per face: no short rows turn at its left side
  std::optional<std::pair<std::size_t, std::uint8_t>> mark;  // a project's face and option
};

struct RingPath {
  std::size_t face = 0;     // the path runs up this face's left side
  std::uint8_t option = 1;  // the stitch mesh's ShiftOption
  bool continued = false;   // the path of a ring below goes on here
};

// `rings` in labelling order (rings below before the rings above them); every ring has a face
// that can start. Paths without a mark take `option`. Linear in the faces of the rings.
std::vector<RingPath> plan_shift_paths(const CoarseMesh& mesh, const Labeling& labeling,
                                       const std::vector<Ring>& rings, std::uint8_t option);

}  // namespace skein
