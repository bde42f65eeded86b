// The program's verifier: replays the steps with runs kept as plain vectors (its own model, not
// the lowering's linked lists) and checks each against the knit graph.
#include <fmt/format.h>

#include <algorithm>

#include "common/error.hpp"
#include "lowering/program.hpp"

namespace skein {
namespace {

enum class LoopState : std::uint8_t { unmade, in_run, along_edge, taken };

struct ReplayRun {
  std::vector<std::uint32_t> loops;  // in run order
  RunShape shape = RunShape::line;
};

class Verifier {
 public:
  Verifier(const KnitGraph& g, const Program& p)
      : g_(g),
        p_(p),
        state_(g.loops.size(), LoopState::unmade),
        run_of_(g.loops.size(), kNoStitch),
        pos_(g.loops.size(), 0),
        worked_(g.size(), 0),
        runs_(p.runs.size()),
        along_edge_(loops_along_edges(g)) {}

  void run() {
    check(
        p_.taken_at.size() == p_.stitches.size() + 1 && p_.made_at.size() == p_.stitches.size() + 1,
        "every worked stitch has its loops indexed");
    for (step_ = 0; step_ < p_.steps.size(); ++step_) replay(p_.steps[step_]);
    if (p_.complete()) check_the_end();
  }

 private:
  void check(bool ok, const std::string& what) const {
    if (!ok)
      throw InternalError(
          fmt::format("the live-loop program breaks a rule at step {}: {}", step_ + 1, what));
  }

  void replay(const Step& s) {
    switch (s.kind) {
      case StepKind::hold:
      case StepKind::resume:
        return;
      case StepKind::split:
        return split(s);
      case StepKind::join:
        return join(s);
      case StepKind::reverse:
        return reverse(s);
      default:
        return course(s);
    }
  }

  ReplayRun& run(RunId r) {
    check(r.valid() && r.index() < runs_.size(), "names a run the program lists");
    return runs_[r.index()];
  }

  // The loops of `seg`, checked live in its run and walked from where it says.
  std::vector<std::uint32_t> read(const Segment& seg) {
    ReplayRun& r = run(seg.run);
    check(seg.first < state_.size() && state_[seg.first] == LoopState::in_run &&
              run_of_[seg.first] == seg.run.index(),
          fmt::format("a segment starts on a loop live in run {}", seg.run.index() + 1));
    check(seg.count >= 1 && seg.count <= r.loops.size(), "a segment is no longer than its run");
    std::vector<std::uint32_t> loops;
    const auto n = static_cast<std::int64_t>(r.loops.size());
    std::int64_t at = pos_[seg.first], step = seg.walk == Walk::forward ? 1 : -1;
    for (std::uint32_t i = 0; i < seg.count; ++i, at += step) {
      bool inside = at >= 0 && at < n;
      check(inside || r.shape == RunShape::ring, "a walk along a line stays on it");
      loops.push_back(r.loops[static_cast<std::size_t>((at % n + n) % n)]);
    }
    return loops;
  }

  // Takes `seg` (forward) out of its run; a ring opens there, a line's tail moves to `tail`.
  void remove(const Segment& seg, RunId& tail) {
    ReplayRun& r = run(seg.run);
    std::size_t first = pos_[seg.first], n = r.loops.size();
    std::vector<std::uint32_t> rest;
    if (r.shape == RunShape::ring) {
      for (std::size_t i = seg.count; i < n; ++i) rest.push_back(r.loops[(first + i) % n]);
      r.shape = RunShape::line;
      set(seg.run, std::move(rest));
      return;
    }
    std::vector<std::uint32_t> after(r.loops.begin() + first + seg.count, r.loops.end());
    rest.assign(r.loops.begin(), r.loops.begin() + first);
    bool cut_in_middle = !rest.empty() && !after.empty();
    check(!cut_in_middle || tail.valid(), "a line cut in its middle gives its tail a run");
    if (cut_in_middle) {
      set(tail, std::move(after));
      tail = RunId();  // used
    } else {
      rest.insert(rest.end(), after.begin(), after.end());
    }
    set(seg.run, std::move(rest));
  }

