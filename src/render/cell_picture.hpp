// A model drawn as a small grid of cells, for schematics (the hand pattern's page): each cell
// holds the label of the front-most face seen through it (which yarn piece knits it) and how
// squarely that face looks at the viewer. The view is the one every picture uses (view.hpp).
// Linear in the faces: a face smaller than a cell marks only the cell under its centre.
#pragma once

#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "mesh/stitch_mesh.hpp"

namespace skein {

struct CellPicture {
  static constexpr std::uint32_t kEmpty = std::numeric_limits<std::uint32_t>::max();
  std::uint32_t columns = 0, rows = 0;
  std::vector<std::uint32_t> label;  // per cell, row by row from the top; kEmpty: nothing seen
  std::vector<std::uint8_t> shade;   // 0: faces the viewer, 1: at a slant, 2: edge-on or inside
  std::uint32_t at(std::uint32_t column, std::uint32_t row) const {
    return label[row * columns + column];
  }
};

// A labelled point drawn over the face it lies on: a stitch with no face of its own (one the
// transforms added along a mismatched edge).
struct LabelledPoint {
  Vec3 at;
  std::uint32_t label;
};

// `face_label[f]` labels face f (kEmpty: not drawn); the longer side of the picture has
// `longest_side` cells.
CellPicture picture_cells(const StitchMesh& mesh, std::span<const std::uint32_t> face_label,
                          std::span<const LabelledPoint> points, std::uint32_t longest_side);

}  // namespace skein
