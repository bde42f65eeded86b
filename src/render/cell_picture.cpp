#include "render/cell_picture.hpp"

#include <algorithm>
#include <cmath>

#include "render/view.hpp"

namespace skein {
namespace {

struct Box {
  double min_x = 1e300, max_x = -1e300, min_y = 1e300, max_y = -1e300;
  void grow(const ViewPoint& p) {
    min_x = std::min(min_x, p.x), max_x = std::max(max_x, p.x);
    min_y = std::min(min_y, p.y), max_y = std::max(max_y, p.y);
  }
};

bool inside(const std::vector<ViewPoint>& polygon, double x, double y) {
  bool in = false;
  for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
    const ViewPoint &a = polygon[i], &b = polygon[j];
    if ((a.y > y) != (b.y > y) && x < (b.x - a.x) * (y - a.y) / (b.y - a.y) + a.x) in = !in;
  }
  return in;
}

// How squarely a face looks at the viewer: its area on the picture over its area in space
// (a face seen from behind, as inside an open tube, counts as edge-on).
std::uint8_t shade_of(const StitchMesh& mesh, Face f, const std::vector<ViewPoint>& polygon) {
  double picture = 0;
  Vec3 normal{0, 0, 0}, first{};
  std::uint32_t i = 0;
  Vec3 prev{};
  for (Halfedge h : mesh.halfedges(f)) {
    Vec3 p = mesh.position[mesh.tail(h)];
    if (i == 0) first = p;
    if (i >= 2) {
      Vec3 a{prev.x - first.x, prev.y - first.y, prev.z - first.z};
      Vec3 b{p.x - first.x, p.y - first.y, p.z - first.z};
      normal = {normal.x + a.y * b.z - a.z * b.y, normal.y + a.z * b.x - a.x * b.z,
                normal.z + a.x * b.y - a.y * b.x};
    }
    prev = p;
    ++i;
  }
  for (std::size_t k = 0; k < polygon.size(); ++k) {
    const ViewPoint &a = polygon[k], &b = polygon[(k + 1) % polygon.size()];
    picture += a.x * b.y - b.x * a.y;
  }
  double space = std::sqrt(normal.x * normal.x + normal.y * normal.y + normal.z * normal.z);
  if (space <= 0 || picture >= 0) return 2;  // y points down: front faces run anticlockwise
  double facing = -picture / space;
  return facing > 0.7 ? 0 : facing > 0.35 ? 1 : 2;
}

class Grid {
 public:
  Grid(const Box& box, std::uint32_t longest_side) : box_(box) {
    double extent = std::max({box.max_x - box.min_x, box.max_y - box.min_y, 1e-9});
    cell_ = extent / longest_side;
    pic_.columns = cells_across(box.max_x - box.min_x);
    pic_.rows = cells_across(box.max_y - box.min_y);
    std::size_t cells = std::size_t{pic_.columns} * pic_.rows;
    pic_.label.assign(cells, CellPicture::kEmpty);
    pic_.shade.assign(cells, 0);
    depth_.assign(cells, -1e300);
  }

  void face(const std::vector<ViewPoint>& polygon, std::uint32_t label, std::uint8_t shade) {
    Box b;
    double depth = 0;
    for (const ViewPoint& p : polygon) b.grow(p), depth += p.depth / polygon.size();
    std::uint32_t c0 = column(b.min_x), c1 = column(b.max_x), r0 = row(b.min_y), r1 = row(b.max_y);
    bool covered = false;
    for (std::uint32_t r = r0; r <= r1; ++r)
      for (std::uint32_t c = c0; c <= c1; ++c)
        if (inside(polygon, centre_x(c), centre_y(r))) {
          paint(c, r, label, shade, depth);
          covered = true;
        }
    if (!covered) {
      double x = (b.min_x + b.max_x) / 2, y = (b.min_y + b.max_y) / 2;
      paint(column(x), row(y), label, shade, depth);
    }
  }

  // Drawn over the face it lies on, not over what is nearer.
  void point(const ViewPoint& p, std::uint32_t label) {
    std::size_t i = index(column(p.x), row(p.y));
    if (p.depth + 2 * cell_ >= depth_[i]) pic_.label[i] = label, depth_[i] = p.depth;
  }

  CellPicture take() { return std::move(pic_); }

 private:
  std::uint32_t cells_across(double length) const {
    return std::max(1u, static_cast<std::uint32_t>(std::ceil(length / cell_ - 1e-9)));
  }
  static std::uint32_t cell_at(double offset, double cell, std::uint32_t cells) {
    return std::min(static_cast<std::uint32_t>(std::max(0.0, offset / cell)), cells - 1);
  }
  std::uint32_t column(double x) const { return cell_at(x - box_.min_x, cell_, pic_.columns); }
  std::uint32_t row(double y) const { return cell_at(y - box_.min_y, cell_, pic_.rows); }
  double centre_x(std::uint32_t c) const { return box_.min_x + (c + 0.5) * cell_; }
  double centre_y(std::uint32_t r) const { return box_.min_y + (r + 0.5) * cell_; }
  std::size_t index(std::uint32_t c, std::uint32_t r) const {
    return std::size_t{r} * pic_.columns + c;
  }
  void paint(std::uint32_t c, std::uint32_t r, std::uint32_t label, std::uint8_t shade,
             double depth) {
    std::size_t i = index(c, r);
    if (depth > depth_[i]) pic_.label[i] = label, pic_.shade[i] = shade, depth_[i] = depth;
  }

  Box box_;
  double cell_ = 1;
  CellPicture pic_;
  std::vector<double> depth_;
};

}  // namespace

CellPicture picture_cells(const StitchMesh& mesh, std::span<const std::uint32_t> face_label,
                          std::span<const LabelledPoint> points, std::uint32_t longest_side) {
  std::vector<ViewPoint> at(mesh.num_vertices());
  Box box;
  for (std::uint32_t v = 0; v < mesh.num_vertices(); ++v) {
    at[v] = project(mesh.position[Vertex(v)]);
    box.grow(at[v]);
  }
  Grid grid(box, longest_side);
  std::vector<ViewPoint> polygon;
  for (Face f : mesh.faces()) {
    if (face_label[f.index()] == CellPicture::kEmpty) continue;
    polygon.clear();
    for (Halfedge h : mesh.halfedges(f)) polygon.push_back(at[mesh.tail(h).index()]);
    grid.face(polygon, face_label[f.index()], shade_of(mesh, f, polygon));
  }
  for (const LabelledPoint& p : points) grid.point(project(p.at), p.label);
  return grid.take();
}

}  // namespace skein
