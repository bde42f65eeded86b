#include "fixtures.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <tuple>

#include "common/error.hpp"
#include "mesh/generate.hpp"

namespace skein::testing {
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
    for (int i = 0; i < 4; ++i) roles[i] = role_from_letter(s.roles.at(i)).value();
    builder.add_face(corners, roles, s.type);
  }
  StitchMesh mesh = std::move(builder).build();
  for (const YarnMark& m : yarn) {
    Edge e = mesh.find_edge(at(m.x0, m.y0), at(m.x1, m.y1));
    mesh.mismatch_yarn[e] = {
        m.kind, m.own_square >= 0 ? Face(static_cast<std::uint32_t>(m.own_square)) : Face()};
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
  return grid_mesh(
      4, 4, squares,
      {{0, 2, 1, 2, MismatchYarn::Kind::own, kB0}, {3, 2, 4, 2, MismatchYarn::Kind::own, kA3}});
}

namespace {

// Marks every joining or splitting edge between rows y and y+1... by the grid row `line`.
std::vector<YarnMark> marks_along(int line, int width, MismatchYarn::Kind yarn, int own_first,
                                  int own_stride) {
  std::vector<YarnMark> marks;
  if (yarn == MismatchYarn::Kind::by_default) return marks;
  for (int x = 0; x < width; ++x)
    marks.push_back({x, line, x + 1, line, yarn,
                     yarn == MismatchYarn::Kind::own ? own_first + x * own_stride : -1});
  return marks;
}

}  // namespace

// Lower piece: cast on (y0) and a row right to left (y1). Upper piece, wales pointing down:
// cast on at the top (y3) and a row right to left (y2). The two meet top to top on y = 2.
StitchMesh join_mesh(MismatchYarn::Kind yarn, bool own_upper) {
  using T = StitchType;
  std::vector<Square> squares;
  for (int x = 0; x < 3; ++x) squares.push_back({x, 0, T::co, "boti"});
  for (int x = 0; x < 3; ++x) squares.push_back({x, 1, T::k, "bito"});
  for (int x = 0; x < 3; ++x) squares.push_back({x, 2, T::k, "tibo"});
  for (int x = 0; x < 3; ++x) squares.push_back({x, 3, T::co, "tobi"});
  return grid_mesh(3, 4, squares, marks_along(2, 3, yarn, own_upper ? 6 : 3, 1));
}

// Lower piece, wales pointing down from y = 2: a row (y1) and a bind-off (y0). Upper piece,
// wales up from y = 2: a row (y2) and a bind-off (y3). They grow apart from y = 2.
StitchMesh split_mesh(MismatchYarn::Kind yarn, bool own_upper) {
  using T = StitchType;
  std::vector<Square> squares;
  for (int x = 0; x < 3; ++x) squares.push_back({x, 0, T::bo, "tibo"});
  for (int x = 0; x < 3; ++x) squares.push_back({x, 1, T::k, "tobi"});
  for (int x = 0; x < 3; ++x) squares.push_back({x, 2, T::k, "boti"});
  for (int x = 0; x < 3; ++x) squares.push_back({x, 3, T::bo, "bito"});
  return grid_mesh(3, 4, squares, marks_along(2, 3, yarn, own_upper ? 6 : 3, 1));
}

StitchMesh mid_row_split_mesh(bool rs_row) {
  using T = StitchType;
  CornerBuilder b("<mid-row split>");
  const float y = rs_row ? 1 : 0;  // with a plain row first, the cast-on comes in a RS row
  auto roles = [](float row) { return static_cast<int>(row) % 2 ? "bito" : "boti"; };
  for (float x = 0; x < 5; ++x) b.square(x, 0, "boti", T::co);
  if (rs_row)
    for (float x = 4; x >= 0; --x) b.square(x, 1, "bito", T::k);
  // The bound-off sts' tops sag below the split line, so that they share no edge with the
  // cast-on above them.
  b.square(0, y + 1, roles(y + 1), T::k);
  b.face({{1, y + 1}, {2, y + 1}, {2, y + 1.8f}, {1, y + 2}}, roles(y + 1), T::bo);
  b.face({{2, y + 1}, {3, y + 1}, {3, y + 1.8f}, {2, y + 1.8f}}, roles(y + 1), T::bo);
  b.face({{3, y + 1}, {4, y + 1}, {4, y + 2}, {3, y + 1.8f}}, roles(y + 1), T::bo);
  b.square(4, y + 1, roles(y + 1), T::k);
  const std::uint32_t split_row = rs_row ? 15 : 10;  // its first face
  for (float x = 0; x < 5; ++x) b.square(x, y + 2, roles(y + 2), T::k);
  for (float x = 0; x < 5; ++x) b.square(x, y + 3, roles(y + 3), T::bo);
  // The second piece, wales down from the split line, inside the gap.
  for (float x = 1; x < 4; ++x)
    b.face({{x, y + 1.5f}, {x + 1, y + 1.5f}, {x + 1, y + 2}, {x, y + 2}}, "tibo", T::k);
  for (float x = 1; x < 4; ++x)
    b.face({{x, y + 1.2f}, {x + 1, y + 1.2f}, {x + 1, y + 1.5f}, {x, y + 1.5f}}, "tobi", T::bo);
  StitchMesh mesh = std::move(b).build();
  for (Edge e : mesh.edges()) {
    Vec3 a = mesh.position[mesh.tail(mesh.halfedge(e))];
    Vec3 c = mesh.position[mesh.head(mesh.halfedge(e))];
    if (a.y != y + 2 || c.y != y + 2 || std::min(a.x, c.x) < 1 || std::max(a.x, c.x) > 4) continue;
    auto above = static_cast<std::uint32_t>(split_row + std::min(a.x, c.x));
    mesh.mismatch_yarn[e] = {MismatchYarn::Kind::own, Face(above)};
  }
  return mesh;
}

