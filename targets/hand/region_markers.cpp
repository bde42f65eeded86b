#include "hand/region_markers.hpp"

#include <algorithm>
#include <limits>
#include <optional>
#include <vector>

#include "hand/marker_plan.hpp"

namespace skein::hand {
namespace {

constexpr std::uint32_t kOther = 0;  // a marker this pass did not place (sections, BOR)
constexpr std::uint32_t kFits = std::numeric_limits<std::uint32_t>::max();

bool is_marker_op(HandOp op) {
  return op == HandOp::pm || op == HandOp::sm || op == HandOp::rm;
}

// Loops an operation takes off the left needle and puts on the right one: DS slips one.
std::uint32_t loops_taken(HandOp op) {
  return op == HandOp::ds ? 1 : info(op).takes;
}
std::uint32_t loops_made(HandOp op) {
  return op == HandOp::ds ? 1 : info(op).makes;
}

bool takes_a_loop(HandOp op) {
  return loops_taken(op) > 0;
}

bool from_spare(HandOp op) {
  return op == HandOp::from_spare || op == HandOp::from_spare_behind ||
         op == HandOp::from_second_spare || op == HandOp::from_second_spare_behind;
}

bool from_spare_behind(HandOp op) {
  return op == HandOp::from_spare_behind || op == HandOp::from_second_spare_behind;
}

// Does the operation need the left needle's tip (a marker there is passed first)?
bool passes(HandOp op) {
  return takes_a_loop(op) || from_spare(op);
}

// The needle as one line of loops in the order RS rows work them: the markers on it, each by
// the loops before it, and the gap the work is at. In the round the line closes at the
// beginning-of-round marker. Counts only: enough to know where a row meets each marker.
class NeedleLine {
 public:
  NeedleLine(std::uint32_t loops, bool ring) : loops_(loops), ring_(ring) {}

  std::uint32_t at() const { return at_; }
  std::size_t markers() const { return markers_.size() + (ring_ ? 1 : 0); }

  // A row worked with the other side facing runs the other way along the line: the work
  // turned, and a marker just behind it is now just ahead.
  void begin_row(const PatternRow& r) {
    bool forward = r.side == Side::rs;
    if (!started_) at_ = forward || ring_ ? 0 : loops_;
    if (started_ && forward != forward_) passed_ = !passed_;
    started_ = true;
    forward_ = forward;
  }

  // The marker just ahead of the work.
  std::optional<std::uint32_t> ahead() {
    wrap();
    auto m = here();
    if (m == markers_.end() || passed_) return std::nullopt;
    return m->id;
  }
  // Between two loops of the line, with no marker there yet.
  bool free_here() {
    wrap();
    return here() == markers_.end() && at_ > 0 && at_ < loops_;
  }
  // The marker at the work's gap, either side of it.
  std::optional<std::uint32_t> id_here() {
    wrap();
    auto m = here();
    if (m == markers_.end()) return std::nullopt;
    return m->id;
  }
  // A marker other than `other` still on the needle.
  std::optional<std::uint32_t> any_but(std::uint32_t other) const {
    for (const Marker& m : markers_)
      if (m.id != other) return m.id;
    return std::nullopt;
  }
  // At the beginning of the rnd (where "sm" slips the BOR marker).
  bool at_round_start() const { return ring_ && (at_ == 0 || at_ == loops_); }

  void slip() { passed_ = true; }
  void place(std::uint32_t id) {
    markers_.push_back({at_, id});
    passed_ = true;
  }
  void remove() {
    markers_.erase(here());
    passed_ = false;
  }

  // Works `takes` loops into `makes`: kFits, or the marker among the loops taken.
  std::uint32_t work(std::uint32_t takes, std::uint32_t makes) {
    wrap();
    if (takes == 0 && makes == 0) return kFits;
    if (forward_ ? at_ + takes > loops_ : at_ < takes) return kOther;  // across the BOR
    std::uint32_t low = forward_ ? at_ : at_ - takes, high = low + takes;
    for (const Marker& m : markers_)
      if (m.gap > low && m.gap < high) return m.id;
    for (Marker& m : markers_)
      if (m.gap > high || (m.gap == high && shifts_at_cursor(takes))) m.gap = m.gap + makes - takes;
    at_ = forward_ ? low + makes : low;
    loops_ = loops_ + makes - takes;
    passed_ = false;
    return kFits;
  }

  // Sl1 from spare: a st joins the left needle at its tip (`behind`: second, behind the st
  // there); false when a marker is next, with no st to slip it behind.
  bool insert_ahead(bool behind) {
    wrap();
    if (behind && ahead()) return false;
    for (Marker& m : markers_)
      if (m.gap > at_ || (m.gap == at_ && passed_ != forward_)) ++m.gap;
    ++loops_;
    if (!forward_) {
      ++at_;
      passed_ = passed_ && here() != markers_.end();
    }
    return true;
  }

  // w&t: the st wrapped goes back to the left needle; a marker placed just before it stays
  // behind the work.
  void unwork_wrapped() {
    at_ = forward_ ? at_ - 1 : at_ + 1;
    passed_ = here() != markers_.end();
  }

