// The front matter of a pattern document: what the whole pattern needs (measurements, yarn,
// needles, gauge) and which abbreviations and techniques it uses.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "hand/pattern_wording.hpp"

namespace skein::hand::document {
namespace {

constexpr double kCircularNeedleCm = 40;  // the shortest common circular needle

std::string cm_and_inches(double cm) {
  return fmt::format("{:.0f} cm ({:.1f} in)", cm, cm / 2.54);
}

// What the front matter needs to know about the whole pattern.
struct Totals {
  bool flat = false, round = false, joins = false;
  bool partial_bind_off = false;   // a row binds off some of its sts
  bool spare_needles = false;      // a piece waits on one
  bool second_spare = false;       // rows take sts from two spare needles at once
  bool provisional = false;        // a provisional cast-on
  bool picks_up = false;           // a piece starts on loops picked up along an edge
  bool picks_up_into_rnd = false;  // loops picked up along an edge go into a rnd
  bool joins_flat_piece = false;   // a flat piece is joined in the rnd in the middle of its work
  bool casts_on_aside = false;     // a yarn that has worked casts on sts onto a holder
  std::uint32_t holders = 0;
  std::uint32_t widest = 0, narrowest_round = 0;
  std::vector<bool> used = std::vector<bool>(kHandOpCount, false);
};

Totals totals_of(const HandPattern& p) {
  Totals t;
  t.narrowest_round = ~0u;
  for (const PatternSection& s : p.sections) {
    t.joins = t.joins || s.joins;
    t.spare_needles = t.spare_needles || s.left_live || s.provisional || !s.holdings.empty();
    t.provisional = t.provisional || s.provisional || s.row_chain > 0;
    for (const PatternSection::Placement& placed : s.placements) {
      t.picks_up_into_rnd = t.picks_up_into_rnd || placed.edge.has_value();
      t.second_spare = t.second_spare || placed.second_spare;
    }
    t.picks_up = t.picks_up || s.picks_up.has_value();
    for (const PatternSection::Holding& h : s.holdings) t.holders = std::max(t.holders, h.holder);
    for (const PatternSection::CastOnAside& c : s.casts_on_aside) {
      t.holders = std::max(t.holders, c.holder);
      t.provisional = t.provisional || c.provisional;
      t.casts_on_aside = true;
    }
    if (s.joins) continue;
    (s.in_round ? t.round : t.flat) = true;
    t.flat = t.flat || s.joined_in_rnd_at;
    t.joins_flat_piece = t.joins_flat_piece || s.joined_in_rnd_at;
    t.widest = std::max(t.widest, s.cast_on);
    if (s.in_round) t.narrowest_round = std::min(t.narrowest_round, s.cast_on);
  }
  for (const PatternRow& r : p.rows) {
    auto ops = p.ops_of(r);
    t.partial_bind_off = t.partial_bind_off || (!r.bind_off && std::find(ops.begin(), ops.end(),
                                                                         HandOp::bo) != ops.end());
    t.widest = std::max(t.widest, r.sts_after);
    if (r.round && !r.bind_off) t.narrowest_round = std::min(t.narrowest_round, r.sts_after);
  }
  for (HandOp op : p.ops) t.used[static_cast<std::size_t>(op)] = true;
  return t;
}

class FrontMatter {
 public:
  FrontMatter(const HandPattern& p, const Gauge& gauge, const std::vector<InstructionLine>& lines)
      : p_(p), gauge_(gauge), t_(totals_of(p)) {
    for (const InstructionLine& l : lines) text_ += l.label + " " + l.text + "\n";
  }

  std::vector<FrontSection> sections() const {
    return {{"Finished measurements", measurements()},
            {"Yarn", yarn()},
            {"Needles and notions", needles()},
            {"Gauge", {gauge_text()}},
            {"Abbreviations", abbreviations()},
            {"Techniques", techniques()},
            {"Notes", notes()}};
  }

 private:
  double width_cm(std::uint32_t sts) const { return sts * 10.0 / gauge_.sts_per_10cm; }
  double length_cm(std::uint32_t rows) const { return rows * 10.0 / gauge_.rows_per_10cm; }

