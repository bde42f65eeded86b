#include "fixtures.hpp"

#include "common/error.hpp"

namespace skein::testing {
namespace {

EdgeRole role_of(char c) {
  switch (c) {
    case 'b': return EdgeRole::bottom;
    case 't': return EdgeRole::top;
    case 'i': return EdgeRole::wale_in;
    case 'o': return EdgeRole::wale_out;
  }
  throw InternalError(std::string("bad role letter ") + c);
}

}  // namespace

StitchMesh grid_mesh(int width, int height, const std::vector<Square>& squares,
                     const std::vector<YarnMark>& yarn) {
  StitchMeshBuilder builder("<grid>");
  auto at = [&](int x, int y) { return Vertex(static_cast<std::uint32_t>(y * (width + 1) + x)); };
  for (int y = 0; y <= height; ++y)
    for (int x = 0; x <= width; ++x)
      builder.add_vertex({static_cast<float>(x), static_cast<float>(y), 0});
  for (const Square& s : squares) {
    Vertex corners[] = {at(s.x, s.y), at(s.x + 1, s.y), at(s.x + 1, s.y + 1), at(s.x, s.y + 1)};
    EdgeRole roles[4];
    for (int i = 0; i < 4; ++i) roles[i] = role_of(s.roles.at(i));
    builder.add_face(corners, roles, s.type);
  }
  StitchMesh mesh = std::move(builder).build();
  for (const YarnMark& m : yarn) {
    Edge e = mesh.find_edge(at(m.x0, m.y0), at(m.x1, m.y1));
    mesh.mismatch_yarn[e] = {m.kind, m.own_square >= 0 ? Face(static_cast<std::uint32_t>(m.own_square)) : Face()};
  }
  return mesh;
}

StitchMesh fig13_deadlock_mesh() {
  using T = StitchType;
  // Lower piece: cast-on row (y0) left to right, then row A (y1) right to left. Upper piece:
  // two single cast-on stitches (y3, wales pointing down) and row B (y2), whose outer stitches
  // point down and meet row A on joining edges; its middle two bind off row A's loops.
  std::vector<Square> squares = {
      {0, 0, T::co, "boti"}, {1, 0, T::co, "boti"}, {2, 0, T::co, "boti"}, {3, 0, T::co, "boti"},
      {0, 1, T::k, "bito"},  {1, 1, T::k, "bito"},  {2, 1, T::k, "bito"},  {3, 1, T::k, "bito"},
      {0, 2, T::k, "tobi"},  {1, 2, T::bo, "boti"}, {2, 2, T::bo, "boti"}, {3, 2, T::k, "tobi"},
      {0, 3, T::co, "tobi"}, {3, 3, T::co, "tobi"},
  };
  constexpr int kA3 = 7, kB0 = 8;
  return grid_mesh(4, 4, squares,
                   {{0, 2, 1, 2, MismatchYarn::Kind::own, kB0},
                    {3, 2, 4, 2, MismatchYarn::Kind::own, kA3}});
}

}  // namespace skein::testing
