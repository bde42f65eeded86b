// Pictures: every stitch is drawn once, in its kind's colour, with a legend; coarse meshes show
// their face numbers; the CLI writes the file whole or not at all.
#include <gtest/gtest.h>

#include <sstream>

#include "labeling/shapes.hpp"
#include "labeling/stitch_generation.hpp"
#include "render/svg.hpp"

namespace skein {
namespace {

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(Render, StitchMeshDrawsEveryFaceInItsColour) {
  Shape s = make_shape("tube", {20, 0, 10}, "t");
  Project p = parse_project(s.project, "t.yaml");
  GeneratedStitchMesh g = generate_stitch_mesh(s.mesh, label_coarse_mesh(s.mesh, p), p);
  std::ostringstream out;
  render_stitch_mesh_svg(g.mesh, "tube", out);
  std::string svg = out.str();
  EXPECT_EQ(svg.rfind("<svg", 0), 0u);
  EXPECT_EQ(count(svg, "<polygon"), g.mesh.num_faces());
  EXPECT_GT(count(svg, R"(fill="#3cb44b")"), 1u);  // the shift-path's faces, green
  EXPECT_NE(svg.find("beside a shift-path"), std::string::npos);
  EXPECT_GT(count(svg, "<line"), g.mesh.num_faces() / 3);  // course arrows on the front
  EXPECT_NE(svg.find(">1</text>"), std::string::npos);     // row numbers
  EXPECT_NE(svg.find("</svg>"), std::string::npos);
}

TEST(Render, ShortRowFacesAreRed) {
  Project p =
      read_project(std::string(SKEIN_SOURCE_DIR) + "/samples/short-row-wedge/short-row-wedge.yaml");
  GeneratedStitchMesh g = build_project(p);
  std::ostringstream out;
  render_stitch_mesh_svg(g.mesh, "wedge", out);
  std::uint32_t turns = 0;
  for (Face f : g.mesh.faces()) turns += info(g.mesh.stitch[f]).wales_adjacent;
  EXPECT_EQ(count(out.str(), R"(fill="#e6194b")"), turns + 1);  // and the legend
}

TEST(Render, CoarseMeshShowsFaceNumbersAndLabels) {
  Shape s = make_shape("sheet", {0, 20, 20}, "s");
  Project p = parse_project(s.project, "s.yaml");
  std::ostringstream out;
  render_coarse_mesh_svg(s.mesh, label_coarse_mesh(s.mesh, p), "sheet", out);
  EXPECT_EQ(count(out.str(), "<polygon"), s.mesh.num_faces());
  EXPECT_NE(out.str().find(">4</text>"), std::string::npos);
  EXPECT_EQ(count(out.str(), "<line"), 2 * s.mesh.num_faces());  // wale and course arrows
}

}  // namespace
}  // namespace skein