  std::vector<std::string> measurements() const {
    std::vector<std::string> items;
    for (const PatternSection& s : p_.sections) {
      if (s.joins || (s.resumed && s.first_row == s.end_row)) continue;  // nothing to measure
      std::uint32_t widest = s.cast_on, rows = 0, short_rows = 0, rnds = 0;
      for (std::uint32_t r = s.first_row; r < s.end_row; ++r) {
        widest = std::max(widest, p_.rows[r].sts_after);
        ++(p_.rows[r].partial ? short_rows : rows);
        rnds += !p_.rows[r].partial && p_.rows[r].round;
      }
      std::string piece = p_.sections.size() > 1 ? fmt::format("{}{}: ", piece_name(p_, s.piece),
                                                               s.resumed ? " (taken up again)" : "")
                                                 : "";
      std::string width = fmt::format("{}{}: {}, {} sts at the widest.", piece,
                                      s.in_round ? "Circumference" : "Width",
                                      cm_and_inches(width_cm(widest)), widest);
      const char* unit = rnds == 0 ? "rows" : rnds == rows ? "rnds" : "rows and rnds";
      items.push_back(width + " " + height(s, rows, short_rows, s.in_round ? unit : "rows"));
    }
    return items;
  }

  // Short rows add length to part of the piece only; a piece of a cast-on alone (along a
  // split) has no height.
  std::string height(const PatternSection& s, std::uint32_t rows, std::uint32_t short_rows,
                     const char* unit) const {
    if (rows == 0 && short_rows == 0) return "A cast-on only: no rows of its own.";
    if (rows == 0)
      return fmt::format("{} short rows (worked on part of the sts), no whole {}.", short_rows,
                         s.in_round ? "rnds" : "rows");
    std::string extra = short_rows ? fmt::format(", plus {} short rows", short_rows) : "";
    return fmt::format("{}: {}, {} {}{}.", s.in_round ? "Height" : "Length",
                       cm_and_inches(length_cm(rows)), rows, unit, extra);
  }

  // "9 stitch holders (or lengths of waste yarn), numbered 1 to 9", or one.
  static std::string holders_text(std::uint32_t holders) {
    if (holders == 1) return "1 stitch holder (or a length of waste yarn).";
    return fmt::format("{} stitch holders (or lengths of waste yarn), numbered 1 to {}.", holders,
                       holders);
  }

  // One line per yarn piece; a piece taken up again goes on with the same yarn.
  std::vector<std::string> yarn() const {
    std::vector<std::uint64_t> stitches(p_.sections.size() + 1, 0);
    for (const PatternSection& s : p_.sections) stitches[s.piece] += s.stitches;
    std::vector<std::string> items;
    for (const PatternSection& s : p_.sections) {
      if (s.resumed) continue;
      double metres = std::ceil(stitches[s.piece] * gauge_.yarn_cm_per_stitch() / 100 + 0.4);
      items.push_back(fmt::format(
          "{}About {:.0f} m ({:.0f} yd) of {}-weight yarn, estimated from its {} sts at the "
          "gauge below, with 20 cm tails at each end.",
          p_.sections.size() > 1
              ? fmt::format("{} (yarn {}): ", piece_name(p_, s.piece), s.yarn + 1)
              : "",
          metres, std::ceil(metres / 0.9144), weight_text(), with_commas(stitches[s.piece])));
    }
    return items;
  }

  std::vector<std::string> needles() const {
    std::vector<std::string> items;
    if (t_.flat)
      items.push_back(needle_text() +
                      " needles: straight, or a circular needle worked back and forth.");
    if (t_.round) {
      auto fits = static_cast<std::uint32_t>(kCircularNeedleCm * gauge_.sts_per_10cm / 10);
      if (t_.widest >= fits)
        items.push_back(
            fmt::format("{} circular needle, 40 cm (16 in) long, for rounds of {} sts or more.",
                        needle_text(), fits));
      if (t_.narrowest_round < fits)
        items.push_back(
            fmt::format("{} double-pointed needles, or a long circular needle for magic loop, "
                        "for rounds of fewer than {} sts.",
                        needle_text(), fits));
    }
    if (p_.markers == 1)
      items.push_back(t_.round ? "1 stitch marker for the beginning of the round."
                               : "1 stitch marker.");
    else if (p_.markers > 1)
      items.push_back(fmt::format("{} stitch markers{}.", p_.markers,
                                  t_.round ? ", one of them in another colour for the beginning "
                                             "of the round"
                                           : ""));
    if (t_.spare_needles)
      items.push_back("A spare needle (or stitch holder) for each piece left to wait on one.");
    if (t_.second_spare)
      items.push_back("A second spare needle, for rows that take sts from two at once.");
    if (t_.holders > 0) items.push_back(holders_text(t_.holders));
    if (t_.joins) items.push_back("A third needle for the three-needle bind-off.");
    items.push_back("Tapestry needle for weaving in ends.");
    return items;
  }

