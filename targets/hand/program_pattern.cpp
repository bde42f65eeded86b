// The hand pattern built on the lowering's live-loop program (issue 13): each run of live loops
// is a piece's needle; each course a row or a rnd, with the side facing that its direction
// gives (right to left seen from the RS: the RS faces the knitter; left to right: the WS), its
// stitches in the course's working order. Nothing here votes on a direction or cuts rows from
// the schedule. Steps the hand vocabulary cannot say yet are refused by name, before any text.
#include "hand/program_pattern.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <optional>
#include <span>
#include <unordered_map>

#include "common/error.hpp"
#include "driver/pipeline.hpp"
#include "hand/marker_plan.hpp"
#include "hand/piece_names.hpp"
#include "hand/region_markers.hpp"
#include "hand/stitch_working.hpp"

namespace skein::hand {
namespace {

using T = StitchType;
constexpr std::uint32_t kNoPiece = 0xffffffffu;
constexpr std::uint32_t kNoLoopHere = 0xffffffffu;

// What the knitter holds for one piece: its sts, split between the left needle (ahead of the
// tip) and the right one (behind) on a flat piece; in the rnd, the ring of its sts from the
// beginning-of-round marker on, the way the rnds go, and where the yarn is.
struct Needle {
  std::uint32_t section = 0;
  std::uint32_t live = 0, ahead = 0, behind = 0;
  bool in_round = false;
  bool double_stitch_next = false;  // German short rows: the next row begins with DS
  bool turned_at_sr4 = false;       // the last course ended on a short row's turn
  bool worked = false;              // a course has worked its sts
  CourseDirection last = CourseDirection::left_to_right;
  CourseDirection rnds = CourseDirection::left_to_right;  // the way its rnds go
  std::vector<std::uint32_t> ring;
  std::uint32_t gap = 0;  // the yarn is before ring[gap], going the way the rnds go
};

class ProgramPatternBuilder {
 public:
  ProgramPatternBuilder(const Compilation& c, TurnMethod turns)
      : c_(c),
        g_(c.knit),
        p_(c.program),
        piece_of_run_(p_.runs.size(), kNoPiece),
        holder_of_run_(p_.runs.size(), 0),
        yarn_started_(c.yarns.size(), 0) {
    out_.source = c.input;
    out_.turns = turns;
    for (const Event& e : c.schedule.events)
      if (e.kind == EventKind::marker && e.marker != MarkerKind::beginning_of_round)
        marked_[e.stitch] = e.marker;
  }

  HandPattern run() && {
    if (p_.gap)
      unsupported(fmt::format("the live-loop program stops at {}: {}", g_.describe(p_.gap->stitch),
                              p_.gap->why));
    for (step_ = 0; step_ < p_.steps.size(); ++step_) {
      const Step& s = p_.steps[step_];
      switch (s.kind) {
        case StepKind::cast_on:
          cast_on(s);
          break;
        case StepKind::course:
        case StepKind::bind_off:
          course(s);
          break;
        case StepKind::split:
          split(s);
          break;
        default:
          not_yet(s, "is not written by the program's pattern builder yet");
      }
    }
    end_section();
    return std::move(out_);
  }

 private:
  [[noreturn]] static void unsupported(const std::string& what) {
    throw UnsupportedError(fmt::format("hand target: {}", what));
  }

  // "step 12 (split of yarn 2 at face 40 (k, row 7)) is not ...".
  [[noreturn]] void not_yet(const Step& s, const std::string& what) const {
    std::string where =
        s.stitches.size() > 0
            ? fmt::format(" at {}", g_.describe(p_.stitches[s.stitches.begin].stitch))
            : "";
    unsupported(fmt::format("step {} ({} of yarn {}{}) {}", step_ + 1, step_kind_name(s.kind),
                            s.yarn + 1, where, what));
  }

