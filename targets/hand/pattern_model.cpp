#include "hand/pattern_model.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>

#include "common/error.hpp"
#include "driver/pipeline.hpp"
#include "hand/fabric_compare.hpp"
#include "hand/marker_plan.hpp"
#include "hand/piece_names.hpp"
#include "hand/region_markers.hpp"
#include "hand/stitch_working.hpp"

namespace skein::hand {
namespace {

using T = StitchType;

[[noreturn]] void unsupported(const std::string& what) {
  throw UnsupportedError(fmt::format("hand target: {}", what));
}

void check_supported(const Compilation& c) {
  const KnitGraph& g = c.knit;
  check_stitch_types(g);
  for (const Loop& l : g.loops) {
    bool joined = l.kind == LoopKind::joined && l.taker != kNoStitch && g.type[l.taker] == T::tnbo;
    bool split = l.kind == LoopKind::split && l.maker != kNoStitch && g.type[l.maker] == T::sco;
    bool across = l.kind == LoopKind::perpendicular && l.maker != kNoStitch;  // see append_ops
    if ((l.kind != LoopKind::wale && !joined && !split && !across) || l.taker == kNoStitch)
      unsupported(fmt::format(
          "the loop {} makes {}: hand patterns cover loops between rows, joins and splits only",
          g.describe(l.maker),
          l.taker == kNoStitch ? "is never worked"
                               : "crosses a mismatched edge to " + g.describe(l.taker)));
  }
}

// Per model row: does it hold both three-needle bind-off sts and others?
std::vector<std::uint8_t> rows_binding_off_among_own_sts(const KnitGraph& g) {
  std::vector<std::uint8_t> kinds(g.row_shape.size(), 0);  // bit 0: tnbo; bit 1: other
  for (StitchId s = 0; s < g.size(); ++s) kinds[g.row[s]] |= g.type[s] == T::tnbo ? 1 : 2;
  for (std::uint8_t& k : kinds) k = k == 3;
  return kinds;
}

// Which way each row runs seen from the RS. Along one yarn piece a turn reverses the
// direction and a shift-path keeps it, so one bit per piece remains: the direction of its
// first row. Two loops side by side in one stitch (slots count left to right) that were made,
// or are taken, by two stitches of one row tell which way that row ran.
class Handedness {
 public:
  explicit Handedness(const Compilation& c)
      : g_(c.knit),
        y_(c.yarns),
        pos_(g_.size(), 0),
        reversed_(g_.size(), 0),
        first_lr_(y_.size(), 0) {
    walk_yarns();
    decide_first_rows();
  }

  // Does the row of `s` run left to right seen from the RS?
  bool left_to_right(StitchId s) const { return first_lr_[y_.piece_of[s]] != reversed_[s]; }

 private:
  void walk_yarns() {
    for (std::uint32_t p = 0; p < y_.size(); ++p) {
      std::uint8_t reversed = 0;
      StitchId s = y_.first[p];
      bool row_starts = true;
      for (std::uint32_t i = 0; i < y_.length[p]; ++i, s = g_.yarn_next[s]) {
        pos_[s] = i;
        reversed_[s] = reversed;
        first_in_row_[s] = row_starts;
        row_starts = g_.yarn_link[s] != YarnLink::course;
        if (g_.yarn_link[s] == YarnLink::turn) reversed ^= 1;
      }
    }
  }

  // A rnd's first and last st (a gusset's last st picked up beside the first st of the rnd)
  // are neighbours whose order along the yarn says nothing of left and right.
  bool meet_across_the_start_of_a_rnd(StitchId a, StitchId b) const {
    bool side_by_side = pos_[a] + 1 == pos_[b] || pos_[b] + 1 == pos_[a];
    return !side_by_side &&
           (g_.yarn_link[a] == YarnLink::shift || g_.yarn_link[b] == YarnLink::shift);
  }

  void decide_first_rows() {
    std::vector<std::array<std::uint32_t, 2>> votes(y_.size(), {0, 0});
    std::vector<std::array<std::uint32_t, 2>> edge_votes(y_.size(), {0, 0});
    auto observe = [&](StitchId left, StitchId right) {
      if (left == right || left == kNoStitch || right == kNoStitch) return;
      std::uint32_t p = y_.piece_of[left];
      if (p != y_.piece_of[right] || g_.row[left] != g_.row[right]) return;
      if (meet_across_the_start_of_a_rnd(left, right)) return;
      bool lr = pos_[left] < pos_[right];
      ++votes[p][lr != static_cast<bool>(reversed_[left])];
    };
    for (StitchId s = 0; s < g_.size(); ++s) {
      auto taken = g_.loops_taken_by(s);
      for (std::size_t i = 1; i < taken.size(); ++i)
        if (!across_a_gap(taken[i - 1]) && !across_a_gap(taken[i]))
          observe(g_.loops[taken[i - 1]].maker, g_.loops[taken[i]].maker);
      auto made = g_.loops_made_by(s);
      for (std::size_t i = 1; i < made.size(); ++i)
        observe(g_.loops[made[i - 1]].taker, g_.loops[made[i]].taker);
      observe_edge(s, edge_votes);
    }
    for (std::uint32_t p = 0; p < y_.size(); ++p) {
      if (!votes[p][0] && !votes[p][1]) votes[p] = edge_votes[p];
      if (votes[p][0] && votes[p][1])
        unsupported(
            fmt::format("the loops of yarn {} do not keep one left-to-right order, so "
                        "its rows cannot be given a right and a wrong side",
                        p + 1));
      if (votes[p][0] || votes[p][1]) {
        first_lr_[p] = votes[p][1] > 0;
      } else if (std::optional<bool> lr = as_the_row_it_takes(p)) {
        first_lr_[p] = *lr;
      } else {
        // No stitch tells: work the first row after the cast-on from the RS.
        StitchId s = y_.first[p];
        while (g_.type[s] == T::co && g_.yarn_next[s] != kNoStitch) s = g_.yarn_next[s];
        first_lr_[p] = reversed_[s];
      }
    }
  }

  // An edge st that makes a loop across the edge beside its own (picked up by another row)
  // has that loop on the side of the edge it is at: the first st of a row at the right edge,
  // or its last at the left, says the row runs left to right seen from the RS (or the other
  // way). Heard only for a piece whose sts tell nothing else (letter-r's flap).
  void observe_edge(StitchId s, std::vector<std::array<std::uint32_t, 2>>& votes) const {
    auto made = g_.loops_made_by(s);
    if (made.size() != 2) return;
    const Loop &a = g_.loops[made[0]], &b = g_.loops[made[1]];
    if ((a.kind == LoopKind::perpendicular) == (b.kind == LoopKind::perpendicular)) return;
    bool first = first_in_row_[s], last = g_.yarn_link[s] != YarnLink::course;
    if (first == last) return;
    const Loop& across = a.kind == LoopKind::perpendicular ? a : b;
    bool on_the_right = across.maker_slot == 1;
    bool lr = on_the_right == last;
    ++votes[y_.piece_of[s]][lr != static_cast<bool>(reversed_[s])];
  }

  // A piece whose own sts do not tell (no increase or decrease) but whose first row takes the
  // loops of an earlier piece's row one after another (a leg joined to sts a tube left on a
  // holder) runs as that row ran, or against it if it takes them in the other order.
  std::optional<bool> as_the_row_it_takes(std::uint32_t p) const {
    for (StitchId s = y_.first[p]; g_.yarn_link[s] == YarnLink::course; s = g_.yarn_next[s]) {
      StitchId a = first_maker(s), b = first_maker(g_.yarn_next[s]);
      if (a == kNoStitch || b == kNoStitch || y_.piece_of[a] >= p || g_.row[a] != g_.row[b])
        continue;
      if (pos_[a] + 1 == pos_[b] || pos_[b] + 1 == pos_[a])
        return (left_to_right(a) == (pos_[a] < pos_[b])) != static_cast<bool>(reversed_[s]);
    }
    return std::nullopt;
  }

  StitchId first_maker(StitchId s) const {
    auto taken = g_.loops_taken_by(s);
    return taken.empty() ? kNoStitch : g_.loops[taken[0]].maker;
  }

  // A loop taken across a perpendicular edge comes from beyond a gap (in the rnd, from across
  // the beginning of the rnd): it is not side by side with the other in its row.
  bool across_a_gap(std::uint32_t loop) const {
    return g_.loops[loop].kind == LoopKind::perpendicular;
  }

  const KnitGraph& g_;
  const YarnPieces& y_;
  std::vector<std::uint32_t> pos_;      // index along its yarn piece
  std::vector<std::uint8_t> reversed_;  // runs against the first row of its piece
  std::vector<std::uint8_t> first_in_row_ = std::vector<std::uint8_t>(g_.size(), 0);
  std::vector<std::uint8_t> first_lr_;  // per piece
};

// Hand knitting works every round right to left with the side facing the knitter. When most
// of the model's rounds run the other way seen from the RS, the pattern knits the mirror image;
// the rounds that still run left to right are worked with the WS facing.
bool needs_mirror(const Compilation& c, const Handedness& hand, Rounds rounds) {
  if (rounds == Rounds::ws_facing) return false;
  const KnitGraph& g = c.knit;
  std::uint64_t left_to_right = 0, closed = 0;
  for (StitchId s = 0; s < g.size(); ++s) {
    if (g.row_shape[g.row[s]] != RowShape::closed) continue;
    ++closed;
    left_to_right += hand.left_to_right(s);
  }
  return 2 * left_to_right > closed;
}

class PatternBuilder {
 public:
  PatternBuilder(const Compilation& c, TurnMethod turns, Rounds rounds)
      : c_(c), g_(c.knit), hand_(c) {
    out_.source = c.input;
    out_.mirror = needs_mirror(c, hand_, rounds);
    out_.turns = turns;
  }

  HandPattern run() && {
    number_parts();
    std::size_t yarns = c_.yarns.size();
    set_aside_.resize(yarns);
    section_of_yarn_.resize(yarns, 0);
    deferred_.resize(yarns);
    taken_up_.resize(yarns, 0);
    for (const Event& e : c_.schedule.events) {
      switch (e.kind) {
        case EventKind::yarn_start:
          start_section(e.yarn);
          break;
        case EventKind::stitch:
          if (taken_up_[e.yarn]) {
            deferred_[e.yarn].push_back(e.stitch);
            unwritten_[e.stitch] = 1;
          } else {
            add_stitch(e.stitch);
          }
          break;
        case EventKind::hold:
          if (!taken_up_[e.yarn]) set_section_aside(e.yarn);
          break;
        case EventKind::resume:
          taken_up_[e.yarn] = 1;
          break;
        case EventKind::yarn_end:
          if (taken_up_[e.yarn]) take_up_section(e.yarn);
          end_section();
          break;
        case EventKind::marker:
          if (e.marker != MarkerKind::beginning_of_round) marked_[e.stitch] = e.marker;
          break;
        default:
          break;  // rows and turns follow from the yarn links and the stitches
      }
    }
    return std::move(out_);
  }

 private:
  PatternSection& section() { return out_.sections.back(); }