  std::string gauge_text() const {
    std::string gauge = fmt::format(
        "{} sts and {} rows = 10 cm (4 in) in stockinette stitch with {}-weight yarn on {} needles",
        decimal(gauge_.sts_per_10cm), decimal(gauge_.rows_per_10cm), weight_text(), needle_text());
    return fmt::format(
        "{}{}. Knit a swatch and change needle size to match it.", gauge,
        gauge_.assumed ? ". The model does not say its gauge: the measurements and yarn amounts "
                         "assume this one, skein's default"
                       : ", the project's gauge: the measurements and yarn amounts assume it");
  }

  // "4.5 mm (US 7)": the US size where the metric size is a standard one.
  std::string needle_text() const {
    constexpr std::pair<double, const char*> kUsSizes[] = {
        {2, "0"},   {2.25, "1"},   {2.75, "2"}, {3.25, "3"}, {3.5, "4"},    {3.75, "5"}, {4, "6"},
        {4.5, "7"}, {5, "8"},      {5.5, "9"},  {6, "10"},   {6.5, "10.5"}, {8, "11"},   {9, "13"},
        {10, "15"}, {12.75, "17"}, {15, "19"},  {19, "35"},  {25, "50"}};
    for (auto [mm, us] : kUsSizes)
      if (std::abs(gauge_.needle_mm - mm) < 0.01)
        return fmt::format("{} mm (US {})", decimal(mm), us);
    return fmt::format("{} mm", decimal(gauge_.needle_mm));
  }

  // "DK", "super bulky": as a yarn label writes the weight.
  std::string weight_text() const {
    if (gauge_.yarn_weight == "dk") return "DK";
    std::string text = gauge_.yarn_weight;
    std::replace(text.begin(), text.end(), '-', ' ');
    return text;
  }

  // 22 -> "22", 22.5 -> "22.5", 2.75 -> "2.75": to a hundredth, no trailing zeros.
  static std::string decimal(double value) {
    std::string text = fmt::format("{:.2f}", value);
    while (text.back() == '0') text.pop_back();
    if (text.back() == '.') text.pop_back();
    return text;
  }

  bool uses(HandOp op) const { return t_.used[static_cast<std::size_t>(op)]; }

  // The first instruction sentence that starts with `start`, without its count and period.
  std::string first_sentence(std::string_view start) const {
    std::size_t at = text_.find(start);
    if (at == std::string::npos) return "";
    std::size_t end = std::min(text_.find(".", at), text_.find(kDash, at) - 1);
    return text_.substr(at, end - at);
  }
  bool says(std::string_view words) const { return text_.find(words) != std::string::npos; }

  // A tube parted into legs: the sts of one leg gathered on a holder from two rnds, then worked
  // in the rnd with a new yarn or the yarn carried on from the other leg.
  std::string held_sts_in_the_rnd_technique() const {
    std::string text;
    if (std::any_of(p_.sections.begin(), p_.sections.end(), parted_between_pieces))
      text +=
          " \"Slip sts 1\u20138 of Row 57 to holder 7, ...\" parts the sts a row left on the "
          "needle between the pieces that work them: it counts them in the order the row "
          "worked them, the first st worked being st 1.";
    if (says(" sts of the row, the "))
      text +=
          " On a flat piece \"after the first 7 sts of the row\" counts the sts the next row "
          "works first, from the tip of the needle that holds them (the last st just worked is "
          "st 1): slide the placed sts onto that needle after them, the st named first next to "
          "them, so that the row goes on into them.";
    if (says(" on it)"))
      text +=
          " \"(after the 1 st on it)\" slips the sts onto the holder after those it already "
          "holds, so they wait in the order they are worked.";
    if (says("slipped to it at the tip. Pm and join"))
      text +=
          " To work a holder's sts in the rnd, slide them onto the needle(s) with the st "
          "named at the tip of the left needle, place the BOR marker and work that st first.";
    if (says("; the rnd begins at its st "))
      text +=
          " \"The rnd begins at its st 6\": count the holder's sts in the order they were "
          "slipped to it; slide them round the needle(s), keeping that order, until st 6 is at "
          "the tip of the left needle (the sts before it come after the other end), place the "
          "BOR marker and work st 6 first.";
    if (says("Do not fasten off: carry the yarn"))
      text +=
          " \"Do not fasten off: carry the yarn to\" them: after binding off, pull the yarn "
          "through the last loop without cutting it and work the held sts with it, leaving a "
          "strand from the bind-off to the first of them.";
    return text;
  }

