#include "mesh/generate.hpp"

#include <fmt/format.h>

#include <cmath>
#include <map>
#include <numbers>
#include <random>
#include <string_view>

#include "common/error.hpp"

namespace skein {
namespace {

std::uint32_t loops_made(const std::vector<StitchType>& row) {
  std::uint32_t n = 0;
  for (StitchType t : row) n += info(t).top_edges;
  return n;
}

std::uint32_t edges_consumed(const std::vector<StitchType>& row) {
  std::uint32_t n = 0;
  for (StitchType t : row) n += info(t).bottom_edges;
  return n;
}

}  // namespace

std::vector<Vertex> add_ring(StitchMeshBuilder& builder, std::uint32_t loops, std::uint32_t level,
                             Layout layout) {
  std::vector<Vertex> ring;
  float y = static_cast<float>(level);
  if (layout == Layout::sheet) {
    for (std::uint32_t i = 0; i <= loops; ++i)
      ring.push_back(builder.add_vertex({static_cast<float>(i) - 0.5f * loops, y, 0}));
  } else {
    float radius = static_cast<float>(loops) / (2 * std::numbers::pi_v<float>);
    for (std::uint32_t i = 0; i < loops; ++i) {
      float angle =
          -2 * std::numbers::pi_v<float> * static_cast<float>(i) / static_cast<float>(loops);
      ring.push_back(builder.add_vertex({radius * std::cos(angle), y, radius * std::sin(angle)}));
    }
    ring.push_back(ring.front());  // closed: index `loops` wraps to 0
  }
  return ring;
}

void add_row(StitchMeshBuilder& builder, const std::vector<StitchType>& row,
             const std::vector<Vertex>& below, const std::vector<Vertex>& above,
             bool left_to_right) {
  std::vector<Vertex> corners;
  std::vector<EdgeRole> roles;
  std::uint32_t a = 0, c = 0;
  for (StitchType type : row) {
    const StitchTypeInfo& t = info(type);
    corners.clear();
    roles.clear();
    for (std::uint32_t i = 0; i <= t.bottom_edges; ++i) corners.push_back(below[a + i]);
    for (std::uint32_t i = 0; i <= t.top_edges; ++i) corners.push_back(above[c + t.top_edges - i]);
    roles.assign(t.bottom_edges, EdgeRole::bottom);
    roles.push_back(left_to_right ? EdgeRole::wale_out : EdgeRole::wale_in);
    roles.insert(roles.end(), t.top_edges, EdgeRole::top);
    roles.push_back(left_to_right ? EdgeRole::wale_in : EdgeRole::wale_out);
    builder.add_face(corners, roles, type);
    a += t.bottom_edges;
    c += t.top_edges;
  }
}

StitchMesh build_from_rows(const RowPlan& plan, Layout layout) {
  if (plan.size() < 2) throw Error("a row plan needs at least a cast-on row and a bind-off row");
  StitchMeshBuilder builder(layout == Layout::tube ? "<generated tube>" : "<generated sheet>");
  std::vector<Vertex> below = add_ring(builder, edges_consumed(plan.front()), 0, layout);
  std::vector<std::pair<Vertex, Vertex>> seam;
  for (std::uint32_t r = 0; r < plan.size(); ++r) {
    if (r > 0 && edges_consumed(plan[r]) != loops_made(plan[r - 1]))
      throw Error(fmt::format("row {} of the plan consumes {} loops, but row {} makes {}", r + 1,
                              edges_consumed(plan[r]), r, loops_made(plan[r - 1])));
    std::vector<Vertex> above = add_ring(builder, loops_made(plan[r]), r + 1, layout);
    bool left_to_right = layout == Layout::tube || r % 2 == 0;
    add_row(builder, plan[r], below, above, left_to_right);
    seam.emplace_back(below.front(), above.front());
    below = std::move(above);
  }
  StitchMesh mesh = std::move(builder).build();
  if (layout == Layout::tube)
    for (auto [a, b] : seam) mesh.shift_path[mesh.find_edge(a, b)] = 1;
  return mesh;
}

RowPlan ribbed_rows(std::uint32_t width, std::uint32_t rows,
                    const std::vector<StitchType>& repeat) {
  RowPlan plan;
  plan.emplace_back(width, StitchType::co);
  for (std::uint32_t r = 0; r < rows; ++r) {
    auto& row = plan.emplace_back();
    for (std::uint32_t i = 0; i < width; ++i) row.push_back(repeat[i % repeat.size()]);
  }
  plan.emplace_back(width, StitchType::bo);
  return plan;
}

RowPlan hat_rows(std::uint32_t circumference, std::uint32_t body_rounds, std::uint32_t sections) {
  if (sections == 0 || circumference % sections != 0)
    throw Error(fmt::format("a hat of {} stitches cannot be split into {} equal crown sections",
                            circumference, sections));
  RowPlan plan = ribbed_rows(circumference, body_rounds, {StitchType::k});
  plan.pop_back();
  for (std::uint32_t wedge = circumference / sections; wedge > 1; --wedge) {
    auto& decrease = plan.emplace_back();
    for (std::uint32_t s = 0; s < sections; ++s) {
      decrease.insert(decrease.end(), wedge - 2, StitchType::k);
      decrease.push_back(StitchType::k2tog);
    }
    if (wedge > 2) plan.emplace_back(sections * (wedge - 1), StitchType::k);
  }
  plan.emplace_back(sections, StitchType::bo);
  return plan;
}

RowPlan random_rows(std::uint32_t width, std::uint32_t rows, const RandomShaping& shaping,
                    std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> chance(0, 1);
  RowPlan plan;
  plan.emplace_back(width, StitchType::co);
  std::uint32_t loops = width;
  for (std::uint32_t r = 0; r < rows; ++r) {
    auto& row = plan.emplace_back();
    std::uint32_t made = 0;
    for (std::uint32_t left = loops; left > 0;) {
      double x = chance(rng);
      std::uint32_t width_now = made + left;  // the next row's width if all else is plain
      if (x < shaping.decrease && left >= 3 && width_now - 2 >= shaping.min_width &&
          chance(rng) < 0.25) {
        row.push_back(StitchType::s2kp);
      } else if (x < shaping.decrease && left >= 2 && width_now - 1 >= shaping.min_width) {
        row.push_back(chance(rng) < 0.5 ? StitchType::k2tog : StitchType::ssk);
      } else if (x < shaping.decrease + shaping.increase && width_now + 1 <= shaping.max_width) {
        constexpr StitchType kIncreases[] = {StitchType::kfb, StitchType::m1l, StitchType::m1r,
                                             StitchType::yo};
        row.push_back(kIncreases[rng() % 4]);
      } else {
        row.push_back(chance(rng) < shaping.purl ? StitchType::p : StitchType::k);
      }
      left -= info(row.back()).bottom_edges;
      made += info(row.back()).top_edges;
    }
    loops = made;
  }
  plan.emplace_back(loops, StitchType::bo);
  return plan;
}

void CornerBuilder::face(std::initializer_list<std::pair<float, float>> corners,
                         std::string_view roles, StitchType type) {
  vertices_.clear();
  roles_.clear();
  for (auto [x, y] : corners) vertices_.push_back(vertex(x, y));
  for (char c : roles) roles_.push_back(role_from_letter(c).value());
  builder_.add_face(vertices_, roles_, type);
}

Vertex CornerBuilder::vertex(float x, float y) {
  auto [it, added] = index_.try_emplace(std::pair{x, y});
  if (added) it->second = builder_.add_vertex({x, y, 0});
  return it->second;
}

namespace {

// Roles of a unit square by wale direction (up or down) and course direction.
std::string_view square_roles(bool wale_up, bool left_to_right) {
  if (wale_up) return left_to_right ? "boti" : "bito";
  return left_to_right ? "tobi" : "tibo";
}

float centre_height(const StitchMesh& mesh, Face f) {
  float sum = 0;
  for (Halfedge h : mesh.halfedges(f)) sum += mesh.position[mesh.tail(h)].y;
  return sum / static_cast<float>(mesh.degree(f));
}

StitchType knit_or_purl(std::mt19937_64& rng) {
  return rng() % 3 ? StitchType::k : StitchType::p;
}

void full_row(CornerBuilder& b, std::uint32_t width, float y, bool wale_up, bool left_to_right,
              StitchType type, std::mt19937_64& rng) {
  for (std::uint32_t x = 0; x < width; ++x)
    b.square(static_cast<float>(x), y, square_roles(wale_up, left_to_right),
             type == StitchType::k ? knit_or_purl(rng) : type);
}

// Rows y0..y0+3: a short row right to left over the stitches right of column c, the turn at c,
// a short row back, and the full row right to left above (stretched left of the turn).
void short_row_pair(CornerBuilder& b, std::uint32_t width, std::uint32_t c, float y0, bool sr5,
                    std::mt19937_64& rng) {
  float fc = static_cast<float>(c);
  for (std::uint32_t x = c + 1; x < width; ++x)
    b.square(static_cast<float>(x), y0, "bito", knit_or_purl(rng));
  if (sr5)
    b.face({{fc, y0}, {fc + 1, y0}, {fc + 1, y0 + 1}, {fc + 1, y0 + 2}, {fc + 0.5f, y0 + 1}},
           "biott", StitchType::sr5);
  else
    b.face({{fc, y0}, {fc + 1, y0}, {fc + 1, y0 + 1}, {fc + 1, y0 + 2}}, "biot", StitchType::sr4);
  for (std::uint32_t x = c + 1; x < width; ++x)
    b.square(static_cast<float>(x), y0 + 1, "boti", knit_or_purl(rng));
  for (std::uint32_t x = 0; x < c; ++x) {
    float fx = static_cast<float>(x);
    b.face({{fx, y0}, {fx + 1, y0}, {fx + 1, y0 + 3}, {fx, y0 + 3}}, "bito", knit_or_purl(rng));
  }
  if (sr5)
    b.face({{fc, y0}, {fc + 0.5f, y0 + 1}, {fc + 1, y0 + 2}, {fc + 1, y0 + 3}, {fc, y0 + 3}},
           "bbito", StitchType::k2tog);
  else
    b.face({{fc, y0}, {fc + 1, y0 + 2}, {fc + 1, y0 + 3}, {fc, y0 + 3}}, "bito", knit_or_purl(rng));
  for (std::uint32_t x = c + 1; x < width; ++x)
    b.square(static_cast<float>(x), y0 + 2, "bito", knit_or_purl(rng));
}

}  // namespace

StitchMesh short_row_sheet(std::uint32_t width, std::uint32_t rows, std::uint64_t seed) {
  if (width < 3) throw Error("a short-row sheet needs at least 3 stitches");
  std::mt19937_64 rng(seed);
  CornerBuilder b("<short-row sheet>");
  full_row(b, width, 0, true, true, StitchType::co, rng);
  float y = 1;
  bool next_left_to_right = false;  // rows alternate, starting back from the cast-on's end
  for (std::uint32_t r = 0; r < rows; ++r) {
    if (!next_left_to_right && rng() % 3 == 0) {  // starts at the right edge: a pair fits
      short_row_pair(b, width, 1 + static_cast<std::uint32_t>(rng() % (width - 2)), y, rng() % 2,
                     rng);
      y += 3;
      next_left_to_right = true;  // the pair's full row ran right to left
      continue;
    }
    full_row(b, width, y, true, next_left_to_right, StitchType::k, rng);
    next_left_to_right = !next_left_to_right;
    y += 1;
  }
  full_row(b, width, y, true, next_left_to_right, StitchType::bo, rng);
  return std::move(b).build();
}

StitchMesh meeting_sheets(Meeting meeting, std::uint32_t width, std::uint32_t lower_rows,
                          std::uint32_t upper_rows, MismatchYarn::Kind yarn, bool own_lower,
                          std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  CornerBuilder b(meeting == Meeting::join ? "<joined sheets>" : "<split sheets>");
  bool join = meeting == Meeting::join;
  // Each piece is knit from its far edge towards the line (join) or from the line outwards
  // (split); its first row is cast on (join) or its last bound off (split).
  auto piece = [&](std::uint32_t rows, bool lower) {
    float line = static_cast<float>(lower_rows);
    for (std::uint32_t r = 0; r < rows; ++r) {
      std::uint32_t from_line = join ? rows - 1 - r : r;
      float y =
          lower ? line - 1 - static_cast<float>(from_line) : line + static_cast<float>(from_line);
      bool wale_up = lower == join;
      StitchType type = join ? (r == 0 ? StitchType::co : StitchType::k)
                             : (r + 1 == rows ? StitchType::bo : StitchType::k);
      full_row(b, width, y, wale_up, r % 2 == 0, type, rng);
    }
  };
  piece(lower_rows, true);
  piece(upper_rows, false);
  StitchMesh mesh = std::move(b).build();
  for (Edge e : mesh.edges()) {
    EdgeKind kind = mesh.kind(e);
    if (kind != EdgeKind::join && kind != EdgeKind::split) continue;
    Face a = mesh.face(mesh.halfedge(e)), b2 = mesh.neighbour(mesh.halfedge(e));
    bool a_is_lower = centre_height(mesh, a) < centre_height(mesh, b2);
    mesh.mismatch_yarn[e] = {yarn, a_is_lower == own_lower ? a : b2};
  }
  return mesh;
}

}  // namespace skein
