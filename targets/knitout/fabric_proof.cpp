#include "knitout/fabric_proof.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <limits>
#include <optional>
#include <unordered_map>

#include "knitout/stitch_recipes.hpp"

namespace skein::knitout {
namespace {

// Fabric loops a stitch makes along its yarn (a bind-off's chain loop included; a slip none).
std::uint32_t fabric_loops(StitchType t) {
  return t == StitchType::sl ? 0 : std::max<std::uint32_t>(info(t).loops_out, 1);
}

// Whether a yarn piece of the input is a tube: some of its rows are closed rounds. Its back half
// is then knit on the back bed, seen from behind; a sheet is knit facing the front bed.
bool piece_is_tube(const KnitGraph& g, const std::vector<StitchId>& order) {
  return std::any_of(order.begin(), order.end(),
                     [&](StitchId s) { return g.row_shape[g.row[s]] == RowShape::closed; });
}

// A yarn piece's stitches in yarn order, from the knit graph alone.
std::vector<StitchId> yarn_order(const KnitGraph& g, const YarnPieces& yarns, std::uint32_t piece) {
  std::vector<StitchId> order;
  order.reserve(yarns.length[piece]);
  for (StitchId s = yarns.first[piece]; s != kNoStitch && order.size() < yarns.length[piece];
       s = g.yarn_next[s])
    order.push_back(s);
  return order;
}

class Matcher {
 public:
  // One matcher for all the pieces: a piece that takes another's loops finds them where the
  // other's match put them.
  Matcher(const Replay& r, std::string_view text, const Compilation& c)
      : f_(r.fabric), r_(r), text_(text), g_(c.knit) {
    loop_of_.assign(g_.loops.size(), kNoLoop);
    kept_.assign(g_.loops.size(), kNoKept);
    stamp_.assign(f_.loops.size(), 0);
    wrap_taker_.assign(f_.loops.size(), kNoStitch);
    wrap_stamp_.assign(f_.loops.size(), 0);
    turned_.assign(f_.loops.size(), 0);
    for (StitchId s = 0; s < g_.size(); ++s) {
      std::uint32_t row = g_.row[s];
      if (row >= latest_taken_row_.size()) latest_taken_row_.resize(row + 1, 0);
      for (std::uint32_t loop : g_.loops_taken_by(s))
        if (StitchId maker = g_.loops[loop].maker; maker != kNoStitch)
          latest_taken_row_[row] = std::max(latest_taken_row_[row], g_.row[maker]);
    }
  }
  void begin_piece(const std::vector<StitchId>& order) {
    order_ = &order;
    tube_ = piece_is_tube(g_, order);
    half_row_ = kNoRow;
  }
  bool tube() const { return tube_; }
  const std::vector<LoopId>& wraps() const { return wraps_; }

  // Tries the stitches against carrier `carrier`'s loops from index `start` on; on success
  // `end` is the index past the piece's last loop; on failure returns false with `why` set and
  // `reached` the number of stitches that matched.
  bool match(std::size_t carrier, std::size_t start, std::string& why, std::size_t& reached,
             std::size_t& end) {
    ++try_;
    half_row_ = kNoRow;
    wraps_.clear();
    turners_.clear();
    last_guess_ = kNoLoop;
    const std::vector<LoopId>& yarn = f_.by_carrier[carrier];
    CarrierMask mask = CarrierMask{1} << carrier;
    std::size_t pos = start;
    LoopId previous_bo = kNoLoop;
    reached = 0;
    for (StitchId s : *order_) {
      StitchType t = g_.type[s];
      std::uint32_t n = fabric_loops(t);
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
      if (previous_bo != kNoLoop && !chained_off(t) && !chain_let_go(s, previous_bo, why))
        return false;
      if (!stitch_matches(s, t, &yarn[pos], previous_bo, why)) return false;
      if (!stays_on_its_half(s, t, yarn[pos], why)) return false;
      for (std::uint32_t i = 0; i < n; ++i) stamp_[yarn[pos + i]] = try_;
      previous_bo = chained_off(t) ? yarn[pos] : kNoLoop;
      pos += n;
      if (pos < yarn.size() && takes_wrap(s, yarn[pos])) {
        stamp_[yarn[pos]] = wrap_stamp_[yarn[pos]] = try_;
        wrap_taker_[yarn[pos]] = kNoStitch;
        wraps_.push_back(yarn[pos++]);
        turners_.push_back(s);
      }
      ++reached;
    }
    end = pos;
    return yarn_ends_with_piece(carrier, end, why) && children_match(why) && wraps_taken(why);
  }