  std::vector<std::string> abbreviations() const {
    std::vector<std::string> items;
    for (auto op = HandOp::k; op <= HandOp::slip_back;
         op = static_cast<HandOp>(static_cast<int>(op) + 1))
      if (uses(op) || (op == HandOp::pm && says("Pm "))) {
        // Ops written alike (the cast-ons in a row, "CO N sts with a ...") are listed once.
        std::string item = fmt::format("**{}**: {}", info(op).abbreviation, info(op).meaning);
        if (std::find(items.begin(), items.end(), item) == items.end()) items.push_back(item);
      }
    auto word = [&](bool used, const char* abbr, const char* meaning) {
      if (used) items.push_back(fmt::format("**{}**: {}", abbr, meaning));
    };
    word(t_.round, "BOR", "beginning of round");
    word(says(" m,") || says(" m.") || says(" m "), "m", "marker");
    word(says("rep") || says("Rep "), "rep", "repeat");
    word(says("Rnd"), "rnd(s)", "round(s)");
    word(says("(RS)") || says("(WS)"), "RS / WS", "right side / wrong side of the work");
    word(true, "st(s)", "stitch(es)");
    return items;
  }

  std::vector<std::string> techniques() const {
    std::vector<std::string> items = {fmt::format(
        "**Cast on** with the long-tail method (any cast-on that makes one loop per stitch will "
        "do). The cast-on is not counted: {} is the first worked after it.",
        t_.flat && t_.round ? "Row 1 (or Rnd 1)"
        : t_.flat           ? "Row 1"
                            : "Rnd 1")};
    if (t_.flat)
      items.push_back(
          "**Working flat:** at the end of every row, turn the work; the next row "
          "starts with the last stitch just worked.");
    if (t_.round)
      items.push_back(
          "**Joining in the round:** spread the cast-on stitches around the needle(s) "
          "with the cast-on edge untwisted, place the BOR marker and knit the first "
          "cast-on stitch with the working yarn. The marker then sits at the start of "
          "every round: slip it as you come to it.");
    if (p_.ws_rounds)
      items.push_back(
          "**Rounds worked with the WS facing** (\"Rnd 30 (WS)\"): the tube is worked inside "
          "out, around in the usual direction with the WS facing you (the wrong side of the "
          "piece shows outside); a st that shows as a knit on the RS is purled. When such rnds "
          "follow rows that end with the WS facing, go on around without turning.");
    if (p_.short_rows) items.push_back(short_rows_technique());
    if (t_.provisional)
      items.push_back(
          "**Provisional cast-on** (a cast-on along a split): with waste yarn crochet a chain a "
          "few sts longer than needed; with the working yarn pick up and knit 1 st through the "
          "back bump of each chain st. The sts on the needle are one side of the split; where "
          "the pattern works \"the loops of its chain\", unzip the waste yarn and put the live "
          "loops on a needle: they are the other side. In the middle of a row (\"CO 3 sts with "
          "a provisional cast-on\") pick up and knit the sts through the chain onto the right "
          "needle and go on with the row.");
    if (t_.casts_on_aside)
      items.push_back(
          "**Casting on with the working yarn** (\"With the working yarn, cast on 4 sts with a "
          "provisional cast-on onto holder 5\"): leave the sts on the needle as they are, cast "
          "the new sts on (through the chain, for a provisional cast-on) onto a spare needle "
          "and let them wait there as the holder named, the first st cast on at one end; the "
          "yarn goes on from the last st cast on.");
    if (says("backward-loop cast-on"))
      items.push_back(
          "**Backward-loop cast-on** in the middle of a row (\"CO 12 sts with a backward-loop "
          "cast-on\", the sts of a gap): wrap the working yarn around your thumb, insert the "
          "right needle up through the loop on your thumb and tighten it on the needle; repeat "
          "for each st, then go on with the row.");
    if (t_.picks_up)
      items.push_back(
          "**Picking up along an edge:** with the RS facing and a new yarn, put the outer loop "
          "of the edge st of each row named onto the needle, one row after the other (the loops "
          "are not knit: the next row works them, starting with the last one picked up).");
    if (t_.picks_up_into_rnd)
      items.push_back(fmt::format(
          "**Picking up onto the needle of a rnd** (\"..., onto the needle after the first 18 sts "
          "of the rnd\"): with the {} facing and no new yarn, put the outer loop of the edge st "
          "of each row named on the needle at that place, one row after the other (the loops "
          "are not knit: the rnd works them in the order picked up).",
          p_.ws_rounds ? "side the rnd is worked from (the WS in a rnd labelled (WS))" : "RS"));
    if (t_.joins_flat_piece)
      items.push_back(
          "**Joining a flat piece in the round** (after rows worked flat): once the last row's "
          "sts are slipped to a holder, place the BOR marker where the yarn is, put the sts the "
          "pattern picks up and places next on the needle after it, in order, and work the next "
          "rnd over them (and any sts the rows left) with the yarn still attached at the end of "
          "the last row (after \"do not turn\", without turning the work): starting with the "
          "first st put on, it joins them into a tube.");
    if (t_.holders > 0)
      items.push_back(
          "**Holders:** \"Slip sts 10\u201318 of the rnd to holder 1\" counts the sts from the "
          "BOR marker, as they are before any is slipped, and moves them in order to holder 1; "
          "they wait there until the pattern places them on the needle, puts them on a spare "
          "needle (for \"sl1 from spare\") or binds them off. \"Place\" puts a holder's sts (a "
          "spare needle's, a chain's loops) on the needle where it says, the st it names "
          "first." +
          held_sts_in_the_rnd_technique());
    if (uses(HandOp::slip_back)) items.push_back(decreasing_across_a_gap_technique());
    if (t_.joins)
      items.push_back(
          "**Three-needle bind-off:** hold the two needles parallel, tips to the right; insert "
          "the third needle knitwise into the first st of the front needle and then the first st "
          "of the back needle, knit them together; *knit the next pair together the same way, "
          "pass the first st on the right needle over the second; rep from * until all pairs "
          "are worked; cut the yarn and pull it through the last loop.");
    if (uses(HandOp::tnbo))
      items.push_back(
          "**Three-needle bind-off in a row** (\"3-needle BO 3 sts\"): hold the spare needle "
          "named behind the left needle, parallel to it. *Knit the first st of the left needle "
          "together with the first st of the back needle; if there is a st before it on the "
          "right needle, pass that one over it; rep from * as many times as said. Work the next "
          "st as the pattern says and pass the last pair over it: it is the first st of what "
          "follows (as when binding off part of a row; where nothing follows, the pattern "
          "fastens off the last st). With more than one needle held, bind off from them in the "
          "order they were held.");
    if (uses(HandOp::bo))
      items.push_back(
          "**Binding off (BO):** work 2 sts as they appear, *pass the first st on the "
          "right needle over the second; work 1 more st; rep from * until 1 st "
          "remains, removing any markers as you come to them; cut the yarn and pull it "
          "through that last loop (fasten off).");
    if (t_.partial_bind_off)
      items.push_back(
          "**Binding off part of a row** (\"BO 8 sts, k40\"): bind off 8 sts as above without "
          "cutting the yarn; the st left on the right needle is the first st of what follows "
          "(the first of the 40).");
    return items;
  }

