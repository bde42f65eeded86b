#include "render/svg.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <ostream>

#include "common/atomic_file.hpp"
#include "labeling/stitch_generation.hpp"
#include "mesh/obj_format.hpp"
#include "render/view.hpp"

namespace skein {
namespace {

using Point = ViewPoint;

struct Colour {
  const char* fill;
  const char* name;
};
// The paper's colours for the structures, quiet ones for plain stitches.
constexpr Colour kShortRow{"#e6194b", "short-row end"}, kShift{"#3cb44b", "beside a shift-path"},
    kSplit{"#ffe119", "splitting mismatch"}, kJoin{"#4363d8", "joining mismatch"},
    kExpanding{"#bfef45", "expanding perpendicular"},
    kContracting{"#911eb4", "contracting perpendicular"}, kCastOn{"#c8c8c8", "cast-on / bind-off"},
    kShaping{"#f4c28a", "increase / decrease"}, kPurl{"#d9cbb0", "purl"}, kKnit{"#f7f2e8", "knit"};

class Canvas {
 public:
  // Returns the depth the face is drawn at, for what is drawn on it.
  double polygon(const std::vector<Point>& pts, const char* fill, bool back) {
    std::string d;
    for (const Point& p : pts) d += fmt::format("{:.2f},{:.2f} ", p.x, p.y);
    double depth = 0;
    for (const Point& p : pts) depth += p.depth / pts.size();
    items_.push_back({depth, fmt::format(R"(<polygon points="{}" fill="{}"{}/>)", d, fill,
                                         back ? R"( opacity="0.35")" : "")});
    grow(pts);
    return depth;
  }
  void arrow(Point a, Point b, double depth) {
    items_.push_back(
        {depth + 1e-6,
         fmt::format(R"(<line x1="{:.2f}" y1="{:.2f}" x2="{:.2f}" y2="{:.2f}" class="a"/>)", a.x,
                     a.y, b.x, b.y)});
  }
  void text(Point p, const std::string& s, double depth) {
    items_.push_back(
        {depth + 2e-6, fmt::format(R"(<text x="{:.2f}" y="{:.2f}">{}</text>)", p.x, p.y, s)});
  }
  void write(std::ostream& out, const std::string& title, const std::vector<Colour>& legend,
             double unit) const {
    double pad = unit * 3, h = max_y_ - min_y_ + 2 * pad;
    double w = std::max(max_x_ - min_x_ + 2 * pad, unit * 0.7 * static_cast<double>(title.size()));
    double legend_h = unit * 1.6 * (legend.size() + 2);
    out << fmt::format(
        R"(<svg xmlns="http://www.w3.org/2000/svg" viewBox="{:.2f} {:.2f} {:.2f} {:.2f}" width="{:.0f}" height="{:.0f}">)"
        "\n",
        min_x_ - pad, min_y_ - pad - legend_h, w, h + legend_h, 900.0, 900.0 * (h + legend_h) / w);
    out << fmt::format(
        "<style>polygon{{stroke:#555;stroke-width:{0:.3f}}} .a{{stroke:#333;stroke-width:{0:.3f};"
        "marker-end:url(#h)}} text{{font:{1:.2f}px sans-serif;fill:#222}}</style>\n"
        R"(<defs><marker id="h" viewBox="0 0 10 10" refX="8" refY="5" markerWidth="4" markerHeight="4" orient="auto"><path d="M0,0L10,5L0,10z" fill="#333"/></marker></defs>)"
        "\n",
        unit * 0.06, unit * 1.2);
    double x = min_x_ - pad, y = min_y_ - pad - legend_h + unit * 1.4;
    out << fmt::format(R"(<text x="{:.2f}" y="{:.2f}">{}</text>)", x, y, title) << '\n';
    for (const Colour& c : legend) {
      y += unit * 1.6;
      out << fmt::format(
                 R"(<rect x="{:.2f}" y="{:.2f}" width="{:.2f}" height="{:.2f}" fill="{}" stroke="#555" stroke-width="{:.3f}"/><text x="{:.2f}" y="{:.2f}">{}</text>)",
                 x, y - unit, unit * 1.2, unit * 1.2, c.fill, unit * 0.06, x + unit * 1.8, y,
                 c.name)
          << '\n';
    }
    std::vector<const std::pair<double, std::string>*> order;
    for (const auto& item : items_) order.push_back(&item);
    std::stable_sort(order.begin(), order.end(),
                     [](auto a, auto b) { return a->first < b->first; });
    for (const auto* item : order) out << item->second << '\n';
    out << "</svg>\n";
  }

