#include <fmt/format.h>

#include <algorithm>

#include "common/error.hpp"
#include "lowering/live_runs.hpp"
#include "lowering/program.hpp"

namespace skein {
namespace {

constexpr std::uint32_t kNone = kNoLoop;
constexpr std::uint32_t kBindsOff = kNoLoop;  // a st that takes loops and leaves none

// A stopped lowering: the stitch and why (turned into Program::gap).
struct Stop {
  StitchId stitch;
  std::string why;
};

// A course's taken loops sorted by where they come from, in the order its walk meets them.
struct Takes {
  std::vector<std::uint32_t> run;     // from runs, in run order if the direction is right
  std::vector<std::uint32_t> second;  // a three-needle bind-off's other needle
  std::uint32_t picked_up = 0;        // along an edge
};

class Lowering {
 public:
  Lowering(const KnitGraph& g, const YarnPieces& yarns, const Schedule& schedule)
      : g_(g), yarns_(yarns), schedule_(schedule), live_(g), along_edge_(loops_along_edges(g)) {
    out_.worked_at.assign(g.size(), kNone);
    out_.stitches.reserve(g.size());
    out_.taken.reserve(g.loops.size());
    out_.made.reserve(g.loops.size());
  }

  Program run() && {
    try {
      walk_schedule();
    } catch (const Stop& stop) {
      out_.gap = LoweringGap{stop.stitch, stop.why};
    }
    index_worked_stitches();
    return std::move(out_);
  }

 private:
  // A course ends where a row starts and where its yarn ends. Where the yarn is set aside
  // (hold) the course waits, unlowered, while other yarns work; it goes on when the yarn is
  // taken up again (resume), so a course is lowered whole, at its end. But where another yarn
  // takes loops the course has made so far (a cast-on along a split, worked on from the other
  // side while this yarn waits), the course ends at the hold and goes on as another.
  void walk_schedule() {
    pending_.resize(yarns_.size());
    index_events();
    for (std::uint32_t i = 0; i < schedule_.events.size(); ++i) {
      const Event& e = schedule_.events[i];
      switch (e.kind) {
        case EventKind::row_start:
        case EventKind::yarn_end:
          close_course(e.yarn);
          break;
        case EventKind::hold:
          if (taken_while_held(pending_[e.yarn], resumed_at_[i])) close_course(e.yarn);
          add_hold(e.yarn, e.waits_for);
          break;
        case EventKind::resume:
          add_step(step_of(StepKind::resume, e.yarn));
          break;
        case EventKind::stitch:
          pending_[e.yarn].push_back(e.stitch);
          break;
        case EventKind::yarn_start:
        case EventKind::turn:
        case EventKind::marker:
          break;
      }
    }
    for (std::uint32_t y = 0; y < pending_.size(); ++y) close_course(y);
  }

  // Per stitch, the index of its event; per hold event, that of the resume after it.
  void index_events() {
    const std::vector<Event>& events = schedule_.events;
    worked_in_event_.assign(g_.size(), kNone);
    resumed_at_.assign(events.size(), kNone);
    std::vector<std::uint32_t> next_resume(yarns_.size(), kNone);
    for (auto i = static_cast<std::uint32_t>(events.size()); i-- > 0;) {
      const Event& e = events[i];
      if (e.kind == EventKind::stitch) worked_in_event_[e.stitch] = i;
      if (e.kind == EventKind::resume) next_resume[e.yarn] = i;
      if (e.kind == EventKind::hold) resumed_at_[i] = next_resume[e.yarn];
    }
  }

  // Does another yarn take a loop of the course before the yarn resumes (event `resume`)?
  bool taken_while_held(const std::vector<StitchId>& course, std::uint32_t resume) const {
    return std::any_of(course.begin(), course.end(), [&](StitchId s) {
      for (std::uint32_t loop : g_.loops_made_by(s)) {
        StitchId taker = g_.loops[loop].taker;
        if (taker != kNoStitch && yarns_.piece_of[taker] != yarns_.piece_of[s] &&
            worked_in_event_[taker] < resume)
          return true;
      }
      return false;
    });
  }