  // Like a heel turn: the rows of a narrow band take one st of the sts waiting beside it at
  // each end.
  static std::string decreasing_across_a_gap_technique() {
    return "**Decreasing across a gap** (as in turning a heel): a row that ends with a decrease "
           "works its last st together with the first st beyond it on the left needle (past the "
           "end of the left needle, around the needle's cable to the far end of the right one). "
           "A row that begins with \"sl1 back\" slips the st at the tip of the right needle (in "
           "the rnd, the last st before the gap) back to the left needle and works it together "
           "with the row's first st. A row that starts at the beginning of the rnd removes the "
           "BOR marker first (rm); the next rnd places it anew (pm), where the yarn is. Until "
           "then, sts \"of the rnd\" (to slip, place or pick up) count from there.";
  }

  // The method the project chose, and how its turns are resolved later.
  std::string short_rows_technique() const {
    if (uses(HandOp::sl1yo)) return tuck_turn_technique();
    if (p_.turns == TurnMethod::wrap_and_turn)
      return "**Short rows (wrap and turn):** a row that ends in w&t stops there: bring the yarn "
             "between the needles, slip the next st purlwise, take the yarn back between the "
             "needles, slip the st back to the left needle and turn the work; the next row starts "
             "with the st worked last. The sts beyond wait on the needle. When a later row comes "
             "to a wrapped st, lift the wrap onto the left needle and work it together with the "
             "st: kw to knit them, pw to purl them." +
             std::string(wraps_a_wrapped_st() ? wrapping_a_wrapped_st() : "");
    return "**Short rows (German short rows):** a row that ends in \"turn\" stops there: turn the "
           "work; the sts beyond wait on the needle. When the next row begins with DS, bring the "
           "yarn to the front, slip the first st (the one worked last) purlwise and pull the yarn "
           "up over the needle to the back until the st shows two legs: a double stitch. When a "
           "later row comes to a double stitch, work its two legs together as one st: k DS to "
           "knit them, p DS to purl them.";
  }