  std::span<const WorkedStitch> stitches_of(const Step& s) const {
    return {p_.stitches.data() + s.stitches.begin, s.stitches.size()};
  }
  std::span<const std::uint32_t> taken_by(std::uint32_t worked) const {
    return {p_.taken.data() + p_.taken_at[worked], p_.taken_at[worked + 1] - p_.taken_at[worked]};
  }
  std::span<const PlacedLoop> made_by(std::uint32_t worked) const {
    return {p_.made.data() + p_.made_at[worked], p_.made_at[worked + 1] - p_.made_at[worked]};
  }

  // The loop of `loops` (left to right seen from the RS) a course going `d` meets first.
  template <class Loops>
  static auto first_met(const Loops& loops, CourseDirection d) {
    return d == CourseDirection::right_to_left ? loops.back() : loops.front();
  }

  PatternSection& section() { return out_.sections.back(); }
  const PatternSection& section() const { return out_.sections.back(); }

  void end_section() {
    if (out_.sections.empty()) return;
    Needle& n = needles_.back();
    if (row_open_)
      unsupported(
          fmt::format("yarn {} stops in the middle of a rnd, which the program's pattern "
                      "builder does not write yet",
                      section().yarn + 1));
    section().end_row = static_cast<std::uint32_t>(out_.rows.size());
    section().left_live = n.live != 0;
    section().live_at_end = n.live;
  }

  void cast_on(const Step& s) {
    for (const WorkedStitch& w : stitches_of(s))
      if (g_.type[w.stitch] != T::co)
        not_yet(s, fmt::format("casts on with {}, which the program's pattern builder does not "
                               "write yet",
                               g_.describe(w.stitch)));
    auto n = static_cast<std::uint32_t>(s.stitches.size());
    if (yarn_started_[s.yarn]) not_yet(s, "casts on with a yarn that worked before");
    start_section(s.yarn, n);
    PatternSection& sec = section();
    sec.in_round = s.run_shape == RunShape::ring;
    sec.last_row_ends[0] = p_.stitches[s.stitches.begin].stitch;
    sec.last_row_ends[1] = p_.stitches[s.stitches.end - 1].stitch;
    Needle& needle = needles_.back();
    needle.live = needle.behind = n;
    needle.in_round = sec.in_round;
    needle.last = s.direction;
    // Joined in the rnd, the first rnd begins with the first st cast on.
    needle.rnds = s.direction;
    for (std::uint32_t i = s.stitches.begin; i < s.stitches.end; ++i)
      for (const PlacedLoop& m : made_by(i)) needle.ring.push_back(m.loop);
    index_ring(needle);
    piece_of_run_[s.run.index()] = static_cast<std::uint32_t>(needles_.size() - 1);
  }

  // A new piece: its section (the one before ends), its needle.
  void start_section(std::uint32_t yarn, std::uint32_t cast_on) {
    end_section();
    yarn_started_[yarn] = 1;
    PatternSection& sec = out_.sections.emplace_back();
    sec.yarn = yarn;
    sec.piece = static_cast<std::uint32_t>(out_.sections.size());
    sec.cast_on = cast_on;
    sec.first_row = sec.end_row = static_cast<std::uint32_t>(out_.rows.size());
    sec.stitches = cast_on;
    Needle& needle = needles_.emplace_back();
    needle.section = static_cast<std::uint32_t>(out_.sections.size() - 1);
  }

  // The needle of the piece whose run the course works: the piece worked now, or one its yarn
  // starts (or carries on to) on the sts of a holder.
  Needle& needle_of(const Step& s) {
    if (s.reads.size() != 1) not_yet(s, "reads more than one run");
    if (s.picked_up > 0) not_yet(s, "picks up loops along an edge");
    const Segment& seg = p_.segments[s.reads.begin];
    if (std::uint32_t h = holder_of_run_[seg.run.index()]) return take_from_holder(s, h);
    std::uint32_t piece = piece_of_run_[seg.run.index()];
    if (piece == kNoPiece || piece + 1 != needles_.size() || section().yarn != s.yarn)
      not_yet(s,
              "works sts of another piece or another yarn, which the program's pattern "
              "builder does not write yet");
    return needles_.back();
  }