  static Step step_of(StepKind kind, std::uint32_t yarn) {
    Step step;
    step.kind = kind;
    step.yarn = yarn;
    return step;
  }

  void add_hold(std::uint32_t yarn, StitchId waits_for) {
    Step step = step_of(StepKind::hold, yarn);
    step.waits_for = waits_for;
    add_step(step);
  }

  StepId add_step(Step step) {
    out_.steps.push_back(step);
    return StepId(static_cast<std::uint32_t>(out_.steps.size() - 1));
  }

  // Records a stitch with its loops by slot, and where each loop it makes goes.
  void work(StitchId s) {
    out_.worked_at[s] = static_cast<std::uint32_t>(out_.stitches.size());
    out_.taken_at.push_back(static_cast<std::uint32_t>(out_.taken.size()));
    out_.made_at.push_back(static_cast<std::uint32_t>(out_.made.size()));
    auto taken = g_.loops_taken_by(s);
    auto made = g_.loops_made_by(s);
    out_.stitches.push_back(
        {s, static_cast<std::uint8_t>(taken.size()), static_cast<std::uint8_t>(made.size())});
    out_.taken.insert(out_.taken.end(), taken.begin(), taken.end());
    for (std::uint32_t loop : made) out_.made.push_back({loop, place_of(loop)});
  }

  LoopPlace place_of(std::uint32_t loop) const {
    const Loop& l = g_.loops[loop];
    if (along_edge_[loop]) return LoopPlace::along_edge;
    if (g_.type[l.maker] == StitchType::sco && l.maker_slot == 1) return LoopPlace::other_side;
    return LoopPlace::in_run;
  }

  // --- one course ---

  void close_course(std::uint32_t yarn) {
    std::vector<StitchId>& course = pending_[yarn];
    if (course.empty()) return;
    Range stitches{static_cast<std::uint32_t>(out_.stitches.size()), 0};
    for (StitchId s : course) work(s);
    stitches.end = static_cast<std::uint32_t>(out_.stitches.size());
    course.clear();
    lower_course(stitches);
  }

  StitchId stitch_at(std::uint32_t i) const { return out_.stitches[i].stitch; }

  CourseDirection input_direction(Range stitches) const {
    CourseDirection d = g_.direction[stitch_at(stitches.begin)];
    for (std::uint32_t i = stitches.begin; i < stitches.end; ++i)
      if (g_.direction[stitch_at(i)] != d)
        throw Stop{stitch_at(i), fmt::format("the course changes direction here without a turn "
                                             "(it began {}, this st runs {})",
                                             course_direction_name(d),
                                             course_direction_name(g_.direction[stitch_at(i)]))};
    return d;
  }

  // Calls f(worked index) for the course's stitches in run order (left to right).
  template <typename F>
  void in_run_order(Range stitches, CourseDirection d, F f) const {
    if (d == CourseDirection::right_to_left)
      for (std::uint32_t i = stitches.end; i-- > stitches.begin;) f(i);
    else
      for (std::uint32_t i = stitches.begin; i < stitches.end; ++i) f(i);
  }

  Takes sort_takes(Range stitches, CourseDirection d) const {
    Takes t;
    in_run_order(stitches, d, [&](std::uint32_t i) {
      StitchId s = stitch_at(i);
      auto taken = g_.loops_taken_by(s);
      for (std::size_t slot = 0; slot < taken.size(); ++slot) {
        std::uint32_t loop = taken[slot];
        if (along_edge_[loop]) {
          if (!live_.along_edge(loop))
            throw Stop{s, "it picks up a loop along an edge that is not there yet"};
          ++t.picked_up;
        } else if (g_.type[s] == StitchType::tnbo && slot == 1) {
          t.second.push_back(loop);
        } else {
          t.run.push_back(loop);
        }
      }
    });
    return t;
  }