  // A knitter's row ends where the yarn turns or goes on into the next round. A three-needle
  // bind-off's yarn goes along its chain of edges as one row; one worked last in a row of the
  // piece's own sts ends that row.
  void add_stitch(StitchId s) {
    row_.push_back(s);
    if (g_.yarn_link[s] != YarnLink::course && (g_.type[s] != T::tnbo || binds_off_in_a_row()))
      flush_row();
  }

  bool binds_off_in_a_row() const {
    return std::any_of(row_.begin(), row_.end(), [&](StitchId s) { return g_.type[s] != T::tnbo; });
  }

  void start_section(std::uint32_t yarn) {
    section_of_yarn_[yarn] = static_cast<std::uint32_t>(out_.sections.size());
    PatternSection& s = out_.sections.emplace_back();
    s.yarn = yarn;
    s.piece = ++pieces_;
    s.first_row = s.end_row = static_cast<std::uint32_t>(out_.rows.size());
    st_ = Needle{};  // a new yarn: nothing of the piece before
  }

  // The yarn waits for another piece: its sts stay on the needle.
  // A row the yarn stops in the middle of is written with the rest, when it is taken up.
  void set_section_aside(std::uint32_t yarn) {
    for (StitchId st : row_) unwritten_[st] = 1;
    deferred_[yarn] = std::move(row_);
    row_.clear();
    section().set_aside = true;
    section().live_at_end = st_.live;
    section().end_row = static_cast<std::uint32_t>(out_.rows.size());
    set_aside_[yarn] = st_;
  }

  // The rest of a yarn set aside, as one section that goes on counting its rows.
  void take_up_section(std::uint32_t yarn) {
    const PatternSection& before = out_.sections[section_of_yarn_[yarn]];
    PatternSection s;
    s.yarn = yarn;
    s.piece = before.piece;
    s.in_round = before.in_round;
    s.resumed = true;
    s.first_number = before.first_number + (before.end_row - before.first_row);
    std::copy(std::begin(before.last_row_ends), std::end(before.last_row_ends), s.last_row_ends);
    s.first_row = s.end_row = static_cast<std::uint32_t>(out_.rows.size());
    section_of_yarn_[yarn] = static_cast<std::uint32_t>(out_.sections.size());
    out_.sections.push_back(s);
    st_ = set_aside_[yarn];
    taken_up_[yarn] = 0;
    for (StitchId st : deferred_[yarn]) {
      unwritten_[st] = 0;
      add_stitch(st);
    }
    deferred_[yarn].clear();
  }

  void end_section() {
    if (!row_.empty() && g_.type[row_.front()] == T::tnbo && !binds_off_held_pieces())
      join_live_sections();
    flush_row();
    part_the_last_row_for_a_heel_turn();
    section().left_live = st_.live != 0;  // every loop is taken by another piece
    section().live_at_end = st_.live;
    section().end_row = static_cast<std::uint32_t>(out_.rows.size());
  }

  // A piece's last row that binds off its own sts with those of more than one other needle
  // (pieces on spare needles, holders) held behind it, one after another: a row of
  // "3-needle BO", not a join of two needles.
  bool binds_off_held_pieces() const {
    if (out_.rows.size() == out_.sections.back().first_row || binds_off_in_a_row()) return false;
    auto behind = [&](StitchId s) {
      StitchId maker = g_.loops[g_.loops_taken_by(s)[1]].maker;
      return std::pair{section_of(maker), holder_of_[maker]};
    };
    auto front_yarn = [&](StitchId s) {
      return c_.yarns.piece_of[g_.loops[g_.loops_taken_by(s)[0]].maker];
    };
    const std::uint32_t yarn = out_.sections.back().yarn;
    return std::all_of(row_.begin(), row_.end(),
                       [&](StitchId s) { return front_yarn(s) == yarn; }) &&
           std::any_of(row_.begin(), row_.end(),
                       [&](StitchId s) { return behind(s) != behind(row_.front()); });
  }

  // A yarn of three-needle bind-off stitches pairs the loops of two sections left live: the
  // first loop of each stitch from the front one.
  void join_live_sections() {
    PatternSection& join = section();
    auto taken = g_.loops_taken_by(row_.front());
    auto section_of = [&](std::uint32_t loop) {
      return section_of_yarn_[c_.yarns.piece_of[g_.loops[loop].maker]];
    };
    join.joins = true;
    join.front = section_of(taken[0]);
    join.back = section_of(taken[1]);
    join.pairs = static_cast<std::uint32_t>(row_.size());
    if (std::optional<std::uint32_t> holder = needle_folded_for(join.front, join.back)) {
      fold_needle(join, *holder);
      join.stitches += row_.size();
      row_.clear();
      return;
    }
    for (int side : {0, 1}) {
      const PatternSection& piece = out_.sections[side == 0 ? join.front : join.back];
      StitchId maker = g_.loops[taken[side]].maker;
      join.holders[side] = holder_of_[maker];
      join.from_last[side] =
          maker == (join.holders[side] != 0 ? holders_[join.holders[side] - 1].last
                                            : piece.last_row_ends[1]);
    }
    join.own_yarn = join.front == section_of_yarn_[join.yarn];
    if (join.own_yarn) st_.live = 0;  // the front needle's sts are the ones bound off
    join.stitches += row_.size();
    row_.clear();
  }

  // The section whose needle holds a section's sts: the one its spare needle was placed into,
  // or its own.
  std::uint32_t holding(std::uint32_t section) const {
    for (std::uint32_t h = 0; h < out_.sections.size(); ++h)
      for (const PatternSection::Placement& p : out_.sections[h].placements)
        if (p.section == section && !p.chain && p.holder == 0 && !p.edge) return h;
    return section;
  }

  // When the sts of a join were placed into another piece's rnd, every pair is on that one
  // needle: the join folds it in half. Pairs held by two needles, one of them another's, are
  // not written yet. Sts slipped to holders wait on needles of their own.
  std::optional<std::uint32_t> needle_folded_for(std::uint32_t front, std::uint32_t back) const {
    for (std::uint32_t l : g_.loops_taken_by(row_.front()))
      if (holder_of_[g_.loops[l].maker] != 0) return std::nullopt;
    std::uint32_t pair[2] = {front, back};
    bool placed = false;
    std::uint32_t holder = holding(front);
    for (StitchId s : row_)
      for (std::uint32_t side : {0u, 1u}) {
        std::uint32_t from = section_of(g_.loops[g_.loops_taken_by(s)[side]].maker);
        placed = placed || holding(from) != from;
        if (holding(from) != holder && placed)
          unsupported(fmt::format(
              "{} binds off sts of Piece {} and of Piece {} on two needles, one of them placed "
              "into another piece's rnd, which is not covered yet",
              g_.describe(s), out_.sections[pair[0]].piece, out_.sections[pair[1]].piece));
      }
    if (!placed && front != back) return std::nullopt;
    return holder;
  }

  // Along a fold each needle's sts follow one another round the needle: where a run goes on
  // along the row its sts came from, its next st must be that row's next one when that is
  // bound off too (a run that jumps elsewhere would need a second bind-off).
  void refuse_pairs_off_the_fold(const std::vector<StitchId>& side,
                                 const std::vector<StitchId> (&run)[2]) const {
    auto joined = [&](StitchId s) {
      return std::find(run[0].begin(), run[0].end(), s) != run[0].end() ||
             std::find(run[1].begin(), run[1].end(), s) != run[1].end();
    };
    for (std::size_t i = 1; i + 1 < side.size(); ++i) {
      StitchId ahead = kNoStitch;
      if (g_.yarn_next[side[i - 1]] == side[i]) ahead = g_.yarn_next[side[i]];
      if (g_.yarn_next[side[i]] == side[i - 1])
        for (const auto& other : run)
          for (StitchId s : other)
            if (g_.yarn_next[s] == side[i]) ahead = s;
      if (ahead == kNoStitch || !joined(ahead) || ahead == side[i + 1]) continue;
      unsupported(fmt::format(
          "{} binds off one needle's sts folded in half, but its pairs do not go along the "
          "fold in one direction (after {} it takes {}, not {}), so it cannot be worked as one "
          "three-needle bind-off",
          g_.describe(row_.front()), g_.describe(side[i]), g_.describe(side[i + 1]),
          g_.describe(ahead)));
    }
  }

  // The ring of the holder's sts starts at the first st of its last row and goes on the way
  // that row went; the back needle's run of the ring holds it (or the front's), and the other
  // run starts beside its tip, across the fold.
  void fold_needle(PatternSection& join, std::uint32_t holder) {
    const PatternSection& h = out_.sections[holder];
    if (2 * row_.size() != h.live_at_end) return fold_with_held_sts(join, holder);
    std::vector<StitchId> run[2];
    runs_of_the_fold(run);
    StitchId first = h.last_row_ends[0], second = g_.yarn_next[first];
    PatternSection::Fold fold;
    fold.sts = h.live_at_end;
    for (std::uint32_t side : {1u, 0u}) {
      auto at = std::find(run[side].begin(), run[side].end(), first);
      if (at == run[side].end()) continue;
      auto j = static_cast<std::uint32_t>(at - run[side].begin());
      bool down = at != run[side].begin() && *(at - 1) == second;
      std::uint32_t tip = down ? j : (fold.sts - j) % fold.sts;  // 0-based
      std::uint32_t other = (down ? tip + 1 : tip + fold.sts - 1) % fold.sts;
      fold.tip[side] = tip + 1;
      fold.down[side] = down;
      fold.tip[1 - side] = other + 1;
      fold.down[1 - side] = !down;
      join.front = holder;
      join.fold = fold;
      return;
    }
    unsupported(
        fmt::format("{} binds off the sts of Piece {} folded in half, but not the first st "
                    "of its last row, which is not covered yet",
                    g_.describe(row_.front()), h.piece));
  }

  // Each needle's run of a fold: the sts its pairs take, from the tip.
  void runs_of_the_fold(std::vector<StitchId> (&run)[2]) const {
    for (StitchId s : row_)
      for (std::uint32_t side : {0u, 1u})
        run[side].push_back(g_.loops[g_.loops_taken_by(s)[side]].maker);
    for (const auto& side : run) refuse_pairs_off_the_fold(side, run);
  }

  // A fold whose pairs also take the sts of one holder: the knitter puts them back on the
  // spare needle first, where the fold has them (the front run goes round the needle into the
  // back one), and folds the whole needle.
  void fold_with_held_sts(PatternSection& join, std::uint32_t holder) {
    const PatternSection& h = out_.sections[holder];
    std::vector<StitchId> run[2];
    runs_of_the_fold(run);
    std::vector<StitchId> ring(run[0].rbegin(), run[0].rend());
    ring.insert(ring.end(), run[1].begin(), run[1].end());
    auto first_held = std::find_if(ring.begin(), ring.end(), [&](StitchId s) { return held(s); });
    std::uint32_t by = first_held == ring.end() ? 0 : holder_of_[*first_held];
    if (!ring_round_the_needle(ring, h) || !one_held_run(ring, by, h.live_at_end))
      unsupported(fmt::format(
          "{} binds off {} pairs from the needle of Piece {}, which holds {} sts: a "
          "three-needle bind-off of a fold together with sts waiting elsewhere (on a holder) "
          "that do not go back on the needle as one run is not covered yet",
          g_.describe(row_.front()), row_.size(), h.piece, h.live_at_end));
    PatternSection::Fold fold = held_sts_placed(ring, by);
    for (std::uint32_t side : {0u, 1u}) {
      auto at = static_cast<std::uint32_t>(std::find(ring.begin(), ring.end(), run[side][0]) -
                                           ring.begin());
      fold.tip[side] = at + 1;
      fold.down[side] =
          run[side].size() > 1 && ring[(at + fold.sts - 1) % fold.sts] == run[side][1];
    }
    join.front = holder;
    join.fold = fold;
  }

