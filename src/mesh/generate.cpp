#include "mesh/generate.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <random>

#include "common/error.hpp"

namespace skein {
namespace {

// Vertices of one ring (the boundary between two rows): `loops` course edges wide.
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
      float angle = -2 * std::numbers::pi_v<float> * static_cast<float>(i) / static_cast<float>(loops);
      ring.push_back(builder.add_vertex({radius * std::cos(angle), y, radius * std::sin(angle)}));
    }
    ring.push_back(ring.front());  // closed: index `loops` wraps to 0
  }
  return ring;
}

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

}  // namespace

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

RowPlan ribbed_rows(std::uint32_t width, std::uint32_t rows, const std::vector<StitchType>& repeat) {
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

}  // namespace skein
