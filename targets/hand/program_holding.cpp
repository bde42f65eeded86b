// The hand pattern built on the live-loop program (program_pattern.cpp): where a course parts a
// spare needle or leaves loops it does not work, the loops go to holders, a block each, counted
// as the knitter can count them. The members' why-comments: program_builder.hpp.
#include <algorithm>

#include "hand/program_builder.hpp"

namespace skein::hand::from_program {

LoopAt ProgramPatternBuilder::hold_parts_of_spare_needle(std::uint32_t section, std::uint32_t loop,
                                                         bool round_the_end_stays) {
  PatternSection& sec = out_.sections[section];
  const LoopAt spare_needle{Place::spare, section};
  std::vector<std::uint32_t> spare = places_.loops_of(spare_needle);
  std::optional<PatternSection::Holding> counted = counting_of_spare_needle(sec, spare);
  if (!counted) return spare_needle;
  // The sts keep the numbers they had when the piece was left, so each part is a run of
  // those numbers, and all parts go to holders in one sentence, in order, but the one that
  // goes round past the end, which stays on the spare needle for a rnd to place from its
  // middle (where `round_the_end_stays`).
  std::vector<std::pair<std::uint32_t, std::uint32_t>> parts;  // [begin, end) in `spare`
  for (std::uint32_t i = 0, end = 0; i < spare.size(); i = end) {
    for (end = i + 1; end < spare.size() &&
                      (taken_together(spare[end - 1], spare[end]) ||
                       taken_by_rows_one_by_one(spare[end - 1], spare[end])) &&
                      places_.counted_at(spare[end]) == places_.counted_at(spare[end - 1]) + 1;
         ++end) {
    }
    parts.emplace_back(i, end);
  }
  bool round_the_end =
      round_the_end_stays && parts.size() > 1 && taken_together(spare.back(), spare.front());
  for (std::size_t k = round_the_end ? 1 : 0; k + (round_the_end ? 1 : 0) < parts.size(); ++k) {
    std::span<const std::uint32_t> part(spare.data() + parts[k].first,
                                        parts[k].second - parts[k].first);
    PatternSection::Holding h = *counted;
    h.first = places_.counted_at(part.front());
    h.count = static_cast<std::uint32_t>(part.size());
    places_.take_off_spare(section, part);
    h.holder = places_.hold(part, section);
    auto later = std::find_if(sec.holdings.begin(), sec.holdings.end(), [&](const auto& o) {
      return o.after_row == h.after_row && o.first > h.first;
    });
    sec.holdings.insert(later, h);
    sec.live_at_end -= hand_stitch_count(g_, part);
  }
  return places_.at(loop);
}

std::optional<Lie> ProgramPatternBuilder::lie_parting_spare_needle(
    LoopAt& source, std::span<const std::uint32_t> block) {
  std::optional<Lie> lie = places_.lie(source, block);
  if (lie || source.place != Place::spare) return lie;
  source = hold_parts_of_spare_needle(source.index, block.front());
  return places_.lie(source, block);
}

bool ProgramPatternBuilder::taken_by_rows_one_by_one(std::uint32_t a, std::uint32_t b) const {
  std::uint32_t at = taker_step_[a], bt = taker_step_[b];
  if (at == kNone || bt == kNone || at == bt) return false;
  const Step &sa = p_.steps[at], &sb = p_.steps[bt];
  auto later_row = [&](const Step& s, std::uint32_t step) {
    return s.shape != RowShape::closed && !starts_its_yarn(step);
  };
  // Taken from one end of the needle: by rows one or two apart (every row, or every other row
  // where the rows take sts at both their ends).
  std::uint32_t apart = std::max(course_number_[at], course_number_[bt]) -
                        std::min(course_number_[at], course_number_[bt]);
  return sa.yarn == sb.yarn && later_row(sa, at) && later_row(sb, bt) && apart <= 2;
}

bool ProgramPatternBuilder::taken_together(std::uint32_t a, std::uint32_t b) const {
  if (taker_step_[a] != taker_step_[b]) return false;
  return taker_step_[a] == kNone || met_at_[a] + 1 == met_at_[b] || met_at_[b] + 1 == met_at_[a];
}

std::optional<PatternSection::Holding> ProgramPatternBuilder::counting_of_spare_needle(
    const PatternSection& sec, const std::vector<std::uint32_t>& spare) const {
  PatternSection::Holding h{};
  if (sec.first_row == sec.end_row) {  // its cast-on only
    if (sec.resumed || sec.starts_from || sec.picks_up || sec.in_round) return std::nullopt;
    h.after_row = sec.first_row - 1;
    h.of_cast_on = true;
    return h;
  }
  h.after_row = sec.end_row - 1;
  const PatternRow& last = out_.rows[h.after_row];
  // A row that began across the gap ("sl1 back") and went on round the needle worked its sts
  // in an order the count below does not follow (the teapot's top at 14/20): not counted.
  auto ops = out_.ops_of(last);
  if (std::find(ops.begin(), ops.end(), HandOp::slip_back) != ops.end()) return std::nullopt;
  // A row in the rnd numbers the sts in the order it worked them: only where it made them all.
  if (sec.in_round != last.round && !std::all_of(spare.begin(), spare.end(), [&](std::uint32_t l) {
        return row_of_[g_.loops[l].maker] == h.after_row;
      }))
    return std::nullopt;
  h.of_row = !last.round;
  return h;
}

std::vector<std::uint32_t> ProgramPatternBuilder::hold_what_it_leaves(const Step& s) {
  Needle& n = needle();
  // After rows that ended away from the marker (a set-in sweater's front, whose yarn goes on
  // to a sleeve) the yarn is at the marker once the sts between them are slipped.
  auto kept = [&](std::uint32_t l) { return in_met_[l] != 0; };
  auto gap = static_cast<std::ptrdiff_t>(n.gap);
  bool at_marker = std::none_of(n.ring.begin(), n.ring.begin() + gap, kept) ||
                   std::none_of(n.ring.begin() + gap, n.ring.end(), kept);
  if (!n.in_round || row_open_ || !at_marker)
    not_yet(s, "gathers sts onto a flat piece, or a tube not at the end of a rnd");
  n.gap = 0;
  if (out_.rows.empty()) not_yet(s, "gathers sts before any row is worked");
  return hold_blocks(n.ring, kept, false);
}

std::vector<std::uint32_t> ProgramPatternBuilder::hold_blocks(
    const std::vector<std::uint32_t>& order, const std::function<bool(std::uint32_t)>& stays,
    bool of_row) {
  Needle& n = needle();
  PatternSection& sec = section();
  auto after_row = static_cast<std::uint32_t>(out_.rows.size()) - 1;
  std::vector<std::uint32_t> stay;
  for (std::uint32_t i = 0; i < order.size();) {
    if (stays(order[i])) {
      stay.push_back(order[i++]);
      continue;
    }
    // A block for each yarn that takes them (a gusset's sts, and a join's beside them).
    std::uint32_t end = i + 1;
    while (end < order.size() && !stays(order[end]) && held_together(order[end - 1], order[end]))
      ++end;
    std::span<const std::uint32_t> block(order.data() + i, end - i);
    std::uint32_t holder = holder_met_before(block, n.section), onto = 0;
    if (holder != 0) {
      onto = static_cast<std::uint32_t>(places_.loops_of({Place::holder, holder}).size());
      places_.hold_onto(holder, block);
    } else {
      holder = places_.hold(block, n.section);
    }
    PatternSection::Holding h{after_row, i + 1, end - i, holder, onto};
    h.of_row = of_row;
    sec.holdings.push_back(h);
    i = end;
  }
  return stay;
}

std::uint32_t ProgramPatternBuilder::holder_met_before(std::span<const std::uint32_t> block,
                                                       std::uint32_t section) const {
  for (std::uint32_t h = places_.holders(); h > 0; --h) {
    if (places_.holder_section(h) != section) continue;
    std::vector<std::uint32_t> all = places_.loops_of({Place::holder, h});
    all.insert(all.end(), block.begin(), block.end());
    return met_one_after_another(all) ? h : 0;
  }
  return 0;
}

bool ProgramPatternBuilder::met_one_after_another(const std::vector<std::uint32_t>& loops) const {
  if (loops.size() < 2 || taker_step_[loops[0]] == kNone) return false;
  int by = static_cast<int>(met_at_[loops[1]]) - static_cast<int>(met_at_[loops[0]]);
  for (std::size_t k = 1; k < loops.size(); ++k)
    if (taker_step_[loops[k]] != taker_step_[loops[0]] ||
        static_cast<int>(met_at_[loops[k]]) - static_cast<int>(met_at_[loops[k - 1]]) != by ||
        (by != 1 && by != -1) || places_.at(loops[k - 1]).place == Place::none)
      return false;
  return true;
}

bool ProgramPatternBuilder::held_together(std::uint32_t a, std::uint32_t b) const {
  if (holder_for(a) != holder_for(b)) return false;
  std::uint32_t at = taker_step_[a], bt = taker_step_[b];
  return at == bt || (!starts_its_yarn(at) && !starts_its_yarn(bt));
}

void ProgramPatternBuilder::index_loops_met() {
  std::vector<std::uint32_t> courses_of_yarn(needle_of_yarn_.size(), 0);  // so far
  for (std::uint32_t i = 0; i < p_.steps.size(); ++i) {
    const Step& s = p_.steps[i];
    bool picks_up = s.kind == StepKind::cast_on && s.picked_up > 0;
    if (s.kind != StepKind::course && s.kind != StepKind::bind_off &&
        s.kind != StepKind::three_needle_bind_off && !picks_up)
      continue;
    course_number_[i] = courses_of_yarn[s.yarn]++;
    std::vector<std::uint32_t> met = loops_met(s);
    for (std::uint32_t k = 0; k < met.size(); ++k) {
      taker_step_[met[k]] = i;
      met_at_[met[k]] = k;
    }
    // A three-needle bind-off's sts held behind are taken too, pair by pair.
    auto k = static_cast<std::uint32_t>(met.size());
    for (std::uint32_t w = s.stitches.begin; w < s.stitches.end; ++w)
      if (binds_off_together(w)) {
        std::uint32_t behind = all_taken_by(w)[1];
        taker_step_[behind] = i;
        met_at_[behind] = k++;
      }
  }
}

}  // namespace skein::hand::from_program
