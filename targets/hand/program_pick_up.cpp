// The hand pattern built on the live-loop program (program_pattern.cpp): the ends of the rows
// and cast-ons written so far, the edges they make, and the loops a new piece picks up along
// them. The members' why-comments: program_builder.hpp.
#include "hand/program_builder.hpp"

namespace skein::hand::from_program {

void ProgramPatternBuilder::note_row_end(StitchId st, const PatternRow& r) {
  auto row = static_cast<std::uint32_t>(out_.rows.size());  // the row being written
  if (row_ends_.size() <= row) row_ends_.resize(row + 1);
  RowEnds& ends = row_ends_[row];
  if (ends.first == kNoStitch) ends.first = st;
  ends.last = st;
  ends.side = r.side;
  row_of_[st] = row;
  number_of_[st] = r.number;
}

void ProgramPatternBuilder::note_cast_on_end(StitchId st, CourseDirection direction) {
  RowEnds& ends = cast_on_ends_[st];
  ends.first = p_.stitches[p_.steps[step_].stitches.begin].stitch;
  ends.last = p_.stitches[p_.steps[step_].stitches.end - 1].stitch;
  ends.side = direction == CourseDirection::right_to_left ? Side::rs : Side::ws;
}

const ProgramPatternBuilder::RowEnds* ProgramPatternBuilder::ends_of_row_of(StitchId st) const {
  if (row_of_[st] != kNone) return &row_ends_[row_of_[st]];
  auto cast_on = cast_on_ends_.find(st);
  return cast_on == cast_on_ends_.end() ? nullptr : &cast_on->second;
}

std::optional<ProgramPatternBuilder::Edge> ProgramPatternBuilder::edge_of(
    StitchId maker, std::uint32_t loop, const RowEnds& ends) const {
  bool at_right = maker == (ends.side == Side::rs ? ends.first : ends.last);
  bool at_left = maker == (ends.side == Side::rs ? ends.last : ends.first);
  auto made = made_by(p_.worked_at[maker]);
  if (made.size() > 1) {  // the loop across the edge made after its wale's is on the right
    bool right = made.back().loop == loop;
    if (!(right ? at_right : at_left)) return std::nullopt;
    return right ? Edge::right : Edge::left;
  }
  if (at_right && at_left) return Edge::either;
  if (!at_right && !at_left) return std::nullopt;
  return at_right ? Edge::right : Edge::left;
}

std::optional<PatternSection::PickUp> ProgramPatternBuilder::pick_up_of(
    LoopAt source, std::span<const std::uint32_t> loops) const {
  auto [p, count] = longest_pick_up(source, loops);
  if (count == 0 || count != loops.size()) return std::nullopt;
  return p;
}

std::pair<PatternSection::PickUp, std::size_t> ProgramPatternBuilder::longest_pick_up(
    LoopAt source, std::span<const std::uint32_t> loops) const {
  PatternSection::PickUp p;
  p.section = source.index;
  std::optional<bool> right_edge;  // known once a st says which edge it is on
  std::size_t i = 0;
  for (; i < loops.size(); ++i) {
    StitchId maker = g_.loops[loops[i]].maker;
    const RowEnds* ends = maker == kNoStitch ? nullptr : ends_of_row_of(maker);
    if (places_.at(loops[i]) != source || !ends) break;
    std::optional<Edge> edge = edge_of(maker, loops[i], *ends);
    if (!edge) break;
    bool right = *edge == Edge::right;
    if (*edge != Edge::either && right != right_edge.value_or(right)) break;
    std::uint32_t row = number_of_[maker];  // 0: the cast-on
    bool up = row == p.to_row + 1 && (i == 1 || p.from_row < p.to_row);
    bool down = row + 1 == p.to_row && (i == 1 || p.from_row > p.to_row);
    if (i > 0 && !(up || down)) break;
    if (*edge != Edge::either) right_edge = right;
    if (i == 0) p.from_row = row;
    p.to_row = row;
  }
  p.right = right_edge.value_or(true);
  return {p, i};
}

std::vector<std::uint32_t> ProgramPatternBuilder::start_from_pick_up(
    const Step& s, const std::vector<std::uint32_t>& host, bool round) {
  // A row after the pick-up works the last loop picked up first; a rnd joined after it, the
  // first.
  std::vector<std::uint32_t> picked(host.rbegin(), host.rend());
  if (round) picked = host;
  std::optional<PatternSection::PickUp> p = pick_up_of(places_.at(host.front()), picked);
  if (!p) not_yet(s, "begins on loops along an edge that are not one in each row of an edge");
  start_section(s.yarn, kNone);
  section().in_round = round;
  section().picks_up = *p;
  section().cast_on = hand_stitch_count(g_, host);
  return host;
}

void ProgramPatternBuilder::pick_up_into_rnd(const Step& s, LoopAt source,
                                             std::span<const std::uint32_t> block,
                                             std::uint32_t after) {
  // One pick-up per edge (a rnd goes down one edge of a flap and up the other).
  while (!block.empty()) {
    auto [p, count] = longest_pick_up(source, block);
    if (count == 0 || !section().in_round)
      not_yet(s, fmt::format("picks up {} loops along an edge into a row, or not one in each "
                             "row of an edge",
                             block.size()));
    PatternSection::Placement placed{p.section, static_cast<std::uint32_t>(count), after, false};
    placed.before_row = static_cast<std::uint32_t>(out_.rows.size());
    placed.edge = p;
    section().placements.push_back(placed);
    block = block.subspan(count);
    after += static_cast<std::uint32_t>(count);
  }
}

}  // namespace skein::hand::from_program
