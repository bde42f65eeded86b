// The emitter knits the courses: the stitches and a short row's wrap, the cast-on border,
// waste section and draw thread, the bind-off, and the yarns in and out (emitter.hpp has the
// state).
#include <fmt/format.h>

#include <algorithm>
#include <cstdlib>
#include <limits>

#include "knitout/emitter.hpp"

namespace skein::knitout::emit {

// ---- knitting ----
void Emitter::made(StitchId s, std::uint32_t slot, Place now) {
  auto loops = g_.loops_made_by(s);
  if (slot < loops.size()) live_[loops[slot]] = {now, plan_[s].home_of(slot)};
}

// The loops on the needles (made and not yet taken), for a short row's shaping to move.
void Emitter::track_loops(StitchId s) {
  for (std::uint32_t loop : taken(s)) {
    std::uint32_t last = on_needles_.back();
    on_needles_[index_on_needles_[loop]] = last;
    index_on_needles_[last] = index_on_needles_[loop];
    on_needles_.pop_back();
  }
  for (std::uint32_t loop : g_.loops_made_by(s)) {
    index_on_needles_[loop] = static_cast<std::uint32_t>(on_needles_.size());
    on_needles_.push_back(loop);
  }
}

void Emitter::knit_stitch(StitchId s) {
  track_loops(s);
  const StitchPlan& sp = plan_[s];
  Needle n{sp.knit, sp.needle};
  StitchType t = g_.type[s];
  if (keeps_loop_below(t)) {  // the needle keeps its loops: a tuck adds one, a slip nothing
    if (t == StitchType::tuck) w_.tuck(sp.travel, n, carrier_);
    made(s, 0, {sp.knit, sp.needle});
    return;
  }
  if (info(t).loops_out < 2) {
    w_.knit(sp.travel, n, carrier_);
    made(s, 0, {sp.knit, sp.needle});
    return;
  }
  std::uint32_t extra = 1u - sp.knit_slot;
  if (t == StitchType::sr5) {  // the turn's loop: a tuck on the facing needle on the way back
    Place turn = facing({sp.knit, sp.needle});
    w_.knit(sp.travel, n, carrier_);
    w_.tuck(opposite(sp.travel), at(turn), carrier_);
    made(s, sp.knit_slot, {sp.knit, sp.needle});
    live_[g_.loops_made_by(s)[extra]] = {turn, turn};  // it waits there for its decrease
    return;
  }
  Place extra_home = sp.home_of(extra);
  if (t == StitchType::kfb) {  // split: the old loop waits on the facing needle, then is knit there
    Needle behind{other(sp.knit), sp.needle};
    w_.split(sp.travel, n, behind, carrier_);
    w_.knit(sp.travel, behind, carrier_);
    made(s, sp.knit_slot, {sp.knit, sp.needle});
    made(s, extra, {behind.bed, behind.index});
    return;
  }
  // yo, m1l, m1r: a tuck on the empty needle beside the knit, in the order the yarn passes.
  bool tuck_first = (extra_home.needle < sp.needle) == (sp.travel == Direction::plus);
  if (tuck_first) w_.tuck(sp.travel, at(extra_home), carrier_);
  w_.knit(sp.travel, n, carrier_);
  if (!tuck_first) w_.tuck(sp.travel, at(extra_home), carrier_);
  made(s, sp.knit_slot, {sp.knit, sp.needle});
  made(s, extra, extra_home);
}

void Emitter::knit_course(const Course& c) {
  source(c, c.partial ? "knit (short row)" : "knit");
  if (needs_rack_zero(c)) w_.rack(0);
  for (std::uint32_t i = c.begin; i < c.end; ++i) knit_stitch(l_.order[i]);
}

// Knitting does not depend on the racking, so a course is knit at the one its transfers left,
// unless it splits (a kfb moves a loop to the facing needle) or works both beds going one way:
// racked, the back needles no longer line up with the front ones and the pass would break.
bool Emitter::needs_rack_zero(const Course& c) const {
  std::array<std::array<bool, 2>, 2> used{};  // per direction, per bed
  auto use = [&](Direction d, Bed b) { used[d == Direction::plus ? 0 : 1][bed_index(b)] = true; };
  for (std::uint32_t i = c.begin; i < c.end; ++i) {
    StitchType t = g_.type[l_.order[i]];
    const StitchPlan& sp = plan_[l_.order[i]];
    if (t == StitchType::kfb) return true;
    use(sp.travel, sp.knit);
    if (t == StitchType::sr5) use(opposite(sp.travel), other(sp.knit));  // the turn's tuck
  }
  return (used[0][0] && used[0][1]) || (used[1][0] && used[1][1]);
}

// Before turning beside a waiting loop, the yarn tucks over its needle, going on the way it
// went: the waiting stitch is later knit through the tuck too, which closes the turn's hole.
// A wrap over the turning stitch's own loop is made on the way back. A turn whose wrap the
// needle has no room for is left bare (keep_wraps_within_limit).
void Emitter::wrap_turn(const Course& c) {
  if (c.wrap == kNoWrap || bare_turn_[static_cast<std::size_t>(&c - l_.courses.data())]) return;
  const LoopPlace& waiting = live_[c.wrap];
  bool on_back = l_.tube && waiting.home.bed == Bed::b;
  bool rightward = (!on_back == c.left_to_right) != c.wrap_back;
  w_.tuck(rightward ? Direction::plus : Direction::minus, at(waiting.now), carrier_);
}

// ---- cast-on and bind-off ----
// The course's needles on the bed a pass in direction d works, in the order it meets them.
std::vector<Needle> Emitter::pass_needles(const Course& c, Direction d) const {
  std::vector<Needle> needles;
  for (std::uint32_t i = c.begin; i < c.end; ++i) {
    const StitchPlan& sp = plan_[l_.order[i]];
    if (sp.travel == d || !l_.tube) needles.push_back({sp.knit, sp.needle});
  }
  std::sort(needles.begin(), needles.end(), [d](const Needle& a, const Needle& b) {
    return d == Direction::plus ? a.index < b.index : a.index > b.index;
  });
  return needles;
}

// Alternating tucks over the cast-on needles, each needle tucked once, starting in the profile's
// first direction; returns the direction of the next pass. Each bed's first pass tucks the
// first needle it meets, so a yarn-inserting hook beside the first stitch is beyond them all.
// Two passes a bed (every other needle) end where a pass the first way starts; where the next
// pass must go the other way (`then`), the first way's bed is tucked in one pass more than the
// other's (three passes of every third needle; on a narrow piece one pass over a sheet of three
// or fewer, or two passes of the first way's two needles and one over the other bed's), so that
// the border ends where that pass starts: no loop of the piece's yarn that the model does not
// have is knitted to take the yarn there. (Only a tube with one needle the first way cannot:
// see cast_on.)
Direction Emitter::tuck_border(const Course& c, const std::string& carrier, Direction then) {
  Direction d = p_.first_pass;
  std::int32_t beds = l_.tube ? 2 : 1, start[2] = {0, 0};
  std::int32_t stride[2] = {2, 2};
  if (then == opposite(p_.first_pass)) {
    // (A sheet of three would tuck its middle needle alone going against the yarn, which comes
    // to it and goes on from it the other way: wrapped round the needle.)
    std::size_t firsts = pass_needles(c, d).size();
    if (firsts >= (l_.tube ? 3u : 4u))
      stride[0] = 3;
    else if (!l_.tube)
      stride[0] = 1;
    else if (firsts == 2)
      stride[1] = 1;
  }
  std::int32_t passes = stride[0] + (l_.tube ? stride[1] : 0);
  // A tube's beds are offset: the other bed's outermost needle may lie beyond the first pass's
  // first needle (where the rounds run right to left), and the hook would hold the yarn over it;
  // a miss there first takes the hook beyond every needle.
  Needle outermost = outermost_against_first_pass(c);
  if (std::vector<Needle> firsts = pass_needles(c, d);
      p_.hook == YarnHook::inhook && !firsts.empty() && firsts.front().index != outermost.index)
    w_.miss(d, outermost, carrier);
  for (std::int32_t pass = 0; pass < passes; ++pass, d = opposite(d)) {
    std::vector<Needle> needles = pass_needles(c, d);
    if (needles.empty()) continue;
    std::int32_t bed = pass % beds, round = pass / beds;
    std::int32_t& first = start[bed];
    if (pass < beds) first = needles.front().index;
    for (const Needle& n : needles)
      if (std::abs(n.index - first) / pitch_ % stride[bed] == round) w_.tuck(d, n, carrier);
  }
  return d;
}
void Emitter::knit_pass(const Course& c, Direction d, const std::string& carrier) {
  for (const Needle& n : pass_needles(c, d)) w_.knit(d, n, carrier);
}
void Emitter::yarn_in(const std::string& carrier) {
  w_.carriers(p_.hook == YarnHook::inhook ? "inhook" : "in", carrier);
}
// A yarn that starts on loops on the bed: its carrier comes in and first moves the profile's
// way (a miss) to the course's needle furthest that way, so that a hook holding its end
// blocks none of the course's needles.
void Emitter::bring_in(const Course& c) {
  w_.line(fmt::format(";!source: carrier {} comes in for yarn piece {}", carrier_, c.yarn + 1));
  yarn_in(carrier_);
  w_.miss(p_.first_pass, outermost_against_first_pass(c), carrier_);
}
// The course's needle furthest against the profile's first way (either bed).
Needle Emitter::outermost_against_first_pass(const Course& c) const {
  bool plus = p_.first_pass == Direction::plus;
  Needle edge = {Bed::f, plus ? std::numeric_limits<std::int32_t>::max() : -1};
  for (std::uint32_t i = c.begin; i < c.end; ++i) {
    const StitchPlan& sp = plan_[l_.order[i]];
    if (plus ? sp.needle < edge.index : sp.needle > edge.index) edge = {sp.knit, sp.needle};
  }
  return edge;
}
// A yarn whose last course leaves its loops to another yarn (a flap's, which a course of the
// other flap's yarn later joins) goes out after it; its loops wait on their needles.
void Emitter::leave_loops(const Course& c) {
  w_.line(fmt::format(";!source: carrier {} goes out: yarn piece {}'s loops wait for another yarn",
                      carrier_, c.yarn + 1));
  yarn_out(carrier_);
}
void Emitter::release(const std::string& carrier) {
  if (p_.hook == YarnHook::inhook) w_.carriers("releasehook", carrier);
}
void Emitter::yarn_out(const std::string& carrier) {
  w_.carriers(p_.hook == YarnHook::inhook ? "outhook" : "out", carrier);
}

// The main yarn's first course is the model's cast-on row. Over a waste section it is knitted
// through the draw thread's loops, its carrier brought in with a miss where the row starts
// against the profile's first way; without one, a tuck border in the main yarn ends where the
// row starts. Either way no loop of the piece's yarn is made before it but the border's tucks.
void Emitter::cast_on(const Course& c) {
  Direction first = plan_[l_.order[c.begin]].travel;
  if (p_.waste_rows > 0) {
    w_.line(fmt::format(";!source: waste section: {} {} of waste yarn (carrier {})", p_.waste_rows,
                        l_.tube ? "rounds" : "rows", p_.waste_carrier));
    yarn_in(p_.waste_carrier);
    Direction d = tuck_border(c, p_.waste_carrier, Direction::none);
    release(p_.waste_carrier);
    for (std::uint32_t row = 0; row < p_.waste_rows * (l_.tube ? 2 : 1); ++row, d = opposite(d))
      knit_pass(c, d, p_.waste_carrier);
    yarn_out(p_.waste_carrier);
    if (!p_.draw_carrier.empty()) draw_thread(c);
    if (first == p_.first_pass)
      yarn_in(carrier_);
    else
      bring_in(c);
    knit_course(c);
    return release(carrier_);  // the hook lets go once the yarn has made its first course
  }
  w_.line(";!source: cast-on border: alternating tucks");
  yarn_in(carrier_);
  Direction next = tuck_border(c, carrier_, first);
  release(carrier_);
  if (next != first) {  // a tube with one needle the first way: one loop more (the proof says so)
    w_.line(";!source: cast-on border: a pass to bring the yarn to where the first row starts");
    knit_pass(c, next, carrier_);
  }
  knit_course(c);
}

// One row (a round on a tube) of the draw thread over the waste loops: pulling it out later
// frees the piece from the waste section.
void Emitter::draw_thread(const Course& c) {
  w_.line(fmt::format(";!source: draw thread (carrier {})", p_.draw_carrier));
  yarn_in(p_.draw_carrier);
  Direction d = p_.first_pass;
  for (int pass = 0; pass < (l_.tube ? 2 : 1); ++pass, d = opposite(d))
    knit_pass(c, d, p_.draw_carrier);
  release(p_.draw_carrier);
  yarn_out(p_.draw_carrier);
}

// Chain bind-off: knit a loop, move it onto the next stitch's needle, knit both, and so on;
// then a tag knit back and forth on the last needle, the yarn out, and the tag dropped. A
// bind-off of part of the work (the rest knit on after it) drops its last loop instead: the
// yarn goes on through it to the next course, as a knitter's does, and its needles are free.
// The chain knits at whatever racking its last link left (knitting does not need rack 0).
void Emitter::bind_off(const Course& c, bool last_course) {
  source(c, last_course ? "bind-off" : "bind-off (part of the work; the rest goes on)");
  std::vector<std::uint8_t> busy = busy_needles();
  for (std::uint32_t i = c.begin; i < c.end; ++i) {
    for (std::uint32_t loop : taken(l_.order[i])) busy[needle_slot(live_[loop].now)] = 0;
    track_loops(l_.order[i]);
    const StitchPlan& sp = plan_[l_.order[i]];
    Place here{sp.knit, sp.needle};
    w_.knit(sp.travel, at(here), carrier_);
    // A yarn that starts with the chain (a three-needle bind-off's new yarn) is held once its
    // first st is knit: the hook lets go before the chain's link moves past it.
    if (i == c.begin && c.first_of_yarn) release(carrier_);
    if (i + 1 == c.end) break;
    const StitchPlan& next = plan_[l_.order[i + 1]];
    chain_link(here, {next.knit, next.needle}, busy);
  }
  const StitchPlan& last = plan_[l_.order[c.end - 1]];
  Needle tag{last.knit, last.needle};
  if (!last_course) return w_.drop(tag);
  if (p_.tag_rows) w_.line(fmt::format(";!source: tag: {} rows on the last loop", p_.tag_rows));
  Direction d = last.travel;
  for (std::uint32_t row = 0; row < p_.tag_rows; ++row) {
    d = opposite(d);
    w_.knit(d, tag, carrier_);
  }
  yarn_out(carrier_);
  w_.drop(tag);
}

// Per needle of both beds (needle_slot), whether a loop made and not yet taken is on it.
std::vector<std::uint8_t> Emitter::busy_needles() const {
  std::vector<std::uint8_t> busy(2 * static_cast<std::size_t>(p_.needles), 0);
  for (std::uint32_t loop : on_needles_) busy[needle_slot(live_[loop].now)] = 1;
  return busy;
}
std::size_t Emitter::needle_slot(Place p) const {
  return bed_index(p.bed) * p_.needles + static_cast<std::size_t>(p.needle);
}

// One link of the chain: its loop from `here` onto `there`. Along one bed the loop goes out to
// a free needle of the other bed and back, at two rackings that differ by the step between
// the needles. The first is the racking the last link ended at wherever it can be, so that
// each stitch racks once (the old way, out to the facing needle at rack 0 and over, racked
// twice); where it cannot (the racking climbed to the limit), the far end of the range, from
// which the following links climb longest.
void Emitter::chain_link(Place here, Place there, const std::vector<std::uint8_t>& busy) {
  if (here.bed != there.bed) return move_across_beds(here, there, &busy);
  bool front = here.bed == Bed::f;
  std::int32_t step = front ? there.needle - here.needle : here.needle - there.needle;
  std::int32_t limit = p_.max_transfer_stretch, dir = step > 0 ? 1 : -1;
  auto out_at = [&](std::int32_t r) {
    return Place{other(here.bed), front ? here.needle - r : here.needle + r};
  };
  auto fits = [&](std::int32_t r) {
    Place out = out_at(r);
    return std::abs(r) <= limit && std::abs(r + step) <= limit && out.needle >= 0 &&
           out.needle < static_cast<std::int32_t>(p_.needles) && !busy[needle_slot(out)];
  };
  std::int32_t r = w_.racking();
  for (std::int32_t far = -dir * limit; !fits(r) && std::abs(far) <= limit; far += dir) r = far;
  if (!fits(r)) {  // no free needle within reach: to the facing needle, then across in hops
    // (past loops that wait between the stitches, as a crotch's between two legs' arcs)
    w_.xfer(at(here), at(facing(here)));
    return move_across_beds(facing(here), there, &busy);
  }
  w_.xfer(at(here), at(out_at(r)));
  w_.xfer(at(out_at(r)), at(there));
}

}  // namespace skein::knitout::emit
