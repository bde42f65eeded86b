// The stitch generator's vertices, faces (quads and short-row faces, column by column) and
// marks on the mesh's edges, and the yarns it chooses (stitch_generator.hpp).
#include "common/error.hpp"
#include "labeling/stitch_generator.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <optional>

namespace skein::generation {

namespace {

Vec3 lerp(Vec3 a, Vec3 b, float t) {
  return {a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t, a.z + (b.z - a.z) * t};
}

// `count` of `n` positions, evenly spaced; odd rows shifted by half a step so shaping does
// not stack.
std::vector<std::uint8_t> spread(std::uint32_t n, std::uint32_t count, std::uint32_t row) {
  std::vector<std::uint8_t> marked(n, 0);
  double step = static_cast<double>(n) / count, phase = row % 2 ? 0.75 : 0.25;
  for (std::uint32_t j = 0; j < count; ++j)
    marked[std::min<std::uint32_t>(n - 1, static_cast<std::uint32_t>((j + phase) * step))] = 1;
  return marked;
}

// The stitches of a row that consumes `below` loops and makes `above` (left to right).
std::vector<Shape> row_shapes(std::uint32_t below, std::uint32_t above, std::uint32_t row) {
  if (above >= below) {
    std::vector<Shape> shapes(below);
    std::vector<std::uint8_t> inc = spread(below, above - below, row);
    for (std::uint32_t i = 0; i < below; ++i) shapes[i].out = inc[i] ? 2 : 1;
    return shapes;
  }
  std::uint32_t extra = below - above;  // loops to absorb: k2tog absorbs 1, s2kp 2
  std::uint32_t doubles = extra > above ? extra - above : 0, singles = extra - 2 * doubles;
  std::vector<Shape> shapes(above);
  std::vector<std::uint8_t> dec = spread(above, singles + doubles, row);
  for (std::uint32_t i = 0, d = 0; i < above; ++i)
    if (dec[i]) shapes[i].in = d++ < doubles ? 3 : 2;
  return shapes;
}

}  // namespace

Vertex Generator::new_vertex(Vec3 p) {
  positions_.push_back(p);
  return Vertex(static_cast<std::uint32_t>(positions_.size() - 1));
}

void Generator::add_vertices() {
  positions_ = m_.position;
  edge_first_.assign(m_.num_halfedges(), 0);
  for (CoarseHalfedge h : m_.halfedges()) {
    if (m_.canonical(h) != h) continue;
    edge_first_[h.index()] = static_cast<std::uint32_t>(positions_.size());
    std::uint32_t n = segments(h);
    for (std::uint32_t i = 1; i < n; ++i)
      new_vertex(lerp(m_.at(m_.tail(h)), m_.at(m_.head(h)), static_cast<float>(i) / n));
  }
}

std::vector<Vertex> Generator::along(CoarseHalfedge h) const {
  CoarseHalfedge c = m_.canonical(h);
  std::uint32_t n = segments(h);
  std::vector<Vertex> v{Vertex(m_.tail(c).index())};
  for (std::uint32_t i = 1; i < n; ++i) v.push_back(Vertex(edge_first_[c.index()] + i - 1));
  v.push_back(Vertex(m_.head(c).index()));
  if (c != h) std::reverse(v.begin(), v.end());
  return v;
}

std::vector<Vertex> Generator::upward(CoarseHalfedge h, bool runs_down) const {
  std::vector<Vertex> v = along(h);
  if (runs_down) std::reverse(v.begin(), v.end());
  return v;
}

std::vector<Vertex> Generator::line(Vertex first, Vertex last, std::uint32_t n) {
  Vec3 a = pos(first), b = pos(last);
  return line(first, last, n, [&](float u) { return lerp(a, b, u); });
}

StitchPattern Generator::pattern(CoarseFace f) const {
  auto it = p_.group_patterns.find(m_.groups[m_.group[f.index()]]);
  return it == p_.group_patterns.end() ? p_.pattern : it->second.pattern;
}

bool Generator::purl_at(StitchPattern pattern, std::uint32_t column) {
  switch (pattern) {
    case StitchPattern::knit:
      return false;
    case StitchPattern::purl:
      return true;
    case StitchPattern::k1p1:
      return column % 2 == 1;
    case StitchPattern::k2p2:
      return column % 4 >= 2;
  }
  return false;
}

StitchType Generator::type_of(Shape s, bool purl) {
  if (s.in == 3) return StitchType::s2kp;
  if (s.in == 2) return purl ? StitchType::p2tog : StitchType::k2tog;
  if (s.out == 2) return StitchType::kfb;
  return purl ? StitchType::p : StitchType::k;
}

void Generator::add_quad(CoarseFace f) {
  CoarseHalfedge hb = side(f, CoarseRole::bottom), hr = side(f, CoarseRole::right),
                 ht = side(f, CoarseRole::top), hl = side(f, CoarseRole::left);

  const std::uint32_t n = segments(hr), nb = segments(hb), nt = segments(ht);
  const bool cast_on = m_.is_border(hb), bind_off = m_.is_border(ht);
  std::vector<Vertex> left = upward(hl, true), right = upward(hr, false);
  std::vector<Vertex> below = along(hb), top = along(ht);
  std::reverse(top.begin(), top.end());
  const std::uint32_t a = cast_on, z = bind_off ? n - 1 : n;  // lines where shaping starts, ends
  const std::vector<std::uint8_t>& rightward = rightward_[f.index()];
  Vec3 bl = m_.at(m_.tail(hb)), br = m_.at(m_.head(hb)), tr = m_.at(m_.tail(ht)),
       tl = m_.at(m_.head(ht));
  SKEIN_ASSERT(rightward.size() == n, "every row of a quad has a direction");
  StitchPattern pat = pattern(f);
  for (std::uint32_t i = 1; i <= n; ++i) {
    std::uint32_t width = i <= a ? nb : i >= z ? nt : width_at(nb, nt, i - a, z - a);
    float t = static_cast<float>(i) / n;
    std::vector<Vertex> above = i == n ? top : line(left[i], right[i], width, [&](float u) {
      return lerp(lerp(bl, br, u), lerp(tl, tr, u), t);
    });
    bool first = i == 1 && cast_on, last = i == n && bind_off;
    std::vector<Shape> shapes = row_shapes(static_cast<std::uint32_t>(below.size() - 1), width, i);
    std::uint32_t u = 0, o = 0;
    for (Shape s : shapes) {
      StitchType type = first  ? StitchType::co
                        : last ? StitchType::bo
                               : type_of(s, purl_at(pat, offset_[f.index()] + u));
      emit(f, {below.begin() + u, below.begin() + u + s.in + 1},
           {above.begin() + o, above.begin() + o + s.out + 1}, rightward[i - 1], type, false);
      u += s.in;
      o += s.out;
    }
    below = std::move(above);
  }
}

void Generator::add_short_row_face(CoarseFace f) {
  const bool wide_left = L_.wide_side[f.index()] == CoarseRole::left;
  CoarseHalfedge hb = side(f, CoarseRole::bottom), ht = side(f, CoarseRole::top);
  CoarseHalfedge wide = side(f, L_.wide_side[f.index()]);
  CoarseHalfedge narrow = side(f, wide_left ? CoarseRole::right : CoarseRole::left);
  const std::uint32_t columns = segments(hb);
  std::vector<Vertex> bottom = along(hb), top = along(ht);
  if (!wide_left) std::reverse(bottom.begin(), bottom.end());
  if (wide_left) std::reverse(top.begin(), top.end());  // both now run from the wide side
  const std::vector<Token>& tokens = tokens_[f.index()];
  auto rows_at = [&](std::uint32_t x) {  // rows on the line x columns from the wide side
    std::uint32_t rows = 0;
    for (const Token& t : tokens) rows += !t.pair ? 1 : t.depth >= x ? 2 : 0;
    return rows;
  };
  std::vector<Vertex> w = upward(wide, wide_left);
  if (m_.is_border(hb) || m_.is_border(ht))
    fail(f, "a short-row face needs neighbours above and below (its bottom or top is open)");
  for (std::uint32_t x = 1; x <= columns; ++x) {
    std::vector<Vertex> p;
    if (x == columns)
      p = narrow.valid() ? upward(narrow, !wide_left) : std::vector<Vertex>{bottom.back()};
    else
      p = line(bottom[x], top[x], rows_at(x));
    if (x == columns && !narrow.valid())
      SKEIN_ASSERT(rows_at(x) == 0, "a triangle's point has no rows");
    add_column(f, tokens, w, p, x, !wide_left);
    w = std::move(p);
  }
}

void Generator::add_column(CoarseFace f, const std::vector<Token>& tokens,
                           const std::vector<Vertex>& w, const std::vector<Vertex>& p,
                           std::uint32_t x, bool mirrored) {
  std::size_t iw = 0, ip = 0;
  std::uint32_t columns = segments(side(f, CoarseRole::bottom));
  bool purl = purl_at(pattern(f), offset_[f.index()] + (mirrored ? columns - x : x - 1));
  std::vector<Vertex> run{w[0], p[0]};  // the bottom course run of the next face
  bool sr5 = p_.short_row_method == ShortRowMethod::sr5;
  for (std::size_t k = 0; k < tokens.size(); ++k) {
    const Token& t = tokens[k];
    auto regular = [&](bool toward) {
      std::vector<Vertex> top{w[iw + 1], p[ip + 1]};
      Shape s{static_cast<std::uint8_t>(run.size() - 1), 1};
      emit(f, run, top, toward, type_of(s, purl), mirrored);
      run = {w[iw + 1], p[ip + 1]};
      ++iw;
      ++ip;
    };
    if (!t.pair) {
      regular(t.toward_narrow);
    } else if (t.depth >= x) {
      regular(true);
      regular(false);
    } else if (t.depth + 1 == x) {
      // The turn: wale edges side by side on the wide side, its top on the narrow point.
      std::size_t up = k + 1;  // the next token with a face in this column
      while (up < tokens.size() && tokens[up].pair && tokens[up].depth + 1 < x) ++up;
      bool covered = up < tokens.size() && (!tokens[up].pair || tokens[up].depth >= x);
      std::vector<Vertex> top{w[iw + 2], p[ip]};
      if (sr5 && covered)
        top.insert(top.begin() + 1, new_vertex(lerp(pos(w[iw + 2]), pos(p[ip]), 0.5f)));
      corners_.assign(run.begin(), run.end());  // ends at the point, where the top starts
      corners_.insert(corners_.end(), top.rbegin() + 1, top.rend());
      corners_.push_back(w[iw + 1]);
      roles_.assign(run.size() - 1, EdgeRole::bottom);
      roles_.insert(roles_.end(), top.size() - 1, EdgeRole::top);
      roles_.push_back(EdgeRole::wale_out);
      roles_.push_back(EdgeRole::wale_in);
      emit_raw(f, top.size() == 3 ? StitchType::sr5 : StitchType::sr4, mirrored);
      run = top;
      iw += 2;
    }
  }
}

void Generator::emit(CoarseFace f, const std::vector<Vertex>& bottom,
                     const std::vector<Vertex>& top, bool rightward, StitchType type,
                     bool mirrored) {
  corners_.assign(bottom.begin(), bottom.end());
  corners_.insert(corners_.end(), top.rbegin(), top.rend());
  roles_.assign(bottom.size() - 1, EdgeRole::bottom);
  roles_.push_back(rightward ? EdgeRole::wale_out : EdgeRole::wale_in);
  roles_.insert(roles_.end(), top.size() - 1, EdgeRole::top);
  roles_.push_back(rightward ? EdgeRole::wale_in : EdgeRole::wale_out);
  emit_raw(f, type, mirrored);
}

void Generator::emit_raw(CoarseFace f, StitchType type, bool mirrored) {
  if (mirrored) {
    std::reverse(corners_.begin(), corners_.end());
    std::reverse(roles_.begin(), roles_.end());
    std::rotate(roles_.begin(), roles_.begin() + 1, roles_.end());
  }
  builder_.add_face(corners_, roles_, type);
  origin_.push_back(f.index());
}

void Generator::choose_yarns(GeneratedStitchMesh& out) const {
  StitchMesh& mesh = out.mesh;
  auto choice = [&](Edge e, YarnHandling use, std::optional<std::uint32_t> coarse_face) {
    EdgeKind k = mesh.kind(e);
    if (k != EdgeKind::join && k != EdgeKind::split) return false;
    if (use == YarnHandling::by_default) return true;
    Halfedge h = mesh.halfedge(e);
    Face a = mesh.face(h), b = mesh.face(mesh.twin(h));
    std::uint32_t ca = out.coarse_face[a.index()], cb = out.coarse_face[b.index()];
    Face own = coarse_face ? (*coarse_face == ca ? a : b) : (L_.order[ca] <= L_.order[cb] ? a : b);
    mesh.mismatch_yarn[e] = use == YarnHandling::extra ? MismatchYarn{MismatchYarn::Kind::extra, {}}
                                                       : MismatchYarn{MismatchYarn::Kind::own, own};
    return true;
  };
  for (Edge e : mesh.edges()) choice(e, p_.default_yarn, std::nullopt);
  for (const YarnMark& y : p_.yarn_marks) {
    CoarseHalfedge h = find_project_edge(m_, p_, y.edge);
    bool any = false;
    mark_edge(mesh, h, [&](Edge e) { any |= choice(e, y.use, y.face); });
    if (!any)
      throw Error(
          fmt::format("{}:{}: {} is not a joining or splitting edge, so it takes no yarn "
                      "choice",
                      p_.file, y.edge.line, m_.describe(h)));
  }
}

}  // namespace skein::generation