  bool held(StitchId s) const { return holder_of_[s] != 0; }

  // Turns the ring of the fold's sts to start at the first st of the needle's last row and go
  // the way that row went (its second st next, past any held sts); false if it cannot.
  bool ring_round_the_needle(std::vector<StitchId>& ring, const PatternSection& h) const {
    StitchId first = h.last_row_ends[0], second = g_.yarn_next[first];
    for (int way = 0; way < 2; ++way) {
      if (way == 1) std::reverse(ring.begin(), ring.end());
      auto at = std::find(ring.begin(), ring.end(), first);
      if (at == ring.end()) return false;
      std::rotate(ring.begin(), at, ring.end());
      auto next = std::find_if(ring.begin() + 1, ring.end(), [&](StitchId s) { return !held(s); });
      if (next != ring.end() && *next == second) return true;
    }
    return false;
  }

  // The held sts of the ring are all those of holder `by`, side by side, and the rest fill the
  // needle.
  bool one_held_run(const std::vector<StitchId>& ring, std::uint32_t by,
                    std::uint32_t on_needle) const {
    if (by == 0) return false;
    auto first = std::find_if(ring.begin(), ring.end(), [&](StitchId s) { return held(s); });
    auto end = std::find_if(first, ring.end(), [&](StitchId s) { return !held(s); });
    auto count = static_cast<std::uint32_t>(end - first);
    return std::none_of(end, ring.end(), [&](StitchId s) { return held(s); }) &&
           std::all_of(first, end, [&](StitchId s) { return holder_of_[s] == by; }) &&
           count == holders_[by - 1].count && ring.size() == on_needle + count;
  }

  // The ring's sts counted from the needle's first: the held ones go after those before them,
  // the end of the holder that comes first in the ring first.
  PatternSection::Fold held_sts_placed(const std::vector<StitchId>& ring, std::uint32_t by) const {
    PatternSection::Fold fold;
    fold.sts = static_cast<std::uint32_t>(ring.size());
    fold.holder = by;
    fold.held = holders_[by - 1].count;
    fold.after = static_cast<std::uint32_t>(
        std::find_if(ring.begin(), ring.end(), [&](StitchId s) { return held(s); }) - ring.begin());
    fold.held_from_last = ring[fold.after] == holders_[by - 1].last;
    return fold;
  }

  void flush_row() {
    if (row_.empty()) return;
    note_last_row_ends();
    section().stitches += row_.size();
    if (!st_.cast_on_done && g_.type[row_.front()] != T::co && g_.type[row_.front()] != T::sco)
      start_from_other_piece();
    if (!st_.cast_on_done)
      cast_on();
    else
      add_row();
    st_.previous_link = g_.yarn_link[row_.back()];
    st_.last_row = std::move(row_);
    row_.clear();
  }

  // A cast-on, or (sco: a cast-on along a split) a provisional cast-on whose chain's loops are
  // the other side's.
  void cast_on() {
    T first = g_.type[row_.front()];
    for (StitchId s : row_)
      if (g_.type[s] != first)
        unsupported(
            fmt::format("yarn {} starts with a row of {} that goes on with {} (a cast-on "
                        "that goes on into worked sts in one row is not covered yet)",
                        section().yarn + 1, info(first).name, g_.describe(s)));
    section().provisional = first == T::sco;
    section().cast_on = st_.live = st_.behind = static_cast<std::uint32_t>(row_.size());
    for (StitchId s : row_) number_of_[s] = 0;
    st_.ahead = 0;
    section().in_round = g_.yarn_link[row_.back()] == YarnLink::shift;
    st_.cast_on_done = true;
  }

  // A piece whose yarn starts on loops of another: picked up along its edge, or on one side of
  // a provisional cast-on.
  void start_from_other_piece() {
    const Loop& first = g_.loops[g_.loops_taken_by(row_.front())[0]];
    const Loop* on_needle = first.kind == LoopKind::perpendicular ? held_loop_worked() : &first;
    if (on_needle == nullptr) {
      refuse_start_on_sts_beside_an_edge();
      return start_from_pick_up();
    }
    start_from_spare_needle(*on_needle);
    // A first row that goes on into the next rnd joins the piece to work in the rnd.
    section().in_round = g_.yarn_link[row_.back()] == YarnLink::shift;
    st_.behind = 0;
    st_.cast_on_done = true;
  }

  // Picked up along an edge, one loop in each row of the piece beside it (paper §3.2: an
  // expanding perpendicular edge): the loop the edge st makes across it. The last picked up
  // is worked first.
  void start_from_pick_up() {
    std::vector<StitchId> edge;
    for (StitchId s : row_)
      for (std::uint32_t l : g_.loops_taken_by(s))
        if (g_.loops[l].kind == LoopKind::perpendicular) edge.push_back(g_.loops[l].maker);
    PatternSection::PickUp p;
    p.section = section_of_yarn_[c_.yarns.piece_of[edge.front()]];
    p.from_row = number_of_[edge.back()];
    p.to_row = number_of_[edge.front()];
    for (StitchId s : edge) {
      auto made = g_.loops_made_by(s);
      if (made.size() < 2) continue;
      p.right = g_.loops[made.front()].kind != LoopKind::perpendicular;
      break;
    }
    section().picks_up = p;
    section().cast_on = st_.live = st_.ahead = static_cast<std::uint32_t>(edge.size());
    st_.behind = 0;
    st_.cast_on_done = true;
  }

  // One side of a split: the loops wait on a spare needle (or on the provisional cast-on's
  // chain: the loops' second slot).
  void start_from_spare_needle(const Loop& first) {
    if (first.maker != kNoStitch && g_.type[first.maker] != T::sco) {
      if (holder_of_[first.maker] == 0 && out_.sections[section_of(first.maker)].set_aside)
        hold_sts_left_on_set_aside_needle(first.maker);
      if (holder_of_[first.maker] == 0) refuse_start_on_live_sts(first);
      return start_from_holder(first);
    }
    if (first.maker == kNoStitch)
      unsupported(
          fmt::format("yarn {} starts with {}, neither with a cast-on nor on the sts of a "
                      "cast-on along a split",
                      section().yarn + 1, g_.describe(row_.front())));
    std::uint32_t from = section_of_yarn_[c_.yarns.piece_of[first.maker]];
    const PatternSection& spare = out_.sections[from];
    bool chain = is_chain_loop(first);
    auto [count, last] = cast_on_sts(spare, chain);
    section().starts_from = PatternSection::Start{from, chain, first.maker == last, count};
    st_.live = st_.ahead = count;
  }

  // The sts of a provisional cast-on on the needle or on its chain (of the piece's cast-on, or
  // of a cast-on in one of its rows): how many, and the last cast on.
  static std::pair<std::uint32_t, StitchId> cast_on_sts(const PatternSection& spare, bool chain) {
    if (chain && !spare.provisional) return {spare.row_chain, spare.row_chain_ends[1]};
    return {spare.cast_on, spare.last_row_ends[1]};
  }

  // A three-needle bind-off in a row, worked with this piece's yarn: its st in front, the other
  // piece's held behind on its spare needle (or a holder), said before the row that works it
  // (as the piece is taken up again to join another, or on a line of its own). The held st
  // comes onto the needle.
  void bind_off_with_held_st(StitchId s) {
    auto taken = g_.loops_taken_by(s);
    StitchId behind = g_.loops[taken[1]].maker;
    PatternSection& sec = section();
    if (c_.yarns.piece_of[g_.loops[taken[0]].maker] != sec.yarn)
      unsupported(
          fmt::format("{} is a three-needle bind-off in a row with this piece's st "
                      "behind, which is not covered yet",
                      g_.describe(s)));
    const std::uint32_t from = section_of(behind), holder = holder_of_[behind];
    bool continues = !sec.holds.empty() && sec.holds.back().section == from &&
                     sec.holds.back().holder == holder && out_.ops.back() == HandOp::tnbo;
    if (!continues) {
      StitchId last = holder ? holders_[holder - 1].last : out_.sections[from].last_row_ends[1];
      sec.holds.push_back(
          {from, 0, behind == last, s, holder, static_cast<std::uint32_t>(out_.rows.size())});
    }
    ++sec.holds.back().count;
    out_.ops.push_back(HandOp::tnbo);
    ++st_.live;
    if (!sec.in_round) ++st_.ahead;
  }

  // Every st of a piece held behind is bound off in the row (the rest of a spare needle would
  // need a holder of its own).
  void refuse_held_sts_left(const PatternRow& r) const {
    for (const PatternSection::Hold& h : out_.sections.back().holds) {
      const PatternSection& spare = out_.sections[h.section];
      if (h.holder ? holders_[h.holder - 1].count == h.count
                   : spare.left_live && spare.live_at_end == h.count)
        continue;
      unsupported(fmt::format(
          "{} {} of Piece {} binds off {} of the {} sts of Piece {} ({}) with a three-needle "
          "bind-off from {} on; holding only some of a piece's sts behind, and the others on "
          "holders for the pieces that work them, is not covered yet",
          r.round ? "Rnd" : "Row", r.number, out_.sections.back().piece, h.count, spare.live_at_end,
          spare.piece, spare.set_aside ? "set aside with its yarn" : "on a spare needle",
          g_.describe(h.first)));
    }
  }

  // A new yarn joined to sts another piece slipped to a holder (a body that goes on as two
  // flaps): the holder's first or last st at the tip. A rnd may begin at any st of the
  // holder (the sts it places, a cast-on along the parting, go round after its last).
  void start_from_holder(const Loop& first) {
    std::uint32_t holder = holder_of_[first.maker];
    const Held& held = holders_[holder - 1];
    std::uint32_t place = place_on_holder_[first.maker];
    bool from_last = first.maker == held.last;
    PatternSection::Start& start = section().starts_from.emplace(
        PatternSection::Start{section_of(first.maker), false, from_last, held.count, holder});
    section().in_round = g_.yarn_link[row_.back()] == YarnLink::shift;  // a leg of a tube
    if (!from_last && place > 1) {
      if (!section().in_round)
        unsupported(
            fmt::format("yarn {} starts with {} in the middle of the sts of holder {} "
                        "and works them in rows, which is not covered yet",
                        section().yarn + 1, g_.describe(row_.front()), holder));
      start.at = place;
      start.from_last = !runs_up_the_holder(first.maker, holder);
    }
    st_.live = st_.ahead = held.count;
  }

  // Does the piece's first row go on from `first` to the st slipped to the holder after it
  // (not to the one before)?
  bool runs_up_the_holder(StitchId first, std::uint32_t holder) const {
    for (StitchId s : row_)
      for (std::uint32_t l : g_.loops_taken_by(s)) {
        StitchId m = g_.loops[l].maker;
        if (m != kNoStitch && m != first && holder_of_[m] == holder)
          return place_on_holder_[m] > place_on_holder_[first];
      }
    return true;
  }