StitchMesh mid_round_split_mesh() {
  using T = StitchType;
  CornerBuilder b("<mid-round split>");
  auto around = [&](float x, float y, float width, T type) {  // x = width is x = 0 again
    auto at = [&](float u) { return u >= width ? u - width : u; };
    b.face({{at(x), y}, {at(x + 1), y}, {at(x + 1), y + 1}, {at(x), y + 1}}, "boti", type);
  };
  for (float x = 0; x < 6; ++x) around(x, 0, 6, T::co);
  around(0, 1, 6, T::k);
  b.face({{1, 1}, {2, 1}, {2, 1.8f}, {1, 2}}, "boti", T::bo);
  b.face({{2, 1}, {3, 1}, {3, 1.8f}, {2, 1.8f}}, "boti", T::bo);
  b.face({{3, 1}, {4, 1}, {4, 2}, {3, 1.8f}}, "boti", T::bo);
  for (float x = 4; x < 6; ++x) around(x, 1, 6, T::k);
  for (float x = 0; x < 6; ++x) around(x, 2, 6, T::k);  // faces 12-17
  for (float x = 0; x < 4; ++x) around(x, 3, 6, T::k);
  b.face({{4, 3}, {5, 3}, {0, 3}, {0, 4}, {4, 4}}, "bboti", T::k2tog);
  for (float x = 0; x < 5; ++x) around(x, 4, 5, T::bo);
  for (float x = 1; x < 4; ++x)
    b.face({{x, 1.5f}, {x + 1, 1.5f}, {x + 1, 2}, {x, 2}}, "tibo", T::k);
  for (float x = 1; x < 4; ++x)
    b.face({{x, 1.2f}, {x + 1, 1.2f}, {x + 1, 1.5f}, {x, 1.5f}}, "tobi", T::bo);
  StitchMesh mesh = std::move(b).build();
  for (Edge e : mesh.edges()) {
    Vec3 a = mesh.position[mesh.tail(mesh.halfedge(e))];
    Vec3 c = mesh.position[mesh.head(mesh.halfedge(e))];
    if (a.x == 0 && c.x == 0 && std::abs(a.y - c.y) == 1) mesh.shift_path[e] = 1;  // the seam
    if (a.y != 2 || c.y != 2 || std::min(a.x, c.x) < 1 || std::max(a.x, c.x) > 4) continue;
    auto above = static_cast<std::uint32_t>(12 + std::min(a.x, c.x));
    mesh.mismatch_yarn[e] = {MismatchYarn::Kind::own, Face(above)};
  }
  return mesh;
}

StitchMesh mid_row_join_mesh() {
  using T = StitchType;
  CornerBuilder b("<mid-row join>");
  for (float x = 0; x < 5; ++x) b.square(x, 0, "boti", T::co);
  for (float x = 0; x < 5; ++x) b.square(x, 1, "bito", T::k);  // faces 5-9
  for (float x = 0; x < 2; ++x) b.square(x, 2, "boti", T::k);
  for (float x = 0; x < 2; ++x) b.square(x, 3, "bito", T::bo);
  // The second piece, wales down to the join line; its side beside the first piece's last
  // rows is moved off x = 2, so that they share no edge.
  auto side = [](float x) { return x == 2 ? 2.1f : x; };
  for (float x = 2; x < 5; ++x)
    b.face({{x, 2}, {x + 1, 2}, {x + 1, 3}, {side(x), 3}}, "tibo", T::k);
  for (float x = 2; x < 5; ++x)
    b.face({{side(x), 3}, {x + 1, 3}, {x + 1, 4}, {side(x), 4}}, "tobi", T::co);
  StitchMesh mesh = std::move(b).build();
  for (Edge e : mesh.edges()) {
    Vec3 a = mesh.position[mesh.tail(mesh.halfedge(e))];
    Vec3 c = mesh.position[mesh.head(mesh.halfedge(e))];
    if (a.y != 2 || c.y != 2 || std::min(a.x, c.x) < 2) continue;
    mesh.mismatch_yarn[e] = {MismatchYarn::Kind::own,
                             Face(static_cast<std::uint32_t>(5 + std::min(a.x, c.x)))};
  }
  return mesh;
}

// A column knit upwards (x0), and beside it two cast-on stitches whose wales point left, at
// the column: their loops are consumed through the column's wale edges.
StitchMesh contracting_mesh() {
  using T = StitchType;
  return grid_mesh(2, 4,
                   {{0, 0, T::co, "boti"},
                    {0, 1, T::k, "bito"},
                    {0, 2, T::k, "boti"},
                    {0, 3, T::bo, "bito"},
                    {1, 1, T::co, "ibot"},
                    {1, 2, T::co, "ibot"}});
}

// A column knit upwards (x0), and beside it three bind-off stitches whose wales point right,
// away from the column: each is picked up through the column's edge.
StitchMesh expanding_mesh() {
  using T = StitchType;
  return grid_mesh(2, 3,
                   {{0, 0, T::co, "boti"},
                    {0, 1, T::k, "bito"},
                    {0, 2, T::bo, "boti"},
                    {1, 0, T::bo, "itob"},
                    {1, 1, T::bo, "itob"},
                    {1, 2, T::bo, "itob"}});
}

StitchMesh short_row_mesh(StitchType turn) {
  using T = StitchType;
  CornerBuilder b("<short rows>");
  for (float x = 0; x < 4; ++x) b.square(x, 0, "boti", T::co);
  for (float x = 2; x < 4; ++x) b.square(x, 1, "bito", T::k);
  // The turn's top run: one edge (sr4), two (sr5) or three (srn, Fig. 10c) up the diagonal.
  constexpr float third = 1.0f / 3;
  if (turn == T::sr4)
    b.face({{1, 1}, {2, 1}, {2, 2}, {2, 3}}, "biot", T::sr4);
  else if (turn == T::sr5)
    b.face({{1, 1}, {2, 1}, {2, 2}, {2, 3}, {1.5f, 2}}, "biott", turn);
  else
    b.face({{1, 1},
            {2, 1},
            {2, 2},
            {2, 3},
            {1 + 2 * third, 1 + 4 * third},
            {1 + third, 1 + 2 * third}},
           "biottt", turn);
  for (float x = 2; x < 4; ++x) b.square(x, 2, "boti", T::k);
  b.face({{0, 1}, {1, 1}, {1, 4}, {0, 4}}, "bito", T::k);
  if (turn == T::sr4)
    b.face({{1, 1}, {2, 3}, {2, 4}, {1, 4}}, "bito", T::k);
  else if (turn == T::sr5)
    b.face({{1, 1}, {1.5f, 2}, {2, 3}, {2, 4}, {1, 4}}, "bbito", T::k2tog);
  else
    b.face({{1, 1},
            {1 + third, 1 + 2 * third},
            {1 + 2 * third, 1 + 4 * third},
            {2, 3},
            {2, 4},
            {1, 4}},
           "bbbito", T::s2kp);
  for (float x = 2; x < 4; ++x) b.square(x, 3, "bito", T::k);
  for (float x = 0; x < 4; ++x) b.square(x, 4, "boti", T::bo);
  return std::move(b).build();
}

