#include "knitout/fabric_stitch_mesh.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <numeric>
#include <sstream>
#include <unordered_map>
#include <vector>

#include "common/error.hpp"
#include "driver/pipeline.hpp"
#include "knitout/fabric_stitch_graph.hpp"
#include "mesh/autoknit_st.hpp"
#include "mesh/obj_format.hpp"

namespace skein::knitout {
namespace {

constexpr std::uint32_t kNone = 0xffffffffu;

// A loop of the fabric between two faces: its maker, which of the maker's loops it is along the
// yarn, and its taker (kNone: it ends nowhere, which the .st reader does not allow).
struct FabricLoop {
  StitchId maker = kNoStitch, taker = kNoStitch;
  std::uint8_t yarn_slot = 0;
  bool alive = true;
};

// How a face stands: its course edges, which way its yarn runs, and whether it is a short-row
// end (its yarn leaves on the side it came in by).
struct FaceShape {
  std::uint32_t first_corner = 0;
  std::uint8_t bottoms = 1, tops = 1;
  bool left_to_right = true;
  bool turns = false;
  StitchType type = StitchType::k;
  std::vector<std::uint32_t> takes, makes;  // loop ids, each left to right in the face's frame
};

// The ends of a wale edge, bottom first, as corner ids.
struct WaleEnds {
  std::uint32_t bottom, top;
};

// Union-find over corners: the faces' corners glued into the mesh's vertices.
struct Corners {
  std::vector<std::uint32_t> parent;
  std::uint32_t add(std::uint32_t n) {
    auto first = static_cast<std::uint32_t>(parent.size());
    parent.resize(parent.size() + n);
    std::iota(parent.begin() + first, parent.end(), first);
    return first;
  }
  std::uint32_t find(std::uint32_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  void glue(std::uint32_t a, std::uint32_t b) {
    a = find(a), b = find(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  }
};

class GluedFabric {
 public:
  GluedFabric(const KnitGraph& g, const std::vector<std::array<double, 3>>& positions,
              const std::vector<bool>& purled, const std::string& file)
      : g_(g),
        positions_(positions),
        purled_(purled),
        file_(file),
        kept_(g.size(), true),
        merged_(g.size(), false),
        turns_after_wrap_(g.size(), false),
        next_(g.yarn_next),
        row_size_(g.row_shape.size(), 0) {
    for (std::uint32_t row : g.row) ++row_size_[row];
    for (const Loop& l : g.loops) loops_.push_back({l.maker, l.taker, yarn_slot(l)});
  }

  StitchMesh build() {
    fold_wraps();
    merge_decrease_chains();
    shape_faces();
    glue_loops();
    glue_yarn();
    return lay_out();
  }

 private:
  [[noreturn]] void refuse(const std::string& why) const {
    throw UnsupportedError(
        fmt::format("the fabric {} makes cannot be written as a stitch mesh: {}; write it as a "
                    "stitch graph (--fabric NAME.st) instead",
                    file_, why));
  }

  std::string where(StitchId s) const {
    return fmt::format("the stitch on needle {} of row {} ({})", positions_[s][0], g_.row[s] + 1,
                       abbreviation(g_.type[s]));
  }

  // A knit graph counts a stitch's loops from its left: along a yarn going right to left, the
  // other way.
  std::uint8_t yarn_slot(const Loop& l) const {
    bool two = g_.loops_made_by(l.maker).size() == 2;
    bool backwards = g_.direction[l.maker] == CourseDirection::right_to_left;
    return two && backwards ? static_cast<std::uint8_t>(1 - l.maker_slot) : l.maker_slot;
  }

  std::uint32_t taken_loop(StitchId s) const { return g_.loops_taken_by(s)[0]; }
  std::uint32_t made_loop(StitchId s) const { return g_.loops_made_by(s)[0]; }

  // A wrap: a tuck the yarn turns at, laid over a loop beside the short row's end. A stitch mesh
  // turns inside a face (sr4, sr5) and has no face beyond the turn, so the wrap is folded into
  // the wale it lies on: the stitch knit through it takes the loop under it.
  void fold_wraps() {
    for (StitchId t = 0; t < g_.size(); ++t)
      if (is_wrap(t)) fold_wrap(t);
  }

  // The yarn turns at the tuck: after it, or before it when the tuck is made going back (round
  // a tube's fold, the wrap on the other bed is tucked in the pass after the turn), the stitch
  // graph then beginning the row after the turn with it.
  bool is_wrap(StitchId t) const {
    if (g_.type[t] != StitchType::tuck) return false;
    if (t == 0 || g_.yarn_next[t - 1] != t) return false;  // a yarn's first stitch turns nothing
    bool made_going_back = g_.direction[t - 1] != g_.direction[t];
    return g_.yarn_link[t] == YarnLink::turn ||
           (made_going_back && g_.yarn_link[t - 1] == YarnLink::turn);
  }

  void fold_wrap(StitchId t) {
    FabricLoop& under = loops_[taken_loop(t)];
    FabricLoop& over = loops_[made_loop(t)];
    over.maker = under.maker, over.yarn_slot = under.yarn_slot;
    under.alive = false;
    kept_[t] = false;
    next_[t - 1] = next_[t];
    turns_after_wrap_[t - 1] = true;
  }

  // `.st` says a decrease of three loops as two `d`s, the second taking the first's loop: one
  // face of the catalogue's widest decrease (s2kp). Wider ones have no face.
  void merge_decrease_chains() {
    for (StitchId s = 1; s < g_.size(); ++s) {
      if (!kept_[s] || g_.type[s] != StitchType::k2tog || g_.type[s - 1] != StitchType::k2tog ||
          next_[s - 1] != s || loops_[made_loop(s - 1)].taker != s)
        continue;
      if (merged_[s - 1]) refuse(fmt::format("{} decreases four loops or more", where(s)));
      loops_[made_loop(s - 1)].alive = false;
      for (std::uint32_t l : g_.loops_taken_by(s - 1)) loops_[l].taker = s;
      kept_[s - 1] = false;
      merged_[s] = true;
      if (s >= 2 && next_[s - 2] == s - 1) next_[s - 2] = s;
    }
  }

  bool is_turn(StitchId s) const {
    return g_.yarn_link[s] == YarnLink::turn || turns_after_wrap_[s];
  }

  // A turn where the next stitch takes none of this one's loops: the work turns in the middle
  // of the row, and this stitch is its short-row end.
  bool is_short_row_end(StitchId s, const FaceShape& f) const {
    if (next_[s] == kNoStitch || !is_turn(s) || f.makes.empty() || f.takes.empty()) return false;
    return std::none_of(f.makes.begin(), f.makes.end(),
                        [&](std::uint32_t l) { return loops_[l].taker == next_[s]; });
  }

  void shape_faces() {
    std::vector<std::vector<std::uint32_t>> taken(g_.size()), made(g_.size());
    for (std::uint32_t l = 0; l < loops_.size(); ++l) {
      if (!loops_[l].alive) continue;
      made[loops_[l].maker].push_back(l);
      taken[loops_[l].taker].push_back(l);
    }
    faces_.resize(g_.size());
    for (StitchId s = 0; s < g_.size(); ++s) {
      if (!kept_[s]) continue;
      FaceShape& f = faces_[s];
      f.left_to_right = g_.direction[s] != CourseDirection::right_to_left;
      f.takes = std::move(taken[s]);
      f.makes = std::move(made[s]);
      f.type = merged_[s] ? StitchType::s2kp : g_.type[s];
      if (f.type == StitchType::k2tog && purled_[s]) f.type = StitchType::p2tog;
      f.turns = is_short_row_end(s, f);
      if (f.turns) f.type = short_row_end(s, f);
      f.bottoms = static_cast<std::uint8_t>(std::max<std::size_t>(f.takes.size(), 1));
      f.tops = static_cast<std::uint8_t>(std::max<std::size_t>(f.makes.size(), 1));
      f.first_corner = corners_.add(f.bottoms + f.tops + 2u);
    }
    for (StitchId s = 0; s < g_.size(); ++s)
      if (kept_[s]) order_loops(s);
  }

  StitchType short_row_end(StitchId s, const FaceShape& f) const {
    if (f.takes.size() != 1)
      refuse(
          fmt::format("{} turns the work in the middle of its row and takes {} loops; a "
                      "short-row end (sr4, sr5) takes one",
                      where(s), f.takes.size()));
    return f.makes.size() == 1 ? StitchType::sr4 : StitchType::sr5;
  }

  // Left to right in the face's frame: a stitch's loops in the order its yarn made them, the
  // other way when it runs right to left; loops taken from several stitches by their makers'
  // order the same way, a round's loops from where the round begins.
  void order_loops(StitchId s) {
    FaceShape& f = faces_[s];
    std::sort(f.makes.begin(), f.makes.end(), [&](std::uint32_t a, std::uint32_t b) {
      return loops_[a].yarn_slot < loops_[b].yarn_slot;
    });
    if (!f.left_to_right) std::reverse(f.makes.begin(), f.makes.end());
    if (f.takes.size() < 2) return;
    auto key = [&](std::uint32_t l) { return std::pair{loops_[l].maker, loops_[l].yarn_slot}; };
    std::sort(f.takes.begin(), f.takes.end(),
              [&](std::uint32_t a, std::uint32_t b) { return key(a) < key(b); });
    rotate_across_round_start(f.takes);
    StitchId maker = loops_[f.takes[0]].maker;
    if (g_.direction[maker] == CourseDirection::right_to_left)
      std::reverse(f.takes.begin(), f.takes.end());
  }

  // Loops taken across the start of a round (its last stitch's and its first's) begin after
  // the widest gap between their makers round the round.
  void rotate_across_round_start(std::vector<std::uint32_t>& takes) const {
    StitchId first = loops_[takes.front()].maker, last = loops_[takes.back()].maker;
    std::uint32_t row = g_.row[first];
    if (g_.row[last] != row || g_.row_shape[row] != RowShape::closed) return;
    std::uint32_t widest = first + row_size_[row] - last;
    std::size_t at = 0;
    for (std::size_t i = 1; i < takes.size(); ++i) {
      std::uint32_t gap = loops_[takes[i]].maker - loops_[takes[i - 1]].maker;
      if (gap > widest) widest = gap, at = i;
    }
    std::rotate(takes.begin(), takes.begin() + static_cast<std::ptrdiff_t>(at), takes.end());
  }

  // Corner ids of a face (B bottom and T top course edges, B + T + 2 corners), counter-clockwise
  // from the bottom left: the bottom corners b_0..b_B, then the top corners from right to left
  // u_T..u_0. A short-row end has a corner where its yarn turns, m, on the side it enters by,
  // and there its top run meets its bottom run: turning on its right, b_0..b_B m u_T..u_1 (u_0
  // is b_0); on its left, b_0..b_B u_T-1..u_0 m (u_T is b_B).
  std::uint32_t bottom_corner(StitchId s, std::uint32_t i) const {
    return faces_[s].first_corner + i;
  }
  std::uint32_t top_corner(StitchId s, std::uint32_t j) const {
    const FaceShape& f = faces_[s];
    std::uint32_t after_bottom = f.first_corner + f.bottoms + 1u;
    if (!f.turns) return after_bottom + (f.tops - j);
    if (!f.left_to_right) return j == 0 ? bottom_corner(s, 0) : after_bottom + 1 + (f.tops - j);
    return j == f.tops ? bottom_corner(s, f.bottoms) : after_bottom + (f.tops - 1 - j);
  }
  std::uint32_t turn_corner(StitchId s) const {
    const FaceShape& f = faces_[s];
    return f.first_corner + f.bottoms + 1u + (f.left_to_right ? f.tops : 0u);
  }

  WaleEnds wale(StitchId s, bool out) const {
    const FaceShape& f = faces_[s];
    WaleEnds left{bottom_corner(s, 0), top_corner(s, 0)};
    WaleEnds right{bottom_corner(s, f.bottoms), top_corner(s, f.tops)};
    if (f.turns) {
      std::uint32_t m = turn_corner(s);
      WaleEnds side = f.left_to_right ? left : right;
      return out ? WaleEnds{m, side.top} : WaleEnds{side.bottom, m};
    }
    return out == f.left_to_right ? right : left;
  }

  std::uint32_t slot_of(const std::vector<std::uint32_t>& loops, std::uint32_t l) const {
    return static_cast<std::uint32_t>(std::find(loops.begin(), loops.end(), l) - loops.begin());
  }

  void glue_loops() {
    for (std::uint32_t l = 0; l < loops_.size(); ++l) {
      if (!loops_[l].alive) continue;
      StitchId maker = loops_[l].maker, taker = loops_[l].taker;
      std::uint32_t i = slot_of(faces_[maker].makes, l), j = slot_of(faces_[taker].takes, l);
      corners_.glue(top_corner(maker, i), bottom_corner(taker, j));
      corners_.glue(top_corner(maker, i + 1), bottom_corner(taker, j + 1));
    }
  }

  // A tube's seam: a wale up from a stitch of its yarn piece's first round (the stitch graph's
  // first closed row), through the loop each seam stitch makes first in its frame, where no row
  // going the other way round crosses it (a heel's short rows turn back before it): the first
  // such wale from the round's start.
  void find_seams() {
    on_seam_.assign(g_.size(), false);
    std::vector<bool> seeded(piece_.back() + 1, false);
    std::vector<StitchId> wale;
    for (StitchId s = 0; s < g_.size(); ++s) {
      bool round_start =
          (s == 0 || g_.row[s - 1] != g_.row[s]) && g_.row_shape[g_.row[s]] == RowShape::closed;
      if (!round_start || seeded[piece_[s]]) continue;
      seeded[piece_[s]] = true;
      for (StitchId seed = s; seed < g_.size() && g_.row[seed] == g_.row[s]; ++seed) {
        if (!kept_[seed] || !wale_up(seed, g_.direction[s], wale)) continue;
        for (StitchId x : wale) on_seam_[x] = true;
        break;
      }
    }
  }

  // The wale up from `seed`; false when a row going against `round_way` crosses it.
  bool wale_up(StitchId seed, CourseDirection round_way, std::vector<StitchId>& wale) const {
    wale.clear();
    for (StitchId x = seed; x != kNoStitch && !on_seam_[x];) {
      if (g_.direction[x] != round_way && next_[x] != kNoStitch && !is_turn(x)) return false;
      wale.push_back(x);
      x = faces_[x].makes.empty() ? kNoStitch : loops_[faces_[x].makes[0]].taker;
    }
    return true;
  }

  void number_pieces() {
    piece_.assign(g_.size(), 0);
    edge_turns_before_.assign(g_.size(), 0);
    tubular_.assign(1, false);
    for (StitchId s = 1; s < g_.size(); ++s) {
      piece_[s] = piece_[s - 1] + (g_.yarn_next[s - 1] == s ? 0 : 1);
      if (piece_[s] == tubular_.size()) tubular_.push_back(false);
      tubular_[piece_[s]] = tubular_[piece_[s]] || g_.row_shape[g_.row[s]] == RowShape::closed;
      bool edge_turn = kept_[s - 1] && is_turn(s - 1) && !faces_[s - 1].turns;
      edge_turns_before_[s] = edge_turns_before_[s - 1] + (edge_turn ? 1 : 0);
    }
  }

  // The round's first stitch under a stitch on the seam: the maker of its loop on the seam, or
  // below a short row's end there (a heel's short row turning at the seam lies on the round
  // it turns on) the stitch under that.
  StitchId seam_below(StitchId s) const {
    for (StitchId x = s;;) {
      auto on_seam = std::find_if(faces_[x].takes.begin(), faces_[x].takes.end(),
                                  [&](std::uint32_t l) { return on_seam_[loops_[l].maker]; });
      if (on_seam == faces_[x].takes.end()) return kNoStitch;
      x = loops_[*on_seam].maker;
      if (!faces_[x].turns) return x;
    }
  }

  // The round ending at `last` closes on `first` when the yarn between them runs round without
  // turning at an edge (it may turn in short-row ends: a heel) and nothing comes into `first`
  // along its row yet.
  bool close_round(StitchId last, StitchId first) {
    if (first == kNoStitch || first >= last || piece_[first] != piece_[last] ||
        edge_turns_before_[last] != edge_turns_before_[first] || entered_[first])
      return false;
    glue_wale(last, first);
    seams_.push_back({wale(last, true).bottom, wale(last, true).top, faces_[first].left_to_right});
    return true;
  }

  void glue_wale(StitchId from, StitchId to) {
    WaleEnds out = wale(from, true), in = wale(to, false);
    corners_.glue(out.bottom, in.bottom);
    corners_.glue(out.top, in.top);
    entered_[to] = true;
  }

  // Along a row, and from a round to the next, the yarn crosses a wale edge the two faces
  // share (a tube's rounds are a helix); where it comes round to the tube's seam, the round
  // closes instead: its last stitch meets its first across a shift-path, as the round bound off
  // last does. From a row to the next at a turn the faces are not glued: the loops they take
  // place them, and the knit graph's reader of meshes finds the yarn's way where it leaves at
  // the top of one face's wale edge and enters at the bottom of the next's.
  void glue_yarn() {
    number_pieces();
    find_seams();
    entered_.assign(g_.size(), false);
    std::vector<bool> laid = lay_cast_on_passes();
    std::vector<StitchId> round_start(piece_.back() + 1, kNoStitch);
    for (StitchId s = 0; s < g_.size(); ++s) {
      if (!kept_[s]) continue;
      StitchId next = next_[s];
      if (laid[s] && next != kNoStitch && laid[next]) continue;
      if (next == kNoStitch) {
        close_round(s, round_start[piece_[s]]);
      } else if (faces_[s].turns) {
        glue_wale(s, next);
      } else if (!is_turn(s)) {
        if (on_seam_[next] && !faces_[next].turns && close_round(s, seam_below(next)))
          round_start[piece_[s]] = next;
        else
          glue_wale(s, next);
      }
    }
  }

  // A cast-on is often made in more than one pass (every other needle one way, the others
  // back), which no row of faces says: its stitches are laid as one row in the order of their
  // needles (round a tube: the front left to right, the back right to left), going the way the
  // row after it goes round a tube, or the other way on a sheet. Returns the stitches laid.
  std::vector<bool> lay_cast_on_passes() {
    std::vector<bool> laid(g_.size(), false);
    auto cast_on = [&](StitchId s) { return s != kNoStitch && g_.type[s] == StitchType::co; };
    std::vector<StitchId> run;
    for (StitchId s = 0; s < g_.size(); ++s) {
      if (!kept_[s] || !cast_on(s) || (s > 0 && next_[s - 1] == s && cast_on(s - 1))) continue;
      run.assign(1, s);
      bool turns = false;
      for (StitchId x = s; cast_on(next_[x]); x = next_[x]) {
        turns = turns || is_turn(x) || g_.direction[x] != g_.direction[next_[x]];
        run.push_back(next_[x]);
      }
      if (!turns) continue;
      bool tube = tubular_[piece_[s]];
      auto place = [&](StitchId c) {
        double x = positions_[c][0], back = positions_[c][2];
        return tube ? std::pair{back, back != 0 ? -x : x} : std::pair{x, back};
      };
      std::stable_sort(run.begin(), run.end(),
                       [&](StitchId a, StitchId b) { return place(a) < place(b); });
      StitchId after = next_[run.back()];
      bool left_to_right = after == kNoStitch || faces_[after].left_to_right == tube;
      for (StitchId c : run) faces_[c].left_to_right = left_to_right, laid[c] = true;
      for (std::size_t i = 0; i + 1 < run.size(); ++i)
        left_to_right ? glue_wale(run[i], run[i + 1]) : glue_wale(run[i + 1], run[i]);
    }
    return laid;
  }

  struct Seam {
    std::uint32_t bottom, top;
    bool left_to_right;
  };

  StitchMesh lay_out() {
    StitchMeshBuilder builder(file_ + " (its fabric)");
    std::vector<std::uint32_t> vertex(corners_.parent.size(), kNone);
    std::vector<Vec3> sum;
    std::vector<float> count;
    auto vertex_of = [&](std::uint32_t corner, Vec3 at) {
      std::uint32_t root = corners_.find(corner);
      if (vertex[root] == kNone) {
        vertex[root] = builder.add_vertex({}).index();
        sum.push_back({});
        count.push_back(0);
      }
      Vec3& p = sum[vertex[root]];
      p.x += at.x, p.y += at.y, p.z += at.z;
      ++count[vertex[root]];
      return Vertex(vertex[root]);
    };
    std::vector<Vertex> corners;
    std::vector<EdgeRole> roles;
    Outlines outlines;
    for (StitchId s = 0; s < g_.size(); ++s) {
      if (!kept_[s]) continue;
      corners.clear();
      roles.clear();
      face_outline(s, corners, roles, vertex_of);
      builder.add_face(corners, roles, faces_[s].type);
      outlines.add(s, corners);
    }
    StitchMesh mesh = build_mesh(std::move(builder), outlines);
    for (Vertex v : mesh.vertices()) {
      const Vec3& p = sum[v.index()];
      float n = count[v.index()];
      mesh.position[v] = {p.x / n, p.y / n, p.z / n};
    }
    for (const Seam& seam : seams_) {
      Edge e = mesh.find_edge(Vertex(vertex[corners_.find(seam.bottom)]),
                              Vertex(vertex[corners_.find(seam.top)]));
      if (e.valid()) mesh.shift_path[e] = seam.left_to_right ? kShiftUpRight : kShiftUpLeft;
    }
    return mesh;
  }

  // The face's corners counter-clockwise, each with the role of the edge from it to the next.
  template <class VertexOf>
  void face_outline(StitchId s, std::vector<Vertex>& corners, std::vector<EdgeRole>& roles,
                    VertexOf& vertex_of) const {
    const FaceShape& f = faces_[s];
    const auto& p = positions_[s];
    float x = static_cast<float>(p[0]), y = static_cast<float>(p[1]), z = static_cast<float>(p[2]);
    float side = z == 0 ? 1.f : -1.f;  // a tube's back is seen from behind
    auto corner = [&](std::uint32_t id, float along, float up, EdgeRole role) {
      corners.push_back(vertex_of(id, Vec3{x + side * (along - 0.5f), y + up, z}));
      roles.push_back(role);
    };
    auto bottom = [&](std::uint32_t i, EdgeRole role) {
      corner(bottom_corner(s, i), static_cast<float>(i) / f.bottoms, -0.5f, role);
    };
    auto top = [&](std::uint32_t j, EdgeRole role) {
      corner(top_corner(s, j), static_cast<float>(j) / f.tops, 0.5f, role);
    };
    for (std::uint32_t i = 0; i < f.bottoms; ++i) bottom(i, EdgeRole::bottom);
    if (!f.turns) {
      bottom(f.bottoms, f.left_to_right ? EdgeRole::wale_out : EdgeRole::wale_in);
      for (std::uint32_t j = f.tops; j > 0; --j) top(j, EdgeRole::top);
      top(0, f.left_to_right ? EdgeRole::wale_in : EdgeRole::wale_out);
    } else if (!f.left_to_right) {  // turning on its right
      bottom(f.bottoms, EdgeRole::wale_in);
      corner(turn_corner(s), 1, 0, EdgeRole::wale_out);
      for (std::uint32_t j = f.tops; j > 0; --j) top(j, EdgeRole::top);
    } else {  // turning on its left
      for (std::uint32_t j = f.tops; j > 0; --j) top(j, EdgeRole::top);
      top(0, EdgeRole::wale_out);
      corner(turn_corner(s), 0, 0, EdgeRole::wale_in);
    }
  }

  // Each face's corners, kept to name the stitches where the builder finds faces folded.
  struct Outlines {
    std::vector<StitchId> stitch;
    std::vector<std::uint32_t> first{0};
    std::vector<Vertex> corners;
    void add(StitchId s, const std::vector<Vertex>& outline) {
      stitch.push_back(s);
      corners.insert(corners.end(), outline.begin(), outline.end());
      first.push_back(static_cast<std::uint32_t>(corners.size()));
    }
  };

  // Faces glued where the fabric's loops and yarn say fold over each other where a face would
  // have two corners at one point, or two faces would run the same way along one edge: the
  // builder finds it, and the outlines say which stitches.
  StitchMesh build_mesh(StitchMeshBuilder builder, const Outlines& outlines) const {
    try {
      return std::move(builder).build();
    } catch (const MeshError& e) {
      name_folded_stitches(outlines);
      refuse(fmt::format("{} ({})", kFolded, e.what()));
    }
  }

  void name_folded_stitches(const Outlines& o) const {
    std::unordered_map<std::uint64_t, StitchId> edge_of;  // tail and head: the stitch
    for (std::size_t f = 0; f + 1 < o.first.size(); ++f) {
      std::uint32_t n = o.first[f + 1] - o.first[f];
      for (std::uint32_t i = 0; i < n; ++i) {
        Vertex a = o.corners[o.first[f] + i], b = o.corners[o.first[f] + (i + 1) % n];
        StitchId s = o.stitch[f];
        if (a == b)
          refuse(fmt::format("{}: {} would have two corners at one point", kFolded, where(s)));
        auto [at, added] = edge_of.try_emplace(std::uint64_t{a.index()} << 32 | b.index(), s);
        if (!added)
          refuse(fmt::format("{}: {} and {} would run the same way along one edge", kFolded,
                             where(at->second), where(s)));
      }
    }
  }
  static constexpr const char* kFolded =
      "its stitches, glued where its loops and yarn join them, fold over each other";

  const KnitGraph& g_;
  const std::vector<std::array<double, 3>>& positions_;
  const std::vector<bool>& purled_;  // per stitch: a decrease knit as a purl
  const std::string& file_;
  std::vector<bool> kept_, merged_;
  std::vector<bool> turns_after_wrap_;  // a stitch whose wrap was folded: the yarn turns after it
  std::vector<StitchId> next_;
  std::vector<std::uint32_t> row_size_;  // per row of the stitch graph: its stitches
  std::vector<FabricLoop> loops_;
  std::vector<FaceShape> faces_;
  Corners corners_;
  std::vector<std::uint32_t> piece_, edge_turns_before_;  // per stitch: see number_pieces
  std::vector<bool> tubular_;                             // per yarn piece: it knits rounds
  std::vector<bool> on_seam_, entered_;                   // entered_: a face whose wale_in is glued
  std::vector<Seam> seams_;
};

// The glued mesh alone: the stitch graph's text, its knit graph and positions are freed once
// the faces are laid (a 1.2M-stitch fabric holds each at a few hundred MB).
StitchMesh fabric_stitch_mesh(const Replay& replay, const std::string& file,
                              const std::vector<bool>* border) {
  std::vector<bool> purled;
  std::vector<std::array<double, 3>> positions;
  KnitGraph graph = [&] {
    std::ostringstream st;
    write_fabric_stitch_graph(replay, file, st, border, &purled);
    return parse_autoknit_st(std::move(st).str(), file + " (its fabric)", &positions);
  }();
  return GluedFabric(graph, positions, purled, file).build();
}

}  // namespace

void write_fabric_stitch_mesh(const Replay& replay, const std::string& file, std::ostream& out,
                              const std::vector<bool>* border) {
  StitchMesh mesh = fabric_stitch_mesh(replay, file, border);
  write_stitch_mesh(mesh, out);
  // Never a mesh `skein check` would refuse: the fabric goes as a stitch graph (.st) instead.
  // Checked after writing so that the mesh is not copied: `out` is thrown away on a throw.
  try {
    (void)compile_stitch_mesh(std::move(mesh), file + " (its fabric)");
  } catch (const UnsupportedError&) {
    throw;
  } catch (const Error& e) {
    throw UnsupportedError(fmt::format(
        "{}: the fabric cannot be written as a stitch mesh yet: the mesh laid out does not check "
        "({}); write it as a stitch graph (.st)",
        file, e.what()));
  }
}

}  // namespace skein::knitout
