// The needle simulator's steps that move sts off and onto the needles: place held sts, put
// them on a spare needle or a holder, leave them.
#include "hand/needle_simulator.hpp"

#include <algorithm>

namespace skein::hand::sim {

void NeedleSimulator::place(const Step& s) {
  if (active_ && !pc_.joined && !s.round) return place_into_row(s);
  if (!active_ || !pc_.joined || !s.round)
    fail(fmt::format("Place the sts of Piece {}: only into a piece worked in the rnd{}", s.number,
                     active_ && !s.round ? " (count them 'of the rnd')" : ""));
  insert_into_rnd(sts_to_place(s), s.last, placing(s));
  release_placed(s);
}

std::string NeedleSimulator::placing(const Step& s) {
  return fmt::format("Place the sts of {} {}", s.holder[0] ? "holder" : "Piece", s.number);
}

std::vector<std::uint32_t> NeedleSimulator::sts_to_place(const Step& s) const {
  std::vector<std::uint32_t> placed =
      s.holder[0] ? held(s.number, s.from_last[0], "Place the sts")
                  : spare_needle(s.number, s.from_last[0], "Place the sts", s.provisional);
  start_at(placed, s);
  if (placed.size() != s.count)
    fail(fmt::format("{}: the pattern says {}, but {} holds {}", placing(s), sts(s.count),
                     s.holder[0]     ? "it"
                     : s.provisional ? "its chain"
                                     : "its needle",
                     placed.size()));
  return placed;
}

void NeedleSimulator::release_placed(const Step& s) {
  if (s.holder[0])
    holders_.erase(s.number);
  else
    spare_needles_.erase({s.number, s.provisional ? kChain : kNeedle});
}

void NeedleSimulator::place_into_row(const Step& s) {
  std::vector<std::uint32_t> placed = sts_to_place(s);
  std::vector<std::uint32_t>& next_row = pc_.turn_before ? pc_.right : pc_.left;
  auto at = next_row.end();
  for (std::uint32_t before = 0; before < s.last; --at) {
    if (at == next_row.begin())
      fail(fmt::format("{}: the row has only {}", placing(s), sts(before)));
    before += !is_marker_entry(*(at - 1));
  }
  next_row.insert(at, placed.rbegin(), placed.rend());
  pc_.live += s.count;
  release_placed(s);
}

void NeedleSimulator::place_on_spare_needle(const Step& s) {
  std::string what = fmt::format("Place the sts of holder {}", s.number);
  std::vector<std::uint32_t> placed = held(s.number, s.from_last[0], what.c_str());
  if (placed.size() != s.count)
    fail(
        fmt::format("{}: the pattern says {}, but it holds {}", what, sts(s.count), placed.size()));
  std::vector<std::uint32_t> ring = spare_needle(s.to_row, false, what.c_str());
  if (s.last > ring.size())
    fail(fmt::format("{}: the spare needle of Piece {} has no st {}", what, s.to_row, s.last));
  ring.insert(ring.begin() + s.last, placed.begin(), placed.end());
  if (s.sts && (++out_.counts_checked, *s.sts != ring.size()))
    fail(fmt::format("{}: the pattern says {}, but the spare needle holds {}", what, sts(*s.sts),
                     ring.size()));
  spare_needles_[{s.to_row, kNeedle}] = ring;
  holders_.erase(s.number);
}

void NeedleSimulator::start_at(std::vector<std::uint32_t>& placed, const Step& s) const {
  if (s.from_row > placed.size())
    fail(fmt::format("Place the sts of Piece {}: its needle holds no st {}", s.number, s.from_row));
  if (s.from_row > 0) std::rotate(placed.begin(), placed.begin() + s.from_row - 1, placed.end());
}

void NeedleSimulator::insert_into_rnd(const std::vector<std::uint32_t>& loops, std::uint32_t after,
                                      const std::string& what) {
  std::vector<std::uint32_t> ring = ring_from_bor();
  if (after > ring.size())
    fail(
        fmt::format("{}: the rnd has only {}", what, sts(static_cast<std::uint32_t>(ring.size()))));
  ring.insert(ring.begin() + after, loops.begin(), loops.end());
  lay_out_from_bor(ring);
  pc_.live += static_cast<std::uint32_t>(loops.size());
}

void NeedleSimulator::lay_out_from_bor(const std::vector<std::uint32_t>& ring) {
  std::vector<std::uint32_t>& needle = pc_.turn_before ? pc_.left : pc_.right;
  needle.clear();
  if (pc_.bor != kNone) needle.push_back(pc_.bor);
  needle.insert(needle.end(), ring.begin(), ring.end());
  (pc_.turn_before ? pc_.right : pc_.left).clear();
}

void NeedleSimulator::put_on_spare_needle(const Step& s) {
  std::vector<std::uint32_t>& spare = spare_for_rows_[s.last];
  if (!spare.empty())
    fail(
        fmt::format("Put the sts of holder {} on a {}spare needle: the {}spare needle still "
                    "holds {}",
                    s.number, s.last ? "second " : "", s.last ? "second " : "",
                    sts(static_cast<std::uint32_t>(spare.size()))));
  std::vector<std::uint32_t> loops = held(s.number, s.from_last[0], "Put the sts");
  if (loops.size() != s.count)
    fail(fmt::format("Put the sts of holder {}: the pattern says {}, but it holds {}", s.number,
                     sts(s.count), loops.size()));
  holders_.erase(s.number);
  spare = std::move(loops);
}

void NeedleSimulator::hold(const Step& s) {
  if (s.of_row || s.of_cast_on) return hold_run_of_row(s);
  if (!active_ || !pc_.joined)
    fail(fmt::format("Slip sts to holder {}: only from a piece worked in the rnd", s.number));
  if (s.onto) check_held_before(s);
  if (!s.onto && holders_.contains(s.number))
    fail(fmt::format("Slip sts to holder {}: it already holds sts", s.number));
  if (s.from_row == 0) fail(fmt::format("Slip sts to holder {}: the sts count from 1", s.number));
  std::vector<std::uint32_t> ring = ring_from_bor();
  if (s.to_row > ring.size())
    fail(fmt::format("Slip sts {}\u2013{} to holder {}: the rnd has only {}", s.from_row, s.to_row,
                     s.number, sts(static_cast<std::uint32_t>(ring.size()))));
  auto first = ring.begin() + (s.from_row - 1), end = ring.begin() + s.to_row;
  holders_[s.number].insert(holders_[s.number].end(), first, end);
  ring.erase(first, end);
  lay_out_from_bor(ring);
  pc_.live -= s.to_row - s.from_row + 1;
}

void NeedleSimulator::hold_run_of_row(const Step& s) {
  std::string what =
      fmt::format("Slip sts {}\u2013{} of {} to holder {}", s.from_row, s.to_row,
                  s.of_cast_on ? "the cast-on" : fmt::format("Row {}", s.of_row), s.number);
  if (!active_) fail(what + ": no piece is on the needle");
  if (holders_.contains(s.number)) fail(what + ": it already holds sts");
  if (s.of_row >= pc_.next_number)
    fail(fmt::format("{}: the last row worked is Row {}", what, pc_.next_number - 1));
  // An earlier row's sts left on the needle (a piece set aside after rows on others) count
  // as the last row's do.
  std::vector<std::uint32_t> row;
  for (const std::vector<std::uint32_t>* needle : {&pc_.right, &pc_.left})
    std::copy_if(needle->begin(), needle->end(), std::back_inserter(row),
                 [&](std::uint32_t entry) { return made_by_row(entry, s.of_row); });
  if (s.from_row == 0 || s.to_row > row.size())
    fail(fmt::format("{}: the {} left {} on the needle", what, s.of_cast_on ? "cast-on" : "row",
                     sts(static_cast<std::uint32_t>(row.size()))));
  std::vector<std::uint32_t> run(row.begin() + (s.from_row - 1), row.begin() + s.to_row);
  for (std::vector<std::uint32_t>* needle : {&pc_.right, &pc_.left})
    std::erase_if(*needle, [&](std::uint32_t entry) {
      return std::find(run.begin(), run.end(), entry) != run.end();
    });
  holders_[s.number] = std::move(run);
  pc_.live -= s.to_row - s.from_row + 1;
}

void NeedleSimulator::check_held_before(const Step& s) const {
  auto at = holders_.find(s.number);
  auto held = static_cast<std::uint32_t>(at == holders_.end() ? 0 : at->second.size());
  if (held != s.count)
    fail(fmt::format("Slip sts to holder {} after the {} on it: it holds {}", s.number,
                     sts(s.count), held == 0 ? "no sts" : sts(held)));
}

void NeedleSimulator::hold_all(const Step& s) {
  std::string what = fmt::format("Slip the sts of Row {} to holder {}", s.from_row, s.number);
  if (!active_ || pc_.joined)
    fail(what + ": only from a piece worked flat (in the rnd, say which sts)");
  if (holders_.contains(s.number)) fail(what + ": it already holds sts");
  if (s.from_row + 1 != pc_.next_number)
    fail(fmt::format("{}: the last row worked is Row {}", what, pc_.next_number - 1));
  std::vector<std::uint32_t> held = sts_of_row_off_the_needle(s.from_row);
  if (held.size() != s.count)
    fail(fmt::format("{}: the pattern says {}, but the row left {} on the needle", what,
                     sts(s.count), sts(static_cast<std::uint32_t>(held.size()))));
  pc_.live -= s.count;
  holders_[s.number] = std::move(held);
  check_printed_count(s, "Slip the sts to holder");
}

std::vector<std::uint32_t> NeedleSimulator::sts_of_row_off_the_needle(std::uint32_t number) {
  std::vector<std::uint32_t> off;
  auto of_last_row = [&](std::uint32_t entry) { return made_by_row(entry, number); };
  for (std::vector<std::uint32_t>* needle : {&pc_.right, &pc_.left}) {
    std::copy_if(needle->begin(), needle->end(), std::back_inserter(off), of_last_row);
    std::erase_if(*needle, of_last_row);
  }
  return off;
}

bool NeedleSimulator::made_by_row(std::uint32_t entry, std::uint32_t number) {
  if (is_marker_entry(entry)) return false;
  const Fabric::RowWorked& r = fab().rows[fab().row[fab().loop_maker[entry]]];
  return r.piece == pc_.number && r.number == number;
}

bool NeedleSimulator::made_by_last_row(std::uint32_t entry) {
  return !is_marker_entry(entry) && fab().row[fab().loop_maker[entry]] == row_;
}

std::vector<std::uint32_t> NeedleSimulator::held(std::uint32_t holder, bool from_last,
                                                 const char* what) const {
  auto at = holders_.find(holder);
  if (at == holders_.end()) fail(fmt::format("{}: holder {} holds no sts", what, holder));
  std::vector<std::uint32_t> loops = at->second;
  if (from_last) std::reverse(loops.begin(), loops.end());
  return loops;
}

std::vector<std::uint32_t> NeedleSimulator::ring_from_bor() const {
  const std::vector<std::uint32_t>& ahead = pc_.turn_before ? pc_.right : pc_.left;
  const std::vector<std::uint32_t>& behind = pc_.turn_before ? pc_.left : pc_.right;
  std::vector<std::uint32_t> ring(ahead.rbegin(), ahead.rend());
  ring.insert(ring.end(), behind.begin(), behind.end());
  auto at = std::find(ring.begin(), ring.end(), pc_.bor);
  std::rotate(ring.begin(), at, ring.end());
  std::erase_if(ring, is_marker_entry);
  return ring;
}

void NeedleSimulator::leave(std::uint32_t n) {
  check_live(n, "Leave the sts");
  std::vector<std::uint32_t>& spare = spare_needles_[{pc_.number, kNeedle}];
  for (std::uint32_t entry : pc_.right)
    if (!is_marker_entry(entry)) spare.push_back(entry);
  for (auto at = pc_.left.rbegin(); at != pc_.left.rend(); ++at)
    if (!is_marker_entry(*at)) spare.push_back(*at);
  start_at_last_row(spare);
  pc_.right.clear();
  pc_.left.clear();
  active_ = false;
  pc_.live = 0;
}

void NeedleSimulator::start_at_last_row(std::vector<std::uint32_t>& ring) {
  const Fabric::RowWorked& last = fab().rows[row_];
  if (!pc_.joined || last.round || last.first == kNoStitch) return;
  auto at = std::find_if(ring.begin(), ring.end(),
                         [&](std::uint32_t loop) { return fab().loop_maker[loop] == last.first; });
  if (at != ring.end()) std::rotate(ring.begin(), at, ring.end());
}

}  // namespace skein::hand::sim
