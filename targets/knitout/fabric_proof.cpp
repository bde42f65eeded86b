#include "knitout/fabric_proof.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <limits>
#include <unordered_map>

#include "knitout/course_layout.hpp"
#include "knitout/stitch_recipes.hpp"

namespace skein::knitout {
namespace {

// Fabric loops a stitch makes along its yarn (a bind-off's chain loop included; a slip none).
std::uint32_t fabric_loops(StitchType t) {
  return t == StitchType::sl ? 0 : std::max<std::uint32_t>(info(t).loops_out, 1);
}

class Matcher {
 public:
  Matcher(const Replay& r, std::string_view text, const Compilation& c, const CourseLayout& l)
      : f_(r.fabric), r_(r), text_(text), g_(c.knit), l_(l) {
    loop_of_.assign(g_.loops.size(), kNoLoop);
    kept_.assign(g_.loops.size(), kNoKept);
    stamp_.assign(f_.loops.size(), 0);
    wrap_after_.assign(g_.size(), kNoWrap);
    wrap_back_.assign(g_.size(), 0);
    for (const Course& course : l_.courses) {
      if (course.wrap == kNoWrap) continue;
      wrap_after_[l_.order[course.end - 1]] = course.wrap;
      wrap_back_[l_.order[course.end - 1]] = course.wrap_back;
    }
  }

  // Tries the stitches against carrier `carrier`'s loops from index `start` on; on failure
  // returns false with `why` set and `reached` the number of stitches that matched.
  bool match(std::size_t carrier, std::size_t start, std::string& why, std::size_t& reached) {
    ++try_;
    sign_ = 0;
    const std::vector<LoopId>& yarn = f_.by_carrier[carrier];
    CarrierMask mask = CarrierMask{1} << carrier;
    std::size_t pos = start;
    LoopId previous_bo = kNoLoop;
    reached = 0;
    wraps_.clear();
    for (StitchId s : l_.order) {
      StitchType t = g_.type[s];
      std::uint32_t n = fabric_loops(t) + (wrap_after_[s] != kNoWrap);
      if (pos + n > yarn.size()) {
        why = fmt::format("the yarn of carrier {} ends before {}", r_.header.carriers[carrier],
                          g_.describe(s));
        return false;
      }
      for (std::uint32_t i = 0; i < n; ++i) {
        const FabricLoop& fl = f_.loops[yarn[pos + i]];
        if (fl.yarn != mask || fl.piece != f_.loops[yarn[start]].piece) {
          why = fmt::format("{}: {} is made {}", g_.describe(s), where(yarn[pos + i]),
                            fl.yarn != mask ? "by several carriers together"
                                            : "by another yarn piece (the yarn was cut)");
          return false;
        }
      }
      if (previous_bo != kNoLoop && t != StitchType::bo && !chain_let_go(s, previous_bo, why))
        return false;
      if (!stitch_matches(s, t, &yarn[pos], previous_bo, why)) return false;
      if (wrap_after_[s] != kNoWrap && !wrap_matches(s, yarn[pos], yarn[pos + n - 1], why))
        return false;
      for (std::uint32_t i = 0; i < n; ++i) stamp_[yarn[pos + i]] = try_;
      previous_bo = t == StitchType::bo ? yarn[pos] : kNoLoop;
      pos += n;
      ++reached;
    }
    return children_match(why) && wraps_taken(why);
  }

