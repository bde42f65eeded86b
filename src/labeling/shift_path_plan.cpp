#include "labeling/shift_path_plan.hpp"

#include <algorithm>

#include "common/error.hpp"

namespace skein {
namespace {

constexpr std::uint32_t kNone = ~0u;

// Paths are planned per chain: the rings one path runs through, bottom to top. A chain whose
// rings are stacked exactly (each face on a face of the ring below) and free of marks and
// turns is *free*: its path may run up any column, so it is placed only when a ring above
// claims it at one of its top corners (or, unclaimed, at its first face).
class PathPlanner {
 public:
  PathPlanner(const CoarseMesh& mesh, const Labeling& labeling, const std::vector<Ring>& rings,
              std::uint8_t option)
      : m_(mesh),
        L_(labeling),
        rings_(rings),
        option_(option),
        paths_(rings.size()),
        chain_of_(rings.size(), kNone),
        ring_of_(mesh.num_faces(), kNone),
        fixed_top_at_(mesh.num_vertices()),
        free_corner_at_(mesh.num_vertices()),
        rings_starting_at_(mesh.num_vertices()) {
    for (std::uint32_t r = 0; r < rings.size(); ++r)
      for (CoarseFace f : rings[r].faces) {
        ring_of_[f.index()] = r;
        rings_starting_at_[bottom_left(f).index()].push_back(r);
      }
  }

  std::vector<RingPath> run() && {
    for (std::uint32_t r = 0; r < rings_.size(); ++r) plan(r);
    for (std::uint32_t c = 0; c < chains_.size(); ++c)
      if (chains_[c].free) fix(c, first_column_top(chains_[c]));
    return std::move(paths_);
  }

 private:
  struct Chain {
    std::vector<std::uint32_t> rings;
    std::uint8_t option = 1;
    bool free = false;
    CoarseVertex top;  // fixed chains: where the path leaves its last ring
  };

  CoarseHalfedge left(CoarseFace f) const { return L_.find(m_, f, CoarseRole::left); }
  CoarseVertex bottom_left(CoarseFace f) const { return m_.head(left(f)); }
  CoarseVertex top_left(CoarseFace f) const { return m_.tail(left(f)); }

  void plan(std::uint32_t r) {
    const Ring& ring = rings_[r];
    if (ring.mark) {
      auto [i, option] = *ring.mark;
      if (!take_fixed_top(r, i, option) && !claim_free_chain(r, i, option))
        start_fixed_chain(r, i, option);
      return;
    }
    if (extend_free_chain(r)) return;
    // Fixed paths first: a free chain below may still be claimed by another ring.
    for (std::size_t i = 0; i < ring.faces.size(); ++i)
      if (ring.can_start[i] && take_fixed_top(r, i, std::nullopt)) return;
    if (claim_scarcest_free_chain(r)) return;
    if (std::all_of(ring.can_start.begin(), ring.can_start.end(), [](auto c) { return c; }))
      return start_free_chain(r);
    std::size_t first =
        std::find(ring.can_start.begin(), ring.can_start.end(), 1) - ring.can_start.begin();
    start_fixed_chain(r, first, option_);
  }

  // Ring r continues chain c with its path up face i's left side.
  void join(std::uint32_t c, std::uint32_t r, std::size_t i, std::optional<std::uint8_t> option) {
    Chain& chain = chains_[c];
    if (option) chain.option = *option;
    paths_[r] = {i, chain.option, true};
    chain.rings.push_back(r);
    chain_of_[r] = c;
    chain.top = top_left(rings_[r].faces[i]);
    fixed_top_at_[chain.top.index()].push_back(c);
  }

  // A fixed chain's top is taken once a ring continues it: the chain's top then moves up.
  bool take_fixed_top(std::uint32_t r, std::size_t i, std::optional<std::uint8_t> option) {
    CoarseVertex v = bottom_left(rings_[r].faces[i]);
    for (std::uint32_t c : fixed_top_at_[v.index()])
      if (!chains_[c].free && chains_[c].top == v) {
        join(c, r, i, option);
        return true;
      }
    return false;
  }
  // The free chain whose last ring has a top corner at v (kNone if none).
  std::uint32_t free_chain_at(CoarseVertex v) const {
    for (auto [c, q] : free_corner_at_[v.index()])
      if (chains_[c].free && chains_[c].rings.back() == q) return c;
    return kNone;
  }

  bool claim_free_chain(std::uint32_t r, std::size_t i, std::optional<std::uint8_t> option) {
    CoarseVertex v = bottom_left(rings_[r].faces[i]);
    std::uint32_t c = free_chain_at(v);
    if (c == kNone) return false;
    fix(c, v);
    join(c, r, i, option);
    return true;
  }

  // Of the free chains ring r could go on from, the one the fewest rings after r could
  // claim instead, so that every ring above a junction finds a path where one can (a
  // greedy matching of incoming tubes to outgoing ones).
  bool claim_scarcest_free_chain(std::uint32_t r) {
    const Ring& ring = rings_[r];
    std::size_t best = ring.faces.size();
    std::size_t best_claimers = 0;
    for (std::size_t i = 0; i < ring.faces.size(); ++i) {
      std::uint32_t c = ring.can_start[i] ? free_chain_at(bottom_left(ring.faces[i])) : kNone;
      if (c == kNone) continue;
      std::size_t n = later_claimers(c, r);
      if (best == ring.faces.size() || n < best_claimers) best = i, best_claimers = n;
    }
    return best < ring.faces.size() && claim_free_chain(r, best, std::nullopt);
  }