  // A new yarn that starts on sts another piece worked and left on its needle (a body whose
  // sts are shared out between pieces) would need them put on a holder first.
  [[noreturn]] void refuse_start_on_live_sts(const Loop& first) const {
    std::uint32_t holder = holder_of_[first.maker];
    unsupported(fmt::format(
        "yarn {} starts with {} on the sts of Piece {} (the first: {}){}; joining a new yarn to "
        "sts another piece leaves is not covered yet",
        out_.sections.back().yarn + 1, g_.describe(row_.front()),
        out_.sections[section_of(first.maker)].piece, g_.describe(first.maker),
        holder ? fmt::format(", slipped to holder {}", holder) : " left on its needle"));
  }

  // A new yarn that starts on sts a piece set aside left on its needle (the teapot's yarn 4,
  // on 7 sts of Piece 4's row 65, its first rnd on the other 7): each run of that row another
  // piece's row takes goes to a holder of its own before the piece is set aside, counted in the
  // order the row worked them ("Slip sts 1–7 of Row 8 to holder 12 and sts 8–14 to holder 13").
  void hold_sts_left_on_set_aside_needle(StitchId first) {
    const std::uint32_t yarn = c_.yarns.piece_of[first];
    std::vector<StitchId> row = sts_of_row(yarn, number_of_[first]);
    for (std::uint32_t i = 0, end = 0; i < row.size(); i = end) {
      std::uint32_t taker_row = row_taking_from_another_piece(row[i]);
      for (end = i + 1; end < row.size() && row_taking_from_another_piece(row[end]) == taker_row;)
        ++end;
      if (taker_row != kNotTaken) hold_run_of_set_aside_row(yarn, row, i, end);
    }
  }

  // The row of another piece that takes the st's loop (kNotTaken: its own piece, or none).
  static constexpr std::uint32_t kNotTaken = ~0U;
  std::uint32_t row_taking_from_another_piece(StitchId s) const {
    auto made = g_.loops_made_by(s);
    if (made.size() != 1) return kNotTaken;
    StitchId taker = g_.loops[made[0]].taker;
    if (taker == kNoStitch || c_.yarns.piece_of[taker] == c_.yarns.piece_of[s]) return kNotTaken;
    return g_.row[taker];
  }

  // A new holder for the sts of a row from `first` to `end` (in the order it worked them);
  // returns its number.
  std::uint32_t hold_run_of_row(const std::vector<StitchId>& row, std::uint32_t first,
                                std::uint32_t end) {
    holders_.push_back({row[end - 1], end - first});
    spare_left_.push_back(0);
    spare_second_.push_back(0);
    auto holder = static_cast<std::uint32_t>(holders_.size());
    for (std::uint32_t i = first; i < end; ++i) {
      holder_of_[row[i]] = holder;
      place_on_holder_[row[i]] = i - first + 1;
    }
    return holder;
  }

  void hold_run_of_set_aside_row(std::uint32_t yarn, const std::vector<StitchId>& row,
                                 std::uint32_t first, std::uint32_t end) {
    const std::uint32_t count = end - first, holder = hold_run_of_row(row, first, end);
    PatternSection& aside = out_.sections[section_of_yarn_[yarn]];
    PatternSection::Holding& h = aside.holdings.emplace_back(
        PatternSection::Holding{aside.end_row - 1, first + 1, count, holder});
    h.of_row = true;
    h.of_number = number_of_[row[first]];
    aside.live_at_end -= count;
    // Set aside after a row, before the next turns: the sts are behind it (a short row's
    // others, ahead of it).
    Needle& needle = set_aside_[yarn];
    needle.live -= count;
    (needle.behind >= count ? needle.behind : needle.ahead) -= count;
  }

  // The sts of a yarn's row (by its number in the piece), in the order it worked them.
  std::vector<StitchId> sts_of_row(std::uint32_t yarn, std::uint32_t number) const {
    std::vector<StitchId> row;
    for (StitchId s = c_.yarns.first[yarn]; s != kNoStitch; s = g_.yarn_next[s])
      if (number_of_[s] == number && !unwritten_[s]) row.push_back(s);
    return row;
  }

  // The first loop of a held st the row works along its wales (a row that starts across an
  // edge, as a heel turn's does, on sts slipped to a holder), if any.
  const Loop* held_loop_worked() const {
    for (StitchId s : row_)
      for (std::uint32_t l : g_.loops_taken_by(s))
        if (const Loop& loop = g_.loops[l];
            loop.kind == LoopKind::wale && loop.maker != kNoStitch && holder_of_[loop.maker] != 0)
          return &loop;
    return nullptr;
  }

  // A flat piece's last row whose sts another piece takes one at a time across an edge (the
  // teapot's top, turned like a heel on some of them) is parted onto holders: a run for each
  // piece (and each edge) that works them, counted in the order the row worked them.
  void part_the_last_row_for_a_heel_turn() {
    if (out_.rows.empty() || out_.rows.back().round || st_.live == 0) return;
    std::vector<std::pair<StitchId, std::uint32_t>> loops;
    bool across = false;
    for (StitchId s : st_.last_row) {
      auto made = g_.loops_made_by(s);
      if (made.size() != 1) continue;  // bound off (or an edge st that makes two)
      const Loop& loop = g_.loops[made[0]];
      if (loop.taker == kNoStitch || c_.yarns.piece_of[loop.taker] == section().yarn) return;
      bool edge = loop.kind == LoopKind::perpendicular;
      across = across || edge;
      loops.emplace_back(s, 3 * part_[loop.taker] + (edge                            ? 1
                                                     : loop.kind == LoopKind::joined ? 2
                                                                                     : 0));
    }
    if (!across || loops.size() != st_.live) return;
    auto row = static_cast<std::uint32_t>(out_.rows.size() - 1);
    for (std::uint32_t i = 0; i < loops.size();) {
      std::uint32_t end = i;
      while (end < loops.size() && loops[end].second == loops[i].second) ++end;
      hold(row, loops, i, end);
      section().holdings.back().of_row = true;
      i = end;
    }
  }

  // A first row that picks up along an edge takes loops across it only. One that also works
  // another piece's sts (the teapot's top: a new yarn on 21 sts of Piece 3's last row, its
  // first st a k2tog with the st beside them across the edge) takes those beside them one at a
  // time, as a heel turn does: not covered yet.
  void refuse_start_on_sts_beside_an_edge() const {
    std::uint32_t across = 0;
    std::optional<StitchId> worked;
    for (StitchId s : row_)
      for (std::uint32_t l : g_.loops_taken_by(s)) {
        const Loop& loop = g_.loops[l];
        if (loop.kind == LoopKind::perpendicular)
          ++across;
        else if (loop.maker != kNoStitch && !worked)
          worked = loop.maker;
      }
    if (!worked) return;
    const PatternSection& from = out_.sections[section_of(*worked)];
    unsupported(fmt::format(
        "yarn {} starts with {}, which works {} across a perpendicular edge with {} of Piece {} "
        "({}): a new yarn on another piece's sts whose rows take the sts beside them, one "
        "across each edge of a row ({} in its first), as a heel turn does, is not covered yet",
        out_.sections.back().yarn + 1, g_.describe(row_.front()),
        g_.describe(g_.loops[g_.loops_taken_by(row_.front())[0]].maker), g_.describe(*worked),
        from.piece,
        holder_of_[*worked] ? fmt::format("on holder {}", holder_of_[*worked])
                            : std::string("left on its needle"),
        across));
  }

  // A provisional cast-on in the middle of a row: the st goes on the needle, the loop of its
  // chain waits for the piece on the other side of the split.
  void cast_on_in_row(StitchId s) {
    PatternSection& sec = section();
    bool next_to_last = !out_.ops.empty() && out_.ops.back() == HandOp::provisional_co &&
                        sec.row_chain > 0 && g_.yarn_next[sec.row_chain_ends[1]] == s;
    if (sec.provisional || (sec.row_chain > 0 && !next_to_last))
      unsupported(
          fmt::format("{} is a second provisional cast-on of yarn {}, which is not "
                      "covered yet (one chain per piece)",
                      g_.describe(s), sec.yarn + 1));
    if (sec.row_chain == 0) sec.row_chain_ends[0] = s;
    sec.row_chain_ends[1] = s;
    ++sec.row_chain;
    out_.ops.push_back(HandOp::provisional_co);
  }

  // The first and last st of the row that stay live (not bound off): the ends a spare needle
  // is taken from.
  void note_last_row_ends() {
    auto live = [&](StitchId s) { return info(g_.type[s]).loops_out > 0; };
    auto first = std::find_if(row_.begin(), row_.end(), live);
    auto last = std::find_if(row_.rbegin(), row_.rend(), live);
    if (first == row_.end()) return;
    section().last_row_ends[0] = *first;
    section().last_row_ends[1] = *last;
  }

  // When a rnd (the first of a piece taken up again, or one in the middle of a piece's work)
  // works sts of pieces left on spare needles, or the loops of a provisional cast-on's chain,
  // the knitter first places them into the rnd where they are worked. When a piece is taken up
  // in the rnd, pieces whose sts its rows take one by one across a perpendicular edge are
  // placed too (beside the band that then decreases into them across a gap), and those first
  // worked by its later rows after them.
  void place_spare_needles() {
    std::uint32_t taken = 0;
    const std::uint32_t self = section_of_yarn_[section().yarn];
    for (StitchId s : row_)
      for (std::uint32_t l : g_.loops_taken_by(s)) {
        const Loop& loop = g_.loops[l];
        if (picked_up_along_an_edge(loop)) pick_up_into_the_rnd(loop, taken++);
        if (loop.kind == LoopKind::joined) continue;  // held behind for a three-needle bind-off
        std::uint32_t from = section_of(loop.maker);
        if (loop.kind == LoopKind::perpendicular && !placed_beside_a_band(loop, from == self))
          continue;  // one by one, picked up, or across the gap
        bool chain = is_chain_loop(loop);
        if (std::uint32_t holder = holder_of_[loop.maker]; holder != 0) {
          if (!holder_placed(holder) && !started_on_holder(holder))
            place_holder(holder, loop, taken);
        } else if (from != self && placeable(from, chain)) {
          place_spare_needle(loop, taken);
        }
        ++taken;
      }
    place_pieces_worked_later();
  }

  // The first row of a piece taken up in the rnd places the pieces beside its band too.
  bool takes_up_in_the_rnd() const {
    const PatternSection& worked = out_.sections.back();
    return worked.in_round && worked.resumed && worked.first_row == out_.rows.size();
  }

  // A loop across a perpendicular edge from another piece (not picked up, not held) whose sts
  // go beside the band of a piece taken up in the rnd.
  bool placed_beside_a_band(const Loop& loop, bool own) const {
    return !own && takes_up_in_the_rnd() && holder_of_[loop.maker] == 0 &&
           !picked_up_along_an_edge(loop);
  }

  // A provisional cast-on st's second loop is its chain's (a mirror image keeps it: the two
  // loops are the two sides of the split, not side by side).
  static bool is_chain_loop(const Loop& l) {
    return l.kind == LoopKind::split && l.maker_slot == 1;
  }