  // Extruded stitches (a join's or split's) take the direction of the walk their loops make.
  CourseDirection resolve(Range stitches, CourseDirection d, Takes& takes) const {
    if (d != CourseDirection::along_its_loops) return d;
    if (takes.run.size() >= 2 && live_.follows(takes.run[0], takes.run[1])) {
      takes = sort_takes(stitches, CourseDirection::right_to_left);
      return CourseDirection::right_to_left;
    }
    return CourseDirection::left_to_right;
  }

  void lower_course(Range stitches) {
    StitchId first = stitch_at(stitches.begin);
    Step step = step_of(StepKind::course, yarns_.piece_of[first]);
    step.shape = g_.row_shape[g_.row[first]];
    step.stitches = stitches;
    Takes takes = sort_takes(stitches, input_direction(stitches));
    step.direction = resolve(stitches, g_.direction[first], takes);
    step.picked_up = takes.picked_up;
    std::vector<Segment> segments =
        walks(takes.run, step.direction, step.shape == RowShape::closed);
    if (segments.size() > 1) segments = {join(split_off(segments), step.yarn)};
    std::vector<Segment> needles = second_needles(takes.second, first);
    segments.insert(segments.end(), needles.begin(), needles.end());
    step.reads = add_segments(segments);
    std::vector<std::uint32_t> in_run, other_side;
    std::vector<Segment> splits;  // a round bound off in more than two places: the lines after
                                  // its third block on, the last first, cut off the second's
    std::vector<std::uint32_t> left_per_stitch;  // in run order: in_run loops it leaves, or
    in_run_order(stitches, step.direction, [&](std::uint32_t i) {  // kBindsOff
      std::size_t before = in_run.size();
      place_made(i, in_run, other_side);
      bool binds_off = in_run.size() == before && out_.stitches[i].taken > 0;
      left_per_stitch.push_back(binds_off ? kBindsOff
                                          : static_cast<std::uint32_t>(in_run.size() - before));
    });
    if (segments.empty()) {
      step.kind = StepKind::cast_on;
      step.run = start(in_run, step.shape == RowShape::closed ? RunShape::ring : RunShape::line,
                       step.yarn, g_.direction[first] != CourseDirection::along_its_loops);
    } else {
      step.kind = !needles.empty() ? StepKind::three_needle_bind_off
                  : in_run.empty() ? StepKind::bind_off
                                   : StepKind::course;
      for (const Segment& needle : needles) keep_tail(step, take_second(needle, step.yarn), first);
      step.run = segments.front().run;
      RowShape shape = step.shape;
      std::vector<std::uint32_t> lines;  // where each line after a block starts, in in_run
      if (segments.front().count == live_.size(step.run) &&
          live_.shape(step.run) == RunShape::ring) {
        lines = opening(left_per_stitch);
        if (!lines.empty()) {  // the ring opens where the course bound off
          auto size = static_cast<std::uint32_t>(in_run.size()), from = lines.front();
          std::rotate(in_run.begin(), in_run.begin() + from, in_run.end());
          for (std::uint32_t& at : lines) at = (at + size - from) % size;
          shape = RowShape::open;
        }
      }
      keep_tail(step, take(segments.front(), in_run, shape, step.yarn), first);
      if (lines.size() > 1) {  // bound off in two places: the loops after the second block
        RunId other = new_run(step.yarn);  // are a line of their own, and so on
        auto size = static_cast<std::uint32_t>(in_run.size());
        live_.cut({step.run, in_run[lines[1]], size - lines[1], Walk::forward}, other, RunId());
        keep_tail(step, other, first);
        for (std::size_t k = lines.size() - 1; k > 1; --k) {  // each ends where the next starts
          splits.push_back({other, in_run[lines[k]], size - lines[k], Walk::forward});
          size = lines[k];
        }
      }
      out_.runs[step.run.index()].yarn = step.yarn;
    }
    if (!other_side.empty()) {
      if (step.other.valid())
        throw Stop{first, "the course cuts a line in its middle and casts on across a split"};
      step.other = start(other_side, RunShape::line, step.yarn, false);
    }
    step.run_shape = live_.shape(step.run);
    step.run_ends = live_.size(step.run) == 0;
    add_step(step);
    for (const Segment& line : splits) split_off({line});  // a line after each further block
  }