  // The loops a course takes, in the order it meets them.
  std::vector<std::uint32_t> loops_met(const Step& s) const {
    std::vector<std::uint32_t> met;
    for (std::uint32_t i = s.stitches.begin; i < s.stitches.end; ++i) {
      auto taken = taken_by(i);
      if (s.direction == CourseDirection::right_to_left)
        met.insert(met.end(), taken.rbegin(), taken.rend());
      else
        met.insert(met.end(), taken.begin(), taken.end());
    }
    return met;
  }

  // Where the holder's sts (in the order slipped) meet the course's order: a rnd that takes
  // them round from one of them on, going up the holder or down it.
  struct HolderStart {
    bool from_last = false;
    std::uint32_t at = 0;  // 1-based in the order slipped; 0: the first (or last) at the tip
  };
  std::optional<HolderStart> start_on(const std::vector<std::uint32_t>& held,
                                      const std::vector<std::uint32_t>& met) const {
    const std::size_t n = held.size();
    auto first = std::find(held.begin(), held.end(), met.front());
    if (met.size() != n || first == held.end()) return std::nullopt;
    auto k = static_cast<std::size_t>(first - held.begin());
    for (bool down : {false, true}) {
      bool same = true;
      for (std::size_t i = 0; i < n && same; ++i)
        same = met[i] == held[(down ? k + n - i : k + i) % n];
      if (!same) continue;
      std::size_t tip = down ? n - 1 : 0;
      return HolderStart{down, k == tip ? 0u : static_cast<std::uint32_t>(k + 1)};
    }
    return std::nullopt;
  }

  // A rnd on the sts of holder `h`: a new yarn joined to them (a piece of its own), or the
  // yarn of the piece just bound off carried on to them.
  Needle& take_from_holder(const Step& s, std::uint32_t h) {
    if (s.shape != RowShape::closed || s.run_shape != RunShape::ring)
      not_yet(s,
              "works the sts of a holder in a row, which the program's pattern builder "
              "does not write yet");
    std::vector<std::uint32_t> met = loops_met(s);
    std::optional<HolderStart> start = start_on(holders_[h - 1], met);
    if (!start) not_yet(s, fmt::format("works the sts of holder {} out of their order", h));
    bool carried = !out_.sections.empty() && section().yarn == s.yarn;
    auto count = static_cast<std::uint32_t>(met.size());
    if (carried) {
      if (needles_.back().live > 0 || start->at != 0)
        not_yet(s, fmt::format("carries its yarn on to holder {} with sts still on the needle "
                               "or from the middle of the holder",
                               h));
      section().carries.push_back(
          {static_cast<std::uint32_t>(out_.rows.size()), h, count, start->from_last});
    } else {
      if (yarn_started_[s.yarn]) not_yet(s, "takes up a yarn worked before on a holder's sts");
      start_section(s.yarn, 0);
      section().in_round = true;
      section().starts_from =
          PatternSection::Start{0, false, start->from_last, count, h, start->at};
    }
    Needle& n = needles_.back();
    n.live = count;
    n.in_round = true;
    n.last = s.direction;
    n.rnds = s.direction;
    n.ring = met;
    n.gap = 0;
    n.worked = false;
    index_ring(n);
    holder_of_run_[s.run.index()] = 0;
    piece_of_run_[s.run.index()] = static_cast<std::uint32_t>(needles_.size() - 1);
    return n;
  }

  // The run cut off waits on a holder of its own: a block of the rnd, counted from the
  // beginning of the rnd. The rest of the rnd stays, its marker where it was.
  void split(const Step& s) {
    const Segment& seg = p_.segments[s.reads.begin];
    std::uint32_t piece = piece_of_run_[seg.run.index()];
    if (piece == kNoPiece || piece + 1 != needles_.size())
      not_yet(s, "cuts off sts of a piece not on the needle");
    Needle& n = needles_.back();
    if (!n.in_round || !n.worked || row_open_ || n.gap != 0)
      not_yet(s, "parts the sts of a flat piece, or of a tube not at the end of a rnd");
    const auto size = static_cast<std::uint32_t>(n.ring.size());
    std::uint32_t at = pos_[seg.first];
    // The run's order is left to right seen from the RS; rnds going right to left meet the
    // segment from its first loop down.
    bool down = n.rnds == CourseDirection::right_to_left;
    std::uint32_t begin = down ? (at + size + 1 - seg.count) % size : at;
    if (n.ring[at] != seg.first || begin + seg.count > size)
      not_yet(s, "cuts off a run of sts across the beginning of the rnd");
    auto holder = static_cast<std::uint32_t>(holders_.size() + 1);
    auto first = n.ring.begin() + begin, end = first + seg.count;
    holders_.emplace_back(first, end);
    n.ring.erase(first, end);
    n.live -= seg.count;
    index_ring(n);
    section().holdings.push_back(
        {static_cast<std::uint32_t>(out_.rows.size() - 1), begin + 1, seg.count, holder});
    holder_of_run_[s.run.index()] = holder;
  }

