// Reads a hand-knitting pattern as a knitter reads it: the sentences under "Instructions"
// ("Cast on 64 sts.", "Rnd 25: *K6, k2tog; rep from * to end — 56 sts.", "Rep Rows 3–4
// twice more.", "Knit every rnd until 24 rnds in all.") become steps, and each row's text a
// small program of operations, groups and "until" forms that the needle simulator executes.
// Markdown, the HTML page (html_to_text) and KnitSpeak rows all read the same way.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "hand/hand_ops.hpp"

namespace skein::hand {

// Where a repeated operation or group stops.
struct Until {
  enum class Kind : std::uint8_t {
    count,          // a fixed number of times
    end,            // "to end"
    marker,         // "to m"
    last,           // "to last N sts"
    before_marker,  // "to N sts before m"
  };
  Kind kind = Kind::count;
  std::uint32_t sts = 0;
};

struct Node {
  enum class Kind : std::uint8_t { op, group, bind_off_all };
  Kind kind = Kind::op;
  HandOp op = HandOp::k;
  std::uint32_t times = 1;  // with Until::count
  Until until;
  std::uint32_t first_child = 0, end_child = 0;  // a group's nodes, in Program::nodes
};

// One row's instructions; its top-level nodes are nodes[top_begin, top_end).
struct Program {
  std::vector<Node> nodes;
  std::uint32_t top_begin = 0, top_end = 0;
};

struct Step {
  enum class Kind : std::uint8_t {
    piece,          // a heading: a new piece or stage begins
    cast_on,        // count = sts
    cast_on_aside,  // "With the working yarn, cast on <count> sts ... onto holder <number>"
    join_round,     // marker: with "pm"
    row,            // number..last (a range "Rows 2–16:"), program
    repeat_rows,    // number..last repeated count more times
    work_even,      // "Knit every rnd until <count> rnds in all": op is k or p
    fasten_off,
    leave,                  // "Leave the <count> sts on a spare needle and cut the yarn"
    set_aside,              // "Leave the <count> sts on the needle and set the yarn aside"
    take_up,                // "Take up Piece <number> again with its yarn"
    place,                  // "Place the <count> sts of Piece <number> ... first <last> sts"
    join_spare,             // "Join a new yarn to the <count> sts of Piece <number>['s chain], ..."
    carry_on,               // "Do not fasten off: carry the yarn to the <count> sts of holder ..."
    pick_up,                // "Pick up <count> sts along the right edge of Piece <number>, ..."
    three_needle_bind_off,  // Piece <number> in front, Piece <last> behind, <count> pairs;
                            // from_last: which ends are at the tips (front, back)
    hold,                   // "Slip sts <from_row>–<to_row> of the rnd (of Row <of_row>, of
                            // the cast-on) to holder <number>"
    hold_all,               // "Slip the <count> sts of Row <from_row> to holder <number>"
    to_spare,               // "Put the <count> sts of holder <number> on a spare needle, ..."
                            // (last 1: "on a second spare needle")
    hold_behind,            // "Hold the <count> sts of Piece <number> behind the needle, the
                            // first (from_last[0]: last) st of its last row at the tip"
    place_on_spare,  // "Place the <count> sts of holder <number> on the spare needle of Piece
                     // <to_row> after its st <last> ..."
  };
  Step(Kind step_kind, std::size_t line_no) : kind(step_kind), line(line_no) {}
  Kind kind;
  std::size_t line = 0;  // 1-based line of the file
  std::uint32_t number = 0, last = 0;
  std::uint32_t count = 0;
  bool round = false;  // row: a rnd; place, pick_up: counted "of the rnd" (not "of the row")
  bool marker = false;
  std::optional<Side> side;
  std::optional<std::uint32_t> sts;  // the printed stitch count ("— 56 sts")
  std::uint32_t program = 0;         // into Script::programs
  bool from_last[2] = {false, false};
  bool provisional = false;  // cast_on: with a provisional cast-on; join_spare, place: its chain
  bool own_yarn = false;     // three_needle_bind_off: with the front piece's yarn
  std::uint32_t from_row = 0, to_row = 0;  // pick_up: one st in each of these rows (provisional:
                                           // along the right edge); place: from_row, the st
                                           // placed first (1-based, 0: the first or last);
                                           // join_spare: the holder's st the rnd begins at
  HandOp op = HandOp::k;
  // place (front), three_needle_bind_off: the number (and last) name a holder, not a piece.
  bool holder[2] = {false, false};
  bool into_rnd = false;  // pick_up: onto the needle of the piece worked, after <last> sts
  // hold: after the <count> sts already on the holder ("(after the 1 st on it)").
  bool onto = false;
  // hold: "sts 1–8 of Row 57", counted in the order that row worked them (0: of the rnd).
  std::uint32_t of_row = 0;
  bool of_cast_on = false;  // hold: "sts 1–11 of the cast-on", counted as cast on
  // three_needle_bind_off of one needle folded in half (Piece <number>, <last> sts): each
  // needle's run from its tip to its end, counted round the needle; from_last: going down.
  bool fold = false;
  std::uint32_t tip[2] = {0, 0}, end[2] = {0, 0};
};

struct Script {
  std::vector<Step> steps;
  // By piece number - 1: the names the headings give ("Thumb"; "" for a "Piece N" heading).
  std::vector<std::string> piece_names;
  std::vector<Program> programs;
};

// Limits (docs/formats.md, "Limits"): any number in a pattern (sts, rows, repeats), and how
// deep repeats nest in one row.
inline constexpr std::uint32_t kMaxPatternNumber = 1'000'000;
inline constexpr std::uint32_t kMaxPatternNesting = 32;

// Throws ParseError (file, line, the line quoted, what was expected) for text it cannot read,
// or that passes a limit.
Script read_pattern(std::string_view text, const std::string& file);

// The text of an HTML page a knitter sees, line for line (tags removed, entities decoded,
// styles and figures blanked), so that line numbers still point into the page.
std::string html_to_text(std::string_view html);

}  // namespace skein::hand