  // Where a course over a whole ring that binds off some of its sts (an underarm, a bag's
  // handle openings) opens it: per block bound off, the index of the first loop it leaves
  // after it, the block the program keeps first (its line runs on round to the first block);
  // none when it binds off none.
  static std::vector<std::uint32_t> opening(const std::vector<std::uint32_t>& left) {
    std::size_t n = left.size();
    std::vector<std::uint32_t> lines;
    std::uint32_t loops = 0;  // made by the sts before st i
    for (std::size_t i = 0; i < n; ++i) {
      bool here = left[i] == kBindsOff, before = left[(i + n - 1) % n] == kBindsOff;
      if (before && !here) lines.push_back(loops);
      if (!here) loops += left[i];
    }
    if (lines.size() > 1) std::rotate(lines.begin(), lines.end() - 1, lines.end());
    return lines;
  }

  // A course may leave one line cut in its middle (its tail a run of its own, `other`).
  static void keep_tail(Step& step, RunId tail, StitchId at) {
    if (!tail.valid()) return;
    if (step.other.valid()) throw Stop{at, "the course cuts two lines in their middles"};
    step.other = tail;
  }

  void place_made(std::uint32_t i, std::vector<std::uint32_t>& in_run,
                  std::vector<std::uint32_t>& other_side) {
    for (std::uint32_t k = 0; k < out_.stitches[i].made; ++k) {
      const PlacedLoop& p = out_.made[out_.made_at[i] + k];
      if (p.place == LoopPlace::in_run) in_run.push_back(p.loop);
      if (p.place == LoopPlace::other_side) other_side.push_back(p.loop);
      if (p.place == LoopPlace::along_edge) live_.lay_along_edge(p.loop);
    }
  }

  // The loops a course takes from runs as maximal walks of one run each, in run order. A run
  // cast on across a split has the order of the side that takes it: the first course that
  // meets it backward turns it round (a reverse step) and walks it again.
  std::vector<Segment> walks(const std::vector<std::uint32_t>& loops, CourseDirection d,
                             bool closed) {
    for (;;) {
      std::vector<Segment> segments;
      RunId backward = find_walks(loops, d, closed, segments);
      if (!backward.valid()) {
        for (const Segment& seg : segments) unoriented_[seg.run.index()] = 0;
        return segments;
      }
      Step step = step_of(StepKind::reverse, out_.runs[backward.index()].yarn);
      step.run = backward;
      step.run_shape = live_.shape(backward);
      live_.reverse(backward);
      unoriented_[backward.index()] = 0;
      add_step(step);
    }
  }

  // Fills `segments`; returns a run still unoriented that the course meets backward. A course
  // may meet one run in several places, each walk further on along it than the last: a round
  // that begins in the middle of the sts it takes and goes round past where it began (a leg's
  // first rnd), or one that leaves loops between its walks to other pieces (a body's rnd over
  // the sts between a spout's and a handle's, which wait for them). Met out of that order, the
  // walks would cross. A round goes on from a line's end to its start: the round joins them.
  RunId find_walks(const std::vector<std::uint32_t>& loops, CourseDirection d, bool closed,
                   std::vector<Segment>& segments) const {
    for (std::size_t i = 0; i < loops.size(); ++i) {
      std::uint32_t loop = loops[i];
      RunId run = live_.run_of(loop);
      if (!run.valid()) throw not_live(loop);
      if (i > 0 && live_.follows(loop, loops[i - 1])) {
        ++segments.back().count;
        continue;
      }
      if (i > 0 && live_.follows(loops[i - 1], loop)) {
        if (unoriented_[run.index()]) return run;
        throw Stop{g_.loops[loop].taker,
                   fmt::format("the course runs {} (as the input says) but meets its loops the "
                               "other way round: it needs a crossing here",
                               course_direction_name(d))};
      }
      if (!further_on(segments, run, loop, closed)) throw two_places(loop);
      segments.push_back({run, loop, 1, Walk::forward});
    }
    return RunId();
  }