  void course(const Step& s) {
    Needle& n = needle_of(s);
    if (n.in_round) return ring_course(s, n);
    PatternRow r = open_row(s, n);
    r.bind_off = std::all_of(stitches_of(s).begin(), stitches_of(s).end(),
                             [&](const WorkedStitch& w) { return g_.type[w.stitch] == T::bo; });
    begin_row(s, n);
    std::uint32_t takes = 0;
    for (std::uint32_t i = s.stitches.begin; i < s.stitches.end; ++i) takes += work(s, i, n, r);
    end_row(s, n, r, takes);
    r.end_op = static_cast<std::uint32_t>(out_.ops.size());
    r.sts_after = n.live;
    out_.rows.push_back(r);
    note_course(s, n);
  }

  PatternRow open_row(const Step& s, const Needle& n) const {
    PatternRow r;
    r.side = s.direction == CourseDirection::right_to_left ? Side::rs : Side::ws;
    r.number = static_cast<std::uint32_t>(out_.rows.size()) - section().first_row + 1;
    r.first_op = static_cast<std::uint32_t>(out_.ops.size());
    r.sts_before = n.live;
    return r;
  }

  // One stitch of the course: its ops; returns the loops it takes.
  std::uint32_t work(const Step& s, std::uint32_t i, Needle& n, PatternRow& r) {
    StitchId st = p_.stitches[i].stitch;
    check_worked_here(s, i);
    note_region_mark(st, r);
    append_stitch_ops(g_, st, r.side, false, out_.turns, out_.ops, r.wraps_again);
    return move_loops(st, n, s);
  }

  void note_course(const Step& s, Needle& n) {
    StitchId last = p_.stitches[s.stitches.end - 1].stitch;
    n.turned_at_sr4 = worked_by_hand(g_, last) == T::sr4;
    n.last = s.direction;
    n.worked = true;
    section().stitches += s.stitches.size();
    section().last_row_ends[0] = p_.stitches[s.stitches.begin].stitch;
    section().last_row_ends[1] = last;
  }

  // --- in the rnd ---------------------------------------------------------------------------
  // A knitter's rnd runs from the beginning-of-round marker round to it, the way the rnds go;
  // a course that turns is a row in the rnd (a short row), which slips the marker where it
  // passes it. Courses going on the same way are one row until the work turns or the marker
  // ends a rnd.