  // A spare needle's sts (or a chain's loops) already placed on this piece's needle.
  bool placed(std::uint32_t from, bool chain) const {
    const auto& placed = out_.sections.back().placements;
    return std::any_of(placed.begin(), placed.end(), [&](const PatternSection::Placement& p) {
      return p.section == from && p.chain == chain && p.holder == 0 && !p.edge;
    });
  }

  // A piece worked in the rnd is placed from the st first worked, wherever its last rnd
  // began: that st's place among the sts its needle holds (1-based; 0 when it is the first).
  // The needle holds the loops the last rnd left: a st bound off there holds none, an
  // increase two.
  std::uint32_t place_in_last_rnd(const PatternSection& spare, StitchId maker) const {
    std::uint32_t at = 1;
    for (StitchId s = spare.last_row_ends[0]; s != kNoStitch && s != maker; s = g_.yarn_next[s]) {
      if (s == spare.last_row_ends[1] || !spare.in_round)
        unsupported(
            fmt::format("{} of Piece {} is worked first after it is placed, but it is "
                        "not in its last rnd, which is not covered yet",
                        g_.describe(maker), spare.piece));
      at += static_cast<std::uint32_t>(g_.loops_made_by(s).size());
    }
    return at == 1 ? 0 : at;
  }

  // Pieces first worked by a later row of the band the piece taken up starts with go on after
  // those placed so far (a whole rnd places what it works itself).
  void place_pieces_worked_later() {
    if (!takes_up_in_the_rnd()) return;
    const std::uint32_t self = section_of_yarn_[section().yarn];
    for (StitchId s : band_of_the_take_up())
      for (std::uint32_t l : g_.loops_taken_by(s)) {
        const Loop& loop = g_.loops[l];
        if (loop.maker == kNoStitch || section_of(loop.maker) == self ||
            holder_of_[loop.maker] != 0 || picked_up_along_an_edge(loop) ||
            !placeable(section_of(loop.maker), is_chain_loop(loop)))
          continue;
        std::uint32_t after = 0;
        for (const PatternSection::Placement& p : section().placements) after += p.count;
        place_spare_needle(loop, after);
      }
  }

  // An edge st that makes a loop across a perpendicular edge besides its own (paper §3.2: an
  // expanding edge) gives a loop to pick up: along another piece, or along the piece's own
  // flap into its rnd (a gusset).
  bool picked_up_along_an_edge(const Loop& loop) const {
    return loop.kind == LoopKind::perpendicular && g_.loops_made_by(loop.maker).size() > 1 &&
           (c_.yarns.piece_of[loop.maker] != out_.sections.back().yarn ||
            out_.sections.back().in_round);
  }

  // Consecutive loops picked up along one edge are one pick-up, in the order the rnd works
  // them: one in each row of the piece beside.
  void pick_up_into_the_rnd(const Loop& loop, std::uint32_t after) {
    auto& placed = section().placements;
    std::uint32_t row = number_of_[loop.maker];
    std::uint32_t before_row = static_cast<std::uint32_t>(out_.rows.size());
    // The edge seen from the RS: the loop across it is the maker's last (right) or first; the
    // mirror image swaps them.
    auto made = g_.loops_made_by(loop.maker);
    bool right = (g_.loops[made.front()].kind != LoopKind::perpendicular) != out_.mirror;
    if (goes_on_picking_up(loop, after, right)) {
      ++placed.back().count;
      placed.back().edge->to_row = row;
    } else {
      PatternSection::Placement p{section_of(loop.maker), 1, after, false};
      p.before_row = before_row;
      p.edge = PatternSection::PickUp{p.section, row, row, right};
      placed.push_back(p);
    }
    ++st_.live;
  }

  // Does the loop go on the last pick-up: right after it in the rnd, along the same edge of the
  // same piece, in the next row (both edges of a flat piece joined in the rnd are side by side
  // in its first rnd)?
  bool goes_on_picking_up(const Loop& loop, std::uint32_t after, bool right) const {
    const auto& placed = out_.sections.back().placements;
    if (placed.empty() || !placed.back().edge) return false;
    const PatternSection::Placement& last = placed.back();
    std::uint32_t row = number_of_[loop.maker], to = last.edge->to_row;
    return last.before_row == out_.rows.size() && last.after + last.count == after &&
           last.section == section_of(loop.maker) && last.edge->right == right &&
           (row + 1 == to || to + 1 == row);
  }

  // The sts of the piece taken up, from its first row up to the first whole rnd after it.
  std::vector<StitchId> band_of_the_take_up() const {
    const std::vector<StitchId>& all = deferred_[out_.sections.back().yarn];
    std::size_t row_start = 0;
    for (std::size_t i = 0; i < all.size(); ++i) {
      if (g_.type[all[i]] == T::tnbo || g_.yarn_link[all[i]] == YarnLink::course) continue;
      if (row_start > 0 && g_.yarn_link[all[i]] != YarnLink::turn)
        return {all.begin(), all.begin() + static_cast<std::ptrdiff_t>(row_start)};
      row_start = i + 1;
    }
    return all;
  }

  // A spare needle (or chain) not yet on this piece's needle: one set aside waits on its own.
  bool placeable(std::uint32_t from, bool chain) const {
    const PatternSection& spare = out_.sections[from];
    return !placed(from, chain) && !started_on_needle_of(from, chain) && !spare.set_aside &&
           (spare.left_live || chain);
  }

  // Places the sts of the loop's piece (or its chain) after the first `after` sts of the rnd,
  // from the st the rnd works first.
  void place_spare_needle(const Loop& loop, std::uint32_t after) {
    std::uint32_t from = section_of(loop.maker);
    const PatternSection& spare = out_.sections[from];
    bool chain = is_chain_loop(loop);
    auto [cast_on, last] = cast_on_sts(spare, chain);
    PatternSection::Placement p{from, chain ? cast_on : spare.live_at_end, after,
                                loop.maker == (chain ? last : spare.last_row_ends[1])};
    p.chain = chain;
    p.start = chain || p.from_last ? 0 : place_in_last_rnd(spare, loop.maker);
    p.before_row = static_cast<std::uint32_t>(out_.rows.size());
    add_placement(p);
  }

  // The piece started on the sts of that section's needle (or chain), not on a holder's: those
  // it has not worked yet are on its needle.
  bool started_on_needle_of(std::uint32_t section, bool chain) const {
    const auto& start = out_.sections.back().starts_from;
    return start && start->holder == 0 && start->section == section && start->chain == chain;
  }

  // The piece started on that holder's sts (or its yarn was carried on to them): those it has
  // not worked yet are on its needle.
  bool started_on_holder(std::uint32_t holder) const {
    const PatternSection& worked = out_.sections.back();
    return (worked.starts_from && worked.starts_from->holder == holder) ||
           std::any_of(worked.carries.begin(), worked.carries.end(),
                       [&](const PatternSection::CarryOn& c) { return c.holder == holder; });
  }

  bool holder_placed(std::uint32_t holder) const {
    const auto& placed = out_.sections.back().placements;
    return std::any_of(placed.begin(), placed.end(),
                       [&](const PatternSection::Placement& p) { return p.holder == holder; });
  }

  void place_holder(std::uint32_t holder, const Loop& loop, std::uint32_t after) {
    const Held& held = holders_[holder - 1];
    PatternSection::Placement p{section_of(loop.maker), held.count, after, loop.maker == held.last};
    p.before_row = static_cast<std::uint32_t>(out_.rows.size());
    p.holder = holder;
    add_placement(p);
  }

  // Placed sts go into the rnd, or on a flat piece after the sts its next row works first (the
  // teapot's top taken up on a chain and a holder at the end of its row): ahead of the tip once
  // the work is turned for that row.
  void add_placement(const PatternSection::Placement& p) {
    section().placements.push_back(p);
    st_.live += p.count;
    if (!section().in_round)
      (st_.previous_link == YarnLink::turn ? st_.behind : st_.ahead) += p.count;
  }

  // Where a rnd's sts go different ways and the piece works some of them itself, the runs
  // that other pieces (or joins) work are slipped to holders after it: the piece's needle
  // keeps its own (those it works across a gap too). A run another piece works one st at a
  // time across a perpendicular edge is a holder of its own.
  void hold_what_others_work(std::uint32_t row) {
    const std::uint32_t own = 3 * part_[row_.front()];
    // maker, taker's yarn (x3; +1 across an edge, +2 bound off with a three-needle bind-off)
    std::vector<std::pair<StitchId, std::uint32_t>> loops;
    for (StitchId s : row_)
      for (std::uint32_t l : g_.loops_made_by(s)) {
        const Loop& loop = g_.loops[l];
        if (loop.taker == kNoStitch) return;
        if (loop.kind == LoopKind::split) continue;  // on a provisional cast-on's chain
        std::uint32_t taker = 3 * part_[loop.taker];
        bool across = loop.kind == LoopKind::perpendicular && taker != own;
        bool joined = loop.kind == LoopKind::joined && taker != own;
        loops.emplace_back(s, taker + (across ? 1 : joined ? 2 : 0));
      }
    if (std::none_of(loops.begin(), loops.end(), [&](const auto& l) { return l.second == own; }))
      return share_out_the_last_rnd(row, loops);
    for (std::uint32_t i = 0; i < loops.size(); ++i) {
      if (loops[i].second == own) continue;
      std::uint32_t end = i;
      while (end < loops.size() && loops[end].second == loops[i].second) ++end;
      hold(row, loops, i, end);
      i = end - 1;
    }
  }

  // A piece's last rnd some of whose sts another piece binds off with a three-needle
  // bind-off in the middle of one of its rows (held behind the needle there) keeps its last
  // run on the needle, left on a spare needle, and slips each run before it (to those rows,
  // to rows that take them one at a time, to a join) to a holder of its own. Otherwise the
  // whole needle waits as it is.
  void share_out_the_last_rnd(std::uint32_t row,
                              const std::vector<std::pair<StitchId, std::uint32_t>>& loops) {
    if (std::none_of(loops.begin(), loops.end(),
                     [&](const auto& l) { return bound_off_in_a_row_of_its_own(l.first); }))
      return;
    std::uint32_t last_run = static_cast<std::uint32_t>(loops.size());
    while (last_run > 0 && loops[last_run - 1].second == loops.back().second) --last_run;
    for (std::uint32_t i = 0; i < last_run;) {
      std::uint32_t end = i;
      while (end < last_run && loops[end].second == loops[i].second) ++end;
      hold(row, loops, i, end);
      i = end;
    }
  }

  // Is the loop of `s` bound off by a three-needle bind-off in a row that works sts of its own
  // too (not a join of whole needles)?
  bool bound_off_in_a_row_of_its_own(StitchId s) const {
    for (std::uint32_t l : g_.loops_made_by(s)) {
      StitchId taker = g_.loops[l].taker;
      if (g_.loops[l].kind == LoopKind::joined && taker != kNoStitch &&
          rows_binding_off_among_own_sts_[g_.row[taker]])
        return true;
    }
    return false;
  }

  void hold(std::uint32_t row, const std::vector<std::pair<StitchId, std::uint32_t>>& loops,
            std::uint32_t first, std::uint32_t end) {
    std::uint32_t onto = 0;
    if (goes_on_from_last_holder(loops[first].first)) {
      onto = holders_.back().count;
      holders_.back() = {loops[end - 1].first, onto + end - first};
    } else {
      holders_.push_back({loops[end - 1].first, end - first});
      spare_left_.push_back(0);
      spare_second_.push_back(0);
    }
    auto holder = static_cast<std::uint32_t>(holders_.size());
    for (std::uint32_t i = first; i < end; ++i) {
      holder_of_[loops[i].first] = holder;
      place_on_holder_[loops[i].first] = onto + i - first + 1;
    }
    section().holdings.push_back({row, first + 1, end - first, holder, onto});
    st_.live -= end - first;
  }

