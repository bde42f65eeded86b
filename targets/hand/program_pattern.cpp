// The hand pattern built on the lowering's live-loop program (issue 13): runs of live loops
// are mapped onto needles, holders, spare needles and provisional cast-ons' chains; each course
// is a row or a rnd with the side facing that its direction gives (right to left seen from the
// RS: the RS faces the knitter; left to right: the WS), its stitches in the course's working
// order. Nothing here votes on a direction or cuts rows from the schedule. A course that takes
// loops from more than one place gathers them first (slips what it leaves to holders, joins a
// yarn to a holder, places the others into the rnd) and checks the needle then holds its loops
// in the order it meets them. Steps the hand vocabulary cannot say yet are refused by name,
// before any text.
#include "hand/program_pattern.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <optional>
#include <span>
#include <unordered_map>

#include "common/error.hpp"
#include "driver/pipeline.hpp"
#include "hand/loop_places.hpp"
#include "hand/marker_plan.hpp"
#include "hand/piece_names.hpp"
#include "hand/region_markers.hpp"
#include "hand/stitch_working.hpp"

namespace skein::hand {
namespace {

using T = StitchType;
constexpr std::uint32_t kNone = 0xffffffffu;

// What the knitter holds for one piece: its sts, split between the left needle (ahead of the
// tip) and the right one (behind) on a flat piece; in the rnd, the ring of its sts from the
// beginning-of-round marker on, the way the rnds go, and where the yarn is.
struct Needle {
  std::uint32_t section = 0;  // its latest section
  std::uint32_t live = 0, ahead = 0, behind = 0;
  bool in_round = false;
  bool double_stitch_next = false;  // German short rows: the next row begins with DS
  std::size_t turn_loops = 0;       // loops of the st the last course turned at (sr4, sr5)
  bool worked = false;              // a course has worked its sts
  bool opened = false;              // a rnd bound off in places: only a rnd takes it up again
  CourseDirection last = CourseDirection::left_to_right;
  CourseDirection rnds = CourseDirection::left_to_right;  // the way its rnds go
  std::vector<std::uint32_t> ring;  // its loops: from the marker (in the rnd), as cast on (flat)
  std::uint32_t gap = 0;            // the yarn is before ring[gap], going the way the rnds go
};

class ProgramPatternBuilder {
 public:
  ProgramPatternBuilder(const Compilation& c, const Program& program, TurnMethod turns, bool mirror)
      : g_(c.knit),
        p_(program),
        places_(c.knit.loops.size()),
        needle_of_yarn_(c.yarns.size(), kNone),
        yarn_of_(c.yarns.piece_of) {
    out_.source = c.input;
    out_.turns = turns;
    out_.mirror = mirror;
    for (const Event& e : c.schedule.events)
      if (e.kind == EventKind::marker && e.marker != MarkerKind::beginning_of_round)
        marked_[e.stitch] = e.marker;
  }

  HandPattern run() && {
    if (p_.gap)
      unsupported(fmt::format("the live-loop program stops at {}: {}", g_.describe(p_.gap->stitch),
                              p_.gap->why));
    index_loops_met();
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
        case StepKind::hold:
          set_aside(s);
          break;
        case StepKind::resume:
          take_up(s);
          break;
        case StepKind::split:  // the loops stay where they are: the course that takes them
        case StepKind::join:   // gathers them
        case StepKind::reverse:
          break;
        case StepKind::three_needle_bind_off:
          three_needle_bind_off(s);
          break;
      }
    }
    end_section();
    return std::move(out_);
  }

 private:
  [[noreturn]] static void unsupported(const std::string& what) {
    throw UnsupportedError(fmt::format("hand target: {}", what));
  }

  // "step 12 (course of yarn 2 at face 40 (k, row 7)) works ...".
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
  std::span<const std::uint32_t> all_taken_by(std::uint32_t worked) const {
    return {p_.taken.data() + p_.taken_at[worked], p_.taken_at[worked + 1] - p_.taken_at[worked]};
  }
  // The loops a stitch takes off the needle it works: a three-needle bind-off st's second
  // loop comes from the needle held behind.
  std::span<const std::uint32_t> taken_by(std::uint32_t worked) const {
    auto all = all_taken_by(worked);
    return g_.type[p_.stitches[worked].stitch] == T::tnbo ? all.first(1) : all;
  }
  std::span<const PlacedLoop> made_by(std::uint32_t worked) const {
    return {p_.made.data() + p_.made_at[worked], p_.made_at[worked + 1] - p_.made_at[worked]};
  }

