#include "labeling/yarn_plan.hpp"

#include <algorithm>
#include <functional>
#include <queue>

#include "common/error.hpp"

namespace skein {
namespace {

constexpr std::uint32_t kNone = ~0u;

// Rows are planned in chains: the rows one yarn runs through, bottom to top, each starting
// where the one before stopped. A chain of rings stacked exactly (each face on a face of the
// ring below) with no marks or turns is *free*: its path may run up any column, so it is
// placed only when a row above claims it at one of its top corners (or, unclaimed, up its
// first face). Rows are taken bottom to top (every row after the rows below it), and each
// takes the chain the fewest later rows could take instead: a greedy matching of incoming
// yarns to outgoing rows.
class YarnPlanner {
 public:
  YarnPlanner(const CoarseMesh& mesh, const Labeling& labeling, const std::vector<PlannedRow>& rows,
              std::uint8_t option)
      : m_(mesh),
        L_(labeling),
        rows_(rows),
        option_(option),
        entries_(rows.size()),
        chain_of_(rows.size(), kNone),
        row_of_(mesh.num_faces(), kNone),
        position_(rows.size(), kNone),
        fixed_top_at_(mesh.num_vertices()),
        free_corner_at_(mesh.num_vertices()),
        rows_entering_at_(mesh.num_vertices()) {
    for (std::uint32_t r = 0; r < rows.size(); ++r) {
      for (CoarseFace f : rows[r].faces) row_of_[f.index()] = r;
      for (auto [corner, choice] : entry_points(r)) rows_entering_at_[corner.index()].push_back(r);
    }
  }

  std::vector<RowEntry> run() && {
    std::vector<std::uint32_t> order = bottom_to_top();
    for (std::uint32_t k = 0; k < order.size(); ++k) position_[order[k]] = k;
    for (std::uint32_t r : order) rows_[r].closed ? plan_ring(r) : plan_open_row(r);
    for (std::uint32_t c = 0; c < chains_.size(); ++c)
      if (chains_[c].free) fix(c, first_column_top(chains_[c]));
    return std::move(entries_);
  }

 private:
  struct Chain {
    std::vector<std::uint32_t> rows;
    std::uint8_t option = 1;
    bool free = false;
    CoarseVertex top;  // fixed chains: where the yarn leaves its last row
  };
  using Entry = std::pair<CoarseVertex, std::size_t>;  // a corner and the choice starting there

  CoarseHalfedge left(CoarseFace f) const { return L_.find(m_, f, CoarseRole::left); }
  CoarseVertex bottom_left(CoarseFace f) const { return m_.head(left(f)); }
  CoarseVertex top_left(CoarseFace f) const { return m_.tail(left(f)); }

  // Where row r may start: rings up the left side of a face (the choice), open rows at an end.
  std::vector<Entry> entry_points(std::uint32_t r) const {
    const PlannedRow& row = rows_[r];
    std::vector<Entry> entries;
    if (row.closed) {
      for (std::size_t i = 0; i < row.faces.size(); ++i)
        if (row.can_start[i] && (!row.mark || row.mark->first == i))
          entries.emplace_back(bottom_left(row.faces[i]), i);
    } else {
      for (std::size_t end : {0, 1})
        if (row.enter[end].valid()) entries.emplace_back(row.enter[end], end);
    }
    return entries;
  }

  // Labelling order, except that a row comes after every row it sits on (its faces' bottoms
  // are their tops) and every row whose yarn may stop where it can start: rows from several
  // starts may reach a junction in any order.
  std::vector<std::uint32_t> bottom_to_top() const {
    const auto n = static_cast<std::uint32_t>(rows_.size());
    std::vector<std::uint32_t> waiting(n, 0), order;
    std::vector<std::vector<std::uint32_t>> after(n);
    auto add = [&](std::uint32_t first, std::uint32_t then) {
      if (first == kNone || first == then) return;
      after[first].push_back(then);
      ++waiting[then];
    };
    std::vector<std::vector<std::uint32_t>> exits_at(m_.num_vertices());
    for (std::uint32_t r = 0; r < n; ++r)
      for (CoarseVertex v : possible_exits(r)) exits_at[v.index()].push_back(r);
    for (std::uint32_t r = 0; r < n; ++r) {
      for (CoarseFace f : rows_[r].faces) {
        CoarseHalfedge bottom = L_.find(m_, f, CoarseRole::bottom);
        if (bottom.valid() && !m_.is_border(bottom) && L_[m_.twin(bottom)] == CoarseRole::top)
          add(row_of_[m_.face(m_.twin(bottom)).index()], r);
      }
      for (auto [corner, choice] : entry_points(r))
        for (std::uint32_t q : exits_at[corner.index()]) add(q, r);
    }
    std::priority_queue<std::uint32_t, std::vector<std::uint32_t>, std::greater<>> ready;
    for (std::uint32_t r = 0; r < n; ++r)
      if (!waiting[r]) ready.push(r);
    std::vector<std::uint8_t> done(n, 0);
    while (!ready.empty()) {
      std::uint32_t r = ready.top();
      ready.pop();
      order.push_back(r);
      done[r] = 1;
      for (std::uint32_t a : after[r])
        if (--waiting[a] == 0) ready.push(a);
    }
    for (std::uint32_t r = 0; r < n; ++r)  // rows waiting on each other: labelling order
      if (!done[r]) order.push_back(r);
    return order;
  }