  // Does `loop` lie further on along its run than every walk of that run in `segments`, before
  // the first of them again? A ring goes on round; a line ends, unless a round goes on to its
  // start.
  bool further_on(const std::vector<Segment>& segments, RunId run, std::uint32_t loop,
                  bool closed) const {
    auto first = std::find_if(segments.begin(), segments.end(),
                              [&](const Segment& seg) { return seg.run == run; });
    if (first == segments.end()) return true;
    auto last = std::find_if(segments.rbegin(), segments.rend(),
                             [&](const Segment& seg) { return seg.run == run; });
    if (round_the_gap(*last, loop)) return true;
    bool wrapped = false;
    for (std::uint32_t at = live_.next(live_.walk_end(*last));; at = live_.next(at)) {
      if (at == kNoLoop) {
        if (!closed || wrapped) return false;
        wrapped = true;
        at = live_.head(run);
      }
      if (at == first->first) return false;
      if (at == loop) return true;
    }
  }

  Stop two_places(std::uint32_t loop) const {
    return Stop{g_.loops[loop].taker,
                "the course takes the loops of one run in two places, out of their order: it "
                "needs a crossing here"};
  }

  Stop not_live(std::uint32_t loop) const {
    StitchId maker = g_.loops[loop].maker;
    if (out_.worked_at[maker] == kNone)
      return Stop{g_.loops[loop].taker,
                  fmt::format("it takes a loop {} makes in a course set aside at a hold before its "
                              "end (the course would have to be cut at the hold)",
                              g_.describe(maker))};
    return Stop{g_.loops[loop].taker,
                fmt::format("it takes a loop that is not live (made by {})", g_.describe(maker))};
  }

  // A line whose two ends a course meets from its last loop round to its first (a ring opened
  // where other loops now fill the gap): the course goes on round, no crossing.
  bool round_the_gap(const Segment& earlier, std::uint32_t loop) const {
    return live_.shape(earlier.run) == RunShape::line &&
           live_.next(live_.walk_end(earlier)) == kNone && live_.prev(loop) == kNone;
  }

  // A three-needle bind-off's other needle: walks of one run each, either way (its side faces
  // the first needle's, so its right side's order may run against the course).
  std::vector<Segment> second_needles(const std::vector<std::uint32_t>& loops, StitchId at) const {
    std::vector<Segment> needles;
    for (std::size_t i = 0; i < loops.size(); ++i) {
      std::uint32_t loop = loops[i];
      RunId run = live_.run_of(loop);
      if (!run.valid()) throw Stop{at, "the three-needle bind-off takes a loop that is not live"};
      if (i > 0 && live_.run_of(loops[i - 1]) == run) {
        Segment& seg = needles.back();
        bool forward = live_.follows(loop, loops[i - 1]);
        bool backward = live_.follows(loops[i - 1], loop);
        if (seg.count == 1 && backward) seg.walk = Walk::backward;
        if (seg.walk == Walk::forward ? forward : backward) {
          ++seg.count;
          continue;
        }
      }
      for (const Segment& seg : needles)
        if (seg.run == run)
          throw Stop{at,
                     "the three-needle bind-off's second needle does not hold its loops in "
                     "one order"};
      needles.push_back({run, loop, 1, Walk::forward});
    }
    return needles;
  }

  RunId take_second(const Segment& seg, std::uint32_t yarn) {
    Segment forward = seg;
    if (seg.walk == Walk::backward) forward.first = live_.walk_end(seg);
    forward.walk = Walk::forward;
    return take(forward, {}, RowShape::short_row, yarn);
  }