Compilation sample_variant(const std::string& sample, const std::string& tag,
                           const std::function<void(std::string&)>& edit) {
  std::string dir = std::string(SKEIN_SOURCE_DIR) + "/samples/" + sample + "/";
  std::ifstream in(dir + sample + ".yaml");
  std::string project((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::string mesh = "mesh: " + sample + ".obj";
  project.replace(project.find(mesh), mesh.size(), "mesh: " + dir + sample + ".obj");
  edit(project);
  // One file per process: ctest runs tests side by side.
  auto path = std::filesystem::temp_directory_path() /
              fmt::format("{}-{}-{}.yaml", sample, tag, static_cast<long>(::getpid()));
  std::ofstream(path) << project;
  return compile_model(path.string());
}

Compilation sample_at_gauge(const std::string& sample, int stitches, int rows) {
  return sample_variant(
      sample, fmt::format("gauge-{}-{}", stitches, rows), [&](std::string& project) {
        std::string gauge = fmt::format("gauge: {{stitches: {}, rows: {}}}", stitches, rows);
        std::size_t at = project.find("\ngauge:");
        if (at == std::string::npos) {
          project += "\n" + gauge + "\n";
          return;
        }
        std::size_t end = project.find('\n', at + 1);
        project.replace(at + 1, end - at - 1, gauge);
      });
}

Compilation sample_turning_at_sr5_faces(const std::string& sample, const std::string& more) {
  return sample_variant(sample, "sr5", [&](std::string& project) {
    if (std::size_t at = project.find("method: sr4"); at != std::string::npos)
      project.replace(at, 11, "method: sr5");
    else
      project += "short_rows: {method: sr5}\n";
    project += more;
  });
}

Compilation sock_turning_twice_at_a_st() {
  return sample_at_gauge("sock", 10, 44);
}

std::size_t occurrences(std::string_view text, std::string_view what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string_view::npos; at = text.find(what, at + 1))
    ++n;
  return n;
}

StitchMesh edging_mesh(int width, int rows) {
  using T = StitchType;
  std::vector<Square> squares;
  for (int y = 0; y <= rows + 1; ++y) {
    T type = y == 0 ? T::co : y == rows + 1 ? T::bo : T::k;
    for (int x = 0; x < width; ++x) squares.push_back({x, y, type, y % 2 ? "bito" : "boti"});
  }
  for (int y = 1; y <= rows; ++y) squares.push_back({width, y, T::co, "ibot"});
  return grid_mesh(width + 1, rows + 2, squares);
}

}  // namespace skein::testing

namespace skein::testing {

namespace {

// The hand-made graphs below number a row's stitches from right to left seen from the RS, and
// a RS row runs right to left: each yarn's first course runs the way its first two stitches
// are numbered (right to left when they count up), and each turn reverses the way.
void record_course_directions(KnitGraph& g) {
  std::vector<std::uint8_t> has_before(g.size(), 0);
  for (StitchId s = 0; s < g.size(); ++s)
    if (g.yarn_next[s] != kNoStitch) has_before[g.yarn_next[s]] = 1;
  for (StitchId start = 0; start < g.size(); ++start) {
    if (has_before[start]) continue;
    StitchId second = g.yarn_next[start];
    auto way = second == kNoStitch || second > start ? CourseDirection::right_to_left
                                                     : CourseDirection::left_to_right;
    for (StitchId s = start; s != kNoStitch; s = g.yarn_next[s]) {
      g.direction[s] = way;
      if (g.yarn_link[s] == YarnLink::turn) way = reversed(way);
    }
  }
}

// A tube's graph with a flap of two rows back and forth between its first rnds and its last:
// cast-on, rnd, row, row, rnd, bind-off.
KnitGraph tube_with_flap(const char* name) {
  KnitGraph g;
  g.source_name = name;
  g.element = "face";
  g.row_shape = {RowShape::closed, RowShape::closed, RowShape::open,
                 RowShape::open,   RowShape::closed, RowShape::closed};
  return g;
}

}  // namespace

KnitGraph heel_turn_graph() {
  using T = StitchType;
  KnitGraph g = tube_with_flap("heel turn");
  auto row_of = [&](std::initializer_list<T> types, std::uint32_t row) {
    std::vector<StitchId> made;
    for (T t : types) made.push_back(g.add_stitch(t, row, g.size(), 0));
    return made;
  };
  auto c = row_of({T::co, T::co, T::co, T::co, T::co, T::co}, 0);
  auto a = row_of({T::k, T::k, T::k, T::k, T::k, T::k}, 1);
  auto b = row_of({T::k, T::k2tog}, 2);      // b0 over a0; b1 over a1 and a2
  auto d = row_of({T::k2tog, T::k2tog}, 3);  // d1 (a3, b1) first, then d0 (b0, a5)
  auto e = row_of({T::k, T::k, T::k}, 4);    // over d0, d1, a4
  auto f = row_of({T::bo, T::bo, T::bo}, 5);
  const StitchId yarn[] = {c[0], c[1], c[2], c[3], c[4], c[5], a[0], a[1], a[2], a[3], a[4],
                           a[5], b[0], b[1], d[1], d[0], e[0], e[1], e[2], f[0], f[1], f[2]};
  for (std::size_t i = 0; i + 1 < std::size(yarn); ++i) {
    g.yarn_next[yarn[i]] = yarn[i + 1];
    g.yarn_link[yarn[i]] = YarnLink::course;
  }
  for (StitchId end_of_round : {c[5], a[5], e[2]}) g.yarn_link[end_of_round] = YarnLink::shift;
  for (StitchId turn : {b[1], d[0]}) g.yarn_link[turn] = YarnLink::turn;
  record_course_directions(g);
  auto loop = [&](StitchId maker, StitchId taker, std::uint8_t slot, LoopKind kind) {
    g.loops.push_back({maker, taker, kind, 0, slot});
  };
  // The decreases across the gap take live loops from the needle beside them, at their
  // makers' tops: wale loops (a perpendicular one would wait along an edge to be picked up).
  const LoopKind w = LoopKind::wale, across = LoopKind::wale;
  for (int i = 0; i < 6; ++i) loop(c[i], a[i], 0, w);
  loop(a[0], b[0], 0, w);
  loop(a[2], b[1], 0, across);  // rows run right to left seen from the RS: a2 is left of a1
  loop(a[1], b[1], 1, w);
  loop(a[3], d[1], 0, across);
  loop(b[1], d[1], 1, w);
  loop(b[0], d[0], 0, w);
  loop(a[5], d[0], 1, across);
  loop(d[0], e[0], 0, w);
  loop(d[1], e[1], 0, w);
  loop(a[4], e[2], 0, w);
  for (int i = 0; i < 3; ++i) loop(e[i], f[i], 0, w);
  g.index_loops();
  return g;
}

namespace {

// A knit graph built row by row: its stitches, the loops between them and the yarn's order.
struct GraphRows {
  KnitGraph g;