 private:
  void grow(const std::vector<Point>& pts) {
    for (const Point& p : pts) {
      min_x_ = std::min(min_x_, p.x), max_x_ = std::max(max_x_, p.x);
      min_y_ = std::min(min_y_, p.y), max_y_ = std::max(max_y_, p.y);
    }
  }
  std::vector<std::pair<double, std::string>> items_;
  double min_x_ = 1e300, max_x_ = -1e300, min_y_ = 1e300, max_y_ = -1e300;
};

Point mid(Point a, Point b, double t = 0.5) {
  return {a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t, a.depth};
}

// Seen from behind when its corners run clockwise on the picture.
bool facing_away(const std::vector<Point>& pts) {
  double area = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const Point &a = pts[i], &b = pts[(i + 1) % pts.size()];
    area += a.x * b.y - b.x * a.y;
  }
  return area > 0;  // y points down on the picture
}

Colour stitch_colour(const StitchMesh& m, Face f) {
  const StitchTypeInfo& t = info(m.stitch[f]);
  if (t.wales_adjacent) return kShortRow;
  for (Halfedge h : m.halfedges(f)) {
    switch (m.kind(m.edge(h))) {
      case EdgeKind::split:
        return kSplit;
      case EdgeKind::join:
        return kJoin;
      case EdgeKind::expanding_perpendicular:
        return kExpanding;
      case EdgeKind::contracting_perpendicular:
        return kContracting;
      default:
        break;
    }
    if (m.shift_path[m.edge(h)]) return kShift;
  }
  if (m.stitch[f] == StitchType::co || m.stitch[f] == StitchType::bo) return kCastOn;
  if (t.bottom_edges != t.top_edges) return kShaping;
  return m.stitch[f] == StitchType::p ? kPurl : kKnit;
}

double typical_edge(const std::vector<std::vector<Point>>& faces) {
  std::vector<double> lengths;
  for (std::size_t i = 0; i < faces.size(); i += std::max<std::size_t>(1, faces.size() / 500)) {
    const auto& f = faces[i];
    lengths.push_back(std::hypot(f[1].x - f[0].x, f[1].y - f[0].y));
  }
  std::nth_element(lengths.begin(), lengths.begin() + lengths.size() / 2, lengths.end());
  return std::max(lengths[lengths.size() / 2], 1e-6);
}

}  // namespace

void render_stitch_mesh_svg(const StitchMesh& m, const std::string& title, std::ostream& out) {
  std::vector<std::vector<Point>> faces;
  for (Face f : m.faces()) {
    auto& pts = faces.emplace_back();
    for (Halfedge h : m.halfedges(f)) pts.push_back(project(m.position[m.tail(h)]));
  }
  double unit = typical_edge(faces);
  Canvas canvas;
  std::uint32_t rows = 0;
  for (Face f : m.faces()) rows = std::max(rows, m.row[f] + 1);
  std::uint32_t every = rows > 80 ? 10 : rows > 30 ? 5 : 1;
  std::vector<Face> leftmost(rows);
  for (Face f : m.faces()) {
    const auto& pts = faces[f.index()];
    bool back = facing_away(pts);
    double depth = canvas.polygon(pts, stitch_colour(m, f).fill, back);
    Halfedge in = m.wale_in(f), out_h = m.wale_out(f);
    if (!back && in.valid() && out_h.valid()) {
      Point a = mid(project(m.position[m.tail(in)]), project(m.position[m.head(in)]));
      Point b = mid(project(m.position[m.tail(out_h)]), project(m.position[m.head(out_h)]));
      canvas.arrow(mid(a, b, 0.25), mid(a, b, 0.75), depth);
    }
    Face& l = leftmost[m.row[f]];
    if (!back && (!l.valid() || pts[0].x < faces[l.index()][0].x)) l = f;
  }
  for (std::uint32_t r = 0; r < rows; r += every) {
    if (!leftmost[r].valid()) continue;
    const auto& pts = faces[leftmost[r].index()];
    Point p = pts[0];
    for (const Point& q : pts) p = q.x < p.x ? q : p;
    canvas.text({p.x - unit * 2.4, p.y, p.depth}, std::to_string(r + 1), 1e9);
  }
  canvas.write(
      out, title + " (row numbers in knitting order)",
      {kShift, kSplit, kJoin, kShortRow, kExpanding, kContracting, kCastOn, kShaping, kPurl, kKnit},
      unit);
}