  // Puts `loops` in place of a forward segment; returns the run a line's tail became, if any.
  RunId take(const Segment& seg, std::span<const std::uint32_t> loops, RowShape shape,
             std::uint32_t yarn) {
    RunId tail = loops.empty() && live_.leaves_tail(seg) ? new_run(yarn) : RunId();
    live_.replace(seg, loops, shape, tail);
    return tail;
  }

  RunId start(std::span<const std::uint32_t> loops, RunShape shape, std::uint32_t yarn,
              bool oriented) {
    RunId id = new_run(yarn);
    unoriented_[id.index()] = !oriented;
    live_.start(id, loops, shape);
    out_.runs[id.index()].shape = shape;
    return id;
  }

  // Cuts each segment that is not a whole run into a run of its own (a split step).
  std::vector<Segment> split_off(std::vector<Segment> segments) {
    for (Segment& seg : segments) {
      seg.run = live_.run_of(seg.first);  // an earlier walk's cut may have moved it to a tail
      if (seg.count == live_.size(seg.run)) continue;
      Step step = step_of(StepKind::split, out_.runs[seg.run.index()].yarn);
      step.reads = add_segments({seg});
      RunId tail = live_.leaves_tail(seg) ? new_run(step.yarn) : RunId();
      step.run = new_run(step.yarn);
      step.other = tail;
      live_.cut(seg, step.run, tail);
      step.run_shape = RunShape::line;
      add_step(step);
      seg = {step.run, seg.first, seg.count, Walk::forward};
    }
    return segments;
  }

  // Runs taken up in one course become one, in the order the course meets them (a join step).
  Segment join(const std::vector<Segment>& segments, std::uint32_t yarn) {
    Step step = step_of(StepKind::join, yarn);
    step.reads = add_segments(segments);
    std::uint32_t count = 0;
    for (const Segment& s : segments) count += s.count;
    step.run = segments.front().run;
    for (const Segment& s : segments) live_.open_at(s.run, s.first);
    for (std::size_t i = 1; i < segments.size(); ++i) live_.append(step.run, segments[i].run);
    step.run_shape = RunShape::line;
    add_step(step);
    return {step.run, segments.front().first, count, Walk::forward};
  }

  Range add_segments(const std::vector<Segment>& segments) {
    Range r{static_cast<std::uint32_t>(out_.segments.size()), 0};
    out_.segments.insert(out_.segments.end(), segments.begin(), segments.end());
    r.end = static_cast<std::uint32_t>(out_.segments.size());
    return r;
  }

  RunId new_run(std::uint32_t yarn) {
    out_.runs.push_back(
        {RunShape::line, yarn, StepId(static_cast<std::uint32_t>(out_.steps.size()))});
    unoriented_.push_back(0);
    return RunId(static_cast<std::uint32_t>(out_.runs.size() - 1));
  }

  // The end of the last worked stitch's loops.
  void index_worked_stitches() {
    out_.taken_at.push_back(static_cast<std::uint32_t>(out_.taken.size()));
    out_.made_at.push_back(static_cast<std::uint32_t>(out_.made.size()));
  }

  const KnitGraph& g_;
  const YarnPieces& yarns_;
  const Schedule& schedule_;
  LiveRuns live_;
  std::vector<std::uint8_t> along_edge_;  // per loop: see loops_along_edges
  std::vector<std::uint8_t> unoriented_;  // per run: cast on across a split, not yet walked
  Program out_;
  std::vector<std::vector<StitchId>> pending_;  // per yarn: its course so far
  std::vector<std::uint32_t> worked_in_event_;  // per stitch: its event's index
  std::vector<std::uint32_t> resumed_at_;       // per hold event: the resume's (kNone: none)
};

}  // namespace

Program lower_to_program(const KnitGraph& graph, const YarnPieces& yarns,
                         const Schedule& schedule) {
  return Lowering(graph, yarns, schedule).run();
}

}  // namespace skein