  // Where row r's yarn may stop: a ring's top corners (its path may run up any face), an
  // open row's stops.
  std::vector<CoarseVertex> possible_exits(std::uint32_t r) const {
    const PlannedRow& row = rows_[r];
    std::vector<CoarseVertex> exits;
    if (row.closed) {
      for (CoarseFace f : row.faces) exits.push_back(top_left(f));
    } else {
      for (CoarseVertex v : row.stop)
        if (v.valid()) exits.push_back(v);
    }
    return exits;
  }

  void plan_ring(std::uint32_t r) {
    const PlannedRow& ring = rows_[r];
    std::optional<std::uint8_t> option;
    if (ring.mark) option = ring.mark->second;
    if (!ring.mark && extend_free_chain(r)) return;
    if (go_on_from_below(r, option)) return;
    if (!ring.mark &&
        std::all_of(ring.can_start.begin(), ring.can_start.end(), [](std::uint8_t c) { return c; }))
      return start_free_chain(r);
    std::size_t first =
        ring.mark
            ? ring.mark->first
            : static_cast<std::size_t>(std::find(ring.can_start.begin(), ring.can_start.end(), 1) -
                                       ring.can_start.begin());
    start_chain(r, first, option.value_or(option_));
  }

  void plan_open_row(std::uint32_t r) {
    if (!go_on_from_below(r, std::nullopt)) start_chain(r, rows_[r].default_left ? 0 : 1, option_);
  }

  // Row r goes on from a chain whose yarn stops (or may stop) where r can start: a fixed top
  // before a free chain; of each, the one the fewest later rows could take instead, then the
  // entry after which r stops where the later row with the fewest ways in can start.
  bool go_on_from_below(std::uint32_t r, std::optional<std::uint8_t> option) {
    std::vector<Entry> entries = entry_points(r);
    for (bool free : {false, true}) {
      std::optional<std::pair<std::size_t, std::uint32_t>> best;  // (entry, chain)
      std::pair<std::size_t, std::size_t> best_cost;  // (rivals, ways into the row served)
      for (std::size_t k = 0; k < entries.size(); ++k) {
        std::uint32_t c = free ? free_chain_at(entries[k].first) : fixed_chain_at(entries[k].first);
        if (c == kNone) continue;
        std::pair<std::size_t, std::size_t> cost{later_rows_entering_at(corners_of(c), r),
                                                 row_served(r, entries[k].second)};
        if (!best || cost < best_cost) best = {k, c}, best_cost = cost;
      }
      if (!best) continue;
      auto [corner, choice] = entries[best->first];
      if (free) fix(best->second, corner);
      join(best->second, r, choice, option);
      entries_[r].continued = rows_[r].closed;
      return true;
    }
    return false;
  }

  // Where row r stops when entered at its choice: the fewest ways into a later row that can
  // start there (none: the most there are).
  std::size_t row_served(std::uint32_t r, std::size_t choice) const {
    const PlannedRow& row = rows_[r];
    CoarseVertex stop = row.closed ? top_left(row.faces[choice]) : row.stop[choice];
    std::size_t fewest = ~std::size_t{0};
    if (!stop.valid()) return fewest;
    for (std::uint32_t r2 : rows_entering_at_[stop.index()])
      if (position_[r2] > position_[r]) fewest = std::min(fewest, entry_points(r2).size());
    return fewest;
  }

  std::uint32_t fixed_chain_at(CoarseVertex v) const {
    for (std::uint32_t c : fixed_top_at_[v.index()])
      if (!chains_[c].free && chains_[c].top == v) return c;
    return kNone;
  }
  std::uint32_t free_chain_at(CoarseVertex v) const {
    for (auto [c, r] : free_corner_at_[v.index()])
      if (chains_[c].free && chains_[c].rows.back() == r) return c;
    return kNone;
  }

  // Where chain c may hand its yarn on: its top, or any top corner of a free chain.
  std::vector<CoarseVertex> corners_of(std::uint32_t c) const {
    const Chain& chain = chains_[c];
    if (!chain.free) return {chain.top};
    std::vector<CoarseVertex> corners;
    for (CoarseFace f : rows_[chain.rows.back()].faces) corners.push_back(top_left(f));
    return corners;
  }

  std::size_t later_rows_entering_at(const std::vector<CoarseVertex>& corners,
                                     std::uint32_t r) const {
    std::vector<std::uint32_t> rivals;
    for (CoarseVertex v : corners)
      for (std::uint32_t r2 : rows_entering_at_[v.index()])
        if (position_[r2] > position_[r]) rivals.push_back(r2);
    std::sort(rivals.begin(), rivals.end());
    return static_cast<std::size_t>(std::unique(rivals.begin(), rivals.end()) - rivals.begin());
  }