 private:
  // A short row's turn: a tuck (a loop through nothing) that the stitch taking the waiting
  // loop later knits through as well, made going on the way the row went (`last` is the
  // turning stitch's loop); in a tube, the other way when the waiting loop lies over the fold.
  bool wrap_matches(StitchId s, LoopId last, LoopId x, std::string& why) {
    const FabricLoop& fl = f_.loops[x];
    if (fl.made_by != OpCode::tuck || fl.parent_count != 0) {
      why = fmt::format("the turn after {} leaves a hole: {} is not a tuck over the waiting loop",
                        g_.describe(s), where(x));
      return false;
    }
    std::uint32_t waiting = wrap_after_[s];
    const Loop& w = g_.loops[waiting];
    auto made = g_.loops_made_by(s);  // `last` is the first of them the yarn makes
    std::uint8_t turning_slot = made.empty()
                                    ? 0
                                    : made_slot_along_yarn(g_.type[s], l_.left_to_right[s], 0,
                                                           static_cast<std::uint8_t>(made.size()));
    bool over_fold = l_.tube && front_half(loop_of_[waiting], w.maker, w.maker_slot) !=
                                    front_half(last, s, turning_slot);
    bool back = over_fold != wrap_back_[s];
    Direction on = back ? opposite(f_.loops[last].dir) : f_.loops[last].dir;
    if (fl.dir != on) {
      why = fmt::format("the turn after {} goes back before its tuck: {} goes {}", g_.describe(s),
                        where(x), direction_char(fl.dir));
      return false;
    }
    wraps_.emplace(g_.loops[waiting].taker, x);
    return true;
  }
  // A bind-off of part of the work, which the yarn leaves for `next`, drops its chain's last
  // loop `x` (the yarn goes on through it), so that its needles are free for the rest.
  bool chain_let_go(StitchId next, LoopId x, std::string& why) const {
    if (f_.loops[x].dropped) return true;
    why = fmt::format(
        "the bind-off before {} leaves its last loop ({}) on the needle: a "
        "bind-off of part of the work drops it",
        g_.describe(next), where(x));
    return false;
  }
  // Whether the loop `x`, made in slot `slot` of `maker`, belongs to a tube's front half: a
  // purl's loop and a kfb's second loop are made on the bed facing their half.
  bool front_half(LoopId x, StitchId maker, std::uint8_t slot) const {
    StitchType t = g_.type[maker];
    bool facing = is_purl(t) || (t == StitchType::kfb &&
                                 slot != knit_slot(StitchType::kfb, l_.left_to_right[maker]));
    return f_.loops[x].front != facing;
  }
  bool is_wrap(StitchId s, LoopId x) const {
    auto [first, last] = wraps_.equal_range(s);
    return std::any_of(first, last, [x](const auto& w) { return w.second == x; });
  }
  // Each turn's tuck is pulled through by the stitch that takes the loop it wraps.
  bool wraps_taken(std::string& why) const {
    for (const auto& [taker, x] : wraps_) {
      std::uint8_t want = g_.type[taker] == StitchType::kfb ? 2 : 1;
      if (f_.loops[x].children != want) {
        why = fmt::format("the turn's tuck {} is pulled through {} times, expected {} (by {})",
                          where(x), f_.loops[x].children, want, g_.describe(taker));
        return false;
      }
    }
    return true;
  }

  std::string where(LoopId x) const {
    if (lines_.empty()) lines_ = split_lines(text_);  // only ever needed for a message
    std::uint32_t line = f_.loops[x].line;
    return fmt::format("line {} ({})", line, line && line <= lines_.size() ? lines_[line - 1] : "");
  }

  std::string describe_parents(LoopId x) const {
    auto parents = f_.parents_of(x);
    if (parents.empty()) return "through nothing";
    std::string out = "through the loop";
    out += parents.size() > 1 ? "s of lines " : " of line ";
    for (std::size_t i = 0; i < parents.size(); ++i)
      out += fmt::format("{}{}", i ? ", " : "", f_.loops[parents[i]].line);
    return out;
  }

  std::string describe_expected(const std::vector<LoopId>& expected) const {
    if (expected.empty()) return "through nothing (a new loop)";
    std::string out = "through the loop";
    out += expected.size() > 1 ? "s of " : " of ";
    for (std::size_t i = 0; i < expected.size(); ++i)
      out +=
          fmt::format("{}{} ({}{})", i ? ", " : "", describe_maker(expected[i]), where(expected[i]),
                      f_.loops[expected[i]].dropped ? ", later dropped" : "");
    return out;
  }
  std::string describe_maker(LoopId x) const {
    for (std::uint32_t loop = 0; loop < loop_of_.size(); ++loop)
      if (loop_of_[loop] == x) return g_.describe(g_.loops[loop].maker);
    return "the bind-off chain";
  }