  std::vector<StitchId> row_of(std::size_t n, StitchType type, std::uint32_t row) {
    std::vector<StitchId> made;
    for (std::size_t i = 0; i < n; ++i) made.push_back(g.add_stitch(type, row, g.size(), 0));
    return made;
  }
  void loop(StitchId maker, StitchId taker, std::uint8_t slot) {
    g.loops.push_back({maker, taker, LoopKind::wale, slot, 0});
  }
  void link(const std::vector<StitchId>& order) {
    for (std::size_t i = 0; i + 1 < order.size(); ++i) {
      g.yarn_next[order[i]] = order[i + 1];
      g.yarn_link[order[i]] = YarnLink::course;
    }
  }
  void finish(std::initializer_list<StitchId> ends_of_rounds,
              std::initializer_list<StitchId> turns) {
    for (StitchId s : ends_of_rounds) g.yarn_link[s] = YarnLink::shift;
    for (StitchId s : turns) g.yarn_link[s] = YarnLink::turn;
    record_course_directions(g);
    g.index_loops();
  }
};

// A graph of `rows` open rows, named for messages, to add stitches to.
GraphRows open_rows(const char* name, std::size_t rows) {
  KnitGraph flat;
  flat.source_name = name;
  flat.element = "face";
  flat.row_shape.assign(rows, RowShape::open);
  return GraphRows{std::move(flat)};
}

}  // namespace

KnitGraph heel_turn_on_new_yarn_graph() {
  using T = StitchType;
  GraphRows r = open_rows("heel turn on a new yarn", 5);
  auto c = r.row_of(6, T::co, 0);
  auto a = r.row_of(6, T::k, 1);
  auto b = r.row_of(2, T::k2tog, 2);  // b0 over a1 and a2, b1 over a3 and a4
  auto d = r.row_of(2, T::k2tog, 3);  // d1 over a5 and b1 first, then d0 over b0 and a0
  auto e = r.row_of(2, T::bo, 4);     // over d0, d1
  r.link({c[0], c[1], c[2], c[3], c[4], c[5], a[5], a[4], a[3], a[2], a[1], a[0]});
  r.link({b[0], b[1], d[1], d[0], e[0], e[1]});
  auto across = [&](StitchId maker, StitchId taker, std::uint8_t slot) {  // from beside
    r.g.loops.push_back({maker, taker, LoopKind::wale, 0, slot});
  };
  for (int i = 0; i < 6; ++i) r.loop(c[i], a[i], 0);
  // Rows run right to left seen from the RS (a RS row takes its second slot first).
  r.g.loops.push_back({a[2], b[0], LoopKind::wale, 0, 0});
  across(a[1], b[0], 1);
  across(a[4], b[1], 0);
  r.g.loops.push_back({a[3], b[1], LoopKind::wale, 0, 1});
  across(a[5], d[1], 0);
  r.g.loops.push_back({b[1], d[1], LoopKind::wale, 0, 1});
  r.loop(b[0], d[0], 0);
  across(a[0], d[0], 1);
  r.loop(d[0], e[0], 0);
  r.loop(d[1], e[1], 0);
  r.finish({}, {c[5], b[1], d[0]});
  return std::move(r.g);
}

KnitGraph new_yarn_on_set_aside_needle_graph() {
  using T = StitchType;
  GraphRows r = open_rows("new yarn on a set-aside needle", 7);
  auto c = r.row_of(4, T::co, 0);
  auto a = r.row_of(4, T::k, 1);     // worked a3 first
  auto b = r.row_of(2, T::k, 2);     // a short row over a0, a1
  auto d = r.row_of(2, T::k, 3);     // back over it
  auto e = r.row_of(2, T::k, 4);     // the new yarn over a2 (worked last of the two), a3
  auto h = r.row_of(2, T::k, 5);     // back over it, left live
  auto f = r.row_of(2, T::tnbo, 6);  // Piece 1's d0 with h1, d1 with h0
  r.link({c[0], c[1], c[2], c[3], a[3], a[2], a[1], a[0], b[0], b[1], d[1], d[0], f[0], f[1]});
  r.link({e[0], e[1], h[1], h[0]});
  for (int i = 0; i < 4; ++i) r.loop(c[i], a[i], 0);
  for (int i = 0; i < 2; ++i) {
    r.loop(a[i], b[i], 0);
    r.loop(b[i], d[i], 0);
    r.loop(a[2 + i], e[i], 0);
    r.loop(e[i], h[i], 0);
  }
  auto join = [&](StitchId maker, StitchId taker, std::uint8_t slot) {
    r.g.loops.push_back({maker, taker, LoopKind::joined, 0, slot});
  };
  join(d[0], f[0], 0);
  join(h[1], f[0], 1);
  join(d[1], f[1], 0);
  join(h[0], f[1], 1);
  r.finish({}, {c[3], a[0], b[1], d[0], e[1]});
  return std::move(r.g);
}

KnitGraph flat_piece_taken_up_on_a_chain_graph() {
  using T = StitchType;
  GraphRows r = open_rows("flat piece taken up on a chain", 11);
  for (std::uint32_t rnd : {8u, 9u, 10u}) r.g.row_shape[rnd] = RowShape::closed;
  auto c = r.row_of(6, T::co, 0), a = r.row_of(6, T::k, 1);  // sts 0-1 left, 2-3 the hole, 4-5
  auto b = r.row_of(2, T::k, 2), d = r.row_of(2, T::k, 3);   // Piece 1 over a0, a1
  auto g = r.row_of(6, T::k, 4), j = r.row_of(6, T::bo, 5);  // over d, the chain and h
  auto e = r.row_of(2, T::k, 6), h = r.row_of(2, T::k, 7);   // the new yarn over a4, a5
  auto co = r.row_of(2, T::sco, 8);                          // the hole's top: co1, co0
  auto rnd = r.row_of(6, T::k, 8);  // picks up d1, b1; takes a2, a3; picks up e0, h0
  auto k = r.row_of(8, T::k, 9), m = r.row_of(8, T::bo, 10);
  r.link({c[0], c[1], c[2], c[3], c[4], c[5], a[5], a[4], a[3], a[2], a[1], a[0], b[0], b[1],
          d[1], d[0], g[0], g[1], g[2], g[3], g[4], g[5], j[5], j[4], j[3], j[2], j[1], j[0]});
  std::vector<StitchId> yarn2 = {e[0], e[1], h[1], h[0], co[1], co[0]};
  yarn2.insert(yarn2.end(), rnd.begin(), rnd.end());
  yarn2.insert(yarn2.end(), k.begin(), k.end());
  yarn2.insert(yarn2.end(), m.begin(), m.end());
  r.link(yarn2);
  auto across = [&](StitchId maker, std::uint8_t maker_slot, StitchId taker) {
    r.g.loops.push_back({maker, taker, LoopKind::perpendicular, maker_slot, 0});
  };
  for (int i = 0; i < 6; ++i) {
    r.loop(c[i], a[i], 0);
    r.loop(g[i], j[i], 0);
  }
  // The edges beside the hole: Piece 1's left one (b1, d1), the new yarn's right one (e0, h0).
  // A st at a left edge makes its loop across it first, one at a right edge last.
  auto wale = [&](StitchId maker, StitchId taker, bool across_first) {
    r.g.loops.push_back({maker, taker, LoopKind::wale, static_cast<std::uint8_t>(across_first), 0});
  };
  for (int i = 0; i < 2; ++i) {
    r.loop(a[i], b[i], 0);
    wale(b[i], d[i], i == 1);
    wale(d[i], g[i], i == 1);
    r.loop(a[4 + i], e[i], 0);
    wale(e[i], h[i], false);
    wale(h[i], g[4 + i], false);
    r.loop(co[i], k[1 - i], 0);
    r.g.loops.push_back({co[i], g[2 + i], LoopKind::split, 1, 0});
    r.loop(a[2 + i], rnd[2 + i], 0);
  }
  across(d[1], 0, rnd[0]);
  across(b[1], 0, rnd[1]);
  across(e[0], 1, rnd[4]);
  across(h[0], 1, rnd[5]);
  for (int i = 0; i < 6; ++i) r.loop(rnd[i], k[2 + i], 0);
  for (int i = 0; i < 8; ++i) r.loop(k[i], m[i], 0);
  r.finish({rnd[5], k[7]}, {c[5], a[0], b[1], d[0], g[5], e[1], h[0]});
  return std::move(r.g);
}

namespace {

// The gusset graphs' tube and flap: 6 sts cast on in the rnd and a rnd (a0..a5), then the flap
// over a0..a2 worked back and forth (b, then d back: d2, d1, d0), on one yarn.
struct GussetFlap : GraphRows {
  std::vector<StitchId> c, a, b, d, yarn;

