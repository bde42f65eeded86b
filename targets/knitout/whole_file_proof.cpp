#include "knitout/whole_file_proof.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <bit>
#include <utility>
#include <vector>

namespace skein::knitout {
namespace {

// Yarn pieces of which some loop is pulled through another loop of the same yarn piece: they
// hold together, so pulling one does not draw it out.
std::vector<bool> knitted_pieces(const Fabric& f, std::uint32_t pieces) {
  std::vector<bool> knitted(pieces + 1, false);
  for (LoopId l = 0; l < f.loops.size(); ++l)
    for (LoopId parent : f.parents_of(l))
      if (f.loops[parent].piece == f.loops[l].piece) knitted[f.loops[l].piece] = true;
  return knitted;
}

std::string describe(const Replay& r, LoopId l) {
  const FabricLoop& loop = r.fabric.loops[l];
  return fmt::format("the loop of line {} (carrier {})", loop.line,
                     carrier_names(r.header, loop.yarn));
}

constexpr std::size_t kNoEnd = ~std::size_t{0};

// How far loop b lies from loop a going the way `d` (negative: behind it).
std::int32_t ahead(const FabricLoop& a, const FabricLoop& b, Direction d) {
  return d == Direction::plus ? b.needle - a.needle : a.needle - b.needle;
}

// The loops of `yarn` from `first` to `last` (included) are a border's passes: each pass goes
// one way, needle after needle the same step apart (every needle, every other one for
// alternating tucks); no loop is made going against the pass it lies in (a pass of one loop
// one step on from the loops on either side, which go the other way), no pass takes up where an
// earlier one its way on its bed left off (a loop of it made after the yarn went elsewhere), and
// the first loop goes the way of its pass or turns back at an end. Else what breaks them. (A
// pass may be one loop long: alternating tucks over three needles tuck the middle one alone.)
std::string passes_broken(const Replay& r, const std::vector<LoopId>& yarn, std::size_t first,
                          std::size_t last) {
  auto loop = [&](std::size_t i) -> const FabricLoop& { return r.fabric.loops[yarn[i]]; };
  auto same_pass = [&](std::size_t i, std::size_t j) { return loop(i).dir == loop(j).dir; };
  auto gap = [&](std::size_t i, std::size_t j, Direction d) { return ahead(loop(i), loop(j), d); };
  auto broken = [&](std::size_t i, const char* how) {
    return fmt::format("{} is made going {} {}", describe(r, yarn[i]),
                       loop(i).dir == Direction::plus ? "right" : "left", how);
  };
  // Per bed, direction and kind of loop (tucks, knits): the steps of its passes longer than one
  // loop, and where the last pass that way ended. (A pass of one loop shows no step: the
  // border's others of its kind on its bed and way say how far on it would have gone on.)
  auto key = [&](std::size_t i) {
    const FabricLoop& l = loop(i);
    return (l.made_by == OpCode::tuck) * 4 + l.front * 2 + (l.dir == Direction::plus);
  };
  std::array<std::vector<std::int32_t>, 8> steps;
  for (std::size_t i = first + 1; i <= last; ++i)
    if (std::int32_t step = gap(i - 1, i, loop(i).dir); same_pass(i - 1, i) && step > 0)
      steps[key(i)].push_back(step);
  std::array<std::size_t, 8> ended;
  ended.fill(kNoEnd);
  for (std::size_t i = first; i <= last; ++i) {
    Direction d = loop(i).dir;
    bool begins = i == first || !same_pass(i - 1, i), ends = i == last || !same_pass(i, i + 1);
    std::int32_t step = begins ? 0 : gap(i - 1, i, d);
    bool steady =
        begins || i - 1 == first || !same_pass(i - 2, i - 1) || step == gap(i - 2, i - 1, d);
    if (!begins && (step <= 0 || !steady)) return broken(i, "out of its pass's order");
    if (begins && i > first && ends && i < last) {
      Direction other = loop(i - 1).dir;
      std::int32_t s = i - 1 > first && same_pass(i - 2, i - 1)   ? gap(i - 2, i - 1, other)
                       : i + 2 <= last && same_pass(i + 1, i + 2) ? gap(i + 1, i + 2, other)
                                                                  : 0;
      if (s > 0 && gap(i - 1, i, other) == s && gap(i, i + 1, other) == s)
        return broken(i, "in the middle of a pass going the other way");
    }
    const std::vector<std::int32_t>& its_steps = steps[key(i)];
    if (std::size_t end = ended[key(i)];
        begins && end != kNoEnd &&
        std::find(its_steps.begin(), its_steps.end(), gap(end, i, d)) != its_steps.end())
      return broken(i, "where an earlier pass its way left off, after the yarn went elsewhere");
    if (ends) ended[key(i)] = i;
  }
  if (last > first && !same_pass(first, first + 1) && gap(first, first + 1, loop(first).dir) <= 0)
    return fmt::format("{} begins the yarn going {}, away from its pass", describe(r, yarn[first]),
                       loop(first).dir == Direction::plus ? "right" : "left");
  return "";
}

// Which way the yarn goes from loop a to loop b along the bed (none: across to the same needle
// of the other bed, which either way reaches).
Direction travel(const FabricLoop& a, const FabricLoop& b) {
  return b.needle > a.needle   ? Direction::plus
         : b.needle < a.needle ? Direction::minus
                               : Direction::none;
}
bool goes(Direction travel, Direction made) {
  return travel == Direction::none || travel == made;
}

// A loop of `yarn` between `first` and `last` made going one way while the yarn comes to it
// along its bed and goes on along its bed going the other: the carriage took the yarn past its
// needle, turned, made the loop and turned again, so the yarn wraps round the needle (a twisted
// loop, which a border laid in passes never makes: a pass's loops go its way, and a turn's loop
// has the next pass's yarn going on its way). Yarn to and from the other bed crosses the gap
// between the beds instead (a narrow tube's border tucks one loop on a bed at a time). Else "".
// (passes_broken sees loops out of order in a pass; this, a loop made the wrong way in a pass
// too short to show its step.)
std::string yarn_wraps_a_needle(const Replay& r, const std::vector<LoopId>& yarn, std::size_t first,
                                std::size_t last) {
  auto loop = [&](std::size_t i) -> const FabricLoop& { return r.fabric.loops[yarn[i]]; };
  for (std::size_t i = first + 1; i < last; ++i) {
    const FabricLoop& l = loop(i);
    Direction from = travel(loop(i - 1), l), on = travel(l, loop(i + 1));
    bool along_its_bed = loop(i - 1).front == l.front && loop(i + 1).front == l.front;
    if (along_its_bed && !goes(from, l.dir) && !goes(on, l.dir))
      return fmt::format(
          "{} is made going {}, and the yarn comes to it and goes on from it going {}: it is "
          "wrapped in its own yarn",
          describe(r, yarn[i]), l.dir == Direction::plus ? "right" : "left",
          on == Direction::plus ? "right" : "left");
  }
  return "";
}

class BorderCheck {
 public:
  BorderCheck(const Replay& r, const std::vector<bool>& mine) : r_(r), f_(r.fabric), mine_(mine) {}

