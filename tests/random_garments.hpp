// Random garments (issue 13), shared by the targets' tests: trees of tubes that part and join,
// bent by short rows, and flat sheets that part into flaps or whose flaps join, at random sizes
// and gauges with random stitch patterns, yarn choices and short-row methods, built as coarse
// meshes and projects the way `skein new` builds its shapes.
#pragma once

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <numbers>
#include <random>
#include <regex>
#include <string>
#include <vector>

#include "common/atomic_file.hpp"
#include "common/error.hpp"
#include "driver/pipeline.hpp"
#include "labeling/coarse_draft.hpp"

namespace skein::testing {

inline constexpr double kPi = std::numbers::pi;
inline constexpr Vec3 kUp{0, 1, 0};

class Dice {
 public:
  explicit Dice(std::uint64_t seed) : rng_(seed) {}
  double real(double lo, double hi) { return std::uniform_real_distribution<>(lo, hi)(rng_); }
  int integer(int lo, int hi) { return std::uniform_int_distribution<>(lo, hi)(rng_); }
  bool chance(double p) { return real(0, 1) < p; }
  template <class T>
  const T& pick(const std::vector<T>& items) {
    return items[static_cast<std::size_t>(integer(0, static_cast<int>(items.size()) - 1))];
  }

 private:
  std::mt19937_64 rng_;
};

// A random garment: its coarse mesh, the project lines it needs (starts, short-row faces) and
// the name of its structure.
struct Garment {
  CoarseDraft draft;
  std::vector<std::string> starts;  // project `start` entries
  std::vector<std::uint32_t> short_row_faces;
  std::string structure;
};

// Rings along `axis` from `start`: `length` in steps of about 5 cm, then maybe a crown
// narrowing it (closing a finger, a toe).
inline Ring random_limb(Garment& g, Dice& dice, const Ring& start, Vec3 axis, double radius,
                        const std::string& group) {
  double length = dice.real(3, 18);
  auto n = static_cast<std::uint32_t>(std::max(1.0, std::round(length / 5)));
  std::vector<double> distances, radii;
  std::vector<std::string> groups;
  for (std::uint32_t i = 1; i <= n; ++i) {
    distances.push_back(length * i / n);
    radii.push_back(radius);
    groups.push_back(group);
  }
  if (dice.chance(0.5)) {
    for (double f : {0.6, 0.3}) {
      distances.push_back(distances.back() + radius * 0.6);
      radii.push_back(radius * f);
      groups.push_back(group + "-tip");
    }
    g.structure += "+crown";
  }
  return g.draft.limb(start, axis, distances, radii, groups);
}

// A vertical tube of 8 sides from y = 0; with a short-row bend (the sock's heel: the top ring
// turned about the front, the two faces where the band grows taller turning short rows).
// Returns {bottom ring, top ring, the top ring's axis}.
struct Trunk {
  Ring bottom, top;
  Vec3 axis;
};
inline Trunk random_trunk(Garment& g, Dice& dice, double radius) {
  CoarseDraft& d = g.draft;
  double length = dice.real(4, 25);
  Trunk t{d.ring(0, radius), {}, kUp};
  Ring below = t.bottom;
  auto n = static_cast<std::uint32_t>(std::max(1.0, std::round(length / 6)));
  for (std::uint32_t i = 1; i <= n; ++i) {
    Ring above = d.ring(length * i / n, radius);
    d.band(below, above, {0, 0, 0}, kUp, i == 1 ? "base" : "trunk");
    below = std::move(above);
  }
  if (dice.chance(0.35)) {  // bend by short rows, as the sock's heel
    double sin_a = dice.real(0.2, 0.6), cos_a = std::sqrt(1 - sin_a * sin_a), band = 1.5;
    Ring turned;
    for (std::uint32_t j = 0; j < 8; ++j) {
      double a = 2 * kPi * j / 8, x = radius * std::cos(a), z = -radius * std::sin(a);
      turned.push_back(
          d.vertex(radius + (x - radius) * cos_a, length + band - (x - radius) * sin_a, z));
    }
    std::uint32_t first = d.band(below, turned, {0, 0, 0}, kUp, "bend");
    g.short_row_faces = {first + 2, first + 7};
    t.axis = unit({static_cast<float>(sin_a), static_cast<float>(cos_a), 0});
    below = std::move(turned);
    g.structure += "+bend";
  }
  t.top = below;
  return t;
}

// One tube, maybe bent, that parts into two branches (a thumb or a pair of legs), one of
// which may part again; knit from the trunk (splits) or from the branch ends (joins).
inline void random_tree(Garment& g, Dice& dice) {
  double radius = dice.real(12, 60) / (2 * kPi);
  g.structure = "tube";
  Trunk trunk = random_trunk(g, dice, radius);
  bool from_branches = dice.chance(0.4);
  std::vector<Ring> ends;
  if (dice.chance(0.8)) {
    // The branch from vertex `last` round to `first` is the smaller one (a thumb: 3 vertices;
    // legs: 5 each).
    bool thumb = dice.chance(0.5);
    std::uint32_t first = thumb ? 1 : 2, last = thumb ? 7 : 6;
    Vec3 c = g.draft.centre(trunk.top);
    Vec3 side = unit({trunk.axis.y, -trunk.axis.x, 0});  // towards +x, across the axis
    Vec3 crotch = moved(moved(c, trunk.axis, radius * 0.3), side, thumb ? radius * 0.45 : 0);
    auto [big, small] = fork(g.draft, trunk.top, first, last, crotch);
    double small_radius = radius * (thumb ? 0.45 : 0.62);
    Vec3 small_axis = unit(moved(trunk.axis, side, thumb ? 0.6 : 0.15));
    Vec3 big_axis = unit(moved(trunk.axis, side, thumb ? 0 : -0.15));
    g.structure += from_branches ? (thumb ? "+thumb joining" : "+legs joining")
                                 : (thumb ? "+thumb parting" : "+legs parting");
    ends.push_back(random_limb(g, dice, small, small_axis, small_radius, "small"));
    ends.push_back(random_limb(g, dice, big, big_axis, radius * (thumb ? 1 : 0.62), "big"));
  } else {
    ends.push_back(random_limb(g, dice, trunk.top, trunk.axis, radius, "top"));
  }
  if (!from_branches) {
    g.starts = {fmt::format("{{vertex: {}}}", trunk.bottom[0] + 1)};
    return;
  }
  // Knit from the branch ends: each open end is a start (a crown's small ring too).
  for (const Ring& end : ends) g.starts.push_back(fmt::format("{{vertex: {}}}", end[0] + 1));
}

// A flat sheet whose upper rows part into two flaps at a slit (knit from the bottom: a split)
// or whose two flaps join into one (knit from the flaps' tops down: a join).
inline void random_sheet(Garment& g, Dice& dice) {
  CoarseDraft& d = g.draft;
  int cols = dice.integer(2, 4), rows = dice.integer(2, 4), slit = dice.integer(1, cols - 1);
  int parted = dice.integer(1, rows - 1);  // rows below the slit
  double w = dice.real(8, 30), h = dice.real(8, 30);
  // Vertices: row r, column c; above the parting the slit's column has a second vertex.
  std::vector<std::vector<std::uint32_t>> left(rows + 1), right(rows + 1);
  for (int r = 0; r <= rows; ++r)
    for (int c = 0; c <= cols; ++c) {
      std::uint32_t v = d.vertex(w * c / cols - w / 2, h * r / rows, 0);
      left[r].push_back(v);
      right[r].push_back(c == slit && r > parted ? d.vertex(w * c / cols - w / 2, h * r / rows, 0)
                                                 : v);
    }
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c) {
      const auto& at = c < slit ? left : right;  // faces right of the slit use its second vertex
      d.add({at[r][c], at[r][c + 1], at[r + 1][c + 1], at[r + 1][c]},
            r == 0 ? "border" : (r >= parted ? "flap" : "body"));
    }
  bool from_flaps = dice.chance(0.4);
  g.structure = from_flaps ? "sheet+flaps joining" : "sheet+flaps parting";
  if (!from_flaps) {
    g.starts = {fmt::format("{{edge: [{}, {}]}}", left[0][0] + 1, left[0][1] + 1)};
    return;
  }
  g.starts = {fmt::format("{{edge: [{}, {}]}}", left[rows][1] + 1, left[rows][0] + 1),
              fmt::format("{{edge: [{}, {}]}}", right[rows][cols] + 1, right[rows][cols - 1] + 1)};
}