  // A yarn works one part of the fabric from its start, and another each time it leaves a
  // row it bound off to go on to other sts (a tube's second leg): sts another part works
  // wait on holders as another yarn's do.
  void number_parts() {
    std::uint32_t parts = 0;
    for (std::uint32_t p = 0; p < c_.yarns.size(); ++p) {
      StitchId s = c_.yarns.first[p];
      for (std::uint32_t i = 0; i < c_.yarns.length[p]; ++i, s = g_.yarn_next[s]) {
        part_[s] = parts;
        bool leaves_bind_off = g_.type[s] == T::bo && g_.yarn_link[s] != YarnLink::course &&
                               g_.yarn_next[s] != kNoStitch && g_.type[g_.yarn_next[s]] != T::bo;
        if (leaves_bind_off) ++parts;
      }
      ++parts;
    }
  }

  // After binding off every st, a row that takes held sts works them with the same yarn,
  // joined in the rnd (written before the row: the yarn carried to them). A rnd that picks up
  // along the edge of held sts (a flat piece joined in the rnd) works no held st.
  void carry_on_to_held_sts() {
    if (st_.live > 0 || out_.rows.size() == section().first_row) return;
    auto taken = g_.loops_taken_by(row_.front());
    if (taken.empty() || g_.loops[taken[0]].kind == LoopKind::perpendicular ||
        holder_of_[g_.loops[taken[0]].maker] == 0)
      return;
    StitchId first = g_.loops[taken[0]].maker;
    std::uint32_t holder = holder_of_[first];
    const Held& held = holders_[holder - 1];
    section().carries.push_back(
        {static_cast<std::uint32_t>(out_.rows.size()), holder, held.count, first == held.last});
    st_.live = held.count;
  }

  // Does the yarn that works the st `first` come to it straight from the last st of the last
  // holder? A tube parted along a helix (a stitch graph's) leaves the last st of one rnd and
  // the first sts of the next to one leg: they go on one holder, in the order it works them.
  bool goes_on_from_last_holder(StitchId first) const {
    if (holders_.empty()) return false;
    auto taker = [&](std::uint32_t loop) { return g_.loops[loop].taker; };
    StitchId before = taker(g_.loops_made_by(holders_.back().last).back());
    return g_.yarn_next[before] == taker(g_.loops_made_by(first).front());
  }

  void add_row() {
    join_flat_piece_in_the_rnd();
    bool turns = g_.yarn_link[row_.back()] == YarnLink::turn || ends_between_turns() ||
                 rounds_a_corner_short_of_the_marker() || (g_.flags[row_.back()] & kGoesOnRound);
    bool first_of_take_up = section().resumed && section().first_row == out_.rows.size();
    bool full_round =
        section().in_round && !turns && st_.previous_link != YarnLink::turn && !after_a_corner();
    bool picked_up = section().picks_up && section().first_row == out_.rows.size();
    Side side = (hand_.left_to_right(row_.front()) != out_.mirror) ? Side::ws : Side::rs;
    if (section().in_round && !turns && after_a_row_that_turned()) hold_the_flap_left(side);
    carry_on_to_held_sts();
    // After rows that turned, a rnd that works every st starts at the beginning of the rnd.
    if (!picked_up && (first_of_take_up || (section().in_round && !turns))) place_spare_needles();
    PatternRow r;
    // In the rnd a row that turns is a short row; a rnd goes on around.
    r.round = section().in_round && !turns;
    r.number =
        static_cast<std::uint32_t>(out_.rows.size()) - section().first_row + section().first_number;
    r.side = side;
    out_.ws_rounds = out_.ws_rounds || (r.round && r.side == Side::ws);
    r.first_op = static_cast<std::uint32_t>(out_.ops.size());
    r.sts_before = st_.live;
    r.bind_off =
        std::all_of(row_.begin(), row_.end(), [&](StitchId s) { return g_.type[s] == T::bo; });
    if (st_.previous_link == YarnLink::turn) std::swap(st_.ahead, st_.behind);
    if (st_.double_stitch_next) slip_double_stitch();
    if (r.round) move_beginning_of_round_to_a_helix();
    if (r.round && st_.bor_removed) place_new_beginning_of_round();
    note_band_from_rnd(r);
    std::uint32_t takes = 0;
    for (StitchId s : row_) {
      number_of_[s] = r.number;
      note_region_mark(s, r);
      pass_beginning_of_round(s, r, true);
      append_ops(s, r);
      pass_beginning_of_round(s, r, false);
      follow_beginning_of_round(s, r);
      takes += info(worked_by_hand(g_, s)).loops_in - (g_.type[s] == T::tnbo);  // one held behind
      move_loops(s);
    }
    refuse_held_sts_left(r);
    note_flap_back_from_the_end(r, takes);
    end_row(r, turns, takes);
    check_make_one_has_a_strand(r);
    r.end_op = static_cast<std::uint32_t>(out_.ops.size());
    r.sts_after = st_.live;
    st_.last_side = r.side;
    out_.rows.push_back(r);
    if (full_round) hold_what_others_work(static_cast<std::uint32_t>(out_.rows.size() - 1));
    if (!r.round && !r.partial) hold_flaps_others_work();
  }

  // A flat piece parting into flaps (its last whole row's sts going to its own next row and
  // to other pieces' rows): each run another piece works is slipped to a holder of its own
  // right after the row, counted in the order the row worked them, and the piece goes on with
  // the sts its own rows work.
  void hold_flaps_others_work() {
    std::vector<StitchId> row = row_;
    bool own = false;
    for (StitchId s : row)
      for (std::uint32_t l : g_.loops_made_by(s)) {
        StitchId taker = g_.loops[l].taker;
        own |= taker != kNoStitch && c_.yarns.piece_of[taker] == c_.yarns.piece_of[s] &&
               g_.loops[l].kind == LoopKind::wale;
      }
    if (!own) return;
    for (std::uint32_t i = 0, end = 0; i < row.size(); i = end) {
      std::uint32_t taker_row = row_taking_from_another_piece(row[i]);
      for (end = i + 1; end < row.size() && row_taking_from_another_piece(row[end]) == taker_row;)
        ++end;
      if (taker_row == kNotTaken || g_.loops[g_.loops_made_by(row[i])[0]].kind != LoopKind::wale)
        continue;
      const std::uint32_t count = end - i, holder = hold_run_of_row(row, i, end);
      PatternSection::Holding& h = section().holdings.emplace_back(PatternSection::Holding{
          static_cast<std::uint32_t>(out_.rows.size() - 1), i + 1, count, holder});
      h.of_row = true;
      st_.live -= count;
      (st_.behind >= count ? st_.behind : st_.ahead) -= count;
    }
  }

  bool works_bor_wale(StitchId s) const {
    auto taken = g_.loops_taken_by(s);
    return st_.bor_st != kNoStitch && std::any_of(taken.begin(), taken.end(), [&](std::uint32_t l) {
             return g_.loops[l].maker == st_.bor_st;
           });
  }

  // A row that turns in the rnd (a stitch graph's short rows go round past the beginning of
  // the rnd) slips the BOR marker where it works the marker's wale: before that st going the
  // way the rnds go, after it going back; not first or last in the row (the simulator slips
  // it at the start of a row, and a row that turns there leaves it behind the turn).
  void pass_beginning_of_round(StitchId s, const PatternRow& r, bool before) {
    if (!section().in_round || r.round || !turns_on_tucks() || !works_bor_wale(s)) return;
    bool forward = r.side == st_.rnd_side;
    if (forward != before || s == (before ? row_.front() : row_.back())) return;
    st_.bor_slipped_at = static_cast<std::uint32_t>(out_.ops.size());
    out_.ops.push_back(HandOp::sm);
  }

  // A rnd after short rows that goes all the way round from where they ended (a stitch
  // graph's helix) begins the rnds there: the last short row to pass the BOR marker removes
  // it, and the rnd places it anew.
  void move_beginning_of_round_to_a_helix() {
    std::uint32_t takes = 0;
    for (StitchId s : row_) takes += info(worked_by_hand(g_, s)).loops_in;
    if (st_.previous_link != YarnLink::turn || takes != st_.live || !turns_on_tucks() ||
        works_bor_wale(row_.front()) || !st_.bor_slipped_at)
      return;
    out_.ops[*st_.bor_slipped_at] = HandOp::rm;
    st_.bor_slipped_at.reset();
    st_.bor_removed = true;
  }

  // Short rows turned on a tuck (a stitch graph's) go round past the beginning of the rnd; the
  // short rows of a stitch mesh turn within the rnd, which the rows among rnds keep to.
  bool turns_on_tucks() const {
    auto tuck_turn = [&](const std::vector<StitchId>& row) {
      return !row.empty() && g_.type[row.back()] == T::tuck &&
             g_.yarn_link[row.back()] == YarnLink::turn;
    };
    return tuck_turn(row_) || (st_.previous_link == YarnLink::turn && tuck_turn(st_.last_row));
  }

  void follow_beginning_of_round(StitchId s, const PatternRow& r) {
    if (!section().in_round) return;
    bool starts_rnd = r.round && s == row_.front() && st_.previous_link != YarnLink::turn;
    if (starts_rnd) st_.rnd_side = r.side;
    if (r.round) st_.bor_slipped_at.reset();
    if (starts_rnd || works_bor_wale(s)) st_.bor_st = s;
  }

  // A flat piece whose next row goes on around (the teapot's second strip going on as a tube
  // between the strips) is joined to work in the rnd in the middle of its work: the sts of its
  // last row, all left to other pieces, are slipped to a holder, and the rnd is made of sts
  // picked up (along the piece's own edges too) and placed onto the empty needle, from the new
  // beginning of the rnd.
  void join_flat_piece_in_the_rnd() {
    PatternSection& sec = section();
    if (sec.in_round || out_.rows.size() == sec.first_row || !goes_on_around(row_.back())) return;
    hold_the_last_row();
    sec.in_round = true;
    sec.joined_in_rnd_at = static_cast<std::uint32_t>(out_.rows.size());
    st_.previous_link = YarnLink::shift;  // the rnd starts at the beginning of the rnd
  }

  // Does the yarn go on around after `last`, not round a corner or back over the sts just made?
  bool goes_on_around(StitchId last) const {
    return g_.yarn_link[last] == YarnLink::shift && !(g_.flags[last] & kRoundsACorner);
  }

  // Does the yarn go round a corner after `last` into the next rnd (its next st picks up the
  // edge of `last`)? The knitter goes on without turning, which a row of a piece worked flat
  // must say ("do not turn").
  bool rounds_a_corner(StitchId last) const { return g_.flags[last] & kRoundsACorner; }