  // The loop of `loops` (left to right seen from the RS) a course going `d` meets first.
  template <class Loops>
  static auto first_met(const Loops& loops, CourseDirection d) {
    return d == CourseDirection::right_to_left ? loops.back() : loops.front();
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

  // --- pieces and sections ------------------------------------------------------------------

  PatternSection& section() { return out_.sections.back(); }
  const PatternSection& section() const { return out_.sections.back(); }
  bool working() const { return current_ != kNone; }
  Needle& needle() { return needles_[current_]; }

  // The section worked now ends: its sts stay on the needle (set aside), wait on a spare
  // needle for another piece (in the order the pattern counts them: as cast on, or round from
  // the marker), or are all bound off.
  void end_section(bool set_aside = false) {
    if (!working()) return;
    Needle& n = needle();
    if (row_open_)
      unsupported(
          fmt::format("yarn {} stops in the middle of a rnd, which the program's pattern "
                      "builder does not write yet",
                      section().yarn + 1));
    PatternSection& sec = section();
    sec.end_row = static_cast<std::uint32_t>(out_.rows.size());
    sec.set_aside = set_aside;
    sec.left_live = !set_aside && n.live != 0;
    sec.live_at_end = n.live;
    // On a spare needle a flat piece's sts lie along the way its last row went; loops whose
    // order there the pattern cannot count wait unnamed.
    bool counted = !n.in_round || !n.worked || n.gap == 0;
    std::vector<std::uint32_t> spare = counted ? n.ring : std::vector<std::uint32_t>{};
    if (!n.in_round && n.last == CourseDirection::right_to_left)
      std::reverse(spare.begin(), spare.end());
    if (sec.left_live) {
      places_.leave(n.section, Place::spare, std::move(spare));
      places_.set(n.ring, {Place::spare, n.section});
    }
    current_ = kNone;
  }

  // A new piece, or the yarn of one set aside taken up again (its rows count on).
  void start_section(std::uint32_t yarn, std::uint32_t needle_index) {
    end_section();
    bool resumed = needle_index != kNone;
    PatternSection sec;
    if (resumed) {
      const PatternSection& before = out_.sections[needles_[needle_index].section];
      sec.piece = before.piece;
      sec.in_round = before.in_round;
      sec.resumed = true;
      sec.first_number = before.first_number + (before.end_row - before.first_row);
      std::copy(std::begin(before.last_row_ends), std::end(before.last_row_ends),
                sec.last_row_ends);
    } else {
      sec.piece = ++pieces_;
      needle_index = static_cast<std::uint32_t>(needles_.size());
      needles_.emplace_back();
    }
    sec.yarn = yarn;
    sec.first_row = sec.end_row = static_cast<std::uint32_t>(out_.rows.size());
    out_.sections.push_back(sec);
    current_ = needle_of_yarn_[yarn] = needle_index;
    needle().section = static_cast<std::uint32_t>(out_.sections.size() - 1);
  }

  void set_aside(const Step& s) {
    if (!working() || section().yarn != s.yarn) not_yet(s, "sets aside a yarn not being worked");
    end_section(true);
  }

  void take_up(const Step& s) {
    std::uint32_t n = needle_of_yarn_[s.yarn];
    if (n == kNone || !out_.sections[needles_[n].section].set_aside)
      not_yet(s, "takes up a yarn that was not set aside");
    start_section(s.yarn, n);
  }

  // A cast-on starts a piece; a provisional one (along a split) keeps its chain's loops for
  // the other side.
  void cast_on(const Step& s) {
    T type = g_.type[p_.stitches[s.stitches.begin].stitch];
    for (const WorkedStitch& w : stitches_of(s))
      if (g_.type[w.stitch] != type || (type != T::co && type != T::sco))
        not_yet(s, fmt::format("casts on with {}, which the program's pattern builder does not "
                               "write yet",
                               g_.describe(w.stitch)));
    if (needle_of_yarn_[s.yarn] != kNone) not_yet(s, "casts on with a yarn that worked before");
    start_section(s.yarn, kNone);
    auto count = static_cast<std::uint32_t>(s.stitches.size());
    PatternSection& sec = section();
    sec.cast_on = count;
    sec.stitches = count;
    sec.provisional = type == T::sco;
    sec.in_round = s.run_shape == RunShape::ring;
    sec.last_row_ends[0] = p_.stitches[s.stitches.begin].stitch;
    sec.last_row_ends[1] = p_.stitches[s.stitches.end - 1].stitch;
    Needle& n = needle();
    n.live = n.behind = count;
    n.in_round = sec.in_round;
    n.last = n.rnds = s.direction;
    // Joined in the rnd, the first rnd begins with the first st cast on.
    std::vector<std::uint32_t> chain;
    for (std::uint32_t i = s.stitches.begin; i < s.stitches.end; ++i)
      for (const PlacedLoop& m : made_by(i)) {
        if (m.place == LoopPlace::along_edge)
          not_yet(s, "casts on a st that makes a loop along an edge, to be picked up");
        (m.place == LoopPlace::in_run ? n.ring : chain).push_back(m.loop);
      }
    if (!n.in_round) {  // a line, left to right seen from the RS; the yarn at its end
      if (s.direction == CourseDirection::right_to_left) std::reverse(n.ring.begin(), n.ring.end());
      n.gap = s.direction == CourseDirection::right_to_left ? 0 : count;
    }
    index_ring(n);
    places_.set(n.ring, {Place::needle, current_});
    if (!chain.empty()) places_.leave(n.section, Place::chain, std::move(chain));
  }

  // A yarn binds off the sts of two pieces together, pair by pair: the first loop of each st
  // from the front needle, the second from the back. A new yarn joins two pieces left on spare
  // needles (or holders); a piece's own yarn binds off all its sts with another's held behind.
  void three_needle_bind_off(const Step& s) {
    bool all_pairs =
        std::all_of(stitches_of(s).begin(), stitches_of(s).end(),
                    [&](const WorkedStitch& w) { return g_.type[w.stitch] == T::tnbo; });
    std::uint32_t own = needle_of_yarn_[s.yarn];
    bool all_of_its_sts =
        own != kNone && current_ == own && !row_open_ && needles_[own].live == s.stitches.size();
    if (!all_pairs || (own != kNone && !all_of_its_sts)) return course(s);
    std::vector<std::uint32_t> side[2];
    for (std::uint32_t i = s.stitches.begin; i < s.stitches.end; ++i) {
      auto taken = all_taken_by(i);
      for (int k : {0, 1}) side[k].push_back(taken[k]);
    }
    std::uint32_t joined = own == kNone ? kNone : needles_[own].section;
    end_section();
    PatternSection join;
    join.yarn = s.yarn;
    join.joins = true;
    join.own_yarn = own != kNone;
    for (int k : {0, 1}) {
      LoopAt source = places_.at(side[k].front());
      std::optional<Lie> lie = places_.lie(source, side[k]);
      bool nameable = source.place == Place::holder || source.place == Place::spare;
      if (!nameable || !lie || lie->at != 0 ||
          (k == 0 && join.own_yarn && source.place != Place::spare))
        not_yet(s,
                "binds off sts that do not wait on one spare needle or holder each, from an "
                "end");
      bool holder = source.place == Place::holder;
      (k == 0 ? join.front : join.back) =
          holder ? places_.holder_section(source.index) : source.index;
      join.holders[k] = holder ? source.index : 0;
      join.from_last[k] = lie->from_last;
    }
    join.pairs = static_cast<std::uint32_t>(s.stitches.size());
    for (int k : {0, 1})
      for (std::uint32_t l : side[k]) places_.take(l);
    if (join.own_yarn) return bind_off_with_its_yarn(join, joined);
    join.piece = ++pieces_;
    join.stitches = join.pairs;
    join.first_row = join.end_row = static_cast<std::uint32_t>(out_.rows.size());
    out_.sections.push_back(join);
  }

  // The piece just worked ends by binding off its sts with another's: its section says so.
  void bind_off_with_its_yarn(const PatternSection& join, std::uint32_t section) {
    PatternSection& sec = out_.sections[section];
    if (join.front != section) unsupported("a piece's yarn binds off sts that are not its own");
    sec.joins = true;
    sec.own_yarn = true;
    sec.front = join.front;
    sec.back = join.back;
    std::copy(std::begin(join.from_last), std::end(join.from_last), sec.from_last);
    std::copy(std::begin(join.holders), std::end(join.holders), sec.holders);
    sec.pairs = join.pairs;
    sec.stitches += join.pairs;
    sec.left_live = false;
    sec.live_at_end = 0;
  }

  // --- gathering a rnd ------------------------------------------------------------------------

  // The needle the course works: the yarn's own, once the loops it meets are on it in order.
  Needle& needle_for(const Step& s, const std::vector<std::uint32_t>& met) {
    std::uint32_t own = needle_of_yarn_[s.yarn];
    if (own != kNone && current_ != own) not_yet(s, "works with a yarn set aside or ended");
    bool on_needle = own != kNone && std::all_of(met.begin(), met.end(), [&](std::uint32_t l) {
                       return places_.at(l) == LoopAt{Place::needle, own};
                     });
    Needle* n = own == kNone ? nullptr : &needles_[own];
    bool leaves_some = n && n->in_round && s.shape == RowShape::closed && met.size() < n->live;
    if (!on_needle || leaves_some) gather(s, met);
    return needle();
  }

  // Slips the needle's loops the rnd leaves to holders, joins the yarn to (or carries it on
  // to) the loops it starts on, places the others: the needle then holds `met` from the
  // marker, the rnd's way round.
  void gather(const Step& s, const std::vector<std::uint32_t>& met) {
    bool round = s.shape == RowShape::closed && s.run_shape == RunShape::ring;
    bool own = working() && needle().live > 0 && current_ == needle_of_yarn_[s.yarn];
    if (!round && own && needle().in_round)
      not_yet(s, "takes sts from elsewhere into a row in the rnd");
    for (std::uint32_t l : met) in_met_[l] = 1;
    std::vector<std::uint32_t> host = !own    ? join_to_first_source(s, met, round)
                                      : round ? hold_what_it_leaves(s)
                                              : row_ahead(s);
    place_the_others(s, met, host);
    for (std::uint32_t l : met) in_met_[l] = 0;
    if (!round) return lay_row_ahead(s, met, own);
    Needle& n = needle();
    n.ring = met;
    n.gap = 0;
    n.live = hand_sts(met);
    n.in_round = true;
    n.rnds = n.last = s.direction;
    n.worked = false;
    index_ring(n);
    places_.set(met, {Place::needle, current_});
  }

  // A flat piece's next row, all of whose own sts it works, takes others placed among them:
  // its own sts are those ahead once it turns, in the order it meets them.
  std::vector<std::uint32_t> row_ahead(const Step& s) {
    Needle& n = needle();
    if (row_open_ || s.direction == n.last || n.live != hand_sts(n.ring))
      not_yet(s, "places sts into a row that does not turn from a whole row");
    for (std::uint32_t l : n.ring)
      if (!in_met_[l]) not_yet(s, "places sts into a row that leaves some of its own");
    std::vector<std::uint32_t> own = n.ring;
    if (s.direction == CourseDirection::right_to_left) std::reverse(own.begin(), own.end());
    return own;
  }

  // After a flat gather the needle holds the row's loops, all ahead of the tip once the work
  // is turned; `own`: the piece's own were there before.
  void lay_row_ahead(const Step& s, const std::vector<std::uint32_t>& met, bool own) {
    Needle& n = needle();
    n.ring = met;
    if (s.direction == CourseDirection::right_to_left) std::reverse(n.ring.begin(), n.ring.end());
    n.gap =
        s.direction == CourseDirection::right_to_left ? static_cast<std::uint32_t>(met.size()) : 0;
    n.live = hand_sts(met);
    n.ahead = 0;
    n.behind = n.live;
    n.last = reversed(s.direction);
    n.worked = own;
    index_ring(n);
    places_.set(met, {Place::needle, current_});
  }

  // Part of a piece in the rnd that waits on a spare needle goes elsewhere (a body's front
  // and back into a yoke, each between the sleeves; a leg's inside to the crotch): before the
  // piece is left, a block of its last rnd goes to a holder of its own, the block taken or
  // (where that one goes round past the beginning of the rnd) the rest. Returns where the
  // block then waits.
  LoopAt hold_part_of_spare_needle(std::uint32_t section, std::span<const std::uint32_t> block) {
    PatternSection& sec = out_.sections[section];
    const LoopAt spare_needle{Place::spare, section};
    const std::vector<std::uint32_t>& spare = places_.loops_of(spare_needle);
    bool rnd = sec.in_round && sec.end_row > sec.first_row && out_.rows[sec.end_row - 1].round;
    // One block a piece (a second would count its sts in the rnd the first left).
    bool held_before = std::any_of(sec.holdings.begin(), sec.holdings.end(),
                                   [&](const auto& h) { return h.after_row + 1 == sec.end_row; });
    if (!rnd || held_before || block.size() >= spare.size()) return spare_needle;
    for (std::uint32_t l : block) in_met_[l] += 2;
    std::vector<std::uint32_t> part = one_block(spare, true);  // the block, in order there
    bool rest = part.empty();
    if (rest) part = one_block(spare, false);
    for (std::uint32_t l : block) in_met_[l] -= 2;
    if (part.empty()) return spare_needle;
    auto at = static_cast<std::uint32_t>(std::find(spare.begin(), spare.end(), part.front()) -
                                         spare.begin());
    places_.take_off_spare(section, part);
    std::uint32_t holder = places_.hold(part, section);
    sec.holdings.push_back(
        {sec.end_row - 1, at + 1, static_cast<std::uint32_t>(part.size()), holder});
    sec.live_at_end -= hand_sts(part);
    return rest ? spare_needle : LoopAt{Place::holder, holder};
  }

  // The loops of `line` marked (in_met_ bit 2) or not, if they lie side by side there; else
  // none.
  std::vector<std::uint32_t> one_block(const std::vector<std::uint32_t>& line, bool marked) const {
    auto in = [&](std::uint32_t l) { return ((in_met_[l] & 2) != 0) == marked; };
    auto first = std::find_if(line.begin(), line.end(), in);
    auto end = std::find_if_not(first, line.end(), in);
    if (std::find_if(end, line.end(), in) != line.end()) return {};
    return {first, end};
  }

  // The sts a knitter counts on the needle: the two loops of an sr5 are one (a DS, a wrapped
  // st).
  std::uint32_t hand_sts(std::span<const std::uint32_t> loops) const {
    std::uint32_t sr5 = 0;
    for (std::uint32_t l : loops)
      sr5 += g_.loops[l].maker != kNoStitch && g_.type[g_.loops[l].maker] == T::sr5;
    return static_cast<std::uint32_t>(loops.size()) - sr5 / 2;
  }

  // The needle's loops the rnd does not take go to holders, a block of the rnd each; the rest
  // stay, from the marker on.
  std::vector<std::uint32_t> hold_what_it_leaves(const Step& s) {
    Needle& n = needle();
    if (!n.in_round || row_open_ || n.gap != 0)
      not_yet(s, "gathers sts onto a flat piece, or a tube not at the end of a rnd");
    PatternSection& sec = section();
    std::uint32_t after_row = static_cast<std::uint32_t>(out_.rows.size()) - 1;
    if (out_.rows.empty()) not_yet(s, "gathers sts before any row is worked");
    std::vector<std::uint32_t> stay;
    for (std::uint32_t i = 0; i < n.ring.size();) {
      if (in_met_[n.ring[i]]) {
        stay.push_back(n.ring[i++]);
        continue;
      }
      std::uint32_t end = i;
      while (end < n.ring.size() && !in_met_[n.ring[end]]) ++end;
      std::span<const std::uint32_t> block(n.ring.data() + i, end - i);
      std::uint32_t holder = holder_met_before(block, n.section), onto = 0;
      if (holder != 0) {
        onto = static_cast<std::uint32_t>(places_.loops_of({Place::holder, holder}).size());
        places_.hold_onto(holder, block);
      } else {
        holder = places_.hold(block, n.section);
      }
      sec.holdings.push_back({after_row, i + 1, end - i, holder, onto});
      i = end;
    }
    return stay;
  }

  // The section's latest holder, if the course that takes its loops meets `block` right after
  // them, one after the other (a tube parting over two rnds: the leg's sts go to one holder);
  // else 0.
  std::uint32_t holder_met_before(std::span<const std::uint32_t> block,
                                  std::uint32_t section) const {
    for (std::uint32_t h = places_.holders(); h > 0; --h) {
      if (places_.holder_section(h) != section) continue;
      std::vector<std::uint32_t> all = places_.loops_of({Place::holder, h});
      all.insert(all.end(), block.begin(), block.end());
      return met_one_after_another(all) ? h : 0;
    }
    return 0;
  }

  // Are the loops met by one course, one after the other (either way)?
  bool met_one_after_another(const std::vector<std::uint32_t>& loops) const {
    if (loops.size() < 2 || taker_step_[loops[0]] == kNone) return false;
    int by = static_cast<int>(met_at_[loops[1]]) - static_cast<int>(met_at_[loops[0]]);
    for (std::size_t k = 1; k < loops.size(); ++k)
      if (taker_step_[loops[k]] != taker_step_[loops[0]] ||
          static_cast<int>(met_at_[loops[k]]) - static_cast<int>(met_at_[loops[k - 1]]) != by ||
          (by != 1 && by != -1) || places_.at(loops[k - 1]).place == Place::none)
        return false;
    return true;
  }

  // Per loop: the course that takes it and its place in the order that course meets them.
  void index_loops_met() {
    for (std::uint32_t i = 0; i < p_.steps.size(); ++i) {
      const Step& s = p_.steps[i];
      if (s.kind != StepKind::course && s.kind != StepKind::bind_off &&
          s.kind != StepKind::three_needle_bind_off)
        continue;
      std::vector<std::uint32_t> met = loops_met(s);
      for (std::uint32_t k = 0; k < met.size(); ++k) {
        taker_step_[met[k]] = i;
        met_at_[met[k]] = k;
      }
    }
  }

  // A yarn that starts on loops another piece left (a holder, a spare needle, a chain) is
  // joined to them; the yarn of a piece all bound off is carried on to a holder's. Returns the
  // loops it starts on, in the order the rnd meets them.
  std::vector<std::uint32_t> join_to_first_source(const Step& s,
                                                  const std::vector<std::uint32_t>& met,
                                                  bool round) {
    if (needle_of_yarn_[s.yarn] == kNone) end_section();  // the piece worked before waits
    LoopAt source = places_.at(met.front());
    std::vector<std::uint32_t> host;
    for (std::uint32_t l : met)
      if (places_.at(l) == source) host.push_back(l);
    if (source.place == Place::edge) return start_from_pick_up(s, host, round);
    std::optional<Lie> lie = places_.lie(source, host);
    if (source.place == Place::none || source.place == Place::needle || !lie)
      not_yet(s, "begins on sts that wait nowhere the pattern can name, or out of their order");
    auto count = static_cast<std::uint32_t>(host.size());
    std::uint32_t own = needle_of_yarn_[s.yarn];
    if (own != kNone) {  // carried on from a bind-off
      if (!round || source.place != Place::holder || lie->at != 0 || needle().live != 0)
        not_yet(s, "carries its yarn on to sts other than a holder's, from their end");
      section().carries.push_back(
          {static_cast<std::uint32_t>(out_.rows.size()), source.index, count, lie->from_last});
      return host;
    }
    bool holder = source.place == Place::holder;
    if ((!holder || !round) && lie->at != 0)
      not_yet(s, "joins a yarn to a spare needle, or to a row's sts, in the middle of its sts");
    start_section(s.yarn, kNone);
    section().in_round = round;
    section().starts_from =
        PatternSection::Start{holder ? places_.holder_section(source.index) : source.index,
                              source.place == Place::chain,
                              lie->from_last,
                              count,
                              holder ? source.index : 0,
                              lie->at};
    return host;
  }

  // Each run of the rnd from elsewhere is placed into it where the rnd meets it, after the
  // sts before it; what stays must then be the rest of the rnd, in order.
  void place_the_others(const Step& s, const std::vector<std::uint32_t>& met,
                        const std::vector<std::uint32_t>& host) {
    std::vector<std::uint32_t> rest;
    LoopAt hosted = places_.at(host.empty() ? met.front() : host.front());
    for (std::uint32_t i = 0; i < met.size();) {
      LoopAt source = places_.at(met[i]);
      if (source == hosted) {
        rest.push_back(met[i++]);
        continue;
      }
      std::uint32_t end = i;
      while (end < met.size() && places_.at(met[end]) == source) ++end;
      place(s, source, std::span<const std::uint32_t>(met.data() + i, end - i), i);
      i = end;
    }
    if (rest != host) not_yet(s, "meets the sts it keeps out of their order on the needle");
  }

  void place(const Step& s, LoopAt source, std::span<const std::uint32_t> block,
             std::uint32_t after) {
    if (source.place == Place::edge) return pick_up_into_rnd(s, source, block, after);
    std::optional<Lie> lie = places_.lie(source, block);
    if (!lie && source.place == Place::spare) {
      source = hold_part_of_spare_needle(source.index, block);
      lie = places_.lie(source, block);
    }
    bool nameable = source.place == Place::holder || source.place == Place::spare ||
                    source.place == Place::chain;
    if (!nameable || !lie || (lie->from_last && lie->at != 0))
      not_yet(s, fmt::format("takes {} sts it cannot place from where they wait (all of a "
                             "holder, spare needle or chain, in their order)",
                             block.size()));
    bool holder = source.place == Place::holder;
    PatternSection::Placement p{holder ? places_.holder_section(source.index) : source.index,
                                static_cast<std::uint32_t>(block.size()), after, lie->from_last};
    p.chain = source.place == Place::chain;
    p.before_row = static_cast<std::uint32_t>(out_.rows.size());
    p.holder = holder ? source.index : 0;
    p.start = lie->at;
    section().placements.push_back(p);
  }

  // --- picking up along an edge ----------------------------------------------------------------
  // A loop made across an expanding perpendicular edge (paper §3.2) waits along the edge of
  // its maker's piece; a knitter picks it up, one in each row, from the edge st of that row.

  // The first and last st a row worked, and the side facing: which is its edge st.
  struct RowEnds {
    StitchId first = kNoStitch, last = kNoStitch;
    Side side = Side::rs;
  };

  void note_row_end(StitchId st, const PatternRow& r) {
    auto row = static_cast<std::uint32_t>(out_.rows.size());  // the row being written
    if (row_ends_.size() <= row) row_ends_.resize(row + 1);
    RowEnds& ends = row_ends_[row];
    if (ends.first == kNoStitch) ends.first = st;
    ends.last = st;
    ends.side = r.side;
    row_of_[st] = row;
    number_of_[st] = r.number;
  }

  // The pick-up that gives `loops` in their order: one in each row, rows numbered one after
  // the other, each from the st at the same edge of its row; none where they are not.
  std::optional<PatternSection::PickUp> pick_up_of(LoopAt source,
                                                   std::span<const std::uint32_t> loops) const {
    PatternSection::PickUp p;
    p.section = source.index;
    for (std::size_t i = 0; i < loops.size(); ++i) {
      StitchId maker = g_.loops[loops[i]].maker;
      if (places_.at(loops[i]) != source || maker == kNoStitch || row_of_[maker] == kNone)
        return std::nullopt;
      auto made = made_by(p_.worked_at[maker]);
      bool right = made.size() > 1 && made.back().loop == loops[i];
      const RowEnds& ends = row_ends_[row_of_[maker]];
      if (maker != ((ends.side == Side::rs) == right ? ends.first : ends.last)) return std::nullopt;
      std::uint32_t row = number_of_[maker];
      if (i == 0) {
        p.right = right;
        p.from_row = p.to_row = row;
        continue;
      }
      bool up = row == p.to_row + 1 && (i == 1 || p.from_row < p.to_row);
      bool down = row + 1 == p.to_row && (i == 1 || p.from_row > p.to_row);
      if (right != p.right || !(up || down)) return std::nullopt;
      p.to_row = row;
    }
    return p;
  }

  // A piece that starts on loops picked up along another's edge: the knitter picks them up,
  // and its first course works them, the last picked up first.
  std::vector<std::uint32_t> start_from_pick_up(const Step& s,
                                                const std::vector<std::uint32_t>& host,
                                                bool round) {
    std::vector<std::uint32_t> picked(host.rbegin(), host.rend());
    std::optional<PatternSection::PickUp> p = pick_up_of(places_.at(host.front()), picked);
    if (!p) not_yet(s, "begins on loops along an edge that are not one in each row of an edge");
    start_section(s.yarn, kNone);
    section().in_round = round;
    section().picks_up = *p;
    section().cast_on = hand_sts(host);
    return host;
  }

  // Loops picked up along an edge go into the rnd where it meets them, in the order picked up.
  void pick_up_into_rnd(const Step& s, LoopAt source, std::span<const std::uint32_t> block,
                        std::uint32_t after) {
    std::optional<PatternSection::PickUp> p = pick_up_of(source, block);
    if (!p || !section().in_round)
      not_yet(s, fmt::format("picks up {} loops along an edge into a row, or not one in each "
                             "row of an edge",
                             block.size()));
    PatternSection::Placement placed{p->section, static_cast<std::uint32_t>(block.size()), after,
                                     false};
    placed.before_row = static_cast<std::uint32_t>(out_.rows.size());
    placed.edge = p;
    section().placements.push_back(placed);
  }

  // --- courses ------------------------------------------------------------------------------

  void course(const Step& s) {
    for (const WorkedStitch& w : stitches_of(s)) check_worked_here(s, p_.worked_at[w.stitch]);
    Needle& n = needle_for(s, loops_met(s));
    if (n.in_round) return ring_course(s, n);
    PatternRow r = open_row(s, n);
    r.bind_off = std::all_of(stitches_of(s).begin(), stitches_of(s).end(),
                             [&](const WorkedStitch& w) { return g_.type[w.stitch] == T::bo; });
    hold_what_others_work(s, n);
    begin_row(s, n);
    check_met_along_the_row(s, n);
    std::uint32_t takes = 0;
    for (std::uint32_t i = s.stitches.begin; i < s.stitches.end; ++i) takes += work(s, i, n, r);
    end_row(s, n, r, takes);
    replace_in_line(s, n);
    r.end_op = static_cast<std::uint32_t>(out_.ops.size());
    r.sts_after = n.live;
    out_.rows.push_back(r);
    note_course(s, n);
  }

  PatternRow open_row(const Step& s, const Needle& n) const {
    PatternRow r;
    r.side = s.direction == CourseDirection::right_to_left ? Side::rs : Side::ws;
    r.number =
        static_cast<std::uint32_t>(out_.rows.size()) - section().first_row + section().first_number;
    r.first_op = static_cast<std::uint32_t>(out_.ops.size());
    r.sts_before = n.live;
    return r;
  }

  // One stitch of the course: its ops; returns the loops it takes.
  std::uint32_t work(const Step& s, std::uint32_t i, Needle& n, PatternRow& r) {
    StitchId st = p_.stitches[i].stitch;
    note_region_mark(st, r);
    note_row_end(st, r);
    if (g_.type[st] == T::sco) return cast_on_in_row(i, n);
    if (g_.type[st] == T::tnbo) return bind_off_with_held_st(i, n);
    append_stitch_ops(g_, st, r.side, out_.mirror, out_.turns, out_.ops, r.wraps_again);
    return move_loops(st, n, s);
  }

  // A three-needle bind-off in a row: its st in front, the other piece's held behind the
  // needle (from a spare needle or holder, all of it, an end at the tip), said before the row
  // that binds off its first st.
  std::uint32_t bind_off_with_held_st(std::uint32_t i, Needle& n) {
    const Step& s = p_.steps[step_];
    if (held_behind_left_ == 0) {
      std::vector<std::uint32_t> behind;
      for (std::uint32_t k = i; k < s.stitches.end; ++k)
        if (g_.type[p_.stitches[k].stitch] == T::tnbo) behind.push_back(all_taken_by(k)[1]);
      LoopAt source = places_.at(behind.front());
      std::optional<Lie> lie = places_.lie(source, behind);
      if (!lie && source.place == Place::spare) {
        source = hold_part_of_spare_needle(source.index, behind);
        lie = places_.lie(source, behind);
      }
      bool nameable = source.place == Place::holder || source.place == Place::spare;
      if (!nameable || !lie || lie->at != 0)
        not_yet(s,
                "binds off sts held behind that do not wait on one spare needle or holder, "
                "from an end");
      bool holder = source.place == Place::holder;
      PatternSection::Hold h;
      h.section = holder ? places_.holder_section(source.index) : source.index;
      h.count = static_cast<std::uint32_t>(behind.size());
      h.from_last = lie->from_last;
      h.first = p_.stitches[i].stitch;
      h.holder = holder ? source.index : 0;
      h.before_row = static_cast<std::uint32_t>(out_.rows.size());
      section().holds.push_back(h);
      held_behind_left_ = h.count;
    }
    --held_behind_left_;
    out_.ops.push_back(HandOp::tnbo);
    --n.live;
    if (!n.in_round) --n.ahead;
    return 1;
  }

  bool binds_off_together(std::uint32_t worked) const {
    return g_.type[p_.stitches[worked].stitch] == T::tnbo;
  }

  // A provisional cast-on in the middle of a row: the st goes on the needle, the loop of its
  // chain waits for the piece on the other side of the split.
  std::uint32_t cast_on_in_row(std::uint32_t i, Needle& n) {
    out_.ops.push_back(HandOp::provisional_co);
    PatternSection& sec = section();
    StitchId st = p_.stitches[i].stitch;
    if (sec.row_chain++ == 0) sec.row_chain_ends[0] = st;
    sec.row_chain_ends[1] = st;
    for (const PlacedLoop& m : made_by(i))
      if (m.place == LoopPlace::other_side) places_.add(n.section, Place::chain, m.loop);
    ++n.live;
    if (!n.in_round) ++n.behind;
    return 0;
  }

  void note_course(const Step& s, Needle& n) {
    StitchId last = p_.stitches[s.stitches.end - 1].stitch;
    for (std::uint32_t i = s.stitches.begin; i < s.stitches.end; ++i) {
      for (std::uint32_t l : all_taken_by(i)) places_.take(l);
      for (const PlacedLoop& m : made_by(i)) {
        if (m.place == LoopPlace::in_run) places_.set({&m.loop, 1}, {Place::needle, current_});
        if (m.place == LoopPlace::along_edge) places_.set({&m.loop, 1}, {Place::edge, n.section});
      }
    }
    n.turn_loops = worked_by_hand(g_, last) == T::sr4 ? made_by(s.stitches.end - 1).size() : 0;
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
    if (n.opened && s.shape != RowShape::closed)
      not_yet(s,
              "works rows on a rnd bound off in places, which the program's pattern builder "
              "does not write yet");
    n.opened = n.opened && s.shape != RowShape::closed;
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
      if (n.turn_loops) step_over_turn(n, s.direction == n.rnds);
    }
    std::vector<std::uint32_t> met = loops_met(s);
    bool forward = s.direction == n.rnds;
    check_met_at_the_yarn(s, n, met, forward);
    const auto size = static_cast<std::uint32_t>(n.ring.size());
    std::uint32_t first = forward ? n.gap : (n.gap + size - 1) % size;
    for (std::uint32_t i = s.stitches.begin; i < s.stitches.end; ++i) {
      auto taken = taken_by(i);
      std::uint32_t at = taken.empty() ? kNone : pos_[first_met(taken, s.direction)];
      bool at_marker = at == (forward ? 0 : size - 1) && row_open_ && pending_takes_ > 0;
      if (at_marker && i > s.stitches.begin && binds_off_together(i - 1) && binds_off_together(i))
        not_yet(s, "binds off with a three-needle bind-off across the beginning-of-round marker");
      if (forward && at == 0 && row_open_ && pending_takes_ > 0) close_ring_row(s, n, false);
      if (!forward && at == size - 1 && row_open_ && pending_takes_ > 0)
        out_.ops.push_back(HandOp::sm);
      if (!row_open_) open_ring_row(s, n, forward);
      pending_takes_ += work(s, i, n, pending_);
    }
    replace_in_ring(s, n, forward, first, static_cast<std::uint32_t>(met.size()));
    note_course(s, n);
    if (forward && (n.gap == 0 || n.ring.empty())) close_ring_row(s, n, false);
    // Bound off in one or two places (underarms), the rest stays on the circular needle in
    // its order, for a rnd that takes it up again with others (a yoke).
    if (s.run_shape == RunShape::line && !n.ring.empty()) n.opened = true;
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
    auto by = static_cast<std::uint32_t>(n.turn_loops % size);
    n.gap = forward ? (n.gap + by) % size : (n.gap + size - by) % size;
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
    std::uint32_t bor = n.ring[0], new_bor = kNone;
    for (std::uint32_t k = 0; k < s.stitches.size(); ++k) {
      std::uint32_t i = forward ? s.stitches.begin + k : s.stitches.end - 1 - k;
      auto m = made_by(i);
      auto taken = taken_by(i);
      bool takes_bor = std::find(taken.begin(), taken.end(), bor) != taken.end();
      std::size_t before = made.size();
      bool reversed = (s.direction == CourseDirection::right_to_left) == forward;
      for (std::size_t j = 0; j < m.size(); ++j) {
        const PlacedLoop& pl = m[reversed ? m.size() - 1 - j : j];
        if (pl.place == LoopPlace::in_run) made.push_back(pl.loop);
      }
      if (takes_bor && made.size() > before) new_bor = made[before];
    }
    // A rnd (or a row) that begins at the marker leaves all its loops after it.
    if (forward && first == 0 && !made.empty()) new_bor = made.front();
    std::vector<std::uint32_t> ring = made;
    for (std::uint32_t k = count; k < size; ++k) ring.push_back(n.ring[(begin + k) % size]);
    // `ring` starts at the block; the marker goes before the loop that takes its place.
    std::uint32_t start = static_cast<std::uint32_t>(made.size());
    bool block_has_bor = begin == 0 || begin + count > size;
    if (block_has_bor) {
      if (new_bor == kNone && !made.empty())
        not_yet(s, "binds off the st the beginning-of-round marker sits before");
      start = new_bor == kNone ? 0
                               : static_cast<std::uint32_t>(
                                     std::find(ring.begin(), ring.end(), new_bor) - ring.begin());
    } else {
      start = static_cast<std::uint32_t>(std::find(ring.begin(), ring.end(), bor) - ring.begin());
    }
    if (!ring.empty()) std::rotate(ring.begin(), ring.begin() + start % ring.size(), ring.end());
    n.ring = std::move(ring);
    index_ring(n);
    // The yarn: after the made loops going the rnds' way, before them going back.
    std::uint32_t edge_loop = made.empty() ? kNone : (forward ? made.back() : made.front());
    if (n.ring.empty()) {
      n.gap = 0;
    } else if (edge_loop == kNone) {
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
    auto by = static_cast<std::uint32_t>(n.turn_loops);  // past the st it turned at
    n.gap =
        s.direction == CourseDirection::left_to_right ? n.gap + by : n.gap - std::min(by, n.gap);
    if (!n.double_stitch_next) return;
    out_.ops.push_back(HandOp::ds);
    n.double_stitch_next = false;
    --n.ahead;
    ++n.behind;
  }

  // The stitch takes and makes live loops of the run only (no cast-on in a course); a loop made
  // along an edge waits there to be picked up.
  void check_worked_here(const Step& s, std::uint32_t worked) const {
    StitchId st = p_.stitches[worked].stitch;
    T type = g_.type[st];
    if (type == T::co)
      not_yet(s, fmt::format("works {}, a {} in a course, which the program's pattern builder "
                             "does not write yet",
                             g_.describe(st), info(type).name));
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

  // Sts of a flat piece that another yarn works (a flap of their own) go to a holder before
  // the row that leaves them: a block of the last row's sts, counted in the order it worked
  // them.
  void hold_what_others_work(const Step& s, Needle& n) {
    std::vector<std::uint32_t> others;
    for (std::uint32_t l : n.ring) {
      StitchId taker = g_.loops[l].taker;
      if (taker != kNoStitch && yarn_of_[taker] != s.yarn) others.push_back(l);
    }
    if (others.empty()) return;
    if (!n.worked || n.ahead != 0 || out_.rows.size() == section().first_row)
      not_yet(s, "leaves sts to another yarn that its last row did not work to the end");
    std::vector<std::uint32_t> order = n.ring;  // as the last row worked them
    if (n.last == CourseDirection::right_to_left) std::reverse(order.begin(), order.end());
    auto first = std::find(order.begin(), order.end(), others.front());
    auto k = static_cast<std::uint32_t>(first - order.begin());
    for (std::uint32_t i = 0; i < others.size(); ++i)
      if (k + i >= order.size() || order[k + i] != others[i]) {
        std::reverse(others.begin(), others.end());
        break;
      }
    k = static_cast<std::uint32_t>(std::find(order.begin(), order.end(), others.front()) -
                                   order.begin());
    if (!std::equal(others.begin(), others.end(),
                    order.begin() + std::min<std::size_t>(k, order.size())))
      not_yet(s, "leaves sts to another yarn that are not side by side");
    std::uint32_t holder = places_.hold(others, n.section);
    PatternSection::Holding h{static_cast<std::uint32_t>(out_.rows.size() - 1), k + 1,
                              static_cast<std::uint32_t>(others.size()), holder};
    h.of_row = true;
    section().holdings.push_back(h);
    for (std::uint32_t l : others) in_met_[l] = 1;
    std::uint32_t before_gap = 0;
    for (std::uint32_t i = 0; i < n.gap; ++i) before_gap += in_met_[n.ring[i]];
    std::erase_if(n.ring, [&](std::uint32_t l) { return in_met_[l] != 0; });
    for (std::uint32_t l : others) in_met_[l] = 0;
    n.gap -= before_gap;
    n.live -= hand_sts(others);
    n.behind -= hand_sts(others);
    index_ring(n);
  }

  // A flat row meets its loops side by side along the line from where the yarn is.
  void check_met_along_the_row(const Step& s, const Needle& n) const {
    std::vector<std::uint32_t> met = loops_met(s);
    bool right = s.direction == CourseDirection::left_to_right;
    if (met.size() > (right ? n.ring.size() - std::min<std::size_t>(n.gap, n.ring.size()) : n.gap))
      not_yet(s, "works past the end of the needle");
    for (std::uint32_t i = 0; i < met.size(); ++i)
      if (n.ring[right ? n.gap + i : n.gap - 1 - i] != met[i])
        not_yet(s, i == 0 ? "begins away from where the yarn is on the needle"
                          : "does not meet its loops side by side on the needle");
  }

  // The row's loops give way to those it made, in the line's order; the yarn stays at the
  // end it went to.
  void replace_in_line(const Step& s, Needle& n) {
    bool right = s.direction == CourseDirection::left_to_right;
    std::vector<std::uint32_t> made;
    std::uint32_t taken = 0;
    for (std::uint32_t k = 0; k < s.stitches.size(); ++k) {
      std::uint32_t i = right ? s.stitches.begin + k : s.stitches.end - 1 - k;
      taken += static_cast<std::uint32_t>(taken_by(i).size());
      for (const PlacedLoop& m : made_by(i))
        if (m.place == LoopPlace::in_run) made.push_back(m.loop);
    }
    std::uint32_t lo = right ? n.gap : n.gap - taken;
    n.ring.erase(n.ring.begin() + lo, n.ring.begin() + lo + taken);
    n.ring.insert(n.ring.begin() + lo, made.begin(), made.end());
    n.gap = right ? lo + static_cast<std::uint32_t>(made.size()) : lo;
    index_ring(n);
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

  const KnitGraph& g_;
  const Program& p_;
  HandPattern out_;
  std::uint32_t pieces_ = 0;
  std::vector<Needle> needles_;    // per piece, in the order they start
  std::uint32_t current_ = kNone;  // the needle of the section being written
  LoopPlaces places_;
  std::vector<std::uint32_t> needle_of_yarn_;  // per yarn
  const std::vector<std::uint32_t>& yarn_of_;  // per stitch
  std::vector<std::uint8_t> in_met_ = std::vector<std::uint8_t>(g_.loops.size(), 0);
  std::unordered_map<StitchId, MarkerKind> marked_;
  std::size_t step_ = 0;
  std::vector<std::uint32_t> pos_ = std::vector<std::uint32_t>(g_.loops.size(), 0);  // in ring
  // Per stitch worked in a row: the row (into out_.rows) and its number; per row, its ends.
  std::vector<std::uint32_t> row_of_ = std::vector<std::uint32_t>(g_.size(), kNone);
  std::vector<std::uint32_t> number_of_ = std::vector<std::uint32_t>(g_.size(), 0);
  std::vector<RowEnds> row_ends_;
  std::vector<std::uint32_t> taker_step_ = std::vector<std::uint32_t>(g_.loops.size(), kNone);
  std::vector<std::uint32_t> met_at_ = std::vector<std::uint32_t>(g_.loops.size(), 0);
  // The row in the rnd being written, until the work turns or the marker ends it.
  PatternRow pending_;
  bool row_open_ = false, row_forward_ = false, ds_next_ = false;
  bool row_at_marker_after_turn_ = false;
  CourseDirection row_dir_ = CourseDirection::left_to_right;
  std::uint32_t pending_takes_ = 0;
  std::uint32_t held_behind_left_ = 0;  // sts held behind the needle for 3-needle BO
};

}  // namespace

HandPattern build_pattern_from_program(const Compilation& c, TurnMethod turns, Rounds rounds) {
  bool mirror = rounds == Rounds::mirror_most &&
                stitches_in_rounds_going(c.program, CourseDirection::left_to_right) >
                    stitches_in_rounds_going(c.program, CourseDirection::right_to_left);
  HandPattern pattern =
      mirror ? ProgramPatternBuilder(c, mirror_image(c.knit, c.program), turns, true).run()
             : ProgramPatternBuilder(c, c.program, turns, false).run();
  name_pieces(c.knit, c.yarns, pattern);
  place_section_markers(pattern);
  place_region_markers(pattern);
  return pattern;
}

}  // namespace skein::hand
