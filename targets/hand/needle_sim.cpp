#include "hand/needle_sim.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "hand/needle_simulator.hpp"

namespace skein::hand {

std::uint8_t Fabric::rs_slot(std::uint32_t loop) const {
  std::uint32_t maker = loop_maker[loop];
  bool left = picked_from[maker] == kLeftEdge;
  if (loop_picked[loop]) return left ? 0 : static_cast<std::uint8_t>(made[maker] - 1);
  auto worked = static_cast<std::uint8_t>(made[maker] - (picked_from[maker] != kNoEdge));
  std::uint8_t slot = facing[maker] == Side::rs
                          ? static_cast<std::uint8_t>(worked - 1 - loop_index[loop])
                          : loop_index[loop];
  return static_cast<std::uint8_t>(slot + left);
}

std::vector<std::uint32_t> Fabric::rs_taken(std::uint32_t stitch) const {
  std::vector<std::uint32_t> loops(taken.begin() + taken_first[stitch],
                                   taken.begin() + taken_first[stitch + 1]);
  // Facing the RS the knitter works right to left: the first loop taken is the rightmost.
  if (facing[stitch] == Side::rs) std::reverse(loops.begin(), loops.end());
  return loops;
}

std::string Fabric::row_label(std::uint32_t r) const {
  const RowWorked& w = rows[r];
  if (w.join) return "Three-needle bind-off";
  if (w.number == 0) return "Cast on";
  std::string word = w.round ? "Rnd" : "Row";
  std::string label = w.round ? fmt::format("Rnd {}", w.number)
                              : fmt::format("Row {} ({})", w.number, side_name(w.side));
  if (w.repeat_of) label += fmt::format(", {} {} again", word, w.repeat_of);
  return label;
}

std::string Fabric::describe(std::uint32_t s) const {
  return fmt::format("{}, st {} ({})", row_label(row[s]), position[s], abbreviation(type[s]));
}

namespace sim {

Replay NeedleSimulator::run() && {
  const Step* step = nullptr;
  try {
    for (const Step& s : script_.steps) {
      step = &s;
      do_step(s);
    }
    finish();
  } catch (const StepFailure& f) {
    out_.ok = false;
    out_.failure = step ? fmt::format("{}:{}: {}", file_, step->line, f.message)
                        : fmt::format("{}: {}", file_, f.message);
  }
  return std::move(out_);
}

void NeedleSimulator::fail(const std::string& why) const {
  throw StepFailure{in_row_ ? fmt::format("{}: {}", out_.fabric.row_label(row_), why) : why};
}

void NeedleSimulator::do_step(const Step& s) {
  switch (s.kind) {
    case Step::Kind::piece:
      if (s.number != 0 && s.number != fab().piece_first.size() + 1 &&
          !set_aside_.contains(s.number))
        fail(fmt::format("Piece {} comes next (or one set aside), not Piece {}",
                         fab().piece_first.size() + 1, s.number));
      break;
    case Step::Kind::cast_on:
      cast_on(s.count, s.provisional);
      break;
    case Step::Kind::cast_on_aside:
      cast_on_aside(s);
      break;
    case Step::Kind::carry_on:
      carry_on(s);
      break;
    case Step::Kind::join_spare:
      join_spare(s);
      break;
    case Step::Kind::pick_up:
      pick_up(s);
      check_printed_count(s, "Pick up");
      break;
    case Step::Kind::join_round:
      join(s);
      break;
    case Step::Kind::row:
      work_rows(s);
      break;
    case Step::Kind::repeat_rows:
      repeat_rows(s);
      break;
    case Step::Kind::work_even:
      work_even(s);
      break;
    case Step::Kind::fasten_off:
      fasten_off();
      break;
    case Step::Kind::leave:
      leave(s.count);
      break;
    case Step::Kind::set_aside:
      set_aside(s.count);
      break;
    case Step::Kind::take_up:
      take_up(s.number);
      break;
    case Step::Kind::place:
      place(s);
      check_printed_count(s, "Place the sts");
      break;
    case Step::Kind::three_needle_bind_off:
      three_needle_bind_off(s);
      break;
    case Step::Kind::hold_behind:
      hold_behind(s);
      break;
    case Step::Kind::hold:
      hold(s);
      check_printed_count(s, "Slip sts to holders");
      break;
    case Step::Kind::hold_all:
      hold_all(s);
      break;
    case Step::Kind::place_on_spare:
      place_on_spare_needle(s);
      break;
    case Step::Kind::to_spare:
      put_on_spare_needle(s);
      break;
  }
}

}  // namespace sim

Replay replay(const Script& script, const std::string& file, std::uint64_t max_work) {
  return sim::NeedleSimulator(script, file, max_work).run();
}

}  // namespace skein::hand