 private:
  // A short row's turn: the yarn tucks over a waiting loop's needle before it turns (or over
  // the turning st's own loop on the way back), so that the turn leaves no hole; the st that
  // takes that loop is knit through the tuck too. Seen in the fabric: after a st whose yarn
  // turns, a tuck through nothing. When the next st that makes a loop could make such a tuck
  // itself (a tuck, yarn-over, make-1), the first guess is a wrap when the tuck goes against
  // that st's course; a try that fails after a guess is made again with the guess turned.
  enum class Wrap : std::uint8_t { no, yes, maybe };
  Wrap wrap_after(StitchId s, LoopId x) const {
    const FabricLoop& fl = f_.loops[x];
    if (g_.yarn_link[s] != YarnLink::turn || fl.made_by != OpCode::tuck || fl.parent_count != 0)
      return Wrap::no;
    StitchId next = g_.yarn_next[s];
    while (next != kNoStitch && fabric_loops(g_.type[next]) == 0) next = g_.yarn_next[next];
    if (next == kNoStitch || g_.type[next] == StitchType::co) return Wrap::no;
    StitchType t = g_.type[next];
    if (t != StitchType::tuck && t != StitchType::yo && t != StitchType::m1l &&
        t != StitchType::m1r)
      return Wrap::yes;
    return Wrap::maybe;
  }
  bool guess_wrap(StitchId s, LoopId x) const {
    StitchId next = g_.yarn_next[s];
    while (fabric_loops(g_.type[next]) == 0) next = g_.yarn_next[next];
    StitchType t = g_.type[next];
    bool ltr = left_to_right(next, t, x);
    return (f_.loops[x].dir == Direction::plus) != (ltr != back_half(t, x));
  }
  bool takes_wrap(StitchId s, LoopId x) {
    Wrap w = wrap_after(s, x);
    if (w != Wrap::maybe) return w == Wrap::yes;
    last_guess_ = x;
    return guess_wrap(s, x) != (turned_[x] == guesses_);
  }

 public:
  // After a failed try: turns the last guess it made (false when it made none or turned it).
  bool turn_last_guess() {
    if (last_guess_ == kNoLoop || turned_[last_guess_] == guesses_) return false;
    turned_[last_guess_] = guesses_;
    return true;
  }
  // A new start: no guess turned.
  void forget_guesses() { ++guesses_; }