 private:
  struct Marker {
    std::uint32_t gap, id;
  };

  std::vector<Marker>::iterator here() {
    return std::find_if(markers_.begin(), markers_.end(),
                        [&](const Marker& m) { return m.gap == at_; });
  }

  // A marker at the gap of an operation's last loop taken moves with the loops made after
  // it; with nothing taken (a make-one), the marker ahead of the work does.
  bool shifts_at_cursor(std::uint32_t takes) const {
    if (takes > 0) return true;
    return forward_ != passed_;
  }

  void wrap() {
    if (!ring_) return;
    if (forward_ && at_ == loops_ && loops_ > 0) {
      at_ = 0;
      passed_ = false;
    } else if (!forward_ && at_ == 0) {
      at_ = loops_;
      passed_ = false;
    }
  }

  std::vector<Marker> markers_;
  std::uint32_t loops_, at_ = 0;
  bool ring_;
  bool forward_ = true, started_ = false;
  bool passed_ = false;  // the marker at the gap (if any) is behind the work
};

// Rows first..end (end included) around marked sts, and the lowest and highest gap marked.
struct Block {
  std::uint32_t first, end;
  std::uint32_t low = kFits, high = 0;
};

struct Target {
  std::uint32_t gap, block;
  bool dropped = false;
};

class SectionPlanner {
 public:
  SectionPlanner(HandPattern& p, const PatternSection& s,
                 const std::vector<std::vector<HandPattern::RegionMark>>& marks)
      : p_(p), s_(s), marks_(marks) {}

  // The section's rows with region markers, or nothing when none fits.
  std::optional<std::vector<std::vector<HandOp>>> run() && {
    std::optional<std::vector<Block>> blocks = find_blocks();
    if (!blocks || blocks->empty()) return std::nullopt;
    blocks_ = std::move(*blocks);
    for (std::uint32_t b = 0; b < blocks_.size(); ++b) {
      targets_.push_back({blocks_[b].low, b});
      if (blocks_[b].high != blocks_[b].low) targets_.push_back({blocks_[b].high, b});
    }
    for (;;) {
      std::uint32_t in_the_way = place();
      if (in_the_way == kFits) break;
      if (in_the_way == kOther) return std::nullopt;
      targets_[in_the_way - 1].dropped = true;
    }
    if (placed_ == 0) return std::nullopt;
    p_.markers = std::max<std::uint32_t>(p_.markers, most_markers_);
    return std::move(rows_);
  }

 private:
  std::span<const HandOp> ops(std::uint32_t row) const { return p_.ops_of(p_.rows[row]); }
  NeedleLine new_line() const { return NeedleLine(p_.rows[s_.first_row].sts_before, s_.in_round); }

  // A block starts at a row with a usable mark and ends at the first row after it with no
  // mark at all that works every st and leaves no short-row turn to resolve (or at the
  // section's end).
  std::optional<std::vector<Block>> find_blocks() const {
    std::vector<Block> blocks;
    NeedleLine line = new_line();
    std::int64_t unresolved = 0;
    bool open = false;
    for (std::uint32_t i = s_.first_row; i < s_.end_row; ++i) {
      const PatternRow& r = p_.rows[i];
      line.begin_row(r);
      bool marked = false;
      std::uint32_t ordinal = 0;
      auto mark = marks_[i].begin();
      for (HandOp op : ops(i)) {
        if (is_marker_op(op)) {
          if (!follow_marker_op(line, op)) return std::nullopt;
          continue;
        }
        for (; mark != marks_[i].end() && mark->op == ordinal; ++mark) {
          marked = marked || open;  // any mark keeps the block going (a turn at the edge)
          if (!line.free_here() || r.bind_off || !at_a_short_row(*mark)) continue;
          if (!open) blocks.push_back({i, i});
          open = marked = true;
          blocks.back().low = std::min(blocks.back().low, line.at());
          blocks.back().high = std::max(blocks.back().high, line.at());
        }
        if (follow(line, op, r.bind_off) != kFits) return std::nullopt;
        unresolved += turns_left(op);
        ++ordinal;
      }
      unresolved -= r.wraps_again ? 1 : 0;  // that w&t wraps a st still to be resolved
      if (open && !marked && !r.partial && unresolved == 0) {
        blocks.back().end = i;
        open = false;
      }
    }
    if (open) blocks.back().end = s_.end_row - 1;
    return blocks;
  }

  // A short row's turn is marked where a row turns short of the end, not at the edge: before
  // the turn of a short row, after the turn that ended one.
  bool at_a_short_row(const HandPattern::RegionMark& m) const {
    if (m.kind == MarkerKind::short_row_begin) return p_.rows[m.row].short_row;
    if (m.kind == MarkerKind::short_row_end)
      return m.row > s_.first_row && p_.rows[m.row - 1].short_row;
    return true;
  }

  // +1 for a turn a later row resolves (a double stitch, a wrap), -1 for one resolved.
  static int turns_left(HandOp op) {
    if (op == HandOp::ds || op == HandOp::wt) return 1;
    return resolves_turn(op) ? -1 : 0;
  }

