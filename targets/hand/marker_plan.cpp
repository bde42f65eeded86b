#include "hand/marker_plan.hpp"

#include <algorithm>
#include <optional>

#include "hand/row_text.hpp"

namespace skein::hand {
namespace {

// A row worked as `count` equal sections, each taking `takes` loops and making `makes`.
struct Shaping {
  std::uint32_t count, takes, makes;
};

// Rows first..last: shaped rows with the same number of sections, each taking what the one
// before made, and only plain rows between them.
struct Group {
  std::uint32_t first, last;
  Shaping shaping;  // of the first
};

using Positions = std::vector<std::uint32_t>;  // loops before each marker, in working order

std::optional<Shaping> shaping_of(const HandPattern& p, const PatternRow& r) {
  if (r.bind_off) return std::nullopt;
  auto ops = p.ops_of(r);
  std::optional<RowRepeat> repeat = whole_row_repeat(ops);
  if (!repeat) return std::nullopt;
  Shaping s{repeat->count, 0, 0};
  for (HandOp op : ops.first(repeat->unit_ops)) {
    s.takes += info(op).takes;
    s.makes += info(op).makes;
  }
  if (s.takes == s.makes) return std::nullopt;
  return s;
}

bool is_plain_row(const HandPattern& p, const PatternRow& r) {
  auto ops = p.ops_of(r);
  return !ops.empty() && is_plain(ops[0]) &&
         std::all_of(ops.begin(), ops.end(), [&](HandOp op) { return op == ops[0]; });
}

// `ops` with `marker` inserted where `at[k]` loops have been taken (or made, `by_made`);
// nullopt when a position falls inside an operation, or (placing) between a stitch and its
// make-one. A make-one at a taken position goes before the marker: it belongs to the stitch
// before. `made_at` receives the loops made before each marker.
std::optional<std::vector<HandOp>> with_markers(std::span<const HandOp> ops, const Positions& at,
                                                HandOp marker, bool by_made, Positions& made_at) {
  std::vector<HandOp> out;
  out.reserve(ops.size() + at.size());
  made_at.clear();
  std::uint32_t taken = 0, made = 0;
  std::size_t k = 0, i = 0;
  auto work = [&](HandOp op) {
    out.push_back(op);
    taken += info(op).takes;
    made += info(op).makes;
  };
  for (;; work(ops[i++])) {
    bool at_marker = k < at.size() && at[k] == (by_made ? made : taken);
    for (; at_marker && i < ops.size() && is_make_one(ops[i]); ++i) {
      if (by_made) return std::nullopt;
      work(ops[i]);
    }
    for (; k < at.size() && at[k] == (by_made ? made : taken); ++k) {
      out.push_back(marker);
      made_at.push_back(made);
    }
    if (k < at.size() && (by_made ? made : taken) > at[k]) return std::nullopt;
    if (i == ops.size()) break;
  }
  if (k != at.size()) return std::nullopt;
  return out;
}

class Planner {
 public:
  explicit Planner(HandPattern& p) : p_(p), rewritten_(p.rows.size()) {}

  void run() && {
    for (const PatternSection& s : p_.sections) {
      if (s.in_round) p_.markers = std::max<std::uint32_t>(p_.markers, 1);
      for (std::uint32_t i = s.first_row + 1; i < s.end_row;) {
        std::optional<Group> g = group_at(i, s.end_row);
        std::optional<std::uint32_t> next = g ? apply(*g, s) : std::nullopt;
        i = next ? *next : i + 1;
      }
    }
    rebuild_ops();
  }

 private:
  std::optional<Group> group_at(std::uint32_t i, std::uint32_t end) const {
    std::optional<Shaping> first = shaping_of(p_, p_.rows[i]);
    if (!first || first->count < 2 || rewritten_[i - 1]) return std::nullopt;
    Group g{i, i, *first};
    Shaping now = *first;
    std::uint32_t shaped = 1;
    for (std::uint32_t j = i + 1; j < end; ++j) {
      if (is_plain_row(p_, p_.rows[j])) continue;
      std::optional<Shaping> s = shaping_of(p_, p_.rows[j]);
      if (!s || s->count != now.count || s->takes != now.makes) break;
      now = *s;
      g.last = j;
      ++shaped;
    }
    if (shaped < 2) return std::nullopt;
    return g;
  }