  // The sts of the flat piece's last row go to a holder, in the order the row worked them; the
  // others on the needle (those short rows left) stay for the rnd. A rnd that works some of
  // the last row's sts itself would join them with the sts picked up: not written yet.
  void hold_the_last_row() {
    std::vector<std::pair<StitchId, std::uint32_t>> held;
    for (StitchId s : st_.last_row)
      if (info(g_.type[s]).loops_out > 0) held.emplace_back(s, 0);
    if (!std::all_of(held.begin(), held.end(),
                     [&](const auto& h) { return left_to_another_piece(h.first); }))
      unsupported(fmt::format(
          "{} starts a rnd of Piece {} after rows worked flat, and works sts of its last row "
          "itself: joining a flat piece in the rnd with the sts of its last row is not covered "
          "yet (only with those sts slipped to a holder for another piece)",
          g_.describe(row_.front()), section().piece));
    if (held.empty()) return;
    hold(static_cast<std::uint32_t>(out_.rows.size() - 1), held, 0,
         static_cast<std::uint32_t>(held.size()));
    section().holdings.back().flat_row = true;
  }

  // A rnd after rows that turned (a gusset's, round a flap) that leaves the sts of the flap's
  // last row to another piece (the flap goes on as a leg of its own): the knitter slips them to
  // a holder first. The flap's rows start at the beginning of the rnd (they follow a rnd), so
  // its sts are the first of the rnd, in the order the rnd goes. (Where the rows before the
  // rnd are another piece's face, as in the two bars, their sts are placed, not held.) A piece
  // taken up again (the teapot's body between its strips) slips them as it is taken up.
  void hold_the_flap_left(Side rnd_side) {
    std::vector<std::pair<StitchId, std::uint32_t>> flap;
    for (StitchId s : st_.last_row)
      if (left_to_another_piece(s)) flap.emplace_back(s, 0);
    if (flap.empty() || flap.size() >= st_.live || !picks_up_its_own_flap()) return;
    if (st_.last_side != rnd_side) std::reverse(flap.begin(), flap.end());
    auto held = static_cast<std::uint32_t>(flap.size());
    std::uint32_t live = st_.live;
    hold(static_cast<std::uint32_t>(out_.rows.size() - 1), flap, 0, held);
    // A flap whose last row went on to the beginning of the rnd, or whose first row went back
    // from there (after an odd number of rows its last ends away from it), is the rnd's last
    // sts.
    if ((st_.previous_link == YarnLink::shift && !last_row_started_at_the_marker()) ||
        st_.flap_back_from_the_end)
      section().holdings.back().first = live - held + 1;
  }

  // The row before turned, or went on round from where rows that turned ended (a flap's last
  // row going on to the beginning of the rnd, down the flap's edge).
  bool after_a_row_that_turned() const {
    return st_.previous_link == YarnLink::turn || after_a_corner() ||
           (out_.rows.size() > out_.sections.back().first_row && out_.rows.back().partial);
  }

  // A row in the rnd that starts at the beginning of the rnd and goes round a corner into the
  // next (the teapot's first strip) leaves the sts before the marker: a row that does not turn,
  // not a rnd. One that ends at the marker (letter-r's flap, worked back from the end of the
  // rnd) goes on as a rnd.
  bool rounds_a_corner_short_of_the_marker() const {
    return out_.sections.back().in_round && rounds_a_corner(row_.back()) &&
           works_bor_wale(row_.front());
  }

  // Did the piece's last row start at the beginning of the rnd (on the marker's wale)?
  bool last_row_started_at_the_marker() const {
    return !st_.last_row.empty() && st_.bor_st == st_.last_row.front();
  }

  // Did the piece's last row go round a corner into this rnd (the teapot's first strip, worked
  // in short rows in its rnd, going on over the sts they left)?
  bool after_a_corner() const {
    return !st_.last_row.empty() && rounds_a_corner(st_.last_row.back());
  }

  bool picks_up_its_own_flap() const {
    const std::uint32_t self = section_of_yarn_[out_.sections.back().yarn];
    return std::any_of(row_.begin(), row_.end(), [&](StitchId s) {
      auto taken = g_.loops_taken_by(s);
      return std::any_of(taken.begin(), taken.end(), [&](std::uint32_t l) {
        return picked_up_along_an_edge(g_.loops[l]) && section_of(g_.loops[l].maker) == self;
      });
    });
  }

  bool left_to_another_piece(StitchId s) const {
    if (holder_of_[s] != 0) return false;
    for (std::uint32_t l : g_.loops_made_by(s))
      if (const Loop& loop = g_.loops[l];
          loop.taker != kNoStitch && loop.kind != LoopKind::split &&
          c_.yarns.piece_of[loop.taker] != out_.sections.back().yarn)
        return true;
    return false;
  }

  // The last row of a yarn in the rnd that goes on from a turn leaves the sts beyond it on
  // the needle: a row that turns (before its sts are left for a join), not a rnd.
  bool ends_between_turns() const {
    StitchId last = row_.back();
    return out_.sections.back().in_round && g_.yarn_link[last] == YarnLink::none &&
           st_.previous_link == YarnLink::turn && info(g_.type[last]).loops_out > 0;
  }

  // The schedule's mismatch and short-row markers go before the stitch's operations.
  void note_region_mark(StitchId s, const PatternRow& r) {
    if (marked_[s] == MarkerKind::none) return;
    out_.region_marks.push_back({static_cast<std::uint32_t>(out_.rows.size()),
                                 static_cast<std::uint32_t>(out_.ops.size()) - r.first_op,
                                 marked_[s]});
  }

  // A row that turns with sts left beyond it says so; German short rows make the st it turned
  // at a double stitch first in the next row (at the edge too).
  void end_row(PatternRow& r, bool turns, std::uint32_t takes) {
    r.short_row = turns && (section().in_round || st_.ahead > 0);
    if (rounds_a_corner(row_.back()) && (!section().in_round || r.short_row))
      out_.ops.push_back(HandOp::no_turn);
    else if (r.short_row && out_.ops.back() != HandOp::wt)
      out_.ops.push_back(HandOp::turn);
    st_.double_stitch_next =
        out_.turns == TurnMethod::german && worked_by_hand(g_, row_.back()) == T::sr4;
    // A rnd works every st, unless it starts where short rows ended (it then goes on to the
    // beginning of the rnd); a flat row ends at the edge or turns short of it.
    bool full_round = r.round && st_.previous_link != YarnLink::turn && !after_a_corner();
    if (full_round && takes != r.sts_before)
      unsupported(fmt::format("the row of {} works {} of the {} live stitches",
                              g_.describe(row_.front()), takes, r.sts_before));
    r.partial = r.short_row || (!r.bind_off && takes != r.sts_before);
    out_.short_rows = out_.short_rows || r.short_row;
  }

  // Loops ahead of and behind the needle tip on a flat piece, as the stitch is worked (the row
  // ends at the edge when none is ahead). A wrapped st goes back to the left needle.
  void move_loops(StitchId s) {
    const StitchTypeInfo& t = info(worked_by_hand(g_, s));
    // A provisional cast-on's chain loop is not on the needle.
    std::uint32_t out = g_.type[s] == T::sco ? 1 : t.loops_out;
    st_.live = st_.live + out - t.loops_in;
    if (section().in_round || (t.type == T::sr4 && out_.turns == TurnMethod::wrap_and_turn)) return;
    if (st_.ahead < t.loops_in)
      unsupported(fmt::format("{} works past the end of the needle", g_.describe(s)));
    st_.ahead -= t.loops_in;
    st_.behind += out;
  }

  // Rows after a row that went on from a rnd over all its sts and turned at its end (letter-r's
  // flap) work back over the rnd's last sts.
  void note_flap_back_from_the_end(const PatternRow& r, std::uint32_t takes) {
    if (r.round)
      st_.flap_back_from_the_end = false;
    else if (section().in_round && g_.yarn_link[row_.back()] == YarnLink::turn &&
             takes == r.sts_before && out_.rows.size() > section().first_row &&
             out_.rows.back().round)
      st_.flap_back_from_the_end = true;
  }

  void note_band_from_rnd(const PatternRow& r) {
    if (r.round) st_.band_from_rnd.reset();
    if (!r.round && section().in_round && st_.previous_link == YarnLink::shift)
      st_.band_from_rnd = std::pair{static_cast<std::uint32_t>(out_.rows.size()), r.first_op};
  }

  void place_new_beginning_of_round() {
    out_.ops.push_back(HandOp::pm);
    st_.bor_removed = false;
  }

  void slip_double_stitch() {
    out_.ops.push_back(HandOp::ds);
    st_.double_stitch_next = false;
    if (section().in_round) return;
    --st_.ahead;
    ++st_.behind;
  }

  // A st that works a loop across a contracting perpendicular edge takes it from the piece
  // beside, waiting on a spare needle: slipped to the tip of the left needle, or behind the st
  // there when the st works it second.
  void slip_from_spare_needle(StitchId s, PatternRow& r) {
    auto taken = g_.loops_taken_by(s);
    for (std::size_t i = 0; i < taken.size(); ++i) {
      const Loop& loop = g_.loops[taken[i]];
      if (loop.kind != LoopKind::perpendicular || picked_up_along_an_edge(loop)) continue;
      // Worked in the order taken off the needle: right to left seen from the RS on a RS row.
      std::size_t worked = (r.side == Side::rs) != out_.mirror ? taken.size() - 1 - i : i;
      if (worked > 1)
        unsupported(
            fmt::format("{} works a loop of {} across a perpendicular edge third, "
                        "which is not covered yet",
                        g_.describe(s), g_.describe(g_.loops[taken[i]].maker)));
      StitchId maker = loop.maker;
      refuse_pick_up_in_the_work(s, maker);
      if (holder_of_[maker] == 0 && on_own_needle(maker)) {
        decrease_across_gap(s, maker, worked, r);
        continue;
      }
      bool second = false;
      if (holder_of_[maker] != 0)
        second = take_from_holder_on_spare_needle(s, holder_of_[maker], maker);
      else
        refuse_edge_loop_off_spare_needle(s, maker);
      out_.ops.push_back(
          second ? (worked == 0 ? HandOp::from_second_spare : HandOp::from_second_spare_behind)
                 : (worked == 0 ? HandOp::from_spare : HandOp::from_spare_behind));
      ++st_.live;
      if (!section().in_round) ++st_.ahead;
    }
  }

  // Sts held for rows that work them one at a time go on a spare needle before the first of
  // those rows, the one they take first at its tip; while one spare needle holds sts, a second
  // holder goes on a second one (rows that take a st at each edge). Is it on the second?
  bool take_from_holder_on_spare_needle(StitchId s, std::uint32_t holder, StitchId first) {
    // A piece set aside and taken up again finds the holder's sts left on their spare needle.
    if (!holder_placed(holder) && spare_left_[holder - 1] == 0)
      put_holder_on_spare_needle(s, holder, first);
    --spare_left_[holder - 1];
    return spare_second_[holder - 1] != 0;
  }

