#include "labeling/shapes.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <functional>
#include <numbers>

#include "common/atomic_file.hpp"
#include "common/error.hpp"
#include "labeling/coarse_draft.hpp"

namespace skein {
namespace {

constexpr std::uint32_t kSides = 8;  // coarse faces around a body tube
constexpr double kPi = std::numbers::pi;

// The radius of the kSides-gon whose perimeter is `circumference`: the fabric runs along the
// polygon's edges, not the circle, so a circle's radius would knit it 2.6% too small.
double radius_for(double circumference) {
  return circumference / (2 * kSides * std::sin(kPi / kSides));
}

constexpr Vec3 kUp{0, 1, 0};

std::uint32_t pieces(double length, double piece) {
  return std::max<std::uint32_t>(1, static_cast<std::uint32_t>(std::lround(length / piece)));
}

std::string project_text(const std::string& name, const std::string& what,
                         const std::string& extra) {
  return fmt::format(
      "# {}: made by `skein new`. Every field is documented in docs/formats.md.\n"
      "mesh: {}.obj\n"
      "unit: cm\n"
      "gauge: {{stitches: 22, rows: 30}}   # per 10 cm\n{}",
      what, name, extra);
}

// Rings up the y axis at the given heights and radii; returns the first ring.
std::vector<std::uint32_t> tube(CoarseDraft& d, const std::vector<double>& heights,
                                const std::vector<double>& radii, const std::string& group,
                                std::vector<std::uint32_t> below = {}) {
  if (below.empty()) below = d.ring(heights[0], radii[0]);
  std::vector<std::uint32_t> first = below;
  for (std::size_t i = 1; i < heights.size(); ++i) {
    std::vector<std::uint32_t> above = d.ring(heights[i], radii[i]);
    d.band(below, above, {0, 0, 0}, kUp, group);
    below = std::move(above);
  }
  return first;
}

Shape sheet(const ShapeSize& s, const std::string& name) {
  double w = s.width > 0 ? s.width : 20, l = s.length > 0 ? s.length : 20;
  std::uint32_t cols = pieces(w, 10), rows = pieces(l, 10);
  CoarseDraft d;
  std::vector<std::uint32_t> v;
  for (std::uint32_t r = 0; r <= rows; ++r)
    for (std::uint32_t c = 0; c <= cols; ++c)
      v.push_back(d.vertex(w * c / cols - w / 2, l * r / rows, 0));
  for (std::uint32_t r = 0; r < rows; ++r)
    for (std::uint32_t c = 0; c < cols; ++c) {
      std::uint32_t a = r * (cols + 1) + c;
      d.add({v[a], v[a + 1], v[a + cols + 2], v[a + cols + 1]}, r == 0 ? "border" : "body");
    }
  return {d.finish(name + ".obj"), project_text(name, fmt::format("a flat sheet {} x {} cm", w, l),
                                                "patterns: {border: k2p2}\n")};
}

Shape straight_tube(const ShapeSize& s, const std::string& name) {
  double c = s.circumference > 0 ? s.circumference : 40, l = s.length > 0 ? s.length : 20;
  std::uint32_t n = pieces(l, 5);
  std::vector<double> heights, radii;
  for (std::uint32_t i = 0; i <= n; ++i) {
    heights.push_back(l * i / n);
    radii.push_back(radius_for(c));
  }
  CoarseDraft d;
  tube(d, heights, radii, "body");
  return {d.finish(name + ".obj"),
          project_text(name, fmt::format("a tube {} cm round, {} cm long", c, l), "")};
}

Shape hat(const ShapeSize& s, const std::string& name) {
  double c = s.circumference > 0 ? s.circumference : 54, l = s.length > 0 ? s.length : 21;
  double r = radius_for(c), body = l * 0.6, rib = std::min(4.0, body / 2);  // a shallow hat too
  std::vector<double> heights{0, rib}, radii{r, r};
  for (double h = rib + 5; h < body; h += 5) heights.push_back(h), radii.push_back(r);
  const double crown[] = {0.85, 0.6, 0.35, 0.15};  // crown rings, fractions of the radius
  for (std::size_t i = 0; i < std::size(crown); ++i) {
    heights.push_back(body + (l - body) * (i + 1) / std::size(crown));
    radii.push_back(r * crown[i]);
  }
  CoarseDraft d;
  std::vector<std::uint32_t> brim = d.ring(heights[0], radii[0]),
                             top = d.ring(heights[1], radii[1]);
  d.band(brim, top, {0, 0, 0}, kUp, "brim");
  tube(d, std::vector<double>(heights.begin() + 1, heights.end()),
       std::vector<double>(radii.begin() + 1, radii.end()), "crown", top);
  return {d.finish(name + ".obj"),
          project_text(name, fmt::format("a hat {} cm round, {} cm deep, crown decreases", c, l),
                       "patterns: {brim: k2p2}\n")};
}

// A tube with a short-row heel: the heel band's top ring is the leg's ring turned about the
// front (the back rises by the heel height), so the band is taller at the back; its two faces
// where the height changes are short-row quads. The foot and toe follow the turned axis.
Shape sock(const ShapeSize& s, const std::string& name) {
  double c = s.circumference > 0 ? s.circumference : 20, leg = s.length > 0 ? s.length : 15;
  double r = radius_for(c), band = 1.5, foot = c;
  double sin_a = std::min(0.95, 0.3 * c / (2 * r)), cos_a = std::sqrt(1 - sin_a * sin_a);
  CoarseDraft d;
  const double cuff = std::min(3.0, leg / 2);  // a short leg still rises above its cuff
  std::vector<std::uint32_t> below = d.ring(0, r), top = d.ring(cuff, r);
  d.band(below, top, {0, 0, 0}, kUp, "cuff");
  below = top;
  for (double h = cuff + 4;; h += 4) {
    std::vector<std::uint32_t> above = d.ring(std::min(h, leg), r);
    d.band(below, above, {0, 0, 0}, kUp, "leg");
    below = std::move(above);
    if (h >= leg) break;
  }
  // A ring of the foot: the leg's ring turned about the front (x = r) and moved `along` the
  // foot's axis (sin a, cos a, 0), scaled by `scale`.
  auto foot_ring = [&](double along, double scale) {
    std::vector<std::uint32_t> ring;
    for (std::uint32_t j = 0; j < kSides; ++j) {
      double a = 2 * kPi * j / kSides, x = r * std::cos(a) * scale, z = -r * std::sin(a) * scale;
      double cx = r - r * scale;  // scaled rings stay centred on the axis
      ring.push_back(d.vertex(r + (x + cx - r) * cos_a + along * sin_a,
                              leg + band - (x + cx - r) * sin_a + along * cos_a, z));
    }
    return ring;
  };
  Vec3 foot_axis{static_cast<float>(sin_a), static_cast<float>(cos_a), 0};
  Vec3 foot_point{static_cast<float>(r - r * cos_a), static_cast<float>(leg + band + r * sin_a), 0};
  std::vector<std::uint32_t> heel_top = foot_ring(0, 1);
  std::uint32_t first = d.band(below, heel_top, {0, 0, 0}, kUp, "heel");
  below = heel_top;
  const double toe[] = {1, 1, 1, 0.7, 0.35};
  for (std::size_t i = 0; i < std::size(toe); ++i) {
    std::vector<std::uint32_t> above = foot_ring(foot * (i + 1) / std::size(toe), toe[i]);
    d.band(below, above, foot_point, foot_axis, i + 2 < std::size(toe) ? "foot" : "toe");
    below = std::move(above);
  }
  return {d.finish(name + ".obj"),
          project_text(name, fmt::format("a sock {} cm round, leg {} cm, short-row heel", c, leg),
                       fmt::format("patterns: {{cuff: k2p2}}\n"
                                   "short_rows:\n  method: sr4\n  faces: [{}, {}]   # where the "
                                   "heel band grows taller towards the back\n",
                                   first + 2, first + 7))};
}

// Body and two sleeves knit in the round from the hem and cuffs, joined at the yoke (the
// paper's sweater: three yarn pieces). Each armpit stays open, bound off on both sides.
Shape sweater(const ShapeSize& s, const std::string& name) {
  double c = s.circumference > 0 ? s.circumference : 90, body = s.length > 0 ? s.length : 36;
  double r = radius_for(c), sleeve_r = r * 0.35, sleeve = 40, yoke = 18, dip = sleeve_r * 0.5;
  CoarseDraft d;
  const double hem = std::min(5.0, body / 2);  // a short body still rises above its hem
  std::vector<std::uint32_t> bottom = d.ring(0, r), below = d.ring(hem, r);
  d.band(bottom, below, {0, 0, 0}, kUp, "hem");
  for (double h = hem + 10;; h += 10) {
    std::vector<std::uint32_t> above = d.ring(std::min(h, body), r);
    d.band(below, above, {0, 0, 0}, kUp, "body");
    below = std::move(above);
    if (h >= body) break;
  }
  // Sleeves along +x and -x, knit from the cuff inwards: rings of 4 (top, front, bottom,
  // back); the innermost ring shares the body's front and back vertices next to the armpit.
  // The sleeve's last ring stands a sleeve radius out from the body's side (the cuff stays
  // `sleeve` out), so the band from it to the armhole runs inwards all round (from x = r, the
  // armhole's underside at 1.1 r lay beyond it: the band folded back over the one before,
  // and yarn laid there crossed).
  auto add_sleeve = [&](int sign, std::uint32_t front, std::uint32_t back,
                        std::uint32_t& top_vertex, std::uint32_t& cuff_vertex) {
    Vec3 axis_point{0, static_cast<float>(body + dip), 0};
    Vec3 axis{1, 0, 0};
    std::vector<std::vector<std::uint32_t>> rings;
    for (int k = 0; k <= 4; ++k) {
      double x = sign * (r + sleeve_r + (sleeve - sleeve_r) * (1 - k / 4.0));
      double rr = k == 0 ? sleeve_r * 0.8 : sleeve_r;
      rings.push_back({d.vertex(x, body + dip + rr, 0), d.vertex(x, body + dip, -rr),
                       d.vertex(x, body + dip - rr, 0), d.vertex(x, body + dip, rr)});
    }
    double x = sign * r * 0.95;
    std::vector<std::uint32_t> inner{d.vertex(x, body + dip + sleeve_r, 0), front,
                                     d.vertex(sign * r * 1.1, body - dip, 0), back};
    for (int k = 0; k < 5; ++k)
      d.band(rings[k], k < 4 ? rings[k + 1] : inner, axis_point, axis, k == 0 ? "cuff" : "sleeve");
    top_vertex = inner[0];
    cuff_vertex = rings[0][0];
  };
  std::uint32_t right_top, left_top, right_cuff, left_cuff;
  add_sleeve(+1, below[1], below[7], right_top, right_cuff);
  add_sleeve(-1, below[3], below[5], left_top, left_cuff);
  std::vector<std::uint32_t> yoke_ring{right_top, below[1], below[2], below[3],
                                       left_top,  below[5], below[6], below[7]};
  const double shrink[] = {0.85, 0.7, 0.55};
  for (std::size_t i = 0; i < std::size(shrink); ++i) {
    std::vector<std::uint32_t> above =
        d.ring(body + dip + yoke * (i + 1) / std::size(shrink), r * shrink[i]);
    d.band(yoke_ring, above, {0, 0, 0}, kUp, i + 1 < std::size(shrink) ? "yoke" : "neck");
    yoke_ring = std::move(above);
  }
  return {
      d.finish(name + ".obj"),
      project_text(name,
                   fmt::format("a sweater {} cm round, body {} cm, sleeves {} cm", c, body, sleeve),
                   fmt::format("start:                 # the hem, then both cuffs\n"
                               "  - vertex: {}\n  - vertex: {}\n  - vertex: {}\n"
                               "patterns: {{hem: k2p2, cuff: k2p2, neck: k2p2}}\n",
                               bottom[2] + 1, right_cuff + 1, left_cuff + 1))};
}

// Distances 0 < d <= length in steps of about `step`, for a limb's rings.
std::vector<double> steps(double length, double step) {
  std::vector<double> d;
  std::uint32_t n = pieces(length, step);
  for (std::uint32_t i = 1; i <= n; ++i) d.push_back(length * i / n);
  return d;
}

// A limb's rings: `straight` of them at `radius`, then a top narrowing by `crown` (fractions of
// the radius) over `crown_length`, each ring's group.
struct LimbRings {
  std::vector<double> distances, radii;
  std::vector<std::string> groups;
  void straight(double from, double length, double step, double radius, const std::string& group) {
    for (double d : steps(length, step)) {
      distances.push_back(from + d);
      radii.push_back(radius);
      groups.push_back(group);
    }
  }
  void crown(double from, double length, std::initializer_list<double> fractions, double radius,
             const std::string& group) {
    std::size_t i = 0;
    for (double f : fractions) {
      distances.push_back(from + length * static_cast<double>(++i) / fractions.size());
      radii.push_back(radius * f);
      groups.push_back(group);
    }
  }
  double end() const { return distances.empty() ? 0 : distances.back(); }
};

// A mitten's or glove's cuff and palm, knit from the cuff up to `base`, where the thumb (of
// radius thumb_r, `thumb` long, closed by decreases) parts from the hand: the thumb takes the
// three vertices round +x, the hand the other seven and the crotch. Returns the hand's ring.
Ring cuff_palm_and_thumb(CoarseDraft& d, double r, double cuff, double base, double thumb,
                         double thumb_r) {
  Ring bottom = d.ring(0, r), below = d.ring(cuff, r);
  d.band(bottom, below, {0, 0, 0}, kUp, "cuff");
  Ring palm = d.ring(base, r);
  d.band(below, palm, {0, 0, 0}, kUp, "palm");
  auto [thumb_base, hand_base] =
      fork(d, palm, kSides - 1, 1,
           {static_cast<float>(r * 0.45), static_cast<float>(base + r * 0.3), 0});
  LimbRings t;
  t.straight(0, thumb * 0.7, 2.5, thumb_r, "thumb");
  t.crown(t.end(), thumb * 0.3, {0.6, 0.3}, thumb_r, "thumb");
  d.limb(thumb_base, unit({0.5, 0.87f, 0}), t.distances, t.radii, t.groups);
  return hand_base;
}

// A mitten knit from the cuff up: at the base of the thumb the tube parts into the hand and
// the thumb (a split: the sts between them are cast on along the crotch), each closed by
// decreases to a small ring.
Shape mitten(const ShapeSize& s, const std::string& name) {
  double c = s.circumference > 0 ? s.circumference : 20, l = s.length > 0 ? s.length : 26;
  double r = radius_for(c), cuff = std::min(5.0, l * 0.2), base = std::max(cuff + 1, l * 0.42);
  double thumb_r = r * 0.45, thumb = std::max(2.0, l * 0.22), top = std::max(2.0, l * 0.16);
  CoarseDraft d;
  Ring hand_base = cuff_palm_and_thumb(d, r, cuff, base, thumb, thumb_r);
  LimbRings h;
  h.straight(0, std::max(1.0, l - base - top), 4, r, "hand");
  h.crown(h.end(), top, {0.8, 0.55, 0.3}, r, "top");
  d.limb(hand_base, kUp, h.distances, h.radii, h.groups);
  return {d.finish(name + ".obj"),
          project_text(name,
                       fmt::format("a mitten {} cm round, {} cm long, the thumb parting from the "
                                   "hand",
                                   c, l),
                       "patterns: {cuff: k2p2}\n")};
}

// A glove knit from the cuff up: the thumb parts from the palm as a mitten's does, then the
// hand parts into four fingers one after another (each fork takes three of the hand's
// vertices and leaves a ring of the same size for the rest: the little finger is what is
// left), each finger closed by decreases.
Shape glove(const ShapeSize& s, const std::string& name) {
  double c = s.circumference > 0 ? s.circumference : 20, l = s.length > 0 ? s.length : 26;
  double r = radius_for(c), cuff = std::min(5.0, l * 0.2), base = std::max(cuff + 1, l * 0.35);
  double knuckles = std::max(base + 2, l * 0.6), finger_r = r * 0.4;
  double finger = std::max(2.0, l - knuckles), thumb = std::max(2.0, l * 0.22);
  CoarseDraft d;
  Ring hand_base = cuff_palm_and_thumb(d, r, cuff, base, thumb, finger_r * 1.1);
  LimbRings h;
  h.straight(0, knuckles - base, 4, r, "hand");
  Ring rest = d.limb(hand_base, kUp, h.distances, h.radii, h.groups);
  const char* names[] = {"index", "middle", "ring", "little"};
  for (int i = 0; i < 4; ++i) {
    Ring tip_base = rest;
    if (i < 3) {
      // The finger takes rest[0..2]; its crotch lies between them and the ring's centre.
      Vec3 mid = d.centre(rest);
      Vec3 crotch = moved(moved(mid, sub(d.at(rest[1]), mid), 0.4), kUp, r * 0.15);
      std::tie(tip_base, rest) = fork(d, rest, 0, 2, crotch);
    }
    Vec3 out = sub(d.centre(tip_base), d.centre(rest));
    Vec3 axis = i < 3 ? unit(moved(kUp, unit(out), 0.25)) : kUp;
    double length = finger * (i == 1 ? 1.0 : i == 3 ? 0.75 : 0.9);
    LimbRings f;
    f.straight(0, length * 0.8, 2.5, finger_r, names[i]);
    f.crown(f.end(), length * 0.2, {0.6, 0.3}, finger_r, names[i]);
    d.limb(tip_base, axis, f.distances, f.radii, f.groups);
  }
  return {d.finish(name + ".obj"),
          project_text(
              name, fmt::format("a glove {} cm round, {} cm long: a thumb and four fingers", c, l),
              "patterns: {cuff: k2p2}\n")};
}

// A sweater with set-in sleeves, knit as by hand from the hem up: the body in the round to the
// armholes (a hole at each side, two of its faces at ±x left open for a band of rows), where it
// divides into front and back, worked flat up to the top of the armholes and joined again in
// the round by a cast-on across each armhole's top. Each sleeve is then picked up round its
// armhole (the body's live sts below it, sts picked up along its sides, the cast-on's other
// side above it) and knit down to the cuff. The armhole's sides are marked as mismatches, so
// the body's rows stop there rather than walk on into the sleeve: every sleeve stitch waits
// only for body stitches, never the other way, and no rows wait for each other both ways.
Shape set_in_sweater(const ShapeSize& s, const std::string& name) {
  double c = s.circumference > 0 ? s.circumference : 90, body = s.length > 0 ? s.length : 36;
  double r = radius_for(c), armhole = std::max(4.0, c * 0.12), shoulder = std::max(3.0, c * 0.06);
  double sleeve = std::max(10.0, c * 0.45), cuff_r = r * 0.3;
  CoarseDraft d;
  const double hem = std::min(5.0, body / 2);
  Ring bottom = d.ring(0, r), below = d.ring(hem, r);
  d.band(bottom, below, {0, 0, 0}, kUp, "hem");
  for (double h = hem + 10;; h += 10) {
    Ring above = d.ring(std::min(h, body), r);
    d.band(below, above, {0, 0, 0}, kUp, "body");
    below = std::move(above);
    if (h >= body) break;
  }
  Ring top = d.ring(body + armhole, r);
  d.band(below, top, {0, 0, 0}, kUp, "body", {0, 4});  // vertex 0 at +x, 4 at -x
  Ring holes[2] = {{below[0], below[1], top[1], top[0]}, {below[4], below[5], top[5], top[4]}};
  Ring shoulders = d.ring(body + armhole + shoulder, r * 0.75),
       neck = d.ring(body + armhole + shoulder + 2, r * 0.7);
  d.band(top, shoulders, {0, 0, 0}, kUp, "yoke");
  d.band(shoulders, neck, {0, 0, 0}, kUp, "neck");
  std::string armhole_sides;  // each hole's sides: from below[j] up to top[j]
  for (const Ring& hole : holes)
    armhole_sides += fmt::format("{}[{}, {}], [{}, {}]", armhole_sides.empty() ? "" : ", ",
                                 hole[0] + 1, hole[3] + 1, hole[1] + 1, hole[2] + 1);
  for (int side = 0; side < 2; ++side) {
    Vec3 axis{side == 0 ? 1.0f : -1.0f, 0, 0};
    Vec3 centre = d.centre(holes[side]);
    double top_r = 0;
    for (std::uint32_t v : holes[side])
      top_r += std::hypot(d.at(v).y - centre.y, d.at(v).z - centre.z);
    top_r /= static_cast<double>(holes[side].size());
    LimbRings l;
    for (double t : steps(sleeve - 5, 10)) {
      l.distances.push_back(t);
      l.radii.push_back(top_r + (cuff_r - top_r) * t / sleeve);
      l.groups.push_back("sleeve");
    }
    l.straight(l.end(), 5, 5, cuff_r, "cuff");
    d.limb(holes[side], axis, l.distances, l.radii, l.groups);
  }
  return {d.finish(name + ".obj"),
          project_text(name,
                       fmt::format("a sweater {} cm round, body {} cm, sleeves {} cm set in at the "
                                   "armholes",
                                   c, body, sleeve),
                       fmt::format("start:                 # the hem: the sleeves are picked "
                                   "up round the armholes\n"
                                   "  - vertex: {}\n"
                                   "mismatches: [{}]   # the armholes' sides: the body's rows "
                                   "stop there\n"
                                   "patterns: {{hem: k2p2, cuff: k2p2, neck: k2p2}}\n",
                                   bottom[2] + 1, armhole_sides))};
}

// A bag knit in the round from the bottom edge up to the rim, with two handles: straps that
// rise from the rim's top edge over one face (the rim's sts there go on into the strap) and
// come down onto it over another, two faces along (where the strap meets the rim's sts from
// above): the body parts into each handle and the handle joins back into it.
Shape bag(const ShapeSize& s, const std::string& name) {
  double c = s.circumference > 0 ? s.circumference : 70, h = s.length > 0 ? s.length : 30;
  double r = radius_for(c), rim = std::max(2.0, h * 0.08);
  double lift = std::max(5.0, c * 0.12);  // how high a handle rises above the rim
  CoarseDraft d;
  Ring below = d.ring(0, r);
  for (double y : steps(h - rim, 10)) {
    Ring above = d.ring(y, r);
    d.band(below, above, {0, 0, 0}, kUp, "body");
    below = std::move(above);
  }
  Ring top = d.ring(h, r);
  d.band(below, top, {0, 0, 0}, kUp, "rim");
  for (std::uint32_t a : {1u, 5u}) {
    // A strap's cross-sections are pairs of vertices (a "ring" of two, its closing face left
    // open), from the rim's edge a, a + 1 to its edge a + 3, a + 2 (the strap does not twist).
    Ring from{top[a], top[a + 1]}, to{top[(a + 3) % kSides], top[a + 2]};
    Vec3 middle = moved(d.centre(from), sub(d.centre(to), d.centre(from)), 0.5);
    Vec3 out = unit({middle.x, 0, middle.z});
    Ring pair = from;
    const int arcs = 6;
    for (int k = 1; k <= arcs; ++k) {
      double u = static_cast<double>(k) / arcs;
      Ring next = to;
      if (k < arcs)
        for (std::size_t i = 0; i < from.size(); ++i) {
          Vec3 p = moved(d.at(from[i]), sub(d.at(to[i]), d.at(from[i])), u);
          double rise = lift * std::sin(kPi * u);
          next[i] = d.vertex(moved(moved(p, out, rise * 0.3), kUp, rise));
        }
      Vec3 centre = d.centre(pair);
      d.band(pair, next, centre, sub(d.centre(next), centre), "handle", {1});
      pair = std::move(next);
    }
  }
  return {d.finish(name + ".obj"),
          project_text(name, fmt::format("a bag {} cm round, {} cm high, with two handles", c, h),
                       "start:                 # the bottom edge\n  - vertex: 1\n"
                       "patterns: {rim: k2p2}\n")};
}

// Shorts or trousers: a body tube from the waist and two legs parting at the crotch (the sts
// between them joined or cast on along it). `from_waist`: knit down from the waist, the body
// splitting into the legs; else up from both leg hems, the legs joining into the body.
Shape legs(const ShapeSize& s, const std::string& name, double default_leg, bool from_waist) {
  double c = s.circumference > 0 ? s.circumference : 90;
  double leg = s.length > 0 ? s.length : default_leg;
  double r = radius_for(c), rise = std::max(6.0, c * 0.28), band = std::min(4.0, rise / 3);
  CoarseDraft d;
  Ring crotch = d.ring(0, r), below = d.ring(rise - band, r), waist = d.ring(rise, r);
  d.band(crotch, below, {0, 0, 0}, kUp, "body");
  d.band(below, waist, {0, 0, 0}, kUp, "waist");
  auto [right, left] = fork(d, crotch, 6, 2, {0, static_cast<float>(-r * 0.15), 0});
  Ring hems[2];
  int side = 0;
  for (const Ring& top : {right, left}) {
    LimbRings g;
    g.straight(0, std::max(1.0, leg - 3), 10, r * 0.62, side == 0 ? "right_leg" : "left_leg");
    g.straight(g.end(), std::min(3.0, leg / 2), 3, r * 0.6, "hem");
    float splay = side++ == 0 ? 0.08f : -0.08f;
    hems[side - 1] = d.limb(top, unit({splay, -1, 0}), g.distances, g.radii, g.groups);
  }
  std::string starts =
      from_waist
          ? fmt::format("start:                 # the waist\n  - vertex: {}\n", waist[0] + 1)
          : fmt::format("start:                 # both hems\n  - vertex: {}\n  - vertex: {}\n",
                        hems[0][0] + 1, hems[1][0] + 1);
  return {d.finish(name + ".obj"),
          project_text(
              name,
              fmt::format("{} {} cm round, legs {} cm, knit {}", from_waist ? "shorts" : "trousers",
                          c, leg, from_waist ? "from the waist down" : "from the hems up"),
              starts + "patterns: {waist: k2p2, hem: k2p2}\n")};
}

}  // namespace

std::vector<std::string> shape_kinds() {
  return {"sheet",  "tube",  "hat",    "sock",     "sweater", "set-in-sweater",
          "mitten", "glove", "shorts", "trousers", "bag"};
}

Shape make_shape(const std::string& kind, const ShapeSize& size, const std::string& name) {
  if (size.circumference < 0 || size.width < 0 || size.length < 0)
    throw UsageError("sizes must be positive");
  if (kind == "sheet") return sheet(size, name);
  if (kind == "tube") return straight_tube(size, name);
  if (kind == "hat") return hat(size, name);
  if (kind == "sock") return sock(size, name);
  if (kind == "sweater") return sweater(size, name);
  if (kind == "mitten") return mitten(size, name);
  if (kind == "glove") return glove(size, name);
  if (kind == "set-in-sweater") return set_in_sweater(size, name);
  if (kind == "bag") return bag(size, name);
  if (kind == "shorts") return legs(size, name, 20, true);
  if (kind == "trousers") return legs(size, name, 75, false);
  throw UsageError(
      fmt::format("unknown shape '{}'; known: {}", kind, fmt::join(shape_kinds(), ", ")));
}

double parse_length_cm(const std::string& text) {
  constexpr std::pair<std::string_view, double> kUnits[] = {
      {"mm", 0.1}, {"cm", 1}, {"in", 2.54}, {"m", 100}};
  double value = 0;
  auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  std::string_view unit(end, text.data() + text.size());
  for (auto [name, cm] : kUnits)
    if (ec == std::errc() && unit == name && value * cm >= kMinLengthCm &&
        value * cm <= kMaxLengthCm)
      return value * cm;
  throw UsageError(fmt::format(
      "'{}' is not a length skein can knit; expected a number with its unit (mm, cm, m or in) "
      "from {:g} cm to {:g} m, e.g. 40cm",
      text, kMinLengthCm, kMaxLengthCm / 100));
}

std::string write_shape(const Shape& shape, const std::string& path_without_extension) {
  std::string obj = path_without_extension + ".obj", yaml = path_without_extension + ".yaml";
  write_file_atomically(obj, [&](std::ostream& out) { write_coarse_mesh(shape.mesh, out); });
  write_file_atomically(yaml, [&](std::ostream& out) { out << shape.project; });
  return yaml;
}

}  // namespace skein