  // Row r goes on from chain c, starting at its choice (a ring's face, an open row's end).
  void join(std::uint32_t c, std::uint32_t r, std::size_t choice,
            std::optional<std::uint8_t> option) {
    Chain& chain = chains_[c];
    const PlannedRow& row = rows_[r];
    if (option) chain.option = *option;
    if (row.closed) {
      entries_[r].face = choice;
      entries_[r].option = chain.option;
      chain.top = top_left(row.faces[choice]);
    } else {
      entries_[r].from_left = choice == 0;
      chain.top = row.stop[choice];
    }
    chain.rows.push_back(r);
    chain_of_[r] = c;
    if (chain.top.valid()) fixed_top_at_[chain.top.index()].push_back(c);
  }

  void start_chain(std::uint32_t r, std::size_t choice, std::uint8_t option) {
    auto c = static_cast<std::uint32_t>(chains_.size());
    chains_.push_back({{}, option, false, {}});
    join(c, r, choice, option);
  }

  void start_free_chain(std::uint32_t r) {
    auto c = static_cast<std::uint32_t>(chains_.size());
    chains_.push_back({{r}, option_, true, {}});
    chain_of_[r] = c;
    register_free_corners(c, r);
  }

  // Ring r sits exactly on the last ring of a free chain: the chain grows and stays free.
  bool extend_free_chain(std::uint32_t r) {
    const PlannedRow& ring = rows_[r];
    if (!std::all_of(ring.can_start.begin(), ring.can_start.end(),
                     [](std::uint8_t c) { return c; }))
      return false;
    std::uint32_t below = kNone;
    for (CoarseFace f : ring.faces) {
      CoarseHalfedge bottom = L_.find(m_, f, CoarseRole::bottom);
      if (m_.is_border(bottom) || L_[m_.twin(bottom)] != CoarseRole::top) return false;
      std::uint32_t q = row_of_[m_.face(m_.twin(bottom)).index()];
      if (q == kNone || (below != kNone && q != below)) return false;
      below = q;
    }
    if (!rows_[below].closed || rows_[below].faces.size() != ring.faces.size()) return false;
    std::uint32_t c = chain_of_[below];
    if (!chains_[c].free || chains_[c].rows.back() != below) return false;
    chains_[c].rows.push_back(r);
    chain_of_[r] = c;
    register_free_corners(c, r);
    return true;
  }

  void register_free_corners(std::uint32_t c, std::uint32_t r) {
    for (CoarseFace f : rows_[r].faces) free_corner_at_[top_left(f).index()].push_back({c, r});
  }

  // Places a free chain's path so that it leaves its last ring at `corner`: down the stack,
  // each ring's path face is the one whose top-left corner is where the path of the ring
  // above starts.
  void fix(std::uint32_t c, CoarseVertex corner) {
    Chain& chain = chains_[c];
    chain.free = false;
    chain.top = corner;
    fixed_top_at_[corner.index()].push_back(c);
    for (std::size_t k = chain.rows.size(); k-- > 0;) {
      std::uint32_t r = chain.rows[k];
      const std::vector<CoarseFace>& faces = rows_[r].faces;
      auto at = std::find_if(faces.begin(), faces.end(),
                             [&](CoarseFace f) { return top_left(f) == corner; });
      SKEIN_ASSERT(at != faces.end(), "a free chain's rings are stacked column on column");
      entries_[r].face = static_cast<std::size_t>(at - faces.begin());
      entries_[r].option = chain.option;
      entries_[r].continued = k > 0;
      corner = bottom_left(*at);
    }
  }

  // Where the path of an unclaimed free chain leaves it when it starts up its first face.
  CoarseVertex first_column_top(const Chain& chain) const {
    CoarseVertex corner = top_left(rows_[chain.rows.front()].faces.front());
    for (std::size_t k = 1; k < chain.rows.size(); ++k)
      for (CoarseFace f : rows_[chain.rows[k]].faces)
        if (bottom_left(f) == corner) {
          corner = top_left(f);
          break;
        }
    return corner;
  }

  const CoarseMesh& m_;
  const Labeling& L_;
  const std::vector<PlannedRow>& rows_;
  std::uint8_t option_;
  std::vector<RowEntry> entries_;
  std::vector<Chain> chains_;
  std::vector<std::uint32_t> chain_of_;                   // per row
  std::vector<std::uint32_t> row_of_;                     // per face
  std::vector<std::uint32_t> position_;                   // per row: when it is planned
  std::vector<std::vector<std::uint32_t>> fixed_top_at_;  // per vertex: chains stopping there
  std::vector<std::vector<std::pair<std::uint32_t, std::uint32_t>>> free_corner_at_;  // (c, r)
  std::vector<std::vector<std::uint32_t>> rows_entering_at_;  // per vertex: rows that may start
};

}  // namespace

std::vector<RowEntry> plan_row_entries(const CoarseMesh& mesh, const Labeling& labeling,
                                       const std::vector<PlannedRow>& rows, std::uint8_t option) {
  return YarnPlanner(mesh, labeling, rows, option).run();
}

}  // namespace skein
