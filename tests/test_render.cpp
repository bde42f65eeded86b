// Pictures: every stitch is drawn once, in its kind's colour, with a legend; coarse meshes show
// their face numbers; the CLI writes the file whole or not at all.
#include <gtest/gtest.h>

#include <set>
#include <sstream>

#include "fixtures.hpp"
#include "labeling/shapes.hpp"
#include "labeling/stitch_generation.hpp"
#include "render/cell_picture.hpp"
#include "render/svg.hpp"

namespace skein {
namespace {

using testing::occurrences;

TEST(Render, StitchMeshDrawsEveryFaceInItsColour) {
  Shape s = make_shape("tube", {20, 0, 10}, "t");
  Project p = parse_project(s.project, "t.yaml");
  GeneratedStitchMesh g = generate_stitch_mesh(s.mesh, label_coarse_mesh(s.mesh, p), p);
  std::ostringstream out;
  render_stitch_mesh_svg(g.mesh, "tube", out);
  std::string svg = out.str();
  EXPECT_EQ(svg.rfind("<svg", 0), 0u);
  EXPECT_EQ(occurrences(svg, "<polygon"), g.mesh.num_faces());
  EXPECT_GT(occurrences(svg, R"(fill="#3cb44b")"), 1u);  // the shift-path's faces, green
  EXPECT_NE(svg.find("beside a shift-path"), std::string::npos);
  EXPECT_GT(occurrences(svg, "<line"), g.mesh.num_faces() / 3);  // course arrows on the front
  EXPECT_NE(svg.find(">1</text>"), std::string::npos);           // row numbers
  EXPECT_NE(svg.find("</svg>"), std::string::npos);
}

// The schematic's picture: each label where its faces are (the upper rows of a tube above its
// lower rows), every cell of the outline seen, a point drawn over the face it lies on.
TEST(Render, CellPictureShowsEachLabelWhereItsFacesAre) {
  Shape s = make_shape("tube", {20, 0, 30}, "t");
  Project p = parse_project(s.project, "t.yaml");
  StitchMesh m = generate_stitch_mesh(s.mesh, label_coarse_mesh(s.mesh, p), p).mesh;
  std::uint32_t rows = 0;
  for (Face f : m.faces()) rows = std::max(rows, m.row[f] + 1);
  std::vector<std::uint32_t> label(m.num_faces());
  for (Face f : m.faces()) label[f.index()] = m.row[f] < rows / 2 ? 0 : 1;
  Vec3 top = m.position[m.tail(*m.halfedges(*m.faces().begin()).begin())];
  LabelledPoint mark{top, 7};
  CellPicture pic = picture_cells(m, label, {&mark, 1}, 60);
  EXPECT_EQ(std::max(pic.columns, pic.rows), 60u);
  double mean_row[2] = {0, 0};
  std::uint32_t count[3] = {0, 0, 0};
  for (std::uint32_t r = 0; r < pic.rows; ++r)
    for (std::uint32_t c = 0; c < pic.columns; ++c) {
      std::uint32_t l = pic.at(c, r);
      if (l == CellPicture::kEmpty) continue;
      ASSERT_TRUE(l < 2 || l == 7) << l;
      ++count[l == 7 ? 2 : l];
      if (l < 2) mean_row[l] += r;
    }
  ASSERT_GT(count[0], 100u);
  ASSERT_GT(count[1], 100u);
  EXPECT_LT(mean_row[1] / count[1], mean_row[0] / count[0]) << "upper rows drawn higher";
  EXPECT_EQ(count[2], 1u);
  EXPECT_GT(count[0] + count[1], pic.columns * pic.rows / 5) << "the tube fills its outline";
  std::set<std::uint8_t> shades(pic.shade.begin(), pic.shade.end());
  EXPECT_GE(shades.size(), 2u) << "the sides of the tube are shaded apart";
}

TEST(Render, ShortRowFacesAreRed) {
  Project p =
      read_project(std::string(SKEIN_SOURCE_DIR) + "/samples/short-row-wedge/short-row-wedge.yaml");
  GeneratedStitchMesh g = build_project(p);
  std::ostringstream out;
  render_stitch_mesh_svg(g.mesh, "wedge", out);
  std::uint32_t turns = 0;
  for (Face f : g.mesh.faces()) turns += info(g.mesh.stitch[f]).wales_adjacent;
  EXPECT_EQ(occurrences(out.str(), R"(fill="#e6194b")"), turns + 1);  // and the legend
}

TEST(Render, CoarseMeshShowsFaceNumbersAndLabels) {
  Shape s = make_shape("sheet", {0, 20, 20}, "s");
  Project p = parse_project(s.project, "s.yaml");
  std::ostringstream out;
  render_coarse_mesh_svg(s.mesh, label_coarse_mesh(s.mesh, p), "sheet", out);
  EXPECT_EQ(occurrences(out.str(), "<polygon"), s.mesh.num_faces());
  EXPECT_NE(out.str().find(">4</text>"), std::string::npos);
  EXPECT_EQ(occurrences(out.str(), "<line"), 2 * s.mesh.num_faces());  // wale and course arrows
}

}  // namespace
}  // namespace skein
