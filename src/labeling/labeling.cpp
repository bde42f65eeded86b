#include "labeling/labeling.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <deque>
#include <map>

namespace skein {

CoarseHalfedge Labeling::find(const CoarseMesh& mesh, CoarseFace f, CoarseRole r) const {
  for (CoarseHalfedge h : mesh.halfedges(f))
    if (role[h.index()] == r) return h;
  return {};
}

CoarseHalfedge find_project_edge(const CoarseMesh& mesh, const Project& project,
                                 const CoarseEdgeRef& ref) {
  CoarseHalfedge h = mesh.find_halfedge(CoarseVertex(ref.a), CoarseVertex(ref.b));
  if (!h.valid()) h = mesh.find_halfedge(CoarseVertex(ref.b), CoarseVertex(ref.a));
  if (!h.valid())
    throw Error(
        fmt::format("{}:{}: vertices {} and {} share no edge in {}; expected the two ends "
                    "of an edge of the coarse mesh",
                    project.file, ref.line, ref.a + 1, ref.b + 1, mesh.source));
  return h;
}

namespace {

// "88-91, 95": face numbers (1-based), consecutive runs collapsed.
std::string face_ranges(std::vector<std::uint32_t> faces) {
  std::sort(faces.begin(), faces.end());
  std::string out;
  for (std::size_t i = 0; i < faces.size();) {
    std::size_t j = i;
    while (j + 1 < faces.size() && faces[j + 1] == faces[j] + 1) ++j;
    out += fmt::format("{}{}", out.empty() ? "" : ", ", faces[i] + 1);
    if (j > i) out += fmt::format("-{}", faces[j] + 1);
    i = j + 1;
  }
  return out;
}

class Labeler {
 public:
  Labeler(const CoarseMesh& mesh, const Project& project) : m_(mesh), p_(project) {
    L_.role.assign(m_.num_halfedges(), CoarseRole::none);
    L_.short_row.assign(m_.num_faces(), 0);
    L_.wide_side.assign(m_.num_faces(), CoarseRole::none);
    L_.order.assign(m_.num_faces(), kUnlabelled);
    L_.row_break.assign(m_.num_halfedges(), 0);
    pending_.assign(m_.num_faces(), CoarseHalfedge());
    wide_mark_.assign(m_.num_faces(), CoarseHalfedge());
    for (CoarseFace f : m_.faces()) L_.short_row[f.index()] = m_.degree(f) == 3;
    for (const CoarseEdgeRef& e : p_.mismatch_edges) {
      CoarseHalfedge h = find_project_edge(m_, p_, e);
      L_.row_break[h.index()] = 1;
      if (!m_.is_border(h)) L_.row_break[m_.twin(h).index()] = 1;
    }
    for (const ShortRowFaceMark& mark : p_.short_row_faces) {
      if (mark.face >= m_.num_faces())
        throw Error(fmt::format("{}:{}: face {} does not exist ({} has {} faces)", p_.file,
                                mark.line, mark.face + 1, m_.source, m_.num_faces()));
      CoarseFace f(mark.face);
      if (m_.degree(f) > 4)
        throw Error(
            fmt::format("{}:{}: face {} has {} sides; a short-row face is a triangle or "
                        "a quad",
                        p_.file, mark.line, mark.face + 1, m_.degree(f)));
      L_.short_row[f.index()] = 1;
      if (!mark.wide_edge) continue;
      CoarseHalfedge h = find_project_edge(m_, p_, *mark.wide_edge);
      if (m_.face(h) != f) h = m_.twin(h);
      if (!h.valid() || m_.face(h) != f)
        throw Error(fmt::format("{}:{}: edge {}-{} is not a side of face {}", p_.file, mark.line,
                                mark.wide_edge->a + 1, mark.wide_edge->b + 1, mark.face + 1));
      wide_mark_[f.index()] = h;
    }
  }