  void set(RunId id, std::vector<std::uint32_t> loops) {
    ReplayRun& r = run(id);
    for (std::uint32_t i = 0; i < loops.size(); ++i) {
      std::uint32_t loop = loops[i];
      state_[loop] = LoopState::in_run;
      run_of_[loop] = id.index();
      pos_[loop] = i;
    }
    r.loops = std::move(loops);
  }

  void split(const Step& s) {
    check(s.reads.size() == 1, "a split reads one segment");
    const Segment& seg = p_.segments[s.reads.begin];
    check(seg.walk == Walk::forward, "a split walks its run forward");
    std::vector<std::uint32_t> part = read(seg);
    RunId tail = s.other;
    remove(seg, tail);
    check(!tail.valid(), "a split names a tail only where it cuts a line in its middle");
    run(s.run).shape = RunShape::line;
    set(s.run, std::move(part));
  }

  void join(const Step& s) {
    std::vector<std::uint32_t> all;
    for (std::uint32_t i = s.reads.begin; i < s.reads.end; ++i) {
      const Segment& seg = p_.segments[i];
      check(seg.count == run(seg.run).loops.size(), "a join takes whole runs");
      std::vector<std::uint32_t> loops = read(seg);
      all.insert(all.end(), loops.begin(), loops.end());
      run(seg.run).loops.clear();
    }
    run(s.run).shape = RunShape::line;
    set(s.run, std::move(all));
  }

  void reverse(const Step& s) {
    check(s.run_shape == run(s.run).shape, "a run keeps its shape when it is turned round");
    std::vector<std::uint32_t> loops = run(s.run).loops;
    std::reverse(loops.begin(), loops.end());
    set(s.run, std::move(loops));
  }

  // --- courses ---

  void course(const Step& s) {
    check(s.stitches.size() > 0, "a course works stitches");
    check_stitches(s);
    std::vector<std::uint32_t> main, second, in_run, other_side;
    std::uint32_t picked = sort_loops(s, main, second, in_run, other_side);
    check(picked == s.picked_up, "the loops picked up along an edge are counted");
    bool cast_on = s.kind == StepKind::cast_on;
    check(cast_on == main.empty() && cast_on == (s.reads.size() == 0),
          "a cast-on, and only a cast-on, takes no loop from a run");
    check((s.kind == StepKind::three_needle_bind_off) == !second.empty(),
          "a three-needle bind-off, and only it, takes a second needle's loops");
    RunId tail = s.other;
    if (!second.empty()) take(s, second, tail);
    if (cast_on) {
      run(s.run).shape = s.shape == RowShape::closed ? RunShape::ring : RunShape::line;
      set(s.run, in_run);
    } else {
      check(s.kind != StepKind::bind_off || in_run.empty(), "a bind-off leaves no loop");
      replace(s, main, in_run, tail);
    }
    check(!tail.valid() || !other_side.empty(), "a course names a tail only where it cuts a line");
    if (!other_side.empty()) {
      run(s.other).shape = RunShape::line;
      set(s.other, other_side);
    }
    check(run(s.run).shape == s.run_shape, "the run's shape is what the step says");
    check(run(s.run).loops.empty() == s.run_ends, "the run ends where the step says");
  }

  void check_stitches(const Step& s) {
    for (std::uint32_t i = s.stitches.begin; i < s.stitches.end; ++i) {
      const WorkedStitch& w = p_.stitches[i];
      check(w.stitch < g_.size() && !worked_[w.stitch], "every stitch is worked once");
      worked_[w.stitch] = 1;
      check(p_.worked_at[w.stitch] == i, "the stitch's index says where it is worked");
      auto taken = g_.loops_taken_by(w.stitch);
      auto made = g_.loops_made_by(w.stitch);
      check(std::equal(taken.begin(), taken.end(), p_.taken.begin() + p_.taken_at[i],
                       p_.taken.begin() + p_.taken_at[i + 1]),
            fmt::format("{} takes the knit graph's loops by slot", g_.describe(w.stitch)));
      check(made.size() == w.made, fmt::format("{} makes its loops", g_.describe(w.stitch)));
      for (std::uint32_t k = 0; k < w.made; ++k)
        check(p_.made[p_.made_at[i] + k].loop == made[k],
              fmt::format("{} makes the knit graph's loops by slot", g_.describe(w.stitch)));
      CourseDirection d = g_.direction[w.stitch];
      check(d == s.direction || d == CourseDirection::along_its_loops,
            fmt::format("{} runs as the input says", g_.describe(w.stitch)));
    }
  }

