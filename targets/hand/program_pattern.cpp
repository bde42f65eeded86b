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
// tip) and the right one (behind) on a flat piece, and where its rnds begin.
struct Needle {
  std::uint32_t section = 0;
  std::uint32_t live = 0, ahead = 0, behind = 0;
  bool in_round = false;
  bool double_stitch_next = false;  // German short rows: the next row begins with DS
  CourseDirection last = CourseDirection::left_to_right;
  std::uint32_t bor_loop = kNoLoopHere;  // the loop a rnd begins with
  // In the rnd after whole rnds: the live loops from the beginning of the rnd, in the order
  // the rnds work them (empty when a row left them otherwise).
  std::vector<std::uint32_t> ring;
  std::uint32_t rnds = 0;  // whole rnds worked
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

  void end_section() {
    if (out_.sections.empty()) return;
    Needle& n = needles_.back();
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
    needle.bor_loop = made_by(s.stitches.begin).front().loop;
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
    n.bor_loop = met.front();
    n.ring = met;
    n.rnds = 0;
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
    if (!n.in_round || n.ring.size() != n.live || n.rnds == 0)
      not_yet(s, "parts the sts of a flat piece, or of a tube before it has worked a rnd");
    const auto size = static_cast<std::uint32_t>(n.ring.size());
    auto at = static_cast<std::uint32_t>(std::find(n.ring.begin(), n.ring.end(), seg.first) -
                                         n.ring.begin());
    // The run's order is left to right seen from the RS; a rnd going right to left meets the
    // segment from its first loop down.
    bool down = n.last == CourseDirection::right_to_left;
    std::uint32_t begin = down ? (at + size + 1 - seg.count) % size : at;
    if (at == size || begin + seg.count > size)
      not_yet(s, "cuts off a run of sts across the beginning of the rnd");
    auto holder = static_cast<std::uint32_t>(holders_.size() + 1);
    auto first = n.ring.begin() + begin, end = first + seg.count;
    holders_.emplace_back(first, end);
    n.ring.erase(first, end);
    n.live -= seg.count;
    if (!n.ring.empty()) n.bor_loop = n.ring.front();
    section().holdings.push_back(
        {static_cast<std::uint32_t>(out_.rows.size() - 1), begin + 1, seg.count, holder});
    holder_of_run_[s.run.index()] = holder;
  }

  void course(const Step& s) {
    Needle& n = needle_of(s);
    const Segment& seg = p_.segments[s.reads.begin];
    PatternRow r;
    r.side = s.direction == CourseDirection::right_to_left ? Side::rs : Side::ws;
    r.round = n.in_round && s.shape == RowShape::closed && seg.count == n.live;
    if (n.in_round && !r.round) not_yet(s, "is a row in the rnd (short rows in a tube)");
    r.number = static_cast<std::uint32_t>(out_.rows.size()) - section().first_row + 1;
    r.first_op = static_cast<std::uint32_t>(out_.ops.size());
    r.sts_before = n.live;
    r.bind_off = std::all_of(stitches_of(s).begin(), stitches_of(s).end(),
                             [&](const WorkedStitch& w) { return g_.type[w.stitch] == T::bo; });
    if (r.round)
      begin_round(s, n);
    else
      begin_row(s, n);
    std::uint32_t takes = 0;
    for (std::uint32_t i = s.stitches.begin; i < s.stitches.end; ++i) {
      StitchId st = p_.stitches[i].stitch;
      check_worked_here(s, i);
      note_region_mark(st, r);
      append_stitch_ops(g_, st, r.side, false, out_.turns, out_.ops, r.wraps_again);
      takes += move_loops(st, n, s);
    }
    end_row(s, n, r, takes);
    note_ring(s, n, r);
    r.end_op = static_cast<std::uint32_t>(out_.ops.size());
    r.sts_after = n.live;
    section().stitches += s.stitches.size();
    section().last_row_ends[0] = p_.stitches[s.stitches.begin].stitch;
    section().last_row_ends[1] = p_.stitches[s.stitches.end - 1].stitch;
    out_.rows.push_back(r);
  }

  // A rnd begins at the beginning-of-round marker: with the loop the last rnd's first st
  // made (the first cast on), going the way the rnds go.
  void begin_round(const Step& s, Needle& n) {
    if (s.direction != n.last && out_.rows.size() > section().first_row)
      not_yet(s, "is a rnd that goes the other way round from the rnd before");
    n.last = s.direction;
    auto taken = taken_by(s.stitches.begin);
    if (taken.empty() || first_met(taken, s.direction) != n.bor_loop)
      not_yet(s, "is a rnd that begins elsewhere than the beginning of the rnd");
    auto made = made_by(s.stitches.begin);
    n.bor_loop = made.empty() ? kNoLoopHere : first_met(made, s.direction).loop;
    out_.ws_rounds = out_.ws_rounds || s.direction == CourseDirection::left_to_right;
  }

  // After a rnd the needle holds the loops it made, from the beginning of the rnd on.
  void note_ring(const Step& s, Needle& n, const PatternRow& r) {
    n.ring.clear();
    if (!r.round) return;
    ++n.rnds;
    for (std::uint32_t i = s.stitches.begin; i < s.stitches.end; ++i) {
      auto made = made_by(i);
      if (s.direction == CourseDirection::right_to_left)
        for (auto m = made.rbegin(); m != made.rend(); ++m) n.ring.push_back(m->loop);
      else
        for (const PlacedLoop& m : made) n.ring.push_back(m.loop);
    }
  }

  // A flat row turns the work: the sts behind the tip come ahead of it. German short rows
  // begin the row after a turn with the double stitch.
  void begin_row(const Step& s, Needle& n) {
    if (s.direction == n.last)
      not_yet(s, "is a row that goes on the way the row before went, without turning");
    n.last = s.direction;
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