  bool parents_are(LoopId x, std::vector<LoopId> expected, StitchId s, std::string& why) const {
    auto parents = f_.parents_of(x);
    std::vector<LoopId> have(parents.begin(), parents.end());
    std::vector<LoopId> want = expected;
    std::sort(have.begin(), have.end());
    std::sort(want.begin(), want.end());
    if (have == want) return true;
    why = fmt::format("{} is not there: {} makes its loop {}, expected {}", g_.describe(s),
                      where(x), describe_parents(x), describe_expected(expected));
    return false;
  }

  // The fabric loops a stitch must be pulled through: the loops it takes, with the loops tucks
  // kept under them, and the tucks of the short-row turns that wrapped them.
  std::vector<LoopId> through_of(StitchId s) const {
    std::vector<LoopId> through;
    for (std::uint32_t loop : g_.loops_taken_by(s))
      for (std::uint32_t l = loop; l != kNoKept; l = kept_[l]) through.push_back(loop_of_[l]);
    auto [wrap, wraps_end] = wraps_.equal_range(s);
    for (; wrap != wraps_end; ++wrap) through.push_back(wrap->second);
    return through;
  }

  // A decrease's top loop (the last pulled through, wraps aside) is the one its lean puts there.
  bool leans_right(StitchId s, StitchType t, LoopId x, std::string& why) const {
    auto parents = f_.parents_of(x);
    auto on_top =
        std::find_if(parents.rbegin(), parents.rend(), [&](LoopId p) { return !is_wrap(s, p); });
    LoopId top = loop_of_[g_.loops_taken_by(s)[stacking_order(t).back()]];
    if (*on_top == top) return true;
    why = fmt::format("{} leans the wrong way: {} has the loop of {} on top, expected that of {}",
                      g_.describe(s), where(x), describe_maker(*on_top), describe_maker(top));
    return false;
  }

  bool stitch_matches(StitchId s, StitchType t, const LoopId* loops, LoopId previous_bo,
                      std::string& why) {
    auto taken = g_.loops_taken_by(s);
    auto made = g_.loops_made_by(s);
    if (keeps_loop_below(t)) return kept_below(s, t, loops, why);
    std::vector<LoopId> through = through_of(s);
    if (t == StitchType::co) {
      for (LoopId parent : f_.parents_of(loops[0]))
        if (stamp_[parent] == try_) {
          why = fmt::format("{} is not a cast-on: {} is pulled through the fabric, not the border",
                            g_.describe(s), where(loops[0]));
          return false;
        }
    } else if (t == StitchType::bo) {
      if (previous_bo != kNoLoop) through.push_back(previous_bo);
      return parents_are(loops[0], through, s, why) && travels_along_course(s, t, loops, 1, why);
    } else if (made.size() == 2) {
      bool ltr = l_.left_to_right[s];
      for (std::uint8_t i = 0; i < 2; ++i) {
        std::uint8_t slot = made_slot_along_yarn(t, ltr, i, 2);
        if (!parents_are(loops[i],
                         made_slot_pulled_through(t, slot, ltr) ? through : std::vector<LoopId>{},
                         s, why))
          return false;
      }
    } else if (!parents_are(loops[0], through, s, why) ||
               (taken.size() > 1 && !leans_right(s, t, loops[0], why))) {
      return false;
    }
    if (!l_.tube && !made.empty() && f_.loops[loops[0]].front == is_purl(t)) {
      why = fmt::format("{} is a {} but {} knits it on the {} bed", g_.describe(s), info(t).name,
                        where(loops[0]), is_purl(t) ? "front" : "back");
      return false;
    }
    if (!travels_along_course(s, t, loops, std::max<std::size_t>(made.size(), 1), why))
      return false;
    for (std::size_t i = 0; i < made.size(); ++i)
      loop_of_[made[made_slot_along_yarn(t, l_.left_to_right[s], static_cast<std::uint8_t>(i),
                                         static_cast<std::uint8_t>(made.size()))]] = loops[i];
    return true;
  }