  // "" when the border holds the piece's cast-on as it should; else what is wrong. Each cast-on
  // loop (a loop of the piece pulled through loops, none of them the piece's) hangs on a border
  // loop of its own, that holds nothing else, and there are as many as the input's cast-ons.
  // The border's yarn runs in passes; one in the piece's own yarn before it stays on the piece:
  // tucks through nothing and loops each through one loop below the piece (fabric the model
  // does not have: counted in `knitted`), every loop held by exactly one; a border of another
  // yarn (a draw thread) is one course of it, every loop of it holding one cast-on loop.
  std::string check(const ProofResult& proof, std::size_t cast_ons) {
    std::size_t found = 0;
    for (const ProofResult::Run& run : proof.pieces) {
      std::vector<LoopId> holders;
      for (std::size_t i = run.start; i < run.start + run.count; ++i)
        if (std::string why = hangs_on_border(f_.by_carrier[run.carrier][i], holders); !why.empty())
          return why;
      found += holders.size();
      if (holders.empty()) continue;
      if (std::string why = unlike_holders(holders); !why.empty()) return why;
      std::string why = f_.loops[holders[0]].piece == piece_of(run, run.start)
                            ? own_yarn_border_broken(run)
                            : draw_thread_broken(holders);
      if (!why.empty()) return why;
    }
    if (found != cast_ons)
      return fmt::format(
          "{} cast-on loops of the piece hang on border loops, the input has {} "
          "cast-on stitches",
          found, cast_ons);
    return "";
  }