  Labeling run() {
    for (const StartSeed& seed : p_.start) add_start(seed);
    if (p_.start.empty()) add_automatic_start();
    do drain();
    while (detect_short_row_ends());
    choose_wide_sides();
    report_leftovers();
    return std::move(L_);
  }

 private:
  static constexpr std::uint32_t kUnlabelled = ~0u;

  bool labelled(CoarseFace f) const { return L_.order[f.index()] != kUnlabelled; }

  void set_roles(CoarseHalfedge first, std::initializer_list<CoarseRole> roles) {
    CoarseHalfedge h = first;
    for (CoarseRole r : roles) {
      L_.role[h.index()] = r;
      h = m_.next(h);
    }
    L_.order[m_.face(first).index()] = next_order_++;
  }

  // A triangle is a short-row end: its wale edge `wale` carries the rows, on the given side.
  void label_triangle(CoarseHalfedge wale, CoarseRole side) {
    if (side == CoarseRole::right)
      set_roles(wale, {CoarseRole::right, CoarseRole::top, CoarseRole::bottom});
    else
      set_roles(wale, {CoarseRole::left, CoarseRole::bottom, CoarseRole::top});
    L_.wide_side[m_.face(wale).index()] = side;
  }

  // Walks a row sideways from `side` (a labelled quad's left or right halfedge).
  void walk(CoarseHalfedge side, bool rightward, std::vector<CoarseFace>& row) {
    while (!m_.is_border(side) && !L_.row_break[side.index()]) {
      CoarseHalfedge g = m_.twin(side);
      CoarseFace next = m_.face(g);
      if (labelled(next)) return;  // the ring closed, or a mismatch
      if (m_.degree(next) == 3) {
        label_triangle(g, rightward ? CoarseRole::left : CoarseRole::right);
        row.push_back(next);
        return;
      }
      if (m_.degree(next) != 4) return;  // reported as left over
      CoarseHalfedge bottom = rightward ? m_.next(g) : m_.prev(g);
      set_roles(bottom, {CoarseRole::bottom, CoarseRole::right, CoarseRole::top, CoarseRole::left});
      row.push_back(next);
      side = rightward ? m_.next(m_.next(g)) : m_.prev(m_.prev(g));
    }
  }

  void label_row(CoarseFace f, CoarseHalfedge bottom) {
    set_roles(bottom, {CoarseRole::bottom, CoarseRole::right, CoarseRole::top, CoarseRole::left});
    std::vector<CoarseFace> row{f};
    walk(m_.next(bottom), true, row);
    walk(m_.prev(bottom), false, row);
    for (CoarseFace g : row) seed_above(g);
  }

  // `bottom` is the halfedge of its face that a labelled row below (or a start) hands it.
  void seed(CoarseHalfedge bottom) {
    CoarseFace f = m_.face(bottom);
    if (labelled(f)) return;  // consistent, or a joining/perpendicular mismatch
    if (m_.degree(f) == 4) return label_row(f, bottom);
    if (m_.degree(f) != 3) return;
    CoarseHalfedge wide = wide_mark_[f.index()];
    if (wide.valid() && wide != bottom) {
      label_triangle(wide, wide == m_.next(bottom) ? CoarseRole::right : CoarseRole::left);
      seed_above(f);
    } else {
      pending_[f.index()] = bottom;
    }
  }

  // A marked top is not handed on either: the face beyond is labelled from another side, so
  // the mark becomes the perpendicular mismatch it asks for.
  void seed_above(CoarseFace f) {
    CoarseHalfedge top = L_.find(m_, f, CoarseRole::top);
    if (!m_.is_border(top) && !L_.row_break[top.index()]) seeds_.emplace_back(m_.twin(top));
  }

  void drain() {
    while (!seeds_.empty()) {
      CoarseHalfedge h = seeds_.front();
      seeds_.pop_front();
      seed(h);
    }
  }

