#include "labeling/coarse_draft.hpp"

#include <optional>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace skein {
Vec3 sub(Vec3 a, Vec3 b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}

namespace {

double dot(Vec3 a, Vec3 b) {
  return static_cast<double>(a.x) * b.x + static_cast<double>(a.y) * b.y +
         static_cast<double>(a.z) * b.z;
}
Vec3 cross(Vec3 a, Vec3 b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
// `v` without its part along the unit vector `axis`.
Vec3 across(Vec3 v, Vec3 axis) {
  return moved(v, axis, -dot(v, axis));
}

}  // namespace

Vec3 moved(Vec3 p, Vec3 d, double along) {
  auto f = static_cast<float>(along);
  return {p.x + d.x * f, p.y + d.y * f, p.z + d.z * f};
}

Vec3 unit(Vec3 v) {
  auto n = static_cast<float>(std::sqrt(dot(v, v)));
  return n > 0 ? Vec3{v.x / n, v.y / n, v.z / n} : v;
}

std::uint32_t CoarseDraft::vertex(Vec3 p) {
  positions_.push_back(p);
  return static_cast<std::uint32_t>(positions_.size() - 1);
}

std::uint32_t CoarseDraft::vertex(double x, double y, double z) {
  return vertex({static_cast<float>(x), static_cast<float>(y), static_cast<float>(z)});
}

// True when the corners run counter-clockwise seen from outside the axis.
bool CoarseDraft::faces_outward(const std::vector<std::uint32_t>& corners, Vec3 axis_point,
                                Vec3 axis) const {
  Vec3 n, c;
  for (std::size_t i = 0; i < corners.size(); ++i) {  // Newell's normal
    Vec3 a = positions_[corners[i]], b = positions_[corners[(i + 1) % corners.size()]];
    n = {n.x + (a.y - b.y) * (a.z + b.z), n.y + (a.z - b.z) * (a.x + b.x),
         n.z + (a.x - b.x) * (a.y + b.y)};
    c = {c.x + a.x, c.y + a.y, c.z + a.z};
  }
  auto k = static_cast<float>(corners.size());
  Vec3 out = across(sub({c.x / k, c.y / k, c.z / k}, axis_point), unit(axis));
  return dot(n, out) >= 0;
}

void CoarseDraft::add(std::vector<std::uint32_t> corners, const std::string& group) {
  for (std::size_t i = 0; i < corners.size(); ++i)
    directed_.insert({corners[i], corners[(i + 1) % corners.size()]});
  faces_.push_back(std::move(corners));
  auto it = std::find(groups_.begin(), groups_.end(), group);
  face_group_.push_back(static_cast<std::uint32_t>(it - groups_.begin()));
  if (it == groups_.end()) groups_.push_back(group);
}

Ring CoarseDraft::ring(double y, double radius, double cx, double cz,
                       const std::vector<double>& lift, std::uint32_t sides) {
  Ring r;
  for (std::uint32_t j = 0; j < sides; ++j) {
    double a = 2 * std::numbers::pi * j / sides;
    r.push_back(vertex(cx + radius * std::cos(a), y + (lift.empty() ? 0 : lift[j]),
                       cz - radius * std::sin(a)));
  }
  return r;
}

std::uint32_t CoarseDraft::band(const Ring& below, const Ring& above, Vec3 axis_point, Vec3 axis,
                                const std::string& group, const std::vector<std::size_t>& open) {
  auto first = static_cast<std::uint32_t>(faces_.size());
  // The first face, on the regular part of every ring, decides the band's orientation.
  std::optional<bool> flip;
  for (std::size_t j = 0; j < below.size(); ++j) {
    if (std::find(open.begin(), open.end(), j) != open.end()) continue;
    std::size_t k = (j + 1) % below.size();
    std::vector<std::uint32_t> corners{below[j], below[k], above[k], above[j]};
    // A band that starts on faces already drawn (a handle set into a hole) goes round the
    // edges it shares with them the other way; one on nothing faces away from its axis.
    if (!flip && directed_.contains({corners[0], corners[1]})) flip = true;
    if (!flip && directed_.contains({corners[1], corners[0]})) flip = false;
    if (!flip) flip = !faces_outward(corners, axis_point, axis);
    if (*flip) std::reverse(corners.begin(), corners.end());
    add(std::move(corners), group);
  }
  return first;
}

Vec3 CoarseDraft::centre(const Ring& ring) const {
  Vec3 c;
  for (std::uint32_t v : ring) c = moved(c, positions_[v], 1.0 / static_cast<double>(ring.size()));
  return c;
}

Ring CoarseDraft::limb(const Ring& start, Vec3 axis, const std::vector<double>& distances,
                       const std::vector<double>& radii, const std::vector<std::string>& groups) {
  axis = unit(axis);
  Vec3 origin = centre(start);
  // A frame round the axis: the start ring's first vertex fixes angle 0.
  Vec3 e1 = unit(across(sub(at(start[0]), origin), axis)), e2 = cross(axis, e1);
  std::vector<double> angle;
  for (std::uint32_t v : start) {
    Vec3 d = sub(at(v), origin);
    angle.push_back(std::atan2(dot(d, e2), dot(d, e1)));
  }
  Ring below = start;
  for (std::size_t i = 0; i < distances.size(); ++i) {
    Vec3 c = moved(origin, axis, distances[i]);
    Ring above;
    for (double a : angle)
      above.push_back(
          vertex(moved(moved(c, e1, radii[i] * std::cos(a)), e2, radii[i] * std::sin(a))));
    band(below, above, origin, axis, groups[i]);
    below = std::move(above);
  }
  return below;
}

CoarseMesh CoarseDraft::finish(const std::string& name) const {
  CoarseMesh m = build_coarse_mesh(name, positions_, faces_);
  m.groups = groups_;
  m.group = face_group_;
  return m;
}

std::pair<Ring, Ring> fork(CoarseDraft& draft, const Ring& ring, std::uint32_t first,
                           std::uint32_t last, Vec3 crotch) {
  std::uint32_t x = draft.vertex(crotch);
  auto n = static_cast<std::uint32_t>(ring.size());
  Ring a, b;
  for (std::uint32_t i = first;; i = (i + 1) % n) {
    a.push_back(ring[i]);
    if (i == last) break;
  }
  for (std::uint32_t i = last;; i = (i + 1) % n) {
    b.push_back(ring[i]);
    if (i == first) break;
  }
  a.push_back(x);
  b.push_back(x);
  return {a, b};
}

}  // namespace skein
