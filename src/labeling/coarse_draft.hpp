// Building coarse meshes out of rings (what `skein new` and the random-garment tests make):
// tubes along any axis, their faces turned outward, and forks where one ring parts into two
// (a hand and its thumb, a body and its legs). Sizes are in centimetres.
#pragma once

#include <cstdint>
#include <set>
#include <string>
#include <vector>

#include "labeling/coarse_mesh.hpp"

namespace skein {

using Ring = std::vector<std::uint32_t>;  // vertex indices, in order round the tube

// The point `along` units from `p` in direction `d`.
Vec3 moved(Vec3 p, Vec3 d, double along);
Vec3 sub(Vec3 a, Vec3 b);  // a - b
Vec3 unit(Vec3 v);

// Collects vertices and faces, each face turned so that its normal points away from its tube's
// axis, and the OBJ group of each face.
class CoarseDraft {
 public:
  std::uint32_t vertex(Vec3 p);
  std::uint32_t vertex(double x, double y, double z);
  Vec3 at(std::uint32_t v) const { return positions_[v]; }
  void add(std::vector<std::uint32_t> corners, const std::string& group);
  // A ring of `sides` vertices round the vertical axis through (cx, cz); lift[j] raises
  // vertex j.
  Ring ring(double y, double radius, double cx = 0, double cz = 0,
            const std::vector<double>& lift = {}, std::uint32_t sides = 8);
  // Faces between two rings of equal size, outward from the axis through `axis_point` along
  // `axis`, but for those in `open` (face j joins vertices j and j + 1 of each ring), left as
  // holes. Returns the first face's index.
  std::uint32_t band(const Ring& below, const Ring& above, Vec3 axis_point, Vec3 axis,
                     const std::string& group, const std::vector<std::size_t>& open = {});
  // A tube going on from `start` along `axis`: a ring at each of `distances` (from the centre
  // of `start`) with the matching radius, each vertex at the angle round the axis of the start
  // ring's vertex it lies above, so that the faces do not twist. Returns the last ring.
  Ring limb(const Ring& start, Vec3 axis, const std::vector<double>& distances,
            const std::vector<double>& radii, const std::vector<std::string>& groups);
  Vec3 centre(const Ring& ring) const;
  std::uint32_t faces() const { return static_cast<std::uint32_t>(faces_.size()); }
  CoarseMesh finish(const std::string& name) const;

 private:
  bool faces_outward(const std::vector<std::uint32_t>& corners, Vec3 axis_point, Vec3 axis) const;

  std::vector<Vec3> positions_;
  std::vector<std::vector<std::uint32_t>> faces_;
  std::vector<std::string> groups_;
  std::vector<std::uint32_t> face_group_;
  std::set<std::pair<std::uint32_t, std::uint32_t>> directed_;  // every face's edges, in order
};

// Where a ring parts into two (a fork): the vertices from `first` to `last` (indices into the
// ring, going round) border one branch, those from `last` round to `first` the other, and a new
// vertex at `crotch` closes both. Returns {branch from first to last, the other}, each
// ending with the crotch vertex; the edges at the crotch border both branches.
std::pair<Ring, Ring> fork(CoarseDraft& draft, const Ring& ring, std::uint32_t first,
                           std::uint32_t last, Vec3 crotch);

}  // namespace skein