  explicit GussetFlap(const char* name) : GraphRows{tube_with_flap(name)} {
    c = row_of(6, StitchType::co, 0);
    a = row_of(6, StitchType::k, 1);
    b = row_of(3, StitchType::k, 2);
    d = row_of(3, StitchType::k, 3);
    for (const auto* run : {&c, &a, &b}) yarn.insert(yarn.end(), run->begin(), run->end());
    yarn.insert(yarn.end(), {d[2], d[1], d[0]});
    for (int i = 0; i < 6; ++i) loop(c[i], a[i], 0);
    for (int i = 0; i < 3; ++i) loop(a[i], b[i], 0);
    loop(b[0], d[0], 0);
    loop(b[1], d[1], 0);
    loop(b[2], d[2], 1);
  }

  // Rows run right to left seen from the RS: the flap's left edge is b2 and d2, whose loop
  // across it is their first; b0 and d0 make theirs last. Picked up down the left edge (d2,
  // b2) and up the right one (b0, d0).
  void pick_up_edges(StitchId from_d2, StitchId from_b2, StitchId from_b0, StitchId from_d0) {
    for (auto [maker, taker, slot] :
         {std::tuple{d[2], from_d2, 0}, {b[2], from_b2, 0}, {b[0], from_b0, 1}, {d[0], from_d0, 1}})
      g.loops.push_back(
          {maker, taker, LoopKind::perpendicular, static_cast<std::uint8_t>(slot), 0});
  }
  // The row over the flap's sts takes d0..d2 (d2's loop is its second, after its edge loop).
  void work_flap(const std::vector<StitchId>& over) {
    loop(d[0], over[0], 0);
    loop(d[1], over[1], 0);
    loop(d[2], over[2], 1);
  }
};

}  // namespace

KnitGraph gusset_graph() {
  GussetFlap t("gusset");
  // In the order worked: over d0..d2, picked up from d2 and b2, over a3..a5, from b0 and d0.
  auto e = t.row_of(10, StitchType::k, 4);
  auto f = t.row_of(10, StitchType::bo, 5);
  for (const auto* run : {&e, &f}) t.yarn.insert(t.yarn.end(), run->begin(), run->end());
  t.link(t.yarn);
  t.work_flap(e);
  t.pick_up_edges(e[3], e[4], e[8], e[9]);
  for (int i = 3; i < 6; ++i) t.loop(t.a[i], e[i + 2], 0);
  for (int i = 0; i < 10; ++i) t.loop(e[i], f[i], 0);
  t.finish({t.c[5], t.a[5], e[9]}, {t.b[2], t.d[0]});
  return std::move(t.g);
}

KnitGraph reversed_gusset_leg_graph() {
  using T = StitchType;
  KnitGraph g = tube_with_flap("reversed gusset leg");
  g.row_shape.insert(g.row_shape.begin(), RowShape::closed);  // z: a rnd before the flap's
  g.row_shape.insert(g.row_shape.end(), {RowShape::open, RowShape::open});
  auto row_of = [&](std::size_t n, T type, std::uint32_t row) {
    std::vector<StitchId> made;
    for (std::size_t i = 0; i < n; ++i) made.push_back(g.add_stitch(type, row, g.size(), 0));
    return made;
  };
  auto c = row_of(6, T::co, 0), z = row_of(6, T::k, 1), a = row_of(6, T::k, 2);
  auto b = row_of(3, T::k, 3);  // over a5, a4, a3: left to right seen from the RS
  auto d = row_of(3, T::k, 4);  // over b2, b1, b0: right to left
  auto e = row_of(7, T::k, 5);  // from d2, b0 (left edge); over a0..a2; from b2, d0 (right)
  auto f = row_of(7, T::bo, 6);
  auto h = row_of(3, T::k, 7);  // the leg, with a yarn of its own: over d0..d2
  auto j = row_of(3, T::bo, 8);
  auto link = [&](std::vector<StitchId> order) {
    for (std::size_t i = 0; i + 1 < order.size(); ++i) {
      g.yarn_next[order[i]] = order[i + 1];
      g.yarn_link[order[i]] = YarnLink::course;
    }
  };
  std::vector<StitchId> yarn;
  for (const auto* run : {&c, &z, &a, &b, &d, &e, &f})
    yarn.insert(yarn.end(), run->begin(), run->end());
  link(yarn);
  link({h[0], h[1], h[2], j[2], j[1], j[0]});
  auto loop = [&](StitchId maker, StitchId taker, std::uint8_t slot, LoopKind kind) {
    g.loops.push_back({maker, taker, kind, slot, 0});
  };
  const LoopKind w = LoopKind::wale, across = LoopKind::perpendicular;
  for (int i = 0; i < 6; ++i) loop(c[i], z[i], 0, w);
  for (int i = 0; i < 6; ++i) loop(z[i], a[i], 0, w);
  for (int i = 0; i < 3; ++i) loop(a[5 - i], b[i], 0, w);
  // The flap's left edge is b0 and d2 (their loop across it first), its right b2 and d0.
  loop(b[2], d[0], 0, w);
  loop(b[1], d[1], 0, w);
  loop(b[0], d[2], 1, w);
  loop(d[2], e[0], 0, across);
  loop(b[0], e[1], 0, across);
  for (int i = 0; i < 3; ++i) loop(a[i], e[i + 2], 0, w);
  loop(b[2], e[5], 1, across);
  loop(d[0], e[6], 1, across);
  for (int i = 0; i < 7; ++i) loop(e[i], f[i], 0, w);
  loop(d[0], h[0], 0, w);
  loop(d[1], h[1], 0, w);
  loop(d[2], h[2], 1, w);
  for (int i = 0; i < 3; ++i) loop(h[i], j[i], 0, w);
  for (StitchId s : {c[5], z[5], a[5], e[6]}) g.yarn_link[s] = YarnLink::shift;
  for (StitchId s : {b[2], d[2], h[2]}) g.yarn_link[s] = YarnLink::turn;
  record_course_directions(g);
  // The flap turns back at the rnd's end (b), and the rnd after it goes on the way d went.
  for (StitchId s : b) g.direction[s] = CourseDirection::left_to_right;
  for (const auto* run : {&d, &e, &f})
    for (StitchId s : *run) g.direction[s] = CourseDirection::right_to_left;
  g.index_loops();
  return g;
}

KnitGraph gusset_leg_graph() {
  GussetFlap t("gusset leg");
  t.g.row_shape.insert(t.g.row_shape.end(), {RowShape::open, RowShape::open});
  // In the order worked: picked up from d2 and b2, over a3..a5, from b0 and d0.
  auto e = t.row_of(7, StitchType::k, 4);
  auto f = t.row_of(7, StitchType::bo, 5);
  auto h = t.row_of(3, StitchType::k, 6);  // the leg, with a yarn of its own: over d0..d2
  auto j = t.row_of(3, StitchType::bo, 7);
  for (const auto* run : {&e, &f}) t.yarn.insert(t.yarn.end(), run->begin(), run->end());
  t.link(t.yarn);
  t.link({h[0], h[1], h[2], j[2], j[1], j[0]});
  t.work_flap(h);
  t.pick_up_edges(e[0], e[1], e[5], e[6]);
  for (int i = 3; i < 6; ++i) t.loop(t.a[i], e[i - 1], 0);
  for (int i = 0; i < 7; ++i) t.loop(e[i], f[i], 0);
  for (int i = 0; i < 3; ++i) t.loop(h[i], j[i], 0);
  t.finish({t.c[5], t.a[5], e[6]}, {t.b[2], t.d[0], h[2]});
  return std::move(t.g);
}

KnitGraph flap_and_strip_graph(bool round_a_corner) {
  GussetFlap t(round_a_corner ? "corner flap and strip" : "flap and strip");
  const RowShape open = RowShape::open;
  t.g.row_shape.insert(t.g.row_shape.end(), {open, open, open, open, open});
  // The flap's third row (RS, g0..g2 over d0..d2), its yarn going round the corner at g2.
  std::vector<StitchId> g;
  if (round_a_corner) {
    t.g.row_shape.push_back(open);
    g = t.row_of(3, StitchType::k, 11);
    t.yarn.insert(t.yarn.end(), g.begin(), g.end());
    t.work_flap(g);
  }
  const std::vector<StitchId>& top = round_a_corner ? g : t.d;
  // In the order worked: picked up from (g2,) d2 and b2, over a3, picked up from h0 and i0.
  const std::size_t left = round_a_corner ? 3 : 2;
  auto e = t.row_of(left + 3, StitchType::k, 4), f = t.row_of(left + 3, StitchType::bo, 5);
  auto h = t.row_of(2, StitchType::k, 6), i = t.row_of(2, StitchType::k, 7);
  auto j = t.row_of(2, StitchType::bo, 8);
  auto m = t.row_of(3, StitchType::k, 9), n = t.row_of(3, StitchType::bo, 10);
  for (const auto* run : {&e, &f}) t.yarn.insert(t.yarn.end(), run->begin(), run->end());
  t.link(t.yarn);
  t.link({h[0], h[1], i[1], i[0], j[0], j[1]});
  t.link({m[0], m[1], m[2], n[2], n[1], n[0]});
  // The flap's top row's sts go on as m (its left edge st's loop across is its first).
  for (int k = 0; k < 3; ++k) t.loop(top[k], m[k], k == 2 ? 1 : 0);
  // The flap's left edge (g2,) d2, b2 down, then the strip's right edge (h0, i0: loop across
  // last) up.
  std::vector<std::tuple<StitchId, StitchId, int>> across;
  if (round_a_corner) across.emplace_back(g[2], e[0], 0);
  across.insert(across.end(), {{t.d[2], e[left - 2], 0},
                               {t.b[2], e[left - 1], 0},
                               {h[0], e[left + 1], 1},
                               {i[0], e[left + 2], 1}});
  for (auto [maker, taker, slot] : across)
    t.g.loops.push_back(
        {maker, taker, LoopKind::perpendicular, static_cast<std::uint8_t>(slot), 0});
  t.loop(t.a[3], e[left], 0);
  for (int k = 0; k < 2; ++k) {
    t.loop(t.a[4 + k], h[k], 0);
    t.loop(h[k], i[k], 0);
    t.loop(i[k], j[k], 0);
  }
  for (std::size_t k = 0; k < e.size(); ++k) t.loop(e[k], f[k], 0);
  for (int k = 0; k < 3; ++k) t.loop(m[k], n[k], 0);
  t.finish({t.c[5], t.a[5], e.back()}, {t.b[2], t.d[0], h[1], i[0], m[2]});
  if (round_a_corner) t.g.yarn_link[g[2]] = YarnLink::turn;  // the model's turn at the corner
  return std::move(t.g);
}

KnitGraph strip_joined_in_the_rnd_graph(bool leg_in_the_rnd) {
  using T = StitchType;
  KnitGraph g;
  g.source_name = "strip joined in the rnd";
  g.element = "face";
  const RowShape leg = leg_in_the_rnd ? RowShape::closed : RowShape::open;
  g.row_shape = {
      RowShape::open, RowShape::open, RowShape::open, RowShape::closed, RowShape::closed, leg, leg};
  auto row_of = [&](std::size_t n, T type, std::uint32_t row) {
    std::vector<StitchId> made;
    for (std::size_t i = 0; i < n; ++i) made.push_back(g.add_stitch(type, row, g.size(), 0));
    return made;
  };
  auto c = row_of(3, T::co, 0), b = row_of(3, T::k, 1), d = row_of(3, T::k, 2);
  auto e = row_of(4, T::k, 3), f = row_of(4, T::bo, 4);
  auto h = row_of(3, T::k, 5), j = row_of(3, T::bo, 6);
  auto link = [&](const std::vector<StitchId>& order) {
    for (std::size_t i = 0; i + 1 < order.size(); ++i) {
      g.yarn_next[order[i]] = order[i + 1];
      g.yarn_link[order[i]] = YarnLink::course;
    }
  };
  link({c[2], c[1], c[0], b[0], b[1], b[2], d[2], d[1], d[0], e[0], e[1], e[2], e[3], f[0], f[1],
        f[2], f[3]});
  if (leg_in_the_rnd)
    link({h[0], h[1], h[2], j[0], j[1], j[2]});
  else
    link({h[0], h[1], h[2], j[2], j[1], j[0]});
  for (StitchId s : {c[0], b[2], d[0]}) g.yarn_link[s] = YarnLink::turn;
  g.yarn_link[h[2]] = leg_in_the_rnd ? YarnLink::shift : YarnLink::turn;
  g.yarn_link[e[3]] = YarnLink::shift;
  auto wale = [&](StitchId maker, StitchId taker, std::uint8_t slot) {
    g.loops.push_back({maker, taker, LoopKind::wale, slot, 0});
  };
  for (int i = 0; i < 3; ++i) wale(c[i], b[i], 0);
  for (int i = 0; i < 3; ++i) wale(b[i], d[i], i == 2 ? 1 : 0);
  // The strip's left edge (d2, b2) makes its loop across it first, the right one (b0, d0) last.
  for (auto [maker, taker, slot] :
       {std::tuple{d[2], e[0], 0}, {b[2], e[1], 0}, {b[0], e[2], 1}, {d[0], e[3], 1}})
    g.loops.push_back({maker, taker, LoopKind::perpendicular, static_cast<std::uint8_t>(slot), 0});
  for (int i = 0; i < 4; ++i) wale(e[i], f[i], 0);
  for (int i = 0; i < 3; ++i) wale(d[i], h[i], i == 2 ? 1 : 0);
  for (int i = 0; i < 3; ++i) wale(h[i], j[i], 0);
  record_course_directions(g);
  g.index_loops();
  return g;
}

KnitGraph strip_and_tube_joined_graph() {
  GraphRows t;
  t.g.source_name = "strip and tube joined";
  t.g.element = "face";
  const RowShape open = RowShape::open, closed = RowShape::closed;
  t.g.row_shape = {open, open, open, closed, closed, closed, closed};
  auto c = t.row_of(3, StitchType::co, 0), b = t.row_of(3, StitchType::k, 1);
  auto d = t.row_of(3, StitchType::k, 2), e = t.row_of(4, StitchType::k, 3);
  auto r = t.row_of(4, StitchType::k, 4);
  auto h = t.row_of(7, StitchType::k, 5), j = t.row_of(7, StitchType::bo, 6);
  std::vector<StitchId> yarn1 = {c[2], c[1], c[0], b[0], b[1], b[2], d[2], d[1], d[0]};
  yarn1.insert(yarn1.end(), e.begin(), e.end());
  yarn1.insert(yarn1.end(), r.begin(), r.end());
  t.link(yarn1);
  std::vector<StitchId> yarn2(h);
  yarn2.insert(yarn2.end(), j.begin(), j.end());
  t.link(yarn2);
  for (int i = 0; i < 3; ++i) {
    t.loop(c[i], b[i], 0);
    t.loop(b[i], d[i], i == 2 ? 1 : 0);
    t.loop(d[i], h[i], i == 2 ? 1 : 0);
  }
  // The strip's left edge (d2, b2: loop across first) down, its right edge (b0, d0) up.
  for (auto [maker, taker, slot] :
       {std::tuple{d[2], e[0], 0}, {b[2], e[1], 0}, {b[0], e[2], 1}, {d[0], e[3], 1}})
    t.g.loops.push_back(
        {maker, taker, LoopKind::perpendicular, static_cast<std::uint8_t>(slot), 0});
  for (int i = 0; i < 4; ++i) {
    t.loop(e[i], r[i], 0);
    t.loop(r[i], h[3 + i], 0);
  }
  for (int i = 0; i < 7; ++i) t.loop(h[i], j[i], 0);
  t.finish({e[3], h[6]}, {c[0], b[2], d[0]});
  return std::move(t.g);
}

KnitGraph corner_strip_graph() {
  GraphRows t;
  t.g.source_name = "corner strip";
  t.g.element = "face";
  const RowShape open = RowShape::open, closed = RowShape::closed;
  t.g.row_shape = {open, open, open, open, closed, closed, open, open};
  auto c = t.row_of(5, StitchType::co, 0), b = t.row_of(3, StitchType::k, 1);
  auto d = t.row_of(3, StitchType::k, 2), r = t.row_of(3, StitchType::k, 3);
  auto e = t.row_of(8, StitchType::k, 4), f = t.row_of(8, StitchType::bo, 5);
  auto h = t.row_of(3, StitchType::k, 6), j = t.row_of(3, StitchType::bo, 7);
  t.link({c[4], c[3], c[2], c[1], c[0], b[0], b[1], b[2], d[2], d[1],
          d[0], r[0], r[1], r[2], e[0], e[1], e[2], e[3], e[4], e[5],
          e[6], e[7], f[0], f[1], f[2], f[3], f[4], f[5], f[6], f[7]});
  t.link({h[0], h[1], h[2], j[2], j[1], j[0]});
  for (int i = 0; i < 3; ++i) {
    t.loop(c[i], b[i], 0);
    t.loop(b[i], d[i], i == 2 ? 1 : 0);
    t.loop(d[i], r[i], i == 2 ? 1 : 0);
    t.loop(r[i], h[i], i == 2 ? 1 : 0);
    t.loop(h[i], j[i], 0);
  }
  // The rnd starts round the corner at r2, the last st of the strip's last row: down the
  // strip's left edge (r2, d2, b2: their loop across it first), over the 2 sts the short rows
  // left (c3, c4), up the right edge (b0, d0, r0: last).
  for (auto [maker, taker, slot] : {std::tuple{r[2], e[0], 0},
                                    {d[2], e[1], 0},
                                    {b[2], e[2], 0},
                                    {b[0], e[5], 1},
                                    {d[0], e[6], 1},
                                    {r[0], e[7], 1}})
    t.g.loops.push_back(
        {maker, taker, LoopKind::perpendicular, static_cast<std::uint8_t>(slot), 0});
  t.loop(c[3], e[3], 0);
  t.loop(c[4], e[4], 0);
  for (int i = 0; i < 8; ++i) t.loop(e[i], f[i], 0);
  t.finish({e[7]}, {c[0], b[2], d[0], h[2]});
  t.g.yarn_link[r[2]] = YarnLink::turn;  // the model's turn at the corner: the rnd goes on RS
  return std::move(t.g);
}

KnitGraph folded_tube_graph() {
  using T = StitchType;
  KnitGraph g;
  g.source_name = "folded tube";
  g.element = "face";
  g.row_shape = {RowShape::closed, RowShape::closed, RowShape::open};
  for (std::uint32_t r = 0; r < 2; ++r)
    for (int i = 0; i < 6; ++i) g.add_stitch(r == 0 ? T::co : T::k, r, g.size(), 0);
  for (int i = 0; i < 3; ++i) g.add_stitch(T::tnbo, 2, g.size(), 0);
  for (StitchId s = 0; s + 1 < g.size(); ++s) {
    if (s == 11) continue;  // the tube's yarn ends with its sts live
    g.yarn_next[s] = s + 1;
    g.yarn_link[s] = s == 5 || s == 11 ? YarnLink::shift : YarnLink::course;
  }
  for (StitchId i = 0; i < 6; ++i) g.loops.push_back({i, 6 + i, LoopKind::wale, 0, 0});
  for (StitchId i = 0; i < 3; ++i) {
    g.loops.push_back({8 - i, 12 + i, LoopKind::joined, 0, 0});  // front: a2, a1, a0
    g.loops.push_back({9 + i, 12 + i, LoopKind::joined, 0, 1});  // back: a3, a4, a5
  }
  // The rnds run left to right; the bind-off's sts are ordered as the mismatch transform
  // extrudes them: along their loops.
  for (StitchId s = 12; s < 15; ++s) g.direction[s] = CourseDirection::along_its_loops;
  g.index_loops();
  return g;
}

StitchMesh random_sheet_or_tube(int trial, std::mt19937_64& rng) {
  RandomShaping shaping;
  shaping.min_width = trial % 2 ? 6 : 3;
  std::uint32_t width = 6 + static_cast<std::uint32_t>(rng() % 30);
  std::uint32_t rows = 1 + static_cast<std::uint32_t>(rng() % 25);
  Layout layout = trial % 2 ? Layout::tube : Layout::sheet;
  return build_from_rows(random_rows(width, rows, shaping, rng()), layout);
}

}  // namespace skein::testing
