// The needle simulator's rows and rnds: their labels and counts, where each begins and ends,
// the marker, the left needle's index.
#include "hand/needle_simulator.hpp"

#include <algorithm>

namespace skein::hand::sim {

void NeedleSimulator::check_kind(bool round_label, const char* what) const {
  if (!active_)
    throw StepFailure{
        set_aside_.empty()
            ? fmt::format("{}: no sts are on the needle (cast on first)", what)
            : fmt::format("{}: no sts are on the needle (take up Piece {} again first)", what,
                          set_aside_.begin()->first)};
  // Joined work has rnds, and rows where it turns (short rows).
  if (round_label && !pc_.joined)
    throw StepFailure{fmt::format(
        "{}: the work is flat (never joined in the rnd), so it has rows, not rnds", what)};
}

void NeedleSimulator::work_rows(const Step& s) {
  check_kind(s.round, s.round ? "Rnd" : "Row");
  if (s.number != pc_.next_number)
    throw StepFailure{fmt::format("{} {} comes next, not {} {}", s.round ? "Rnd" : "Row",
                                  pc_.next_number, s.round ? "Rnd" : "Row", s.number)};
  for (std::uint32_t n = s.number; n <= s.last; ++n) {
    if (pc_.defined.size() <= n) pc_.defined.resize(n + 1, kNone);
    pc_.defined[n] = s.program;
    work_row(script_.programs[s.program], s.round, 0, n == s.number ? label_of(s) : std::nullopt,
             s.line);
  }
  check_count(s);
}

void NeedleSimulator::repeat_rows(const Step& s) {
  std::string what =
      s.number == s.last
          ? fmt::format("Rep {} {}", s.round ? "Rnd" : "Row", s.number)
          : fmt::format("Rep {} {}\u2013{}", s.round ? "Rnds" : "Rows", s.number, s.last);
  check_kind(s.round, what.c_str());
  for (std::uint32_t n = s.number; n <= s.last; ++n)
    if (n >= pc_.defined.size() || pc_.defined[n] == kNone)
      throw StepFailure{
          fmt::format("{}: {} {} is not written out above", what, s.round ? "Rnd" : "Row", n)};
  if (s.last + 1 != pc_.next_number)
    throw StepFailure{fmt::format("{}: the rows to repeat must be the last ones worked ({} {})",
                                  what, s.round ? "Rnd" : "Row", pc_.next_number - 1)};
  for (std::uint32_t t = 0; t < s.count; ++t)
    for (std::uint32_t n = s.number; n <= s.last; ++n) {
      std::uint32_t number = pc_.next_number;
      if (pc_.defined.size() <= number) pc_.defined.resize(number + 1, kNone);
      pc_.defined[number] = pc_.defined[n];
      work_row(script_.programs[pc_.defined[n]], s.round, n, std::nullopt, s.line);
    }
  check_count(s);
}

void NeedleSimulator::work_even(const Step& s) {
  check_kind(s.round, s.round ? "every rnd" : "every row");
  if (s.count < pc_.next_number)
    throw StepFailure{fmt::format("until {} {} in all: {} are already worked", s.count,
                                  s.round ? "rnds" : "rows", pc_.next_number - 1)};
  std::uint32_t program = s.op == HandOp::k ? 0 : 1;
  while (pc_.next_number <= s.count)
    work_row(work_even_[program], s.round, 0, std::nullopt, s.line);
}

void NeedleSimulator::check_count(const Step& s) {
  if (!s.sts) return;
  ++out_.counts_checked;
  if (*s.sts != pc_.live)
    throw StepFailure{fmt::format("{}: the pattern says {}, but {} on the needle",
                                  fab().row_label(row_), sts(*s.sts),
                                  pc_.live == 1 ? "1 st is" : fmt::format("{} sts are", pc_.live))};
}

std::optional<Side> NeedleSimulator::label_of(const Step& s) {
  return s.round ? s.side.value_or(Side::rs) : s.side;
}

Side NeedleSimulator::facing_of(std::optional<Side> label) const {
  if (!pc_.last_side) return label.value_or(Side::rs);
  return pc_.turn_before ? other(*pc_.last_side) : *pc_.last_side;
}

void NeedleSimulator::work_row(const Program& p, bool round, std::uint32_t repeat_of,
                               std::optional<Side> label, std::size_t line) {
  Side facing = facing_of(label);
  fab().rows.push_back({line, pc_.next_number, repeat_of, round, facing});
  row_ = static_cast<std::uint32_t>(fab().rows.size() - 1);
  in_row_ = true;
  row_round_ = round;
  if (round && label == Side::rs && facing == Side::ws)
    fail(
        "the WS faces you (the work was turned): a rnd worked with the WS facing is "
        "labelled (WS)");
  if (label && *label != facing)
    fail(fmt::format("labelled {}, but the {} faces you: {}", side_name(*label), side_name(facing),
                     !pc_.turn_before ? "the work was not turned"
                     : !pc_.joined    ? "every row turns the work"
                                      : "the work was turned"));
  begin_row(facing);
  run_nodes(p, p.top_begin, p.top_end);
  end_row();
  in_row_ = false;
  pc_.last_side = facing;
  ++pc_.next_number;
  ++(round ? out_.rounds : out_.rows);
}

void NeedleSimulator::begin_row(Side facing) {
  facing_ = facing;
  position_ = 0;
  row_last_stitch_ = kNone;
  row_ended_ = not_turned_ = false;
  pending_.clear();
  last_make_ = std::nullopt;
  next_link_ = pc_.cast_on_aside ? YarnLink::course
               : pc_.turn_before ? YarnLink::turn
                                 : YarnLink::shift;
  pc_.cast_on_aside = false;
  if (pc_.turn_before) pc_.left.swap(pc_.right);
  if (row_round_)
    gather_round();
  else if (!pc_.turn_before)
    slip_bor_if_next();
  place_bor_before_first_row();
  index_left_needle();
}

void NeedleSimulator::place_bor_before_first_row() {
  if (row_round_ || !pc_.place_bor) return;
  pc_.right.push_back(pc_.bor = new_marker());
  pc_.place_bor = false;
}

void NeedleSimulator::slip_bor_if_next() {
  wrap_around();
  if (pc_.left.empty() || pc_.left.back() != pc_.bor) return;
  pc_.right.push_back(pc_.bor);
  pc_.left.pop_back();
}

void NeedleSimulator::gather_round() {
  std::vector<std::uint32_t> ring(pc_.left.rbegin(), pc_.left.rend());  // from here onwards
  ring.insert(ring.end(), pc_.right.begin(), pc_.right.end());
  auto at = std::find(ring.begin(), ring.end(), pc_.bor);
  if (pc_.place_bor || at == ring.end()) {
    pc_.left.assign(ring.rbegin(), ring.rend());
    pc_.right.clear();
    if (pc_.place_bor) pc_.right.push_back(pc_.bor = new_marker());
    pc_.place_bor = false;
    return;
  }
  if (at == ring.begin()) {
    std::rotate(ring.begin(), ring.begin() + 1, ring.end());
    at = ring.end() - 1;
  }
  pc_.left.assign(std::make_reverse_iterator(at), ring.rend());
  pc_.right.assign(at, ring.end());
}

void NeedleSimulator::wrap_around() {
  if (!pc_.joined || row_round_ || !pc_.left.empty()) return;
  pc_.left.assign(pc_.right.rbegin(), pc_.right.rend());
  pc_.right.clear();
  index_left_needle();
}

void NeedleSimulator::look_round_for_marker() {
  bool beyond = std::any_of(pc_.right.begin(), pc_.right.end(), is_marker_entry);
  if (!pc_.joined || row_round_ || marker_ahead() || !beyond) return;
  pc_.left.insert(pc_.left.begin(), pc_.right.rbegin(), pc_.right.rend());
  pc_.right.clear();
  index_left_needle();
}

void NeedleSimulator::reach_around(std::uint32_t takes) {
  if (!pc_.joined || row_round_ || left_loops_ >= takes || pc_.left.empty()) return;
  std::size_t moved = 0;
  while (left_loops_ + moved < takes && moved < pc_.right.size() &&
         !is_marker_entry(pc_.right[moved]))
    ++moved;
  pc_.left.insert(pc_.left.begin(), pc_.right.rend() - static_cast<std::ptrdiff_t>(moved),
                  pc_.right.rend());
  pc_.right.erase(pc_.right.begin(), pc_.right.begin() + static_cast<std::ptrdiff_t>(moved));
  index_left_needle();
}

void NeedleSimulator::end_row() {
  const char* what = row_round_ ? "rnd" : "row";
  if (!row_ended_ && pc_.joined && !row_round_)
    fail("a row worked in the rnd ends where the work turns: end it with w&t or turn");
  if (!row_ended_ && left_loops_ > 0)
    fail(fmt::format("{} left unworked at the end of the {}", sts(left_loops_), what));
  if (!row_ended_ && !pc_.left.empty())
    fail(
        fmt::format("a marker is left at the end of the {}: slip it (sm) or remove it (rm)", what));
  if (!held_behind_.empty())
    fail(fmt::format("{} held behind the needle left unworked at the end of the {}",
                     sts(static_cast<std::uint32_t>(held_behind_.size())), what));
  if (!pending_.empty())
    fail(fmt::format("{} with no st worked in the {} to go with it",
                     info(pending_.front().op).abbreviation, what));
  if (!row_round_ && last_make_ && *last_make_ != HandOp::yo)
    fail(fmt::format("{} at the end of a row: there is no strand after the last st to lift",
                     info(*last_make_).abbreviation));
  pc_.turn_before = (row_ended_ || !pc_.joined) && !not_turned_;
}

void NeedleSimulator::index_left_needle() {
  to_marker_.resize(pc_.left.size());
  marker_ahead_.resize(pc_.left.size());
  left_loops_ = 0;
  for (std::size_t i = 0; i < pc_.left.size(); ++i) {
    bool marker = is_marker_entry(pc_.left[i]);
    to_marker_[i] = marker ? 0 : (i ? to_marker_[i - 1] : 0) + 1;
    marker_ahead_[i] = marker || (i && marker_ahead_[i - 1]);
    left_loops_ += !marker;
  }
}

std::uint32_t NeedleSimulator::loops_to_marker() const {
  return pc_.left.empty() ? 0 : to_marker_[pc_.left.size() - 1];
}

bool NeedleSimulator::marker_ahead() const {
  return (!pc_.left.empty() && marker_ahead_[pc_.left.size() - 1]) || end_is_marker();
}

}  // namespace skein::hand::sim