  void ring_course(const Step& s, Needle& n) {
    if (s.run_shape != RunShape::ring && s.run_shape != RunShape::line)
      not_yet(s, "leaves its sts in no known order");
    if (!n.worked && s.direction != n.rnds) {  // the first rnd goes against the cast-on
      std::reverse(n.ring.begin() + 1, n.ring.end());
      n.rnds = s.direction;
      index_ring(n);
    }
    bool turns = n.worked && s.direction != n.last;
    if (turns) {
      if (!row_open_) turn_after_last_rnd();
      close_ring_row(s, n, true);
      if (n.turned_at_sr4) step_over_turn(n, s.direction == n.rnds);
    }
    std::vector<std::uint32_t> met = loops_met(s);
    bool forward = s.direction == n.rnds;
    check_met_at_the_yarn(s, n, met, forward);
    const auto size = static_cast<std::uint32_t>(n.ring.size());
    std::uint32_t first = forward ? n.gap : (n.gap + size - 1) % size;
    for (std::uint32_t i = s.stitches.begin; i < s.stitches.end; ++i) {
      auto taken = taken_by(i);
      std::uint32_t at = pos_[first_met(taken, s.direction)];
      if (forward && at == 0 && row_open_ && out_.ops.size() > pending_.first_op)
        close_ring_row(s, n, false);
      if (!forward && at == size - 1 && row_open_ && out_.ops.size() > pending_.first_op)
        out_.ops.push_back(HandOp::sm);
      if (!row_open_) open_ring_row(s, n, forward);
      work(s, i, n, pending_);
      pending_takes_ += static_cast<std::uint32_t>(taken.size());
    }
    replace_in_ring(s, n, forward, first, static_cast<std::uint32_t>(met.size()));
    note_course(s, n);
    if (forward && (n.gap == 0 || n.ring.empty())) close_ring_row(s, n, false);
    if (s.run_shape == RunShape::line && !n.ring.empty())
      not_yet(s, "opens the rnd into rows (binds off part of it)");
  }

  // The work turns right after a rnd ended at the marker: that rnd ends with the turn.
  void turn_after_last_rnd() {
    PatternRow& r = out_.rows.back();
    if (r.end_op != out_.ops.size() || out_.ops.back() == HandOp::wt) return;
    out_.ops.push_back(HandOp::turn);
    ++r.end_op;
  }

  // German short rows slip the st the work turned at (DS); a wrapped st went back to the left
  // needle: either way the row after the turn begins past it.
  void step_over_turn(Needle& n, bool forward) {
    if (n.ring.empty()) return;
    auto size = static_cast<std::uint32_t>(n.ring.size());
    n.gap = forward ? (n.gap + 1) % size : (n.gap + size - 1) % size;
    if (out_.turns == TurnMethod::german) ds_next_ = true;
  }

  // The course meets its loops side by side on the needle, from where the yarn is.
  void check_met_at_the_yarn(const Step& s, const Needle& n, const std::vector<std::uint32_t>& met,
                             bool forward) const {
    const auto size = static_cast<std::uint32_t>(n.ring.size());
    if (met.empty() || met.size() > size) not_yet(s, "takes no loop of the rnd, or too many");
    std::uint32_t first = forward ? n.gap : (n.gap + size - 1) % size;
    for (std::uint32_t i = 0; i < met.size(); ++i) {
      std::uint32_t want = forward ? (first + i) % size : (first + size - i) % size;
      if (pos_[met[i]] != want || n.ring[want] != met[i])
        not_yet(s, i == 0 ? "begins away from where the yarn is on the needle"
                          : "does not meet its loops side by side on the needle");
    }
  }

  void open_ring_row(const Step& s, Needle& n, bool forward) {
    pending_ = open_row(s, n);
    pending_takes_ = 0;
    row_open_ = true;
    row_forward_ = forward;
    row_at_marker_after_turn_ = forward && n.gap == 0 && n.worked && s.direction != row_dir_;
    row_dir_ = s.direction;
    if (ds_next_) out_.ops.push_back(HandOp::ds);
    ds_next_ = false;
  }

  // Ends the hand row: at a turn, a row in the rnd (a short row); at the marker, a rnd.
  void close_ring_row(const Step& s, Needle& n, bool turn) {
    if (!row_open_) return;
    PatternRow& r = pending_;
    if (!turn && (!row_forward_ || (n.gap != 0 && !n.ring.empty())))
      not_yet(s, "leaves a row in the rnd that neither turns nor ends at the marker");
    r.round = !turn;
    r.short_row = turn;
    if (turn && out_.ops.back() != HandOp::wt) out_.ops.push_back(HandOp::turn);
    if (turn && row_at_marker_after_turn_)
      out_.ops.insert(out_.ops.begin() + r.first_op, HandOp::sm);
    r.end_op = static_cast<std::uint32_t>(out_.ops.size());
    r.sts_after = n.live;
    r.bind_off = n.live == 0 && std::all_of(out_.ops.begin() + r.first_op, out_.ops.end(),
                                            [](HandOp op) { return op == HandOp::bo; });
    r.partial = r.short_row || (!r.bind_off && pending_takes_ != r.sts_before);
    out_.short_rows = out_.short_rows || r.short_row;
    out_.ws_rounds = out_.ws_rounds || (r.round && r.side == Side::ws);
    out_.rows.push_back(r);
    row_open_ = false;
  }

