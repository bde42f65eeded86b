#include "knitout/fabric_stitch_mesh.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <sstream>
#include <vector>

#include "common/error.hpp"
#include "knitout/fabric_stitch_graph.hpp"
#include "mesh/autoknit_st.hpp"
#include "mesh/generate.hpp"
#include "mesh/obj_format.hpp"

namespace skein::knitout {
namespace {

constexpr std::uint32_t kNotBelow = 0xffffffffu;

struct Row {
  std::vector<StitchId> chart;  // its stitches left to right on the side facing the front bed
  std::vector<StitchType> types;
  bool left_to_right = true;
  std::uint32_t turn = 0;  // on a round: which loop of the round below the first stitch takes
};

class MeshOfFabric {
 public:
  MeshOfFabric(const KnitGraph& g, const std::vector<std::array<double, 3>>& positions,
               const std::string& file)
      : g_(g), positions_(positions), file_(file), position_below_(g.loops.size(), kNotBelow) {}

  StitchMesh build() {
    split_rows();
    for (std::size_t r = 0; r < rows_.size(); ++r) name_types(r);
    for (std::size_t r = 1; r < rows_.size(); ++r) place_on_row_below(r);
    return lay_out();
  }

 private:
  [[noreturn]] void refuse(const std::string& why) const {
    throw UnsupportedError(
        fmt::format("the fabric {} makes cannot be written as a stitch mesh: {}; write it as a "
                    "stitch graph (--fabric NAME.st) instead",
                    file_, why));
  }

  std::string where(StitchId s) const {
    return fmt::format("stitch {} of row {}", s - first_of_row_[g_.row[s]] + 1, g_.row[s] + 1);
  }

  void split_rows() {
    tube_ = !g_.row_shape.empty() && g_.row_shape[0] == RowShape::closed;
    for (std::uint32_t r = 0; r < g_.row_shape.size(); ++r) {
      if (g_.row_shape[r] == RowShape::short_row)
        refuse(fmt::format("row {} is a short row", r + 1));
      if ((g_.row_shape[r] == RowShape::closed) != tube_)
        refuse(fmt::format("row {} is {} and row 1 is {}", r + 1, row_shape_name(g_.row_shape[r]),
                           row_shape_name(g_.row_shape[0])));
    }
    rows_.resize(g_.row_shape.size());
    first_of_row_.assign(rows_.size(), 0);
    for (StitchId s = 0; s < g_.size(); ++s) {
      Row& row = rows_[g_.row[s]];
      bool left_to_right = g_.direction[s] == CourseDirection::left_to_right;
      if (row.chart.empty()) first_of_row_[g_.row[s]] = s, row.left_to_right = left_to_right;
      if (s > 0 && g_.yarn_next[s - 1] != s)
        refuse(fmt::format("its {} begins a second yarn piece", where(s)));
      if (left_to_right != row.left_to_right && g_.row[s] > 0)
        refuse(fmt::format("row {} goes both ways (a course knit in two passes): its {} turns back",
                           g_.row[s] + 1, where(s)));
      row.chart.push_back(s);
    }
    for (Row& row : rows_)
      if (!row.left_to_right) std::reverse(row.chart.begin(), row.chart.end());
    if (rows_.size() > 1) lay_cast_on_row();
  }

  // A cast-on is often made in more than one pass (every other needle one way, the others
  // back): its loops are one row, placed by their needles (left to right on a sheet, round the
  // tube: the front left to right, the back right to left), made the way the row above goes
  // (a round) or the other way (a sheet).
  void lay_cast_on_row() {
    Row& row = rows_[0];
    auto place = [&](StitchId s) {
      double x = positions_[s][0], back = positions_[s][2];
      return tube_ ? std::pair{back, back != 0 ? -x : x} : std::pair{x, back};
    };
    std::stable_sort(row.chart.begin(), row.chart.end(),
                     [&](StitchId a, StitchId b) { return place(a) < place(b); });
    row.left_to_right = rows_[1].left_to_right == tube_;
  }