  void put_holder_on_spare_needle(StitchId s, std::uint32_t holder, StitchId first) {
    const Held& held = holders_[holder - 1];
    bool in_use[2] = {false, false};
    for (std::size_t h = 0; h < holders_.size(); ++h)
      if (spare_left_[h] > 0) in_use[spare_second_[h]] = true;
    bool second = in_use[0] || taken_beside_a_waiting_piece(s, holder);
    if (second && in_use[1])
      unsupported(fmt::format(
          "{} works a st of holder {} across a perpendicular edge while two spare needles still "
          "hold sts for the rows: a third spare needle is not covered yet",
          g_.describe(s), holder));
    PatternSection::Placement p{section_of(first), held.count, 0, first == held.last};
    p.before_row = static_cast<std::uint32_t>(out_.rows.size());
    p.holder = holder;
    p.to_spare = true;
    p.second_spare = second;
    section().placements.push_back(p);
    spare_left_[holder - 1] = held.count;
    spare_second_[holder - 1] = second;
  }

  // Do the rows that take the holder's sts (from `s` on, while it holds sts) also take sts of
  // a piece waiting on a spare needle (letter-r at 27 sts/39 rows: its bowl takes Piece 1's sts
  // at one edge and holder 3's at the other)? `sl1 from spare` then means that piece's needle,
  // and the holder goes on a second one.
  bool taken_beside_a_waiting_piece(StitchId s, std::uint32_t holder) const {
    std::uint32_t left = holders_[holder - 1].count;
    for (; s != kNoStitch && left > 0; s = g_.yarn_next[s])
      for (std::uint32_t l : g_.loops_taken_by(s)) {
        const Loop& loop = g_.loops[l];
        if (loop.kind != LoopKind::perpendicular || loop.maker == kNoStitch ||
            picked_up_along_an_edge(loop))
          continue;
        if (holder_of_[loop.maker] == holder)
          --left;
        else if (holder_of_[loop.maker] == 0 && !on_own_needle(loop.maker))
          return true;
      }
    return false;
  }

  // The latest section of the yarn that worked `maker`.
  std::uint32_t section_of(StitchId maker) const {
    return section_of_yarn_[c_.yarns.piece_of[maker]];
  }

  // Is the maker's st on the needle of the piece being worked: its own, one of a spare needle
  // (or a chain) placed into its rnd, a holder placed there (or the one it started on), or
  // one of the spare needle it started on?
  bool on_own_needle(StitchId maker, bool chain = false) const {
    if (holder_of_[maker] != 0)
      return holder_placed(holder_of_[maker]) || started_on_holder(holder_of_[maker]);
    std::uint32_t from = section_of(maker);
    const PatternSection& worked = out_.sections.back();
    return c_.yarns.piece_of[maker] == worked.yarn || started_on_needle_of(from, chain) ||
           placed(from, chain);
  }

  // An edge st that makes a loop across the edge besides its own (an expanding edge) gives
  // it to be picked up; a row that picks it up and knits it in the middle of the work (a
  // gusset's "pick up and knit") is not written yet.
  void refuse_pick_up_in_the_work(StitchId s, StitchId maker) const {
    if (g_.loops_made_by(maker).size() < 2) return;
    unsupported(fmt::format(
        "{} picks up a loop along the edge of {} (an expanding perpendicular edge) in the middle "
        "of the work (a gusset's \"pick up and knit\"), which is not covered yet",
        g_.describe(s), g_.describe(maker)));
  }

  // A st of the piece's own needle across a gap (a heel turn's decrease): worked second, it is
  // the next st on the left needle; worked first by the row's first st, it is the one at the
  // tip of the right needle, slipped back ("sl1 back"). A row that goes on from the end of a
  // rnd removes the beginning-of-rnd marker there first; the next rnd places a new one.
  void decrease_across_gap(StitchId s, StitchId maker, std::size_t worked, PatternRow& r) {
    remove_beginning_of_round(r);
    if (worked == 1) return;
    if (s != row_.front())
      unsupported(fmt::format(
          "{} works a loop of {} across a perpendicular edge from its own needle first, but "
          "not first in its row, where a knitter could slip it back from the right needle; "
          "which is not covered yet",
          g_.describe(s), g_.describe(maker)));
    out_.ops.push_back(HandOp::slip_back);
    if (section().in_round) return;
    ++st_.ahead;
    --st_.behind;
  }

  // A band worked back and forth from the end of a rnd starts at the beginning-of-rnd marker,
  // which is then in its gap: the band's first row removes it (the next rnd places a new one).
  void remove_beginning_of_round(PatternRow& r) {
    if (st_.bor_removed || !st_.band_from_rnd) return;
    auto [row, op] = *st_.band_from_rnd;
    out_.ops.insert(out_.ops.begin() + op, HandOp::rm);
    for (std::size_t i = row; i < out_.rows.size(); ++i) {
      out_.rows[i].first_op += i > row;
      ++out_.rows[i].end_op;
    }
    r.first_op += out_.rows.size() > row;
    st_.bor_removed = true;
  }

  // "Sl1 from spare" takes the st from a piece waiting on a spare needle. One of a piece set
  // aside waits on that piece's needle (a knitter would put it on a holder first): not written
  // yet.
  void refuse_edge_loop_off_spare_needle(StitchId s, StitchId maker) const {
    const PatternSection& from = out_.sections[section_of(maker)];
    if (from.set_aside)
      unsupported(fmt::format(
          "{} works a loop of {} across a perpendicular edge from the needle of Piece {}, set "
          "aside, not from a spare needle, which is not covered yet",
          g_.describe(s), g_.describe(maker), from.piece));
  }

  // Sts of another piece's spare needle are placed into a rnd that works them. A piece set
  // aside keeps its sts on its own needle with those it works later (a knitter would slip the
  // others to a holder first), and a row that is no whole rnd has no place for them: neither
  // is written yet.
  void refuse_loop_of_a_piece_not_placed(StitchId s) const {
    for (std::uint32_t l : g_.loops_taken_by(s)) {
      const Loop& loop = g_.loops[l];
      if (loop.kind == LoopKind::perpendicular || loop.maker == kNoStitch ||
          on_own_needle(loop.maker, is_chain_loop(loop)))
        continue;
      const PatternSection& from = out_.sections[section_of(loop.maker)];
      if (from.set_aside)
        unsupported(fmt::format(
            "{} works a loop of {} off the needle of Piece {}, set aside with sts it works "
            "itself later; a knitter would first slip the sts other pieces take to holders, "
            "which is not covered yet",
            g_.describe(s), g_.describe(loop.maker), from.piece));
      unsupported(fmt::format(
          "{} works a loop of {} (Piece {}) in a row that is not a whole rnd, where its sts "
          "cannot be placed on the needle (that is written only before a rnd), which is not "
          "covered yet",
          g_.describe(s), g_.describe(loop.maker), from.piece));
    }
  }

  void append_ops(StitchId s, PatternRow& r) {
    T type = worked_by_hand(g_, s);
    if (type == T::sr4)
      return append_stitch_ops(g_, s, r.side, out_.mirror, out_.turns, out_.ops, r.wraps_again);
    for (std::uint32_t l : g_.loops_taken_by(s))
      if (g_.loops[l].maker != kNoStitch && unwritten_[g_.loops[l].maker])
        unsupported(
            fmt::format("{} works a loop of {}, which this pattern writes later (its yarn "
                        "is taken up again after the pieces it waits for)",
                        g_.describe(s), g_.describe(g_.loops[l].maker)));
    bool first_row = out_.rows.size() == section().first_row;
    if (!(section().picks_up && first_row)) slip_from_spare_needle(s, r);
    if (type == T::sco) return cast_on_in_row(s);
    if (type == T::tnbo) return bind_off_with_held_st(s);
    // A cast-on between worked sts of one row.
    if (type == T::co)
      unsupported(fmt::format("{} is a {} in the middle of the work, which is not covered yet",
                              g_.describe(s), info(type).name));
    refuse_loop_of_a_piece_not_placed(s);
    append_stitch_ops(g_, s, r.side, out_.mirror, out_.turns, out_.ops, r.wraps_again);
  }

  void check_make_one_has_a_strand(const PatternRow& r) const {
    if (!r.round) hand::check_make_one_has_a_strand(g_, row_.back());
  }

  const Compilation& c_;
  const KnitGraph& g_;
  Handedness hand_;
  std::uint32_t pieces_ = 0;
  HandPattern out_;
  std::vector<StitchId> row_;
  // What the knitter has on the needle for the yarn being worked (kept while it is set aside).
  struct Needle {
    std::uint32_t live = 0;
    std::uint32_t ahead = 0, behind = 0;  // loops on the left and right needle (flat pieces)
    bool double_stitch_next = false;
    bool cast_on_done = false;
    bool bor_removed = false;  // by a row across the gap; the next rnd places a new one
    // The row (and its first op) that went on from the end of the last rnd.
    std::optional<std::pair<std::uint32_t, std::uint32_t>> band_from_rnd;
    bool flap_back_from_the_end = false;  // rows in the rnd that turned at its end
    YarnLink previous_link = YarnLink::none;
    // The BOR marker sits before the loop of this st's wale (the latest st worked there), and
    // the side the rnds are worked with.
    StitchId bor_st = kNoStitch;
    Side rnd_side = Side::rs;
    std::optional<std::uint32_t> bor_slipped_at;  // the op of a short row that slipped it
    std::vector<StitchId> last_row;  // the piece's row flushed last, and the side it faced
    Side last_side = Side::rs;
  };
  Needle st_;
  std::vector<Needle> set_aside_;               // per yarn
  std::vector<std::uint32_t> section_of_yarn_;  // its latest section
  std::vector<std::uint32_t> number_of_ = std::vector<std::uint32_t>(g_.size(), 0);  // row no.
  // A yarn taken up again is written from there to its end in one go, after the pieces it
  // waited for: its stitches wait here meanwhile.
  std::vector<std::vector<StitchId>> deferred_;                                    // per yarn
  std::vector<std::uint8_t> taken_up_;                                             // per yarn
  std::vector<std::uint8_t> unwritten_ = std::vector<std::uint8_t>(g_.size(), 0);  // deferred
  std::vector<MarkerKind> marked_ = std::vector<MarkerKind>(g_.size(), MarkerKind::none);
  // Sts slipped to holders: per model stitch its holder (1-based, 0: none); per holder its
  // last st (in the order its rnd worked them) and how many it holds.
  std::vector<std::uint32_t> holder_of_ = std::vector<std::uint32_t>(g_.size(), 0);
  std::vector<std::uint32_t> part_ = std::vector<std::uint32_t>(g_.size(), 0);  // number_parts
  struct Held {
    StitchId last;
    std::uint32_t count;
  };
  // Per model stitch slipped to a holder: its place there, 1-based in the order slipped.
  std::vector<std::uint32_t> place_on_holder_ = std::vector<std::uint32_t>(g_.size(), 0);
  std::vector<Held> holders_;
  // Per holder put on a spare needle for rows: the sts still on it, and whether that needle
  // is the second of two.
  std::vector<std::uint32_t> spare_left_;
  std::vector<std::uint8_t> spare_second_;
  // Per model row: it binds off with a three-needle bind-off among sts of its own.
  std::vector<std::uint8_t> rows_binding_off_among_own_sts_ = rows_binding_off_among_own_sts(g_);
};

}  // namespace

HandPattern build_hand_pattern(const Compilation& c, TurnMethod turns, Rounds rounds) {
  check_supported(c);
  HandPattern pattern = PatternBuilder(c, turns, rounds).run();
  name_pieces(c.knit, c.yarns, pattern);
  place_section_markers(pattern);
  place_region_markers(pattern);
  return pattern;
}

}  // namespace skein::hand