 private:
  std::uint32_t piece_of(const ProofResult::Run& run, std::size_t i) const {
    return f_.loops[f_.by_carrier[run.carrier][i]].piece;
  }

  // The loops holding the cast-on on one bed are made alike (a swg091n2 tube's border has a
  // pass over its front only).
  std::string unlike_holders(const std::vector<LoopId>& holders) const {
    std::array<LoopId, 2> first{kNoLoop, kNoLoop};
    for (LoopId h : holders) {
      LoopId& like = first[f_.loops[h].front];
      if (like == kNoLoop) like = h;
      if (f_.loops[h].made_by != f_.loops[like].made_by ||
          f_.loops[h].parent_count != f_.loops[like].parent_count)
        return fmt::format(
            "{} holding the cast-on is not made as {} is (a loop missing below "
            "it, or one more)",
            describe(r_, h), describe(r_, like));
    }
    return "";
  }

  std::string hangs_on_border(LoopId l, std::vector<LoopId>& holders) const {
    auto parents = f_.parents_of(l);
    if (parents.empty() ||
        std::any_of(parents.begin(), parents.end(), [&](LoopId p) { return mine_[p]; }))
      return "";
    if (parents.size() != 1)
      return fmt::format("{} of the piece's cast-on hangs on {} border loops, not one",
                         describe(r_, l), parents.size());
    if (f_.loops[parents[0]].children != 1)
      return fmt::format("{} of the border holds {} loops, not one cast-on loop",
                         describe(r_, parents[0]), f_.loops[parents[0]].children);
    holders.push_back(parents[0]);
    return "";
  }

  std::string own_yarn_border_broken(const ProofResult::Run& run) {
    const std::vector<LoopId>& yarn = f_.by_carrier[run.carrier];
    std::size_t first = run.start;
    while (first > 0 && piece_of(run, first - 1) == piece_of(run, run.start)) --first;
    for (std::size_t i = first; i < run.start; ++i) {
      const FabricLoop& l = f_.loops[yarn[i]];
      auto parents = f_.parents_of(yarn[i]);
      bool tuck = l.made_by == OpCode::tuck && parents.empty();
      if (!tuck && (parents.size() != 1 || mine_[parents[0]]))
        return fmt::format(
            "{} of the border is pulled through {} loops, not a tuck through none or a loop "
            "through one loop below the piece",
            describe(r_, yarn[i]), parents.size());
      knitted += !tuck;
      if (l.children != 1)
        return fmt::format("{} of the border holds {} loops, not one", describe(r_, yarn[i]),
                           l.children);
    }
    if (std::string why = passes_broken(r_, yarn, first, run.start); !why.empty()) return why;
    return yarn_wraps_a_needle(r_, yarn, first, run.start);
  }

  std::string draw_thread_broken(const std::vector<LoopId>& holders) const {
    std::uint32_t piece = f_.loops[holders[0]].piece;
    std::size_t carrier = static_cast<std::size_t>(std::countr_zero(f_.loops[holders[0]].yarn));
    const std::vector<LoopId>& yarn = f_.by_carrier[carrier];
    std::vector<bool> holds(f_.loops.size(), false);
    for (LoopId h : holders) holds[h] = true;
    for (LoopId l : yarn)
      if (f_.loops[l].piece == piece && !holds[l])
        return fmt::format("{} of the border's yarn holds no cast-on loop of the piece",
                           describe(r_, l));
    return "";
  }

  const Replay& r_;
  const Fabric& f_;
  const std::vector<bool>& mine_;