  // A triangle reached from below whose other neighbours are labelled: the one that treats
  // the shared edge as a side carries the short rows (paper §3.4).
  bool detect_short_row_ends() {
    bool found = false;
    for (CoarseFace f : m_.faces()) {
      CoarseHalfedge bottom = pending_[f.index()];
      if (labelled(f) || !bottom.valid()) continue;
      CoarseHalfedge candidates[] = {m_.next(bottom), m_.prev(bottom)};
      int sides = 0, known = 0;
      CoarseHalfedge wale;
      for (CoarseHalfedge c : candidates) {
        if (m_.is_border(c) || !labelled(m_.face(m_.twin(c)))) continue;
        ++known;
        if (is_side(L_.role[m_.twin(c).index()])) {
          ++sides;
          wale = c;
        }
      }
      if (known < 2 || sides != 1) continue;
      label_triangle(wale, wale == candidates[0] ? CoarseRole::right : CoarseRole::left);
      seed_above(f);
      found = true;
    }
    drain();
    return found;
  }

  // Short-row quads carry their extra rows on the side the project names, else the longer.
  void choose_wide_sides() {
    for (CoarseFace f : m_.faces()) {
      if (!L_.short_row[f.index()] || m_.degree(f) != 4 || !labelled(f)) continue;
      CoarseHalfedge left = L_.find(m_, f, CoarseRole::left),
                     right = L_.find(m_, f, CoarseRole::right);
      CoarseHalfedge wide = wide_mark_[f.index()];
      if (wide.valid() && wide != left && wide != right)
        throw LabelingError(fmt::format(
            "{}: the wide edge named for short-row {} is {}, but that face's rows run across "
            "it; expected one of its sides, {} or {}",
            p_.file, m_.describe(f), m_.describe(wide), m_.describe(left), m_.describe(right)));
      if (!wide.valid()) wide = m_.length(left) >= m_.length(right) ? left : right;
      L_.wide_side[f.index()] = wide == left ? CoarseRole::left : CoarseRole::right;
    }
  }

  void add_start(const StartSeed& s) {
    if (s.kind == StartSeed::Kind::lowest) return add_automatic_start();
    CoarseHalfedge h;
    if (s.kind == StartSeed::Kind::vertex) {
      for (CoarseHalfedge c : m_.halfedges())
        if (m_.is_border(c) && m_.tail(c).index() == s.edge.a) h = c;
      if (!h.valid())
        throw Error(
            fmt::format("{}:{}: vertex {} is not on an open boundary of {}; expected a "
                        "vertex of a boundary loop",
                        p_.file, s.edge.line, s.edge.a + 1, m_.source));
      seeds_.push_back(h);
      return;
    }
    h = find_project_edge(m_, p_, s.edge);
    seeds_.push_back(h);  // an interior edge starts both faces: a cast-on along it (a split)
    if (!m_.is_border(h)) seeds_.push_back(m_.twin(h));
  }

  // The lowest boundary edge (smallest y of its midpoint) starts the lowest boundary loop.
  void add_automatic_start() {
    CoarseHalfedge best;
    float best_y = 0;
    for (CoarseHalfedge h : m_.halfedges()) {
      if (!m_.is_border(h)) continue;
      float y = m_.at(m_.tail(h)).y + m_.at(m_.head(h)).y;
      if (!best.valid() || y < best_y) {
        best = h;
        best_y = y;
      }
    }
    if (!best.valid())
      throw LabelingError(fmt::format(
          "{}: the mesh has no open boundary to start from; name an interior edge to cast on "
          "along in the project file (start: [{{edge: [a, b]}}])",
          m_.source));
    seeds_.push_back(best);
  }