 private:
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
  bool is_wrap(LoopId x) const { return wrap_stamp_[x] == try_; }
  // A piece whose yarn ends on live loops (another yarn knits on from them, as the course that
  // joins two flaps) ends its yarn there: the carrier's next loops of the same piece of yarn are
  // not pulled through the piece's loops. (Otherwise a flap could be matched where another yarn
  // knits a flap of the same size and then goes on.)
  bool yarn_ends_with_piece(std::size_t carrier, std::size_t end, std::string& why) const {
    const std::vector<LoopId>& yarn = f_.by_carrier[carrier];
    StitchId last = order_->back();
    if (chained_off(g_.type[last]) || end == 0) return true;  // a tag follows a bind-off
    std::uint32_t piece = f_.loops[yarn[end - 1]].piece;
    for (std::size_t i = end; i < yarn.size() && f_.loops[yarn[i]].piece == piece; ++i)
      for (LoopId parent : f_.parents_of(yarn[i]))
        if (stamp_[parent] == try_) {
          why = fmt::format("the yarn of {} goes on after it: {} is pulled through its loops",
                            g_.describe(last), where(yarn[i]));
          return false;
        }
    return true;
  }
  // Each turn's tuck is pulled through by one st (twice by a kfb), which takes a loop too, in a
  // row that knits across the turn: one that takes loops made at or after it. Beside a slit (a
  // sheet parted into flaps) the row taking the other flap's loop takes none: a tuck there
  // would join the flaps.
  bool wraps_taken(std::string& why) const {
    for (std::size_t i = 0; i < wraps_.size(); ++i) {
      LoopId x = wraps_[i];
      StitchId taker = wrap_taker_[x];
      if (taker != kNoStitch && latest_taken_row_[g_.row[taker]] < g_.row[turners_[i]]) {
        why = fmt::format(
            "the turn's tuck {} after {} joins what the model leaves apart: {}, pulled through "
            "it, is in a row that takes no loop made since the turn",
            where(x), g_.describe(turners_[i]), g_.describe(taker));
        return false;
      }
      std::uint8_t want = taker != kNoStitch && g_.type[taker] == StitchType::kfb ? 2 : 1;
      if (taker == kNoStitch || f_.loops[x].children != want) {
        why = fmt::format("the turn's tuck {} is pulled through {} times, expected {} by {}",
                          where(x), f_.loops[x].children, want,
                          taker == kNoStitch ? "a st of the piece" : g_.describe(taker));
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

  // The loops `x` is pulled through are `expected`, and perhaps turns' tucks (which `s` claims).
  bool parents_are(LoopId x, std::vector<LoopId> expected, StitchId s, std::string& why) {
    std::vector<LoopId> have;
    for (LoopId parent : f_.parents_of(x)) {
      if (!is_wrap(parent)) {
        have.push_back(parent);
      } else if (wrap_taker_[parent] == kNoStitch || wrap_taker_[parent] == s) {
        wrap_taker_[parent] = s;
      } else {
        why = fmt::format("the turn's tuck {} is pulled through by {} and by {}", where(parent),
                          g_.describe(wrap_taker_[parent]), g_.describe(s));
        return false;
      }
    }
    std::vector<LoopId> want = expected;
    std::sort(have.begin(), have.end());
    std::sort(want.begin(), want.end());
    if (have == want) return true;
    why = fmt::format("{} is not there: {} makes its loop {}, expected {}", g_.describe(s),
                      where(x), describe_parents(x), describe_expected(expected));
    return false;
  }

  // The fabric loops a stitch must be pulled through: the loops it takes, with the loops tucks
  // kept under them (a turn's tuck, which it may be pulled through too, aside).
  std::vector<LoopId> through_of(StitchId s) const {
    std::vector<LoopId> through;
    for (std::uint32_t loop : g_.loops_taken_by(s))
      for (std::uint32_t l = loop; l != kNoKept; l = kept_[l]) through.push_back(loop_of_[l]);
    return through;
  }

  // A decrease's top loop (the last pulled through, wraps aside) is the one its lean puts there.
  bool leans_right(StitchId s, StitchType t, LoopId x, std::string& why) const {
    auto parents = f_.parents_of(x);
    auto on_top =
        std::find_if(parents.rbegin(), parents.rend(), [&](LoopId p) { return !is_wrap(p); });
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
    } else if (chained_off(t)) {
      if (previous_bo != kNoLoop) through.push_back(previous_bo);
      return parents_are(loops[0], through, s, why) && travels_along_course(s, t, loops, 1, why);
    } else if (made.size() == 2) {
      bool ltr = left_to_right(s, t, loops[0]);
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
    if (!tube_ && !made.empty() && f_.loops[loops[0]].front == is_purl(t)) {
      why = fmt::format("{} is a {} but {} knits it on the {} bed", g_.describe(s), info(t).name,
                        where(loops[0]), is_purl(t) ? "front" : "back");
      return false;
    }
    if (!travels_along_course(s, t, loops, std::max<std::size_t>(made.size(), 1), why))
      return false;
    for (std::size_t i = 0; i < made.size(); ++i)
      loop_of_[made[made_slot_along_yarn(t, left_to_right(s, t, loops[0]),
                                         static_cast<std::uint8_t>(i),
                                         static_cast<std::uint8_t>(made.size()))]] = loops[i];
    return true;
  }

  // A round of a tube goes once along each half: its plain sts are on one half, then on the
  // other (then back on the first, where it began partway along it). A knit made on the other
  // bed (a purl seen from the right side, and the reverse) would break in with a third change.
  bool stays_on_its_half(StitchId s, StitchType t, LoopId first, std::string& why) {
    if (!tube_ || (t != StitchType::k && t != StitchType::p)) return true;
    std::uint32_t row = g_.row[s];
    bool back = back_half(t, first);
    if (row != half_row_) {
      half_row_ = row;
      half_changes_ = 0;
    } else if (back != half_back_ && g_.row_shape[row] == RowShape::closed && ++half_changes_ > 2) {
      why = fmt::format(
          "{} is a {} on the {} half of its round, between sts of the {} half: {} is "
          "made on the other bed (a {} seen from the right side)",
          g_.describe(s), info(t).name, back ? "back" : "front", back ? "front" : "back",
          where(first), t == StitchType::k ? "purl" : "knit");
      return false;
    }
    half_back_ = back;
    return true;
  }

  // Whether the st's half of a tube is the back: the bed it is made on, the other for a purl.
  bool back_half(StitchType t, LoopId first) const {
    return tube_ && f_.loops[first].front == is_purl(t);
  }

  // Which way the yarn runs through the st in its own frame: as the input says; a st the input
  // orders by its loops (one extruded along a join or split) as the fabric shows it.
  bool left_to_right(StitchId s, StitchType t, LoopId first) const {
    CourseDirection d = g_.direction[s];
    if (d != CourseDirection::along_its_loops) return d == CourseDirection::left_to_right;
    bool rightward = f_.loops[first].dir == Direction::plus;
    return rightward != back_half(t, first);  // the first loop: an sr5 turns after it
  }

  // The yarn runs through each st the way the input says, seen from the right side: on a
  // sheet's front bed (a purl's back bed) left to right is rightward; a tube's back half is seen
  // from behind, so there left to right is leftward. An sr5's second loop is made on the way
  // back, after the turn. A loop made against its course leaves a float where the carrier turns.
  bool travels_along_course(StitchId s, StitchType t, const LoopId* loops, std::size_t n,
                            std::string& why) const {
    bool ltr = left_to_right(s, t, loops[0]), back = back_half(t, loops[0]);
    for (std::size_t i = 0; i < n; ++i) {
      const FabricLoop& fl = f_.loops[loops[i]];
      bool turned = t == StitchType::sr5 && i == 1;
      bool rightward = fl.dir == Direction::plus;
      if ((ltr != turned) != (rightward != back)) {
        why = fmt::format("{} is knit against the direction of its row ({}): {} goes {}",
                          g_.describe(s), course_direction_name(g_.direction[s]), where(loops[i]),
                          direction_char(fl.dir));
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
    for (StitchId s : *order_)
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
  const std::vector<StitchId>* order_ = nullptr;  // the piece's sts in yarn order
  bool tube_ = false;
  static constexpr std::uint32_t kNoRow = 0xffffffffu;
  std::uint32_t half_row_ = kNoRow;  // the row of the last plain st, its half, and the changes
  bool half_back_ = false;           // of half along that row so far
  std::uint32_t half_changes_ = 0;
  std::vector<LoopId> loop_of_;  // per knit graph loop: its fabric loop
  static constexpr std::uint32_t kNoKept = 0xffffffffu;
  std::vector<std::uint32_t> kept_;        // per knit graph loop: the loop a tuck kept under it
  std::vector<std::uint32_t> stamp_;       // per fabric loop: the try that matched it
  std::vector<std::uint32_t> wrap_stamp_;  // per fabric loop: the try that took it for a wrap
  std::vector<StitchId> wrap_taker_;       // per fabric loop (a wrap): the st pulled through it
  std::vector<LoopId> wraps_;              // the turns' tucks of this try
  std::vector<StitchId> turners_;          // per wrap: the st whose yarn turns before it
  std::vector<std::uint32_t> latest_taken_row_;  // per row: the latest row whose loops it takes
  std::vector<std::uint32_t> turned_;  // per fabric loop: `guesses_` when its guess is turned
  std::uint32_t guesses_ = 1;
  LoopId last_guess_ = kNoLoop;  // the last tuck of this try guessed a wrap or not
  std::uint32_t try_ = 0;
};

// Where one piece was found: along which carrier, after how many border loops.
struct PieceMatch {
  bool found = false;
  std::size_t carrier = 0, start = 0, needed = 0;
  std::vector<std::uint32_t> wrap_lines;
  std::string why;  // when not found: the first difference of the closest try
};

// Looks for the piece along every carrier's yarn, in a yarn piece no other piece matched; after
// `after` (an earlier match of it) when given.
PieceMatch find_piece(const Replay& r, const Compilation& c, const std::vector<StitchId>& order,
                      Matcher& m, std::vector<std::uint32_t>& used, const PieceMatch* after) {
  PieceMatch match;
  std::size_t least = 0;  // the piece's loops, the turns' tucks aside
  for (StitchId s : order) least += fabric_loops(c.knit.type[s]);
  m.begin_piece(order);
  std::size_t best = 0;
  for (std::size_t carrier = after ? after->carrier : 0; carrier < r.fabric.by_carrier.size();
       ++carrier) {
    const auto& yarn = r.fabric.by_carrier[carrier];
    std::size_t first = after && carrier == after->carrier ? after->start + 1 : 0;
    for (std::size_t start = first; start + least <= yarn.size(); ++start) {
      std::uint32_t piece = r.fabric.loops[yarn[start]].piece;
      if (std::find(used.begin(), used.end(), piece) != used.end()) continue;
      std::string why;
      std::size_t reached = 0, end = 0;
      m.forget_guesses();
      bool matched = m.match(carrier, start, why, reached, end);
      while (!matched && m.turn_last_guess()) matched = m.match(carrier, start, why, reached, end);
      if (matched) {
        used.push_back(piece);
        match.found = true;
        match.carrier = carrier;
        match.start = start;
        match.needed = end - start;
        for (LoopId x : m.wraps()) match.wrap_lines.push_back(r.fabric.loops[x].line);
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
        least, most);
  }
  return match;
}

}  // namespace

// The yarn pieces, each after those whose loops it takes (a leg knit on after a leg); pieces
// that take each other's loops keep their order.
std::vector<std::uint32_t> pieces_in_knitting_order(const KnitGraph& g, const YarnPieces& yarns) {
  std::vector<std::vector<std::uint32_t>> takes_from(yarns.size());
  for (const Loop& l : g.loops) {
    if (l.maker == kNoStitch || l.taker == kNoStitch) continue;
    std::uint32_t maker = yarns.piece_of[l.maker], taker = yarns.piece_of[l.taker];
    if (maker != taker) takes_from[taker].push_back(maker);
  }
  std::vector<std::uint32_t> order;
  std::vector<std::uint8_t> state(yarns.size(), 0);  // 0 new, 1 on the way, 2 placed
  auto place = [&](auto& self, std::uint32_t piece) -> void {
    if (state[piece]) return;
    state[piece] = 1;
    for (std::uint32_t other : takes_from[piece]) self(self, other);
    state[piece] = 2;
    order.push_back(piece);
  };
  for (std::uint32_t piece = 0; piece < yarns.size(); ++piece) place(place, piece);
  return order;
}

// Each piece in knitting order, where its loops are; when a piece is not found, an earlier one
// is looked for further on (two flaps of one size, a flap the size of the waste section: the
// first place an earlier piece matched may be where a later one is knit). Within a bound: the
// first failure is reported once it is reached.
std::optional<std::vector<PieceMatch>> match_pieces(const Replay& r, std::string_view text,
                                                    const Compilation& c,
                                                    const std::vector<std::uint32_t>& pieces,
                                                    std::string& why) {
  constexpr int kMaxRetries = 64;
  std::vector<std::vector<StitchId>> orders;
  for (std::uint32_t i : pieces) orders.push_back(yarn_order(c.knit, c.yarns, i));
  Matcher matcher(r, text, c);
  std::vector<std::uint32_t> used;
  std::vector<PieceMatch> found;
  bool resume = false;
  int retries = 0;
  for (std::size_t k = 0; k < pieces.size();) {
    PieceMatch m = find_piece(r, c, orders[k], matcher, used, resume ? &found[k] : nullptr);
    found.resize(k);
    if (m.found) {
      found.push_back(std::move(m));
      ++k;
      resume = false;
      continue;
    }
    if (why.empty())
      why = fmt::format(
          "{}{}", c.yarns.size() > 1 ? fmt::format("yarn piece {}: ", pieces[k] + 1) : "", m.why);
    if (k == 0 || ++retries > kMaxRetries) return std::nullopt;
    --k;
    used.pop_back();
    resume = true;
  }
  return found;
}

ProofResult prove_fabric(const Replay& r, std::string_view text, const Compilation& c) {
  const YarnPieces& yarns = c.yarns;
  ProofResult result;
  result.first_line = std::numeric_limits<std::size_t>::max();
  std::vector<std::string> where;
  bool sheets = true;
  std::vector<std::uint32_t> pieces = pieces_in_knitting_order(c.knit, yarns);
  std::string why;
  std::optional<std::vector<PieceMatch>> found = match_pieces(r, text, c, pieces, why);
  if (!found) {
    result.summary = fmt::format("NOT proven against {}: {}", c.input, why);
    return result;
  }
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    const PieceMatch& m = (*found)[k];
    std::uint32_t i = pieces[k];
    sheets &= !piece_is_tube(c.knit, yarn_order(c.knit, yarns, i));
    const auto& yarn = r.fabric.by_carrier[m.carrier];
    result.pieces.push_back({m.carrier, m.start, m.needed});
    result.wrap_lines.insert(result.wrap_lines.end(), m.wrap_lines.begin(), m.wrap_lines.end());
    result.first_line =
        std::min<std::size_t>(result.first_line, r.fabric.loops[yarn[m.start]].line);
    result.last_line =
        std::max<std::size_t>(result.last_line, r.fabric.loops[yarn[m.start + m.needed - 1]].line);
    where.push_back(fmt::format("{}carrier {} in yarn order after a border of {} loops",
                                yarns.size() > 1 ? fmt::format("piece {} with ", i + 1) : "with ",
                                r.header.carriers[m.carrier], m.start));
  }
  result.proven = true;
  result.summary = fmt::format(
      "proven against {}: all {} stitches are there, knit {}, each pulled through the right "
      "loops{}",
      c.input, c.knit.size(), fmt::join(where, "; "), sheets ? " on the right bed" : "");
  return result;
}

}  // namespace skein::knitout