 public:
  std::size_t knitted = 0;  // loops of the piece's yarn knitted in its border
};

// "" when the piece comes free; else the first loop that holds it.
// Per loop: it is one of the piece's (a loop of the input), or with `border` one of the loops
// its yarn makes before it (its cast-on border, which comes off the machine with it).
std::vector<bool> loops_of_the_piece(const Replay& r, const ProofResult& proof, bool border) {
  const Fabric& f = r.fabric;
  std::vector<bool> mine(f.loops.size(), false);
  for (const ProofResult::Run& run : proof.pieces) {
    const std::vector<LoopId>& yarn = f.by_carrier[run.carrier];
    std::size_t first = run.start;
    while (border && first > 0 && f.loops[yarn[first - 1]].piece == f.loops[yarn[run.start]].piece)
      --first;
    for (std::size_t i = first; i < run.start + run.count; ++i) mine[yarn[i]] = true;
  }
  return mine;
}

std::string what_holds_the_piece(const Replay& r, const ProofResult& proof,
                                 const std::vector<bool>& mine) {
  const Fabric& f = r.fabric;
  std::vector<bool> own_yarn;
  std::uint32_t pieces = 0;
  for (const FabricLoop& l : f.loops) pieces = std::max(pieces, l.piece);
  own_yarn.assign(pieces + 1, false);
  for (const ProofResult::Run& run : proof.pieces)
    for (std::size_t i = run.start; i < run.start + run.count; ++i) {
      own_yarn[f.loops[f.by_carrier[run.carrier][i]].piece] = true;
    }
  std::vector<bool> knitted = knitted_pieces(f, pieces);
  for (LoopId l = 0; l < f.loops.size(); ++l)
    for (LoopId parent : f.parents_of(l)) {
      std::uint32_t held_by = f.loops[parent].piece;
      if (mine[parent] && !mine[l] && !own_yarn[f.loops[l].piece])
        return fmt::format("{} of the piece is caught in {}, which is not the piece's yarn",
                           describe(r, parent), describe(r, l));
      if (mine[l] && !mine[parent] && !own_yarn[held_by] && knitted[held_by])
        return fmt::format(
            "{} of the piece is pulled through {}, which is knitted into itself: pulling it "
            "does not free the piece",
            describe(r, l), describe(r, parent));
    }
  return "";
}

}  // namespace

ProofResult prove_whole_file(const Replay& replay, std::string_view text, const Compilation& c) {
  ProofResult proof = prove_fabric(replay, text, c);
  if (!proof.proven) return proof;
  std::vector<bool> mine = loops_of_the_piece(replay, proof, false);
  auto cast_ons =
      static_cast<std::size_t>(std::count(c.knit.type.begin(), c.knit.type.end(), StitchType::co));
  std::string held = what_holds_the_piece(replay, proof, loops_of_the_piece(replay, proof, true));
  BorderCheck check(replay, mine);
  std::string border = held.empty() ? check.check(proof, cast_ons) : "";
  if (held.empty() && border.empty()) {
    proof.summary += "; it comes free of everything else in the file, off a whole border";
    if (check.knitted)
      proof.summary += fmt::format(
          " (with {} loop{} of the piece's yarn knitted in it, which stay{} on the piece: fabric "
          "the model does not have)",
          check.knitted, check.knitted == 1 ? "" : "s", check.knitted == 1 ? "s" : "");
    return proof;
  }
  proof.proven = false;
  proof.summary = held.empty() ? fmt::format(
                                     "NOT proven against {}: the border it is cast on is "
                                     "not whole: {}",
                                     c.input, border)
                               : fmt::format(
                                     "NOT proven against {}: the piece does not come "
                                     "free: {}",
                                     c.input, held);
  return proof;
}

std::vector<bool> own_yarn_border(const Replay& replay, const ProofResult& proof) {
  std::vector<bool> border = loops_of_the_piece(replay, proof, true);
  std::vector<bool> piece = loops_of_the_piece(replay, proof, false);
  for (std::size_t l = 0; l < border.size(); ++l) border[l] = border[l] && !piece[l];
  return border;
}

}  // namespace skein::knitout