  // The loops the course took, a block of the ring, give way to those it made; the marker
  // stays before the loops of the st that took the one after it.
  void replace_in_ring(const Step& s, Needle& n, bool forward, std::uint32_t first,
                       std::uint32_t count) {
    const auto size = static_cast<std::uint32_t>(n.ring.size());
    std::uint32_t begin = forward ? first : (first + size + 1 - count) % size;  // in ring order
    std::vector<std::uint32_t> made;
    std::uint32_t bor = n.ring[0], new_bor = kNoLoopHere;
    for (std::uint32_t k = 0; k < s.stitches.size(); ++k) {
      std::uint32_t i = forward ? s.stitches.begin + k : s.stitches.end - 1 - k;
      auto m = made_by(i);
      auto taken = taken_by(i);
      bool takes_bor = std::find(taken.begin(), taken.end(), bor) != taken.end();
      std::size_t before = made.size();
      if ((s.direction == CourseDirection::right_to_left) == forward)
        for (auto it = m.rbegin(); it != m.rend(); ++it) made.push_back(it->loop);
      else
        for (const PlacedLoop& pl : m) made.push_back(pl.loop);
      if (takes_bor && made.size() > before) new_bor = made[before];
    }
    std::vector<std::uint32_t> ring = made;
    for (std::uint32_t k = count; k < size; ++k) ring.push_back(n.ring[(begin + k) % size]);
    // `ring` starts at the block; the marker goes before the loop that takes its place.
    std::uint32_t start = static_cast<std::uint32_t>(made.size());
    bool block_has_bor = begin == 0 || begin + count > size;
    if (block_has_bor) {
      if (new_bor == kNoLoopHere && !made.empty())
        not_yet(s, "binds off the st the beginning-of-round marker sits before");
      start = new_bor == kNoLoopHere
                  ? 0
                  : static_cast<std::uint32_t>(std::find(ring.begin(), ring.end(), new_bor) -
                                               ring.begin());
    } else {
      start = static_cast<std::uint32_t>(std::find(ring.begin(), ring.end(), bor) - ring.begin());
    }
    if (!ring.empty()) std::rotate(ring.begin(), ring.begin() + start % ring.size(), ring.end());
    n.ring = std::move(ring);
    index_ring(n);
    // The yarn: after the made loops going the rnds' way, before them going back.
    std::uint32_t edge_loop = made.empty() ? kNoLoopHere : (forward ? made.back() : made.front());
    if (n.ring.empty()) {
      n.gap = 0;
    } else if (edge_loop == kNoLoopHere) {
      n.gap = 0;
      not_yet(s, "leaves no loop where the yarn is");
    } else {
      auto sz = static_cast<std::uint32_t>(n.ring.size());
      n.gap = forward ? (pos_[edge_loop] + 1) % sz : pos_[edge_loop];
    }
  }

  void index_ring(const Needle& n) {
    for (std::uint32_t i = 0; i < n.ring.size(); ++i) pos_[n.ring[i]] = i;
  }

  // A flat row turns the work: the sts behind the tip come ahead of it. German short rows
  // begin the row after a turn with the double stitch.
  void begin_row(const Step& s, Needle& n) {
    if (s.direction == n.last)
      not_yet(s, "is a row that goes on the way the row before went, without turning");
    std::swap(n.ahead, n.behind);
    if (!n.double_stitch_next) return;
    out_.ops.push_back(HandOp::ds);
    n.double_stitch_next = false;
    --n.ahead;
    ++n.behind;
  }