  std::string why_left_over(const std::vector<std::uint32_t>& faces) const {
    std::vector<std::string> reasons;
    for (std::uint32_t i : faces) {
      CoarseFace f(i);
      if (m_.degree(f) > 4)
        return fmt::format(
            "face {} has {} sides; labeling knows quads and triangles (short-row "
            "ends) only",
            i + 1, m_.degree(f));
      if (pending_[i].valid())
        return fmt::format(
            "triangle {} is reached only from below ({}), so which side carries its short rows "
            "is unknown; label the faces beside it first, or mark it (short_rows: faces: [{{face: "
            "{}, wide_edge: [a, b]}}])",
            i + 1, m_.describe(pending_[i]), i + 1);
    }
    CoarseHalfedge border, from_above, from_side;
    for (std::uint32_t i : faces)
      for (CoarseHalfedge h : m_.halfedges(CoarseFace(i))) {
        if (m_.is_border(h)) {
          if (!border.valid()) border = h;
          continue;
        }
        CoarseFace other = m_.face(m_.twin(h));
        if (!labelled(other)) continue;
        CoarseRole r = L_.role[m_.twin(h).index()];
        if (r == CoarseRole::bottom && !from_above.valid()) from_above = h;
        if (is_side(r) && !from_side.valid()) from_side = h;
      }
    if (from_side.valid())
      return fmt::format(
          "they are reached only across {}, where rows stop (a mismatch mark or a "
          "face rows cannot cross); add a start for them",
          m_.describe(from_side));
    if (from_above.valid() && !border.valid())
      return fmt::format(
          "they form a ring with no open boundary, reached only from above ({}); "
          "add a start on one of their edges (a cast-on along it)",
          m_.describe(from_above));
    if (from_above.valid())
      return fmt::format(
          "they are reached only from above ({}), so rows would run into them "
          "head-on; add a start at their own boundary, e.g. start: [{{edge: [{}, "
          "{}]}}]",
          m_.describe(from_above), m_.tail(border).index() + 1, m_.head(border).index() + 1);
    if (!border.valid())
      return "they form a closed surface with no open boundary; add a start on one of their "
             "edges (a cast-on along it)";
    return fmt::format(
        "they are not connected to any start; add one at their boundary, e.g. "
        "start: [{{edge: [{}, {}]}}]",
        m_.tail(border).index() + 1, m_.head(border).index() + 1);
  }

  void report_leftovers() const {
    std::vector<std::uint32_t> component(m_.num_faces(), kUnlabelled);
    std::string report;
    std::uint32_t groups = 0;
    for (CoarseFace f : m_.faces()) {
      if (labelled(f) || component[f.index()] != kUnlabelled) continue;
      std::vector<std::uint32_t> faces{f.index()};
      component[f.index()] = groups;
      for (std::size_t k = 0; k < faces.size(); ++k)
        for (CoarseHalfedge h : m_.halfedges(CoarseFace(faces[k]))) {
          if (m_.is_border(h)) continue;
          CoarseFace g = m_.face(m_.twin(h));
          if (labelled(g) || component[g.index()] != kUnlabelled) continue;
          component[g.index()] = groups;
          faces.push_back(g.index());
        }
      ++groups;
      Vec3 c;
      for (std::uint32_t i : faces) {
        Vec3 p = m_.centroid(CoarseFace(i));
        c = {c.x + p.x / faces.size(), c.y + p.y / faces.size(), c.z + p.z / faces.size()};
      }
      report += fmt::format("\n  face{} {} (around {}): {}", faces.size() == 1 ? "" : "s",
                            face_ranges(faces), format_point(c), why_left_over(faces));
    }
    if (!report.empty())
      throw LabelingError(fmt::format("{}: {} of {} faces could not be labelled:{}", m_.source,
                                      std::count(L_.order.begin(), L_.order.end(), kUnlabelled),
                                      m_.num_faces(), report));
  }

  const CoarseMesh& m_;
  const Project& p_;
  Labeling L_;
  std::deque<CoarseHalfedge> seeds_;
  std::vector<CoarseHalfedge> pending_;    // per triangle: the bottom a row below handed it
  std::vector<CoarseHalfedge> wide_mark_;  // per face: the wide side the project names
  std::uint32_t next_order_ = 0;
};

}  // namespace

Labeling label_coarse_mesh(const CoarseMesh& mesh, const Project& project) {
  return Labeler(mesh, project).run();
}

}  // namespace skein