  // The yarn runs the same way through every stitch of a course as through the first stitch
  // matched: on a sheet, rows alternate; in a tube the back half runs against the front half
  // (a stitch's half is the bed it is made on, the other for a purl). A loop made against
  // its course leaves a float where the carrier turns back.
  // An sr5's second loop is made on the way back, after the turn.
  bool travels_along_course(StitchId s, StitchType t, const LoopId* loops, std::size_t n,
                            std::string& why) {
    bool back_half = l_.tube && f_.loops[loops[0]].front == is_purl(t);
    for (std::size_t i = 0; i < n; ++i) {
      const FabricLoop& fl = f_.loops[loops[i]];
      bool turned = t == StitchType::sr5 && i == 1;
      int sign = (l_.left_to_right[s] != turned ? 1 : -1) * (back_half ? -1 : 1) *
                 static_cast<int>(fl.dir);
      if (sign_ == 0) sign_ = sign;
      if (sign != sign_) {
        why = fmt::format("{} is knit against the direction of its row: {} goes {}", g_.describe(s),
                          where(loops[i]), direction_char(fl.dir));
        return false;
      }
    }
    return true;
  }

  // A tuck: a loop through nothing, over the loop it takes, which stays on the needle for the
  // stitch above (kept_); a slip makes no loop: its loop is the one it takes.
  bool kept_below(StitchId s, StitchType t, const LoopId* loops, std::string& why) {
    std::uint32_t below = g_.loops_taken_by(s)[0], made = g_.loops_made_by(s)[0];
    if (t == StitchType::sl) {
      loop_of_[made] = loop_of_[below];
      kept_[made] = kept_[below];
      return true;
    }
    if (f_.loops[loops[0]].made_by != OpCode::tuck) {
      why = fmt::format("{} is not there: {} is not a tuck", g_.describe(s), where(loops[0]));
      return false;
    }
    if (!parents_are(loops[0], {}, s, why) || !travels_along_course(s, t, loops, 1, why))
      return false;
    loop_of_[made] = loops[0];
    kept_[made] = below;
    return true;
  }

  // How often a loop is pulled through: once, twice for a kfb; a tuck or slip above passes it
  // on to the stitch that takes their loop.
  std::uint32_t pulls(std::uint32_t loop) const {
    StitchId taker = g_.loops[loop].taker;
    if (keeps_loop_below(g_.type[taker])) return pulls(g_.loops_made_by(taker)[0]);
    return g_.type[taker] == StitchType::kfb ? 2 : 1;
  }

  // Every loop of the input is pulled through as often as its taker needs.
  bool children_match(std::string& why) const {
    for (StitchId s : l_.order)
      for (std::uint32_t loop : g_.loops_made_by(s)) {
        const Loop& l = g_.loops[loop];
        std::uint32_t want = pulls(loop);
        LoopId x = loop_of_[loop];
        if (f_.loops[x].children != want) {
          why = fmt::format("the loop {} makes for {} is pulled through {} time{}, expected {}",
                            where(x), g_.describe(l.maker), f_.loops[x].children,
                            f_.loops[x].children == 1 ? "" : "s", want);
          return false;
        }
      }
    return true;
  }

