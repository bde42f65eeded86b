#include "labeling/stitch_generation.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <optional>
#include <set>

#include "common/error.hpp"
#include "common/yaml_source.hpp"
#include "labeling/stitch_generator.hpp"
#include "labeling/yarn_plan.hpp"

namespace skein {
namespace generation {
namespace {

struct UnionFind {
  std::vector<std::uint32_t> parent;
  explicit UnionFind(std::uint32_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0u); }
  std::uint32_t find(std::uint32_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  void unite(std::uint32_t a, std::uint32_t b) { parent[find(a)] = find(b); }
};

}  // namespace

GeneratedStitchMesh Generator::run() {
  choose_counts();
  plan_rows();
  add_vertices();
  for (CoarseFace f : m_.faces()) {
    if (L_.short_row[f.index()])
      add_short_row_face(f);
    else
      add_quad(f);
  }
  for (Vec3 p : positions_) builder_.add_vertex(p);
  GeneratedStitchMesh out{
      std::move(builder_).build(), std::move(origin_), {}, closed_rows_, open_rows_, chains_};
  for (CoarseHalfedge h : m_.halfedges()) out.segments.push_back(segments(h));
  for (const auto& [h, option] : shift_edges_) {
    std::uint8_t o = option;  // a lambda may not capture a structured binding before clang 16
    mark_edge(out.mesh, h, [&](Edge e) { out.mesh.shift_path[e] = o; });
  }
  choose_yarns(out);
  name_parts(out);
  return out;
}

void Generator::name_parts(GeneratedStitchMesh& out) const {
  auto named = [](const std::string& group) { return !group.empty(); };
  if (m_.group.size() != m_.num_faces() || std::none_of(m_.groups.begin(), m_.groups.end(), named))
    return;
  for (const std::string& group : m_.groups) out.mesh.part_names.push_back(knitters_name(group));
  out.mesh.part.resize(out.mesh.num_faces(), kNoPart);
  for (Face f : out.mesh.faces()) {
    std::uint32_t group = m_.group[out.coarse_face[f.index()]];
    if (named(m_.groups[group])) out.mesh.part[f] = group;
  }
}

std::string Generator::knitters_name(std::string name) {
  std::replace_if(
      name.begin(), name.end(), [](char ch) { return ch == '_' || ch == '-'; }, ' ');
  if (!name.empty() && name[0] >= 'a' && name[0] <= 'z')
    name[0] = static_cast<char>(name[0] - 'a' + 'A');
  return name;
}

void Generator::fail(CoarseFace f, const std::string& what) const {
  throw Error(
      fmt::format("{}: cannot generate stitches for {}: {}", m_.source, m_.describe(f), what));
}

void Generator::choose_counts() {
  const double width = p_.stitch_width_in_units(), height = p_.stitch_height_in_units();
  const std::uint32_t n = m_.num_halfedges();
  UnionFind groups(n);
  for (CoarseFace f : m_.faces()) {
    if (!L_.short_row[f.index()]) {
      groups.unite(m_.canonical(side(f, CoarseRole::left)).index(),
                   m_.canonical(side(f, CoarseRole::right)).index());
    } else {
      groups.unite(m_.canonical(side(f, CoarseRole::bottom)).index(),
                   m_.canonical(side(f, CoarseRole::top)).index());
    }
  }
  std::vector<double> sum(n, 0), weight(n, 0);
  for (CoarseHalfedge h : m_.halfedges()) {
    std::uint32_t g = groups.find(m_.canonical(h).index());
    sum[g] += m_.length(h) / (is_side(L_[h]) ? height : width);
    weight[g] += 1;
  }
  count_.assign(n, 0);
  for (CoarseHalfedge h : m_.halfedges()) {
    std::uint32_t g = groups.find(m_.canonical(h).index());
    double count = std::round(sum[g] / weight[g]);
    if (!(count <= kMaxCountPerEdge)) too_many(h, count);
    count_[h.index()] = std::max<std::uint32_t>(1, static_cast<std::uint32_t>(count));
  }
  auto group_count = [&](CoarseHalfedge h) -> std::uint32_t& {
    return count_[groups.find(m_.canonical(h).index())];
  };
  // Minimums, raised until they all hold. Each count only grows and is refused beyond
  // kMaxCountPerEdge, so this settles: the first pass that raises none ends it.
  for (bool changed = true; changed;) {
    changed = false;
    auto at_least = [&](CoarseHalfedge h, std::uint32_t minimum) {
      if (group_count(h) < minimum) {
        // Only short rows raise side counts without end: a cycle of them.
        if (minimum > kMaxCountPerEdge)
          fail(m_.face(h),
               fmt::format("its rows keep growing past {}: short-row faces in one row whose "
                           "wide sides each ask the other's narrow side for more rows (mark "
                           "their wide_edge on the same side of the row)",
                           kMaxCountPerEdge));
        group_count(h) = minimum;
        changed = true;
      }
    };
    for (CoarseFace f : m_.faces()) {
      if (L_.short_row[f.index()]) {
        CoarseHalfedge wide = side(f, L_.wide_side[f.index()]);
        CoarseHalfedge narrow = side(
            f, L_.wide_side[f.index()] == CoarseRole::left ? CoarseRole::right : CoarseRole::left);
        if (narrow.valid() &&
            groups.find(m_.canonical(narrow).index()) == groups.find(m_.canonical(wide).index()))
          fail(f,
               "a short-row face's wide side needs more rows than its narrow side, but the "
               "quads of its row join the two (a quad's sides have the same rows); mark a "
               "second short-row face in this row, or none");
        std::uint32_t base = narrow.valid() ? group_count(narrow) : 0;
        std::uint32_t w = std::max(group_count(wide), base + 2);
        at_least(wide, w + (w - base) % 2);
        continue;
      }
      at_least(side(f, CoarseRole::left), rows_needed(f, group_count));
    }
  }
  for (CoarseHalfedge h : m_.halfedges()) count_[h.index()] = group_count(h);
  check_total();
}

void Generator::too_many(CoarseHalfedge h, double count) const {
  throw Error(fmt::format(
      "{}: {} of face {} would have {:.0f} {}; at most {} are allowed per coarse edge (is the "
      "gauge or the unit right? docs/formats.md, \"Limits\")",
      m_.source, m_.describe(h), m_.face(h).index() + 1, count,
      is_side(L_[h]) ? "rows" : "stitches", kMaxCountPerEdge));
}

void Generator::check_total() const {
  double total = 0;
  for (CoarseFace f : m_.faces()) {
    double rows = 0, width = 0;
    for (CoarseHalfedge h : m_.halfedges(f)) {
      double& extent = is_side(L_[h]) ? rows : width;
      extent = std::max<double>(extent, count_[h.index()]);
    }
    total += rows * width;
  }
  if (total > kMaxStitches)
    throw Error(
        fmt::format("{}: the stitch mesh would have about {:.0f} stitches; at most {} "
                    "are allowed (is the gauge or the unit right? docs/formats.md, "
                    "\"Limits\")",
                    m_.source, total, kMaxStitches));
}

std::uint32_t Generator::width_at(std::uint32_t nb, std::uint32_t nt, std::uint32_t i,
                                  std::uint32_t taper) {
  return static_cast<std::uint32_t>(std::lround(nb + (double(nt) - nb) * i / taper));
}

bool Generator::taper_fits(std::uint32_t nb, std::uint32_t nt, std::uint32_t taper) {
  for (std::uint32_t i = 1; i <= taper; ++i) {
    std::uint32_t below = width_at(nb, nt, i - 1, taper), above = width_at(nb, nt, i, taper);
    if (above > 2 * below || 3 * above < below) return false;
  }
  return true;
}

CoarseFace Generator::across(CoarseFace f, CoarseRole r, CoarseRole expected) const {
  CoarseHalfedge h = side(f, r);
  if (!h.valid() || m_.is_border(h) || L_.row_break[h.index()]) return {};
  CoarseHalfedge t = m_.twin(h);
  return L_[t] == expected ? m_.face(t) : CoarseFace();
}

}  // namespace generation

namespace {

// A pattern for a group the mesh does not have would knit nothing: a misspelt name.
void check_group_names(const CoarseMesh& coarse, const Project& project) {
  std::vector<std::string_view> known;
  for (const std::string& g : coarse.groups)
    if (!g.empty()) known.push_back(g);
  for (const auto& [name, group] : project.group_patterns)
    if (std::find(known.begin(), known.end(), name) == known.end())
      throw Error(fmt::format(
          "{}:{}: 'patterns' names the group '{}', but {} has {}", project.file, group.line, name,
          coarse.source,
          known.empty() ? std::string("no groups ('g' or 'o' lines)")
                        : fmt::format("no such group; did you mean '{}'? (groups: {})",
                                      nearest_name(name, known), fmt::join(known, ", "))));
}

}  // namespace

GeneratedStitchMesh generate_stitch_mesh(const CoarseMesh& coarse, const Labeling& labeling,
                                         const Project& project) {
  check_group_names(coarse, project);
  return generation::Generator(coarse, labeling, project).run();
}

GeneratedStitchMesh build_project(const Project& project) {
  CoarseMesh coarse = read_coarse_mesh(project.mesh);
  return generate_stitch_mesh(coarse, label_coarse_mesh(coarse, project), project);
}

std::string describe_generation(const CoarseMesh& coarse, const Labeling& labeling,
                                const GeneratedStitchMesh& generated) {
  std::vector<std::uint32_t> stitches(coarse.num_faces(), 0);
  for (std::uint32_t f : generated.coarse_face) ++stitches[f];
  std::string out = fmt::format(
      "{} coarse faces -> {} stitches; coarse rows: {} closed, {} open; shift-paths: {}\n",
      coarse.num_faces(), generated.mesh.num_faces(), generated.closed_rows, generated.open_rows,
      generated.shift_paths);
  auto count = [&](CoarseHalfedge h) { return generated.segments[h.index()]; };
  for (CoarseFace f : coarse.faces()) {
    CoarseHalfedge b = labeling.find(coarse, f, CoarseRole::bottom),
                   t = labeling.find(coarse, f, CoarseRole::top),
                   l = labeling.find(coarse, f, CoarseRole::left),
                   r = labeling.find(coarse, f, CoarseRole::right);
    std::string rows = labeling.short_row[f.index()]
                           ? fmt::format("short rows: {} left, {} right", l.valid() ? count(l) : 0,
                                         r.valid() ? count(r) : 0)
                           : fmt::format("rows {}", count(l));
    out += fmt::format("face {}: labelled #{}, bottom {}, {}, stitches {} -> {}, {} faces\n",
                       f.index() + 1, labeling.order[f.index()] + 1, coarse.describe(b), rows,
                       count(b), count(t), stitches[f.index()]);
  }
  return out;
}

}  // namespace skein