  // How many rings after r start at a top corner of free chain c.
  std::size_t later_claimers(std::uint32_t c, std::uint32_t r) const {
    std::vector<std::uint32_t> claimers;
    for (CoarseFace f : rings_[chains_[c].rings.back()].faces)
      for (std::uint32_t r2 : rings_starting_at_[top_left(f).index()])
        if (r2 > r) claimers.push_back(r2);
    std::sort(claimers.begin(), claimers.end());
    return static_cast<std::size_t>(std::unique(claimers.begin(), claimers.end()) -
                                    claimers.begin());
  }

  // Ring r sits exactly on the last ring of a free chain: the chain grows and stays free.
  bool extend_free_chain(std::uint32_t r) {
    const Ring& ring = rings_[r];
    if (!std::all_of(ring.can_start.begin(), ring.can_start.end(), [](auto c) { return c; }))
      return false;
    std::uint32_t below = kNone;
    for (CoarseFace f : ring.faces) {
      CoarseHalfedge bottom = L_.find(m_, f, CoarseRole::bottom);
      if (m_.is_border(bottom) || L_[m_.twin(bottom)] != CoarseRole::top) return false;
      std::uint32_t q = ring_of_[m_.face(m_.twin(bottom)).index()];
      if (q == kNone || (below != kNone && q != below)) return false;
      below = q;
    }
    if (rings_[below].faces.size() != ring.faces.size()) return false;
    std::uint32_t c = chain_of_[below];
    if (!chains_[c].free || chains_[c].rings.back() != below) return false;
    chains_[c].rings.push_back(r);
    chain_of_[r] = c;
    register_free_corners(c, r);
    return true;
  }

  void start_free_chain(std::uint32_t r) {
    std::uint32_t c = static_cast<std::uint32_t>(chains_.size());
    chains_.push_back({{r}, option_, true, {}});
    chain_of_[r] = c;
    register_free_corners(c, r);
  }

  void start_fixed_chain(std::uint32_t r, std::size_t i, std::uint8_t option) {
    std::uint32_t c = static_cast<std::uint32_t>(chains_.size());
    chains_.push_back({{}, option, false, {}});
    join(c, r, i, option);
    paths_[r].continued = false;
  }

  void register_free_corners(std::uint32_t c, std::uint32_t r) {
    for (CoarseFace f : rings_[r].faces) free_corner_at_[top_left(f).index()].push_back({c, r});
  }

  // Places a free chain's path so that it leaves its last ring at `corner`: down the stack,
  // each ring's path face is the one whose top-left corner is where the path of the ring
  // above starts.
  void fix(std::uint32_t c, CoarseVertex corner) {
    Chain& chain = chains_[c];
    chain.free = false;
    chain.top = corner;
    fixed_top_at_[corner.index()].push_back(c);
    for (std::size_t k = chain.rings.size(); k-- > 0;) {
      std::uint32_t r = chain.rings[k];
      const std::vector<CoarseFace>& faces = rings_[r].faces;
      auto at = std::find_if(faces.begin(), faces.end(),
                             [&](CoarseFace f) { return top_left(f) == corner; });
      SKEIN_ASSERT(at != faces.end(), "a free chain's rings are stacked column on column");
      paths_[r] = {static_cast<std::size_t>(at - faces.begin()), chain.option, k > 0};
      corner = bottom_left(*at);
    }
  }

  // Where the path of an unclaimed free chain leaves it when it starts at its first face.
  CoarseVertex first_column_top(const Chain& chain) const {
    CoarseVertex corner = top_left(rings_[chain.rings.front()].faces.front());
    for (std::size_t k = 1; k < chain.rings.size(); ++k)
      for (CoarseFace f : rings_[chain.rings[k]].faces)
        if (bottom_left(f) == corner) {
          corner = top_left(f);
          break;
        }
    return corner;
  }

  const CoarseMesh& m_;
  const Labeling& L_;
  const std::vector<Ring>& rings_;
  std::uint8_t option_;
  std::vector<RingPath> paths_;
  std::vector<Chain> chains_;
  std::vector<std::uint32_t> chain_of_;                   // per ring
  std::vector<std::uint32_t> ring_of_;                    // per face (kNone: not in a ring)
  std::vector<std::vector<std::uint32_t>> fixed_top_at_;  // per vertex: chains whose top it was
  std::vector<std::vector<std::pair<std::uint32_t, std::uint32_t>>> free_corner_at_;  // (c, r)
  std::vector<std::vector<std::uint32_t>> rings_starting_at_;  // per vertex: rings with a face
                                                               // whose bottom-left corner it is
};

}  // namespace

std::vector<RingPath> plan_shift_paths(const CoarseMesh& mesh, const Labeling& labeling,
                                       const std::vector<Ring>& rings, std::uint8_t option) {
  return PathPlanner(mesh, labeling, rings, option).run();
}

}  // namespace skein