  // Places the markers on the row before the group and slips them on; returns the first row
  // after the rows it rewrote, or nullopt (and changes nothing) when they cannot stay aligned.
  std::optional<std::uint32_t> apply(const Group& g, const PatternSection& s) {
    std::vector<std::pair<std::uint32_t, std::vector<HandOp>>> rows;
    Positions at, made_at;
    for (std::uint32_t k = 1; k < g.shaping.count; ++k) at.push_back(k * g.shaping.takes);
    auto placed = with_markers(ops(g.first - 1), at, HandOp::pm, true, made_at);
    if (!placed) return std::nullopt;
    rows.emplace_back(g.first - 1, std::move(*placed));
    // The markers come off with the last shaped row where other rows follow, or where the sts
    // go on to be worked after this section (a piece set aside, left on a spare needle or
    // parted to holders): counted instructions there would meet them.
    bool worked_on = s.set_aside || s.left_live || s.last_row_held();
    bool remove = worked_on || std::any_of(p_.rows.begin() + g.last + 1,
                                           p_.rows.begin() + s.end_row, [&](const PatternRow& r) {
                                             return !r.bind_off && !is_plain_row(p_, r);
                                           });
    std::uint32_t j = g.first;
    for (; j < s.end_row && !p_.rows[j].bind_off && (j <= g.last || !remove); ++j) {
      if (rearranged_before(s, j)) return std::nullopt;
      auto slipped =
          with_markers(ops(j), at, remove && j == g.last ? HandOp::rm : HandOp::sm, false, made_at);
      if (!slipped) return std::nullopt;
      rows.emplace_back(j, std::move(*slipped));
      at = next_positions(p_.rows[j], made_at);
    }
    for (auto& [row, new_ops] : rows) rewritten_[row] = std::move(new_ops);
    p_.markers = std::max(p_.markers, g.shaping.count - 1 + (s.in_round ? 1 : 0));
    return j;
  }

  // Sts placed into the needle or slipped to holders before the row move the sts the markers
  // were counted between (the teapot at 14/20 places a holder at the beginning of the rnd
  // between the row that places them and the first shaped one).
  static bool rearranged_before(const PatternSection& s, std::uint32_t row) {
    return std::any_of(s.placements.begin(), s.placements.end(),
                       [&](const PatternSection::Placement& p) { return p.before_row == row; }) ||
           std::any_of(s.holdings.begin(), s.holdings.end(),
                       [&](const PatternSection::Holding& h) { return h.after_row + 1 == row; });
  }

  // Where the markers are for the next row: in the round in the same order, on a flat piece
  // counted from the other end.
  static Positions next_positions(const PatternRow& r, const Positions& made_at) {
    if (r.round) return made_at;
    Positions at;
    for (auto it = made_at.rbegin(); it != made_at.rend(); ++it) at.push_back(r.sts_after - *it);
    return at;
  }

  std::span<const HandOp> ops(std::uint32_t row) const {
    if (rewritten_[row]) return *rewritten_[row];
    return p_.ops_of(p_.rows[row]);
  }

  void rebuild_ops() { rewrite_rows(p_, rewritten_); }

  HandPattern& p_;
  std::vector<std::optional<std::vector<HandOp>>> rewritten_;
};

}  // namespace

void place_section_markers(HandPattern& pattern) {
  Planner(pattern).run();
}

void rewrite_rows(HandPattern& pattern,
                  const std::vector<std::optional<std::vector<HandOp>>>& rewritten) {
  std::vector<HandOp> all;
  all.reserve(pattern.ops.size());
  for (std::uint32_t r = 0; r < pattern.rows.size(); ++r) {
    auto row_ops =
        rewritten[r] ? std::span<const HandOp>(*rewritten[r]) : pattern.ops_of(pattern.rows[r]);
    std::uint32_t first = static_cast<std::uint32_t>(all.size());
    all.insert(all.end(), row_ops.begin(), row_ops.end());
    pattern.rows[r].first_op = first;
    pattern.rows[r].end_op = static_cast<std::uint32_t>(all.size());
  }
  pattern.ops = std::move(all);
}

}  // namespace skein::hand