  bool wraps_a_wrapped_st() const {
    return std::ranges::any_of(p_.rows, [](const PatternRow& r) { return r.wraps_again; });
  }

  // Heel-turn patterns' double-wrapped st: wrapped again, resolved with both its wraps.
  static const char* wrapping_a_wrapped_st() {
    return " When w&t comes to a st that is already wrapped, wrap it again as it is (do not "
           "work its wrap): it now has two wraps. kw and pw lift all of a st's wraps and work "
           "them together with the st, as one st.";
  }

  // A stitch graph's short rows (AutoKnit's) turn on a tuck, whatever the project chose.
  static std::string tuck_turn_technique() {
    return "**Short rows (turned on a tuck):** a row that ends in \"sl1yo, turn\" stops there: "
           "with the yarn in front slip the next st purlwise, take the yarn over the needle to "
           "the back (the yo lies over the st, which is not worked) and turn the work; the sts "
           "beyond wait on the needle. The next row begins with sl1: slip that st and its yo "
           "purlwise as one. When a later row comes to it, work the st and its yo together as "
           "one st: brk on the RS, brp on the WS (a decrease takes them as one of its sts). The "
           "short rows go round past the beginning of the rnd: slip the marker as you come to "
           "it; where a row says rm, remove it, and the next rnd places it anew (pm) where it "
           "begins.";
  }

  std::vector<std::string> notes() const {
    std::vector<std::string> items;
    if (says(kDash))
      items.push_back(
          fmt::format("When a {} changes the number of stitches, the count on the "
                      "needle at its end follows the dash: {} 56 sts.",
                      t_.round ? (t_.flat ? "row or rnd" : "rnd") : "row", kDash));
    if (std::string rep = first_sentence("Rep "); !rep.empty())
      items.push_back(
          fmt::format("\"{}\" works those rows again that many more times after "
                      "the first (once more in all than the number says); a stitch "
                      "count after it is the count once all the repeats are done.",
                      rep));
    if (std::string even = first_sentence("Knit every "); !even.empty())
      items.push_back(
          fmt::format("\"{}\" counts every {} from the cast-on, those already "
                      "worked included.",
                      even, t_.round ? "rnd" : "row"));
    if (p_.short_rows && t_.round)
      items.push_back(
          "In the rnd, a row that ends with a turn is a short row: it is worked back and forth "
          "over part of the rnd while the other sts wait. A rnd after short rows starts where "
          "the last one ended and goes on to the BOR marker; the row and rnd numbers count "
          "both.");
    if (p_.markers > 1)
      items.push_back(t_.round ? "Slip the markers as you come to them. The beginning-of-round "
                                 "marker is the last \"m\" of every round: \"to m\" in the last "
                                 "section of a round goes up to it."
                               : "Slip the markers as you come to them.");
    if (uses(HandOp::m1l) || uses(HandOp::m1r) || uses(HandOp::m1pl) || uses(HandOp::m1pr) ||
        uses(HandOp::yo))
      items.push_back(
          "A make-one or yarn over goes with the stitch worked just before it: \"k1, "
          "M1L\" makes 2 sts from 1.");
    if (p_.mirror)
      items.push_back(fmt::format(
          "The rounds of the model ({}) run left to right as seen from the right side; hand "
          "knitting runs right to left, so this pattern knits the model's mirror image: decreases "
          "and increases lean the other way (ssk where the model has k2tog, M1R for M1L).",
          p_.source));
    return items;
  }

  const HandPattern& p_;
  const Gauge& gauge_;
  Totals t_;
  std::string text_;  // every instruction, to see which abbreviations are used
};

}  // namespace

std::vector<FrontSection> front_matter(const HandPattern& p, const Gauge& gauge,
                                       const std::vector<InstructionLine>& lines) {
  return FrontMatter(p, gauge, lines).sections();
}

}  // namespace skein::hand::document