  // The stitch takes and makes live loops of the run only (no cast-on, no three-needle
  // bind-off, no loop left along an edge or on the other side of a split).
  void check_worked_here(const Step& s, std::uint32_t worked) const {
    StitchId st = p_.stitches[worked].stitch;
    T type = g_.type[st];
    if (type == T::co || type == T::sco || type == T::tnbo)
      not_yet(s, fmt::format("works {}, a {} in a course, which the program's pattern builder "
                             "does not write yet",
                             g_.describe(st), info(type).name));
    for (const PlacedLoop& m : made_by(worked))
      if (m.place != LoopPlace::in_run)
        not_yet(s, fmt::format("makes a loop at {} that waits along an edge or across a split",
                               g_.describe(st)));
  }

  // Loops ahead of and behind the needle tip as the stitch is worked; returns the loops it
  // takes. A wrapped st goes back to the left needle.
  std::uint32_t move_loops(StitchId st, Needle& n, const Step& s) const {
    const StitchTypeInfo& t = info(worked_by_hand(g_, st));
    n.live = n.live + t.loops_out - t.loops_in;
    if (n.in_round || (t.type == T::sr4 && out_.turns == TurnMethod::wrap_and_turn))
      return t.loops_in;
    if (n.ahead < t.loops_in)
      not_yet(s, fmt::format("works past the end of the needle at {}", g_.describe(st)));
    n.ahead -= t.loops_in;
    n.behind += t.loops_out;
    return t.loops_in;
  }

  // A row that stops with sts left ahead turns there (a short row); German short rows make the
  // st it turned at a double stitch first in the next row.
  void end_row(const Step& s, Needle& n, PatternRow& r, std::uint32_t takes) {
    StitchId last = p_.stitches[s.stitches.end - 1].stitch;
    r.short_row = !r.round && n.ahead > 0;
    if (r.short_row && out_.ops.back() != HandOp::wt) out_.ops.push_back(HandOp::turn);
    n.double_stitch_next = out_.turns == TurnMethod::german && worked_by_hand(g_, last) == T::sr4;
    if (r.round && takes != r.sts_before)
      not_yet(s,
              fmt::format("is a rnd that works {} of the {} live stitches", takes, r.sts_before));
    r.partial = r.short_row || (!r.bind_off && takes != r.sts_before);
    out_.short_rows = out_.short_rows || r.short_row;
    if (!r.round) check_make_one_has_a_strand(g_, last);
  }

  // The schedule's mismatch and short-row markers go before the stitch's operations.
  void note_region_mark(StitchId st, const PatternRow& r) {
    auto at = marked_.find(st);
    if (at == marked_.end()) return;
    out_.region_marks.push_back({static_cast<std::uint32_t>(out_.rows.size()),
                                 static_cast<std::uint32_t>(out_.ops.size()) - r.first_op,
                                 at->second});
  }

  const Compilation& c_;
  const KnitGraph& g_;
  const Program& p_;
  HandPattern out_;
  std::vector<Needle> needles_;                      // per piece, in the order they start
  std::vector<std::uint32_t> piece_of_run_;          // per run: its piece's needle, or kNoPiece
  std::vector<std::uint32_t> holder_of_run_;         // per run: its holder (1-based), or 0
  std::vector<std::vector<std::uint32_t>> holders_;  // per holder: its loops, in the order slipped
  std::vector<std::uint8_t> yarn_started_;           // per yarn
  std::unordered_map<StitchId, MarkerKind> marked_;
  std::size_t step_ = 0;
  std::vector<std::uint32_t> pos_ = std::vector<std::uint32_t>(g_.loops.size(), 0);  // in ring
  // The row in the rnd being written, until the work turns or the marker ends it.
  PatternRow pending_;
  bool row_open_ = false, row_forward_ = false, ds_next_ = false;
  bool row_at_marker_after_turn_ = false;
  CourseDirection row_dir_ = CourseDirection::left_to_right;
  std::uint32_t pending_takes_ = 0;
};

}  // namespace

HandPattern build_pattern_from_program(const Compilation& c, TurnMethod turns) {
  HandPattern pattern = ProgramPatternBuilder(c, turns).run();
  name_pieces(c.knit, c.yarns, pattern);
  place_section_markers(pattern);
  place_region_markers(pattern);
  return pattern;
}

}  // namespace skein::hand