  // The stitch mesh's types: a cast-on only in the first row, a bind-off only in the last (a
  // loop through nothing or a wale ending anywhere else has no face); the rest are the stitch
  // graph's (its `p` a purl).
  void name_types(std::size_t r) {
    for (StitchId s : rows_[r].chart) {
      StitchType t = g_.type[s];
      if ((t == StitchType::co) != (r == 0))
        refuse(r == 0 ? fmt::format("its {} takes a loop, and the first row is a cast-on", where(s))
                      : fmt::format("its {} is pulled through nothing", where(s)));
      if ((t == StitchType::bo) != (r + 1 == rows_.size()))
        refuse(t == StitchType::bo ? fmt::format("its {} ends a wale inside the fabric", where(s))
                                   : fmt::format("its {} is left on a needle", where(s)));
      rows_[r].types.push_back(t);
    }
  }

  // The loops a row makes, left to right: a stitch's two loops in the order its yarn made them.
  std::vector<std::uint32_t> loops_made(const Row& row) const {
    std::vector<std::uint32_t> loops;
    for (StitchId s : row.chart) {
      auto made = g_.loops_made_by(s);
      if (row.left_to_right)
        loops.insert(loops.end(), made.begin(), made.end());
      else
        loops.insert(loops.end(), made.rbegin(), made.rend());
    }
    return loops;
  }

  // Row r must take the loops of row r - 1 one after the other, left to right (a round may
  // start anywhere along the round below: its turn).
  void place_on_row_below(std::size_t r) {
    std::vector<std::uint32_t> below = loops_made(rows_[r - 1]);
    auto m = static_cast<std::uint32_t>(below.size());
    for (std::uint32_t i = 0; i < m; ++i) position_below_[below[i]] = i;
    std::uint32_t expected = kNotBelow, taken = 0;
    for (StitchId s : rows_[r].chart) {
      std::vector<std::uint32_t> at;
      for (std::uint32_t loop : g_.loops_taken_by(s)) {
        if (position_below_[loop] == kNotBelow)
          refuse(fmt::format("its {} takes a loop that is not the row below's", where(s)));
        at.push_back(position_below_[loop]);
      }
      std::sort(at.begin(), at.end());
      if (tube_ && at.size() == 2 && at[0] == 0 && at[1] == m - 1) std::swap(at[0], at[1]);
      for (std::uint32_t p : at) {
        if (expected == kNotBelow) rows_[r].turn = expected = p;
        if (p != expected)
          refuse(
              fmt::format("its {} takes the loops of the row below out of their order", where(s)));
        expected = (p + 1) % m;
        ++taken;
      }
    }
    if (taken != m || (!tube_ && rows_[r].turn != 0))
      refuse(fmt::format("row {} does not take every loop of row {} in order", r + 1, r));
    for (std::uint32_t loop : below) position_below_[loop] = kNotBelow;
  }

  static std::uint32_t edges(const std::vector<StitchType>& types, bool top) {
    std::uint32_t n = 0;
    for (StitchType t : types) n += top ? info(t).top_edges : info(t).bottom_edges;
    return n;
  }

  StitchMesh lay_out() const {
    StitchMeshBuilder builder(file_ + " (its fabric)");
    Layout layout = tube_ ? Layout::tube : Layout::sheet;
    std::vector<Vertex> below = add_ring(builder, edges(rows_[0].types, false), 0, layout);
    for (std::uint32_t r = 0; r < rows_.size(); ++r) {
      const Row& row = rows_[r];
      if (row.turn) {  // the round begins `turn` loops along: so does its bottom ring
        below.pop_back();
        std::rotate(below.begin(), below.begin() + row.turn, below.end());
        below.push_back(below.front());
      }
      std::vector<Vertex> above = add_ring(builder, edges(row.types, true), r + 1, layout);
      add_row(builder, row.types, below, above, row.left_to_right);
      below = std::move(above);
    }
    return std::move(builder).build();
  }

  const KnitGraph& g_;
  const std::vector<std::array<double, 3>>& positions_;
  const std::string& file_;
  bool tube_ = false;
  std::vector<Row> rows_;
  std::vector<StitchId> first_of_row_;
  std::vector<std::uint32_t> position_below_;  // per loop: where in the row below it lies
};

}  // namespace

void write_fabric_stitch_mesh(const Replay& replay, const std::string& file, std::ostream& out,
                              const std::vector<bool>* border) {
  std::ostringstream st;
  write_fabric_stitch_graph(replay, file, st, border);
  std::vector<std::array<double, 3>> positions;
  KnitGraph graph = parse_autoknit_st(st.str(), file + " (its fabric)", &positions);
  write_stitch_mesh(MeshOfFabric(graph, positions, file).build(), out);
}

}  // namespace skein::knitout