inline std::string project_text(const Garment& g, Dice& dice, const std::string& name) {
  std::string text = fmt::format("mesh: {}.obj\nunit: cm\ngauge: {{stitches: {}, rows: {}}}\n",
                                 name, dice.integer(12, 30), dice.integer(16, 40));
  text += fmt::format("pattern: {}\n", dice.pick<std::string>({"knit", "knit", "purl", "k1p1"}));
  // Stitch patterns for the groups this garment has (a project may name no other).
  std::string edge = dice.pick<std::string>({"k2p2", "k1p1", "knit", "purl"});
  std::vector<std::string> patterns;
  for (const std::string& group : g.draft.finish(name).groups) {
    if (group == "border" || group == "base") patterns.push_back(group + ": " + edge);
    if (group == "small-tip") patterns.push_back(group + ": knit");
  }
  if (!patterns.empty()) text += fmt::format("patterns: {{{}}}\n", fmt::join(patterns, ", "));
  text += fmt::format("yarn: {{default: {}}}\n", dice.pick<std::string>({"auto", "extra", "own"}));
  if (!g.starts.empty()) text += fmt::format("start: [{}]\n", fmt::join(g.starts, ", "));
  if (!g.short_row_faces.empty())
    text += fmt::format("short_rows: {{method: {}, faces: [{}]}}\n",
                        dice.pick<std::string>({"sr4", "sr5"}), fmt::join(g.short_row_faces, ", "));
  return text;
}