void render_coarse_mesh_svg(const CoarseMesh& m, const Labeling& labeling, const std::string& title,
                            std::ostream& out) {
  std::vector<std::vector<Point>> faces;
  for (CoarseFace f : m.faces()) {
    auto& pts = faces.emplace_back();
    for (CoarseHalfedge h : m.halfedges(f)) pts.push_back(project(m.at(m.tail(h))));
  }
  double unit = typical_edge(faces) / 6;
  Canvas canvas;
  auto edge_mid = [&](CoarseHalfedge h) {
    return mid(project(m.at(m.tail(h))), project(m.at(m.head(h))));
  };
  for (CoarseFace f : m.faces()) {
    const auto& pts = faces[f.index()];
    bool back = facing_away(pts);
    double depth =
        canvas.polygon(pts, labeling.short_row[f.index()] ? kShortRow.fill : kKnit.fill, back);
    if (back) continue;
    CoarseHalfedge b = labeling.find(m, f, CoarseRole::bottom),
                   t = labeling.find(m, f, CoarseRole::top),
                   l = labeling.find(m, f, CoarseRole::left),
                   r = labeling.find(m, f, CoarseRole::right);
    if (b.valid() && t.valid())
      canvas.arrow(mid(edge_mid(b), edge_mid(t), 0.2), mid(edge_mid(b), edge_mid(t), 0.8), depth);
    Point c = mid(edge_mid(b), edge_mid(t));
    if (l.valid() && r.valid())
      canvas.arrow(mid(edge_mid(l), edge_mid(r), 0.3), mid(edge_mid(l), edge_mid(r), 0.7), depth);
    canvas.text(c, fmt::format("{}", f.index() + 1), depth);
  }
  canvas.write(out, title + " (arrows: wale up, course left to right; numbers: faces)",
               {kShortRow, {kKnit.fill, "quad"}}, unit);
}

std::string render_file(const std::string& input, bool coarse, std::ostream& out) {
  if (is_project_file(input)) {
    Project project = read_project(input);
    CoarseMesh mesh = read_coarse_mesh(project.mesh);
    Labeling labeling = label_coarse_mesh(mesh, project);
    if (coarse) {
      render_coarse_mesh_svg(mesh, labeling, input, out);
      return fmt::format("the labelled coarse mesh of {}, {} faces", input, mesh.num_faces());
    }
    GeneratedStitchMesh g = generate_stitch_mesh(mesh, labeling, project);
    render_stitch_mesh_svg(g.mesh, input, out);
    return fmt::format("the stitch mesh of {}, {} stitches", input, g.mesh.num_faces());
  }
  std::string text = read_file(input);
  if (text.find("#~skein-stitch-mesh") != std::string::npos) {
    StitchMesh mesh = parse_stitch_mesh(text, input);
    render_stitch_mesh_svg(mesh, input, out);
    return fmt::format("the stitch mesh {}, {} stitches", input, mesh.num_faces());
  }
  Project project;
  project.file = input;
  project.mesh = input;
  CoarseMesh mesh = read_coarse_mesh(input);
  render_coarse_mesh_svg(mesh, label_coarse_mesh(mesh, project), input, out);
  return fmt::format("the coarse mesh {}, labelled from its lowest boundary, {} faces", input,
                     mesh.num_faces());
}

}  // namespace skein
