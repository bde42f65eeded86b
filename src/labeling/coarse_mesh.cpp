#include "labeling/coarse_mesh.hpp"

#define TINYOBJLOADER_IMPLEMENTATION
#include <fmt/format.h>
#include <tiny_obj_loader.h>

#include <charconv>
#include <cmath>
#include <ostream>
#include <string_view>

#include "common/atomic_file.hpp"
#include "common/error.hpp"

namespace skein {

CoarseHalfedge CoarseMesh::next(CoarseHalfedge h) const {
  std::uint32_t f = face(h).index(), n = h.index() + 1;
  return CoarseHalfedge(n == face_first_[f + 1] ? face_first_[f] : n);
}

CoarseHalfedge CoarseMesh::prev(CoarseHalfedge h) const {
  std::uint32_t f = face(h).index();
  return CoarseHalfedge(h.index() == face_first_[f] ? face_first_[f + 1] - 1 : h.index() - 1);
}

CoarseHalfedge CoarseMesh::find_halfedge(CoarseVertex a, CoarseVertex b) const {
  if (a.index() >= num_vertices() || b.index() >= num_vertices()) return {};
  for (CoarseHalfedge h : outgoing_[a.index()])
    if (head(h) == b) return h;
  return {};
}

Vec3 CoarseMesh::centroid(CoarseFace f) const {
  Vec3 sum;
  for (CoarseHalfedge h : halfedges(f)) {
    Vec3 p = at(tail(h));
    sum = {sum.x + p.x, sum.y + p.y, sum.z + p.z};
  }
  float n = static_cast<float>(degree(f));
  return {sum.x / n, sum.y / n, sum.z / n};
}

float CoarseMesh::length(CoarseHalfedge h) const {
  Vec3 a = at(tail(h)), b = at(head(h));
  return std::hypot(b.x - a.x, b.y - a.y, b.z - a.z);
}

std::string format_point(Vec3 p) {
  return fmt::format("({:.3g}, {:.3g}, {:.3g})", p.x, p.y, p.z);
}

std::string CoarseMesh::describe(CoarseHalfedge h) const {
  return fmt::format("edge {}-{}", tail(h).index() + 1, head(h).index() + 1);
}

std::string CoarseMesh::describe(CoarseFace f) const {
  return fmt::format("face {} at {}", f.index() + 1, format_point(centroid(f)));
}

CoarseMesh build_coarse_mesh(std::string source, std::vector<Vec3> positions,
                             const std::vector<std::vector<std::uint32_t>>& faces) {
  CoarseMesh m;
  m.source = std::move(source);
  m.position = std::move(positions);
  m.outgoing_.resize(m.num_vertices());
  for (const auto& corners : faces) {
    CoarseFace f(m.num_faces());
    if (corners.size() < 3)
      throw MeshError(fmt::format("{}: face {} has {} corners; expected at least 3", m.source,
                                  f.index() + 1, corners.size()));
    for (std::uint32_t v : corners) {
      if (v >= m.num_vertices())
        throw MeshError(fmt::format("{}: face {} uses vertex {}, but there are only {}", m.source,
                                    f.index() + 1, v + 1, m.num_vertices()));
      m.outgoing_[v].push_back(CoarseHalfedge(m.num_halfedges()));
      m.tail_.push_back(CoarseVertex(v));
      m.face_.push_back(f);
    }
    m.face_first_.push_back(m.num_halfedges());
  }
  m.twin_.assign(m.num_halfedges(), CoarseHalfedge());
  for (CoarseHalfedge h : m.halfedges()) {
    CoarseVertex a = m.tail(h), b = m.head(h);
    if (a == b)
      throw MeshError(fmt::format("{}: face {} repeats vertex {}", m.source, m.face(h).index() + 1,
                                  a.index() + 1));
    for (CoarseHalfedge o : m.outgoing_[a.index()])
      if (o != h && m.head(o) == b)
        throw MeshError(fmt::format(
            "{}: the edge {}-{} is used twice in the same direction (faces {} and {}); expected "
            "neighbouring faces with the same orientation (counter-clockwise)",
            m.source, a.index() + 1, b.index() + 1, m.face(h).index() + 1, m.face(o).index() + 1));
    m.twin_[h.index()] = m.find_halfedge(b, a);
  }
  m.group.assign(m.num_faces(), 0);
  m.groups = {""};
  return m;
}

namespace {

std::string trimmed(std::string s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.pop_back();
  return s;
}

// tinyobjloader reads a coordinate it cannot parse as 0, so `v nan 0 0`, `v inf 0 0` or
// `v x 0 0` would silently become the origin: every `v` line is checked here first.
void check_vertex_lines(std::string_view text, const std::string& name) {
  std::size_t line_no = 0;
  for (std::size_t start = 0; start < text.size(); ++line_no) {
    std::size_t end = std::min(text.find('\n', start), text.size());
    std::string_view line = text.substr(start, end - start);
    start = end + 1;
    std::string_view rest = line.substr(std::min(line.size(), line.find_first_not_of(" \t")));
    if (!rest.starts_with("v ") && !rest.starts_with("v\t")) continue;
    rest.remove_prefix(2);
    for (int axis = 0; axis < 3; ++axis) {
      std::size_t from = rest.find_first_not_of(" \t\r");
      std::size_t to = rest.find_first_of(" \t\r", from);
      std::string_view word = from == std::string_view::npos ? "" : rest.substr(from, to - from);
      double value = 0;
      auto [used, ec] = std::from_chars(word.data(), word.data() + word.size(), value);
      if (word.empty() || ec != std::errc() || used != word.data() + word.size() ||
          !std::isfinite(value) || std::abs(value) > kMaxCoordinate)
        throw ParseError(name, line_no + 1, std::string(trimmed(std::string(line))),
                         fmt::format("expected 3 coordinates (finite numbers of at most {:g} in "
                                     "magnitude) after 'v', found '{}'",
                                     kMaxCoordinate, word));
      rest = to == std::string_view::npos ? "" : rest.substr(to);
    }
  }
}

// Two corners of a face at one point give the stitches between them no length: no gauge can
// say how many there are.
void check_edge_lengths(const CoarseMesh& mesh) {
  for (CoarseHalfedge h : mesh.halfedges())
    if (!(mesh.length(h) > 0))
      throw MeshError(fmt::format(
          "{}: {} of face {} has no length (vertices {} and {} are at {}); "
          "expected the corners of a face at different points",
          mesh.source, mesh.describe(h), mesh.face(h).index() + 1, mesh.tail(h).index() + 1,
          mesh.head(h).index() + 1, format_point(mesh.at(mesh.tail(h)))));
}

}  // namespace

CoarseMesh parse_coarse_mesh(const std::string& text, const std::string& name) {
  check_vertex_lines(text, name);
  tinyobj::ObjReaderConfig config;
  config.triangulate = false;
  config.vertex_color = false;
  tinyobj::ObjReader reader;
  if (!reader.ParseFromString(text, "", config))
    throw Error(fmt::format("{}: {}", name,
                            reader.Error().empty() ? "cannot read" : trimmed(reader.Error())));
  const auto& v = reader.GetAttrib().vertices;
  std::vector<Vec3> positions;
  for (std::size_t i = 0; i + 2 < v.size(); i += 3) positions.push_back({v[i], v[i + 1], v[i + 2]});
  std::vector<std::vector<std::uint32_t>> faces;
  std::vector<std::string> names;
  std::vector<std::uint32_t> face_group;
  for (const tinyobj::shape_t& shape : reader.GetShapes()) {
    std::size_t at = 0;
    for (unsigned char n : shape.mesh.num_face_vertices) {
      auto& corners = faces.emplace_back();
      for (unsigned char i = 0; i < n; ++i)
        corners.push_back(static_cast<std::uint32_t>(shape.mesh.indices[at + i].vertex_index));
      at += n;
      face_group.push_back(static_cast<std::uint32_t>(names.size()));
    }
    names.push_back(shape.name);
  }
  CoarseMesh mesh = build_coarse_mesh(name, std::move(positions), faces);
  check_edge_lengths(mesh);
  if (!names.empty()) {
    mesh.groups = std::move(names);
    mesh.group = std::move(face_group);
  }
  return mesh;
}

CoarseMesh read_coarse_mesh(const std::string& path) {
  return parse_coarse_mesh(read_file(path), path);
}

void write_coarse_mesh(const CoarseMesh& mesh, std::ostream& out) {
  for (Vec3 p : mesh.position) out << fmt::format("v {} {} {}\n", p.x, p.y, p.z);
  std::uint32_t current = 0;
  for (CoarseFace f : mesh.faces()) {
    std::uint32_t g = mesh.group[f.index()];
    if ((f.index() == 0 || g != current) && !mesh.groups[g].empty())
      out << "g " << mesh.groups[g] << '\n';
    current = g;
    out << 'f';
    for (CoarseHalfedge h : mesh.halfedges(f)) out << ' ' << mesh.tail(h).index() + 1;
    out << '\n';
  }
}

}  // namespace skein