  const Fabric& f_;
  const Replay& r_;
  std::string_view text_;
  mutable std::vector<std::string_view> lines_;
  const KnitGraph& g_;
  const CourseLayout& l_;
  std::vector<LoopId> loop_of_;  // per knit graph loop: its fabric loop
  static constexpr std::uint32_t kNoKept = 0xffffffffu;
  std::vector<std::uint32_t> kept_;        // per knit graph loop: the loop a tuck kept under it
  std::vector<std::uint32_t> stamp_;       // per fabric loop: the try that matched it
  std::vector<std::uint32_t> wrap_after_;  // per stitch: the loop its course's turn wraps
  std::vector<std::uint8_t> wrap_back_;    // per stitch: ... its own loop, going back
  std::unordered_multimap<StitchId, LoopId> wraps_;  // per stitch: the turn tucks it knits
  std::uint32_t try_ = 0;
  int sign_ = 0;  // the first stitch's direction relative to its frame
};

// Where one piece was found: along which carrier, after how many border loops.
struct PieceMatch {
  bool found = false;
  std::size_t carrier = 0, start = 0, needed = 0;
  std::string why;  // when not found: the first difference of the closest try
};

// Looks for the piece along every carrier's yarn, in a yarn piece no other piece matched.
PieceMatch find_piece(const Replay& r, std::string_view text, const Compilation& c,
                      const CourseLayout& l, std::vector<std::uint32_t>& used) {
  PieceMatch match;
  for (StitchId s : l.order) match.needed += fabric_loops(c.knit.type[s]);
  for (const Course& course : l.courses) match.needed += course.wrap != kNoWrap;
  Matcher m(r, text, c, l);
  std::size_t best = 0;
  for (std::size_t carrier = 0; carrier < r.fabric.by_carrier.size(); ++carrier) {
    const auto& yarn = r.fabric.by_carrier[carrier];
    for (std::size_t start = 0; start + match.needed <= yarn.size(); ++start) {
      std::uint32_t piece = r.fabric.loops[yarn[start]].piece;
      if (std::find(used.begin(), used.end(), piece) != used.end()) continue;
      std::string why;
      std::size_t reached = 0;
      if (m.match(carrier, start, why, reached)) {
        used.push_back(piece);
        match.found = true;
        match.carrier = carrier;
        match.start = start;
        return match;
      }
      if (reached >= best) best = reached, match.why = why;
    }
  }
  if (match.why.empty()) {
    std::size_t most = 0;
    for (const auto& yarn : r.fabric.by_carrier) most = std::max(most, yarn.size());
    match.why = fmt::format(
        "no carrier makes enough loops: the input needs {} (one per stitch, two "
        "per increase), the busiest carrier makes {}",
        match.needed, most);
  }
  return match;
}

}  // namespace

ProofResult prove_fabric(const Replay& r, std::string_view text, const Compilation& c) {
  std::vector<CourseLayout> pieces = lay_out_pieces(c);
  ProofResult result;
  result.first_line = std::numeric_limits<std::size_t>::max();
  std::vector<std::uint32_t> used;
  std::vector<std::string> where;
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    std::string piece = pieces.size() > 1 ? fmt::format("yarn piece {}: ", i + 1) : "";
    PieceMatch m = find_piece(r, text, c, pieces[i], used);
    if (!m.found) {
      result.summary = fmt::format("NOT proven against {}: {}{}", c.input, piece, m.why);
      return result;
    }
    const auto& yarn = r.fabric.by_carrier[m.carrier];
    result.pieces.push_back({m.carrier, m.start, m.needed});
    result.first_line =
        std::min<std::size_t>(result.first_line, r.fabric.loops[yarn[m.start]].line);
    result.last_line =
        std::max<std::size_t>(result.last_line, r.fabric.loops[yarn[m.start + m.needed - 1]].line);
    where.push_back(fmt::format("{}carrier {} in yarn order after a border of {} loops",
                                pieces.size() > 1 ? fmt::format("piece {} with ", i + 1) : "with ",
                                r.header.carriers[m.carrier], m.start));
  }
  bool sheets =
      std::none_of(pieces.begin(), pieces.end(), [](const CourseLayout& l) { return l.tube; });
  result.proven = true;
  result.summary = fmt::format(
      "proven against {}: all {} stitches are there, knit {}, each pulled through the right "
      "loops{}",
      c.input, c.knit.size(), fmt::join(where, "; "), sheets ? " on the right bed" : "");
  return result;
}

}  // namespace skein::knitout