struct RandomGarment {
  std::string project;    // the project file written
  std::string text;       // its text
  std::string structure;  // "tube+legs parting+crown", "sheet+flaps joining", ...
};

// The next random garment (a tree of tubes 3 times in 4, else a sheet with flaps): its coarse
// mesh and project written into `dir` as garment<trial>.obj and .yaml.
inline RandomGarment write_random_garment(Dice& dice, int trial, const std::string& dir) {
  Garment g;
  if (dice.chance(0.75))
    random_tree(g, dice);
  else
    random_sheet(g, dice);
  std::string name = fmt::format("garment{}", trial);
  std::string project = fmt::format("{}/{}.yaml", dir, name);
  std::string text = project_text(g, dice, name);
  write_file_atomically(dir + "/" + name + ".obj",
                        [&](std::ostream& out) { write_coarse_mesh(g.draft.finish(name), out); });
  write_file_atomically(project, [&](std::ostream& out) { out << text; });
  return {project, text, g.structure};
}

// "hand target: the row of face 12 (k, row 7) works 9 of the 10 live stitches" -> "the row of
// face N works N of the N live stitches": what the refusal is, without where.
inline std::string refusal_kind(const std::string& message) {
  std::string kind = message.substr(message.rfind("hand target: ", 0) == 0 ? 13 : 0);
  kind = std::regex_replace(kind, std::regex(R"(\((?:[^()]|\([^()]*\))*\))"), "");
  kind = std::regex_replace(kind, std::regex(R"(\d+)"), "N");
  kind = std::regex_replace(kind, std::regex(R"(\s+)"), " ");
  return kind.substr(0, 110);
}

struct Tally {
  std::map<std::string, std::array<int, 3>> by_structure;  // proven, refused, not knittable
  std::map<std::string, int> refusals;
  int proven = 0, refused = 0, unknittable = 0;

  // "300 random garments on knitout: 241 proven, 49 refused by name, 10 not knittable", then
  // the table (`proven_word`: what the test calls a success).
  std::string report(int models, const std::string& what, const std::string& proven_word = "proven",
                     const std::string& refused_word = "refused by name") const {
    return fmt::format("{} random garments{}: {} {}, {} {}, {} not knittable\n", models, what,
                       proven, proven_word, refused, refused_word, unknittable) +
           table();
  }

  std::string table() const {
    std::string out = "structure | proven | refused by name | not knittable (skein check)\n";
    for (const auto& [s, n] : by_structure)
      out += fmt::format("{} | {} | {} | {}\n", s, n[0], n[1], n[2]);
    out += "\nrefusal | count\n";
    for (const auto& [r, n] : refusals) out += fmt::format("{} | {}\n", r, n);
    return out;
  }
};

// What a target made of one knittable garment: proven, or refused by name (`refusal`, the
// target's message) before writing.
struct Verdict {
  bool proven = false;
  std::string refusal;
};

// `models` random garments (dice seeded 2026), each knittable one given to `judge` (which may
// roll the dice too, for its options) and tallied by structure.
inline Tally tally_random_garments(int models,
                                   const std::function<Verdict(const Compilation&, Dice&)>& judge) {
  Dice dice(2026);
  const std::string dir = ::testing::TempDir();
  Tally tally;
  for (int trial = 0; trial < models; ++trial) {
    RandomGarment g = write_random_garment(dice, trial, dir);
    SCOPED_TRACE(fmt::format("trial {}: {} ({})\n{}", trial, g.project, g.structure, g.text));
    auto& row = tally.by_structure[g.structure];
    Compilation c;
    try {
      c = compile_model(g.project);
    } catch (const Error& e) {  // the random geometry can make a coarse mesh skein refuses
      ++row[2], ++tally.unknittable;
      ++tally.refusals["model refused by skein check: " + refusal_kind(e.what())];
      continue;
    }
    if (!c.knittability.knittable) {
      ++row[2], ++tally.unknittable;
      continue;
    }
    Verdict v = judge(c, dice);
    if (!v.refusal.empty()) {
      ++row[1], ++tally.refused, ++tally.refusals[refusal_kind(v.refusal)];
      continue;
    }
    if (v.proven) ++row[0], ++tally.proven;
  }
  return tally;
}

}  // namespace skein::testing
