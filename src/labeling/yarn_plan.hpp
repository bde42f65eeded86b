// Where the yarn enters each coarse row (paper §3.1 and §4.2). A ring (a closed coarse row)
// starts its rounds at a coarse side edge, its shift-path; an open row starts at its left or
// right end. Every separate chain of rows is a yarn piece, so the yarn that stops at the top of
// a row goes on into one row that starts there, and where tubes meet (several knit towards a
// junction, several away from it, with open rows between them), each incoming yarn is led to
// an outgoing row of its own.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "labeling/coarse_mesh.hpp"
#include "labeling/labeling.hpp"

namespace skein {

struct PlannedRow {
  std::vector<CoarseFace> faces;  // left to right
  bool closed = false;
  // Rings: per face, no short rows turn at its left side; the project's face and option.
  std::vector<std::uint8_t> can_start;
  std::optional<std::pair<std::size_t, std::uint8_t>> mark;
  // Open rows: the corner where the yarn enters at the left [0] or right [1] end (invalid
  // where it cannot), where it then stops (invalid if nowhere), and the end it enters at when
  // no yarn arrives.
  std::array<CoarseVertex, 2> enter, stop;
  bool default_left = true;
};

struct RowEntry {
  std::size_t face = 0;     // rings: the path runs up this face's left side
  std::uint8_t option = 1;  // rings: the stitch mesh's ShiftOption
  bool continued = false;   // rings: the path of a ring below goes on here
  bool from_left = true;    // open rows: the yarn enters at the left end
};

// `rows` in labelling order; every ring has a face that can start, every open row an end.
// Paths without a mark take `option`.
std::vector<RowEntry> plan_row_entries(const CoarseMesh& mesh, const Labeling& labeling,
                                       const std::vector<PlannedRow>& rows, std::uint8_t option);

}  // namespace skein