  // The course's loops in the order its walk meets them (run order), sorted by where they
  // come from and go; returns the number picked up along an edge.
  std::uint32_t sort_loops(const Step& s, std::vector<std::uint32_t>& main,
                           std::vector<std::uint32_t>& second, std::vector<std::uint32_t>& in_run,
                           std::vector<std::uint32_t>& other_side) {
    std::uint32_t picked = 0;
    bound_off_.clear();
    made_by_.clear();
    bool backward = s.direction == CourseDirection::right_to_left;
    for (std::uint32_t k = 0; k < s.stitches.size(); ++k) {
      std::uint32_t i = backward ? s.stitches.end - 1 - k : s.stitches.begin + k;
      StitchId st = p_.stitches[i].stitch;
      for (std::uint32_t t = p_.taken_at[i]; t < p_.taken_at[i + 1]; ++t) {
        std::uint32_t loop = p_.taken[t];
        if (along_edge_[loop]) {
          check(state_[loop] == LoopState::along_edge, "a loop picked up waits along an edge");
          state_[loop] = LoopState::taken;
          ++picked;
        } else if (g_.type[st] == StitchType::tnbo && t - p_.taken_at[i] == 1) {
          second.push_back(loop);
        } else {
          main.push_back(loop);
        }
      }
      std::size_t before = in_run.size();
      for (std::uint32_t m = p_.made_at[i]; m < p_.made_at[i + 1]; ++m)
        place(p_.made[m], st, in_run, other_side);
      bound_off_.push_back(in_run.size() == before && p_.taken_at[i + 1] > p_.taken_at[i]);
      made_by_.push_back(in_run.size() - before);
    }
    return picked;
  }

  void place(const PlacedLoop& p, StitchId st, std::vector<std::uint32_t>& in_run,
             std::vector<std::uint32_t>& other_side) {
    check(state_[p.loop] == LoopState::unmade, "every loop is made once");
    bool edge = along_edge_[p.loop];
    check(edge == (p.place == LoopPlace::along_edge), "loops made across an edge wait along it");
    check(p.place != LoopPlace::other_side || g_.type[st] == StitchType::sco,
          "only a cast-on along a split makes loops for its other side");
    if (p.place == LoopPlace::in_run) in_run.push_back(p.loop);
    if (p.place == LoopPlace::other_side) other_side.push_back(p.loop);
    if (p.place == LoopPlace::along_edge) state_[p.loop] = LoopState::along_edge;
  }

  // The second needle's segments, walked in order, hold its loops; each is bound off.
  void take(const Step& s, const std::vector<std::uint32_t>& loops, RunId& tail) {
    std::size_t at = 0;
    for (std::uint32_t i = s.reads.begin + 1; i < s.reads.end; ++i) {
      const Segment& seg = p_.segments[i];
      std::vector<std::uint32_t> part = read(seg);
      check(at + part.size() <= loops.size() &&
                std::equal(part.begin(), part.end(), loops.begin() + at),
            "the second needle's loops are where the step says");
      at += part.size();
      Segment forward = seg;
      if (seg.walk == Walk::backward) forward.first = part.back(), forward.walk = Walk::forward;
      if (part.size() == run(seg.run).loops.size())
        run(seg.run).loops.clear();
      else
        remove(forward, tail);
      for (std::uint32_t loop : part) state_[loop] = LoopState::taken;
    }
    check(at == loops.size(), "the second needle's segments hold all its loops");
  }

