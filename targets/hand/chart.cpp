#include "hand/chart.hpp"

#include <algorithm>
#include <optional>

#include "hand/hand_ops.hpp"

namespace skein::hand {
namespace {

constexpr std::uint32_t kChartWidest = 60;
constexpr std::uint32_t kChartRows = 80;

// The RS view of a row's stitches, left to right, when every one is a knit or a purl.
std::optional<std::vector<StitchType>> plain_faces(const HandPattern& p, const PatternRow& row) {
  std::vector<StitchType> faces;
  for (HandOp op : p.ops_of(row)) {
    if (!is_plain(op)) return std::nullopt;
    faces.push_back(*rs_face(op, row.side));
  }
  if (row.side == Side::rs) std::reverse(faces.begin(), faces.end());  // worked right to left
  return faces;
}

}  // namespace

std::vector<ChartRow> chart_rows(const HandPattern& p, const PatternSection& s) {
  std::vector<ChartRow> rows;
  bool purls = false, knits = false;
  for (std::uint32_t r = s.first_row; r < s.end_row; ++r) {
    if (p.rows[r].bind_off) continue;
    auto faces = plain_faces(p, p.rows[r]);
    if (!faces || faces->size() != s.cast_on) return {};
    for (StitchType t : *faces) (t == StitchType::p ? purls : knits) = true;
    rows.push_back({r, std::move(*faces)});
  }
  if (!purls || !knits || s.cast_on > kChartWidest || rows.size() > kChartRows) return {};
  return rows;
}

}  // namespace skein::hand