  // The section markers and the BOR marker the rows already place, slip and remove.
  static bool follow_marker_op(NeedleLine& line, HandOp op) {
    if (op == HandOp::pm) {
      if (!line.free_here() && !line.at_round_start()) return false;
      line.place(kOther);
      return true;
    }
    if (!line.ahead()) return line.at_round_start();
    if (op == HandOp::sm)
      line.slip();
    else
      line.remove();
    return true;
  }

  static std::uint32_t follow(NeedleLine& line, HandOp op, bool bind_off) {
    if (from_spare(op)) return line.insert_ahead(from_spare_behind(op)) ? kFits : kOther;
    while (bind_off && takes_a_loop(op) && line.ahead()) line.remove();  // BO removes them
    std::uint32_t in_the_way = line.work(loops_taken(op), loops_made(op));
    if (op == HandOp::wt) line.unwork_wrapped();
    return in_the_way;
  }

  // Writes the section's rows with the targets not dropped: kFits, kOther when the rows
  // cannot be followed, or the id of a marker in the way (of an operation or a section
  // marker).
  std::uint32_t place() {
    rows_.assign(s_.end_row - s_.first_row, {});
    placed_at_.assign(targets_.size(), 0);
    placed_ = 0;
    most_markers_ = 0;
    NeedleLine line = new_line();
    std::uint32_t block = 0;
    for (std::uint32_t i = s_.first_row; i < s_.end_row; ++i) {
      const PatternRow& r = p_.rows[i];
      std::vector<HandOp>& out = rows_[i - s_.first_row];
      line.begin_row(r);
      while (block + 1 < blocks_.size() && blocks_[block].end < i) ++block;
      for (HandOp op : ops(i)) {
        if (is_marker_op(op)) {
          // A section marker where one of this pass's is: the latter is left out.
          if (auto mine = line.id_here(); mine && *mine != kOther) return *mine;
          if (!follow_marker_op(line, op)) return kOther;
        } else if (passes(op) && !r.bind_off) {
          pass_marker_ahead(line, i, out);
          if (op != HandOp::ds) place_targets_here(line, i, block, out);
        }
        if (!is_marker_op(op))
          if (std::uint32_t in_the_way = follow(line, op, r.bind_off); in_the_way != kFits)
            return in_the_way;
        out.push_back(op);
        most_markers_ = std::max(most_markers_, line.markers());
      }
    }
    // One the section's last rows do not reach stays on the needle: left out.
    return line.any_but(kOther).value_or(kFits);
  }

  // A marker of this pass ahead is slipped, or removed from the end row of its block on.
  void pass_marker_ahead(NeedleLine& line, std::uint32_t row, std::vector<HandOp>& out) {
    std::optional<std::uint32_t> mine = line.ahead();
    if (!mine || *mine == kOther) return;
    bool done = row >= blocks_[targets_[*mine - 1].block].end;
    out.push_back(done ? HandOp::rm : HandOp::sm);
    if (done)
      line.remove();
    else
      line.slip();
  }

  void place_targets_here(NeedleLine& line, std::uint32_t row, std::uint32_t block,
                          std::vector<HandOp>& out) {
    if (block >= blocks_.size() || row < blocks_[block].first || row >= blocks_[block].end) return;
    for (std::uint32_t t = 0; t < targets_.size(); ++t) {
      Target& target = targets_[t];
      if (target.dropped || target.block != block || target.gap != line.at() || placed_at_[t] ||
          !line.free_here())
        continue;
      out.push_back(HandOp::pm);
      line.place(t + 1);
      placed_at_[t] = 1;
      ++placed_;
    }
  }

  HandPattern& p_;
  const PatternSection& s_;
  const std::vector<std::vector<HandPattern::RegionMark>>& marks_;
  std::vector<Block> blocks_;
  std::vector<Target> targets_;
  std::vector<std::uint8_t> placed_at_;
  std::vector<std::vector<HandOp>> rows_;
  std::uint32_t placed_ = 0;
  std::size_t most_markers_ = 0;
};

// Holders and placements rearrange a section's needle between its rows, which the planner's
// line (rows only) does not follow, and they already say where the sts of the other piece (or
// of a split) are: such a section gets no region markers.
bool rearranged_between_rows(const PatternSection& s) {
  return !s.holdings.empty() || !s.placements.empty();
}

}  // namespace

void place_region_markers(HandPattern& pattern) {
  if (pattern.region_marks.empty()) return;
  std::vector<std::vector<HandPattern::RegionMark>> marks(pattern.rows.size());
  for (const HandPattern::RegionMark& m : pattern.region_marks) marks[m.row].push_back(m);
  std::vector<std::optional<std::vector<HandOp>>> rewritten(pattern.rows.size());
  for (const PatternSection& s : pattern.sections) {
    if (rearranged_between_rows(s)) continue;
    auto rows = SectionPlanner(pattern, s, marks).run();
    if (!rows) continue;
    for (std::uint32_t i = s.first_row; i < s.end_row; ++i)
      rewritten[i] = std::move((*rows)[i - s.first_row]);
  }
  rewrite_rows(pattern, rewritten);
}

}  // namespace skein::hand