  void replace(const Step& s, const std::vector<std::uint32_t>& main,
               const std::vector<std::uint32_t>& made, RunId& tail) {
    const Segment& seg = p_.segments[s.reads.begin];
    check(seg.run == s.run && seg.walk == Walk::forward, "a course works its run in place");
    check(read(seg) == main, "the course meets its loops where the step says, in order");
    ReplayRun& r = run(s.run);
    bool whole = main.size() == r.loops.size();
    for (std::uint32_t loop : main) state_[loop] = LoopState::taken;
    if (made.empty()) {
      if (whole)
        r.loops.clear();
      else
        remove(seg, tail);
      return;
    }
    std::size_t first = pos_[seg.first], n = r.loops.size();
    std::vector<std::uint32_t> loops;
    std::vector<std::uint32_t> second;
    if (r.shape == RunShape::ring && whole && opens_after_bind_off(made, loops, second)) {
      r.shape = RunShape::line;
      set(s.run, std::move(loops));
      if (second.empty()) return;
      check(tail.valid(), "a ring bound off in two places names its second line");
      run(tail).shape = RunShape::line;
      set(tail, std::move(second));
      tail = RunId();
      return;
    }
    if (r.shape == RunShape::ring) {  // from the segment on round the ring
      loops = made;
      for (std::size_t i = main.size(); i < n; ++i) loops.push_back(r.loops[(first + i) % n]);
    } else {
      loops.assign(r.loops.begin(), r.loops.begin() + first);
      loops.insert(loops.end(), made.begin(), made.end());
      loops.insert(loops.end(), r.loops.begin() + first + main.size(), r.loops.end());
    }
    if (whole)
      r.shape = s.shape == RowShape::closed                                   ? RunShape::ring
                : s.shape == RowShape::short_row && r.shape == RunShape::ring ? RunShape::ring
                                                                              : RunShape::line;
    set(s.run, std::move(loops));
  }

  // A round over a whole ring that binds off a block of its sts leaves a line that starts
  // after them: `line` gets its loops; false when it binds off none. Bound off in two blocks
  // or more, the line ends at the second and `second` gets the loops after it (split steps
  // part them further).
  bool opens_after_bind_off(const std::vector<std::uint32_t>& made,
                            std::vector<std::uint32_t>& line,
                            std::vector<std::uint32_t>& second) const {
    std::size_t n = bound_off_.size();
    std::vector<std::size_t> starts;  // sts that follow a bound-off block
    for (std::size_t i = 0; i < n; ++i)
      if (bound_off_[(i + n - 1) % n] && !bound_off_[i]) starts.push_back(i);
    if (starts.empty()) return false;
    auto loops_before = [&](std::size_t end) {
      std::size_t count = 0;
      for (std::size_t i = 0; i < end; ++i) count += made_by_[i];
      return count;
    };
    std::size_t from = loops_before(starts.back()) % made.size();
    std::vector<std::uint32_t> ring(made.begin() + static_cast<std::ptrdiff_t>(from), made.end());
    ring.insert(ring.end(), made.begin(), made.begin() + static_cast<std::ptrdiff_t>(from));
    std::size_t cut = ring.size();
    if (starts.size() >= 2) cut = loops_before(starts.front()) + made.size() - from;
    cut %= made.size() == 0 ? 1 : made.size();
    if (starts.size() == 1) cut = ring.size();
    line.assign(ring.begin(), ring.begin() + static_cast<std::ptrdiff_t>(cut));
    second.assign(ring.begin() + static_cast<std::ptrdiff_t>(cut), ring.end());
    return true;
  }

  void check_the_end() {
    for (StitchId s = 0; s < g_.size(); ++s)
      check(worked_[s], fmt::format("{} is worked", g_.describe(s)));
    for (std::uint32_t l = 0; l < g_.loops.size(); ++l) {
      bool open_end = g_.loops[l].taker == kNoStitch;
      check(state_[l] == (open_end ? LoopState::in_run : LoopState::taken),
            fmt::format("the loop {} makes is {}", g_.describe(g_.loops[l].maker),
                        open_end ? "left live" : "taken once"));
    }
  }

  const KnitGraph& g_;
  const Program& p_;
  std::vector<LoopState> state_;
  std::vector<std::uint32_t> run_of_, pos_;
  std::vector<std::uint8_t> worked_;
  std::vector<ReplayRun> runs_;
  std::vector<std::uint8_t> along_edge_;
  std::vector<bool> bound_off_;       // per st of the course, in run order: takes, leaves none
  std::vector<std::size_t> made_by_;  // per st of the course, in run order: loops it leaves
  std::size_t step_ = 0;
};

}  // namespace

void verify_program(const KnitGraph& graph, const Program& program) {
  Verifier(graph, program).run();
}

}  // namespace skein
