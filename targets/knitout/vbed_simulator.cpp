#include "knitout/vbed_simulator.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cstring>
#include <limits>

#include "common/error.hpp"

namespace skein::knitout {
namespace {

// The magic line, the header and the line after it: all that is ever quoted by number.
std::vector<std::string_view> header_lines(std::string_view text) {
  std::vector<std::string_view> lines;
  for (std::size_t pos = 0; pos < text.size();) {
    std::size_t end = std::min(text.find('\n', pos), text.size());
    lines.push_back(text.substr(pos, end - pos));
    if (lines.size() > 1 && !lines.back().starts_with(";;")) break;
    pos = end + 1;
  }
  return lines;
}

constexpr std::uint32_t kMaxStack = 15;  // the most loops a profile may allow on one needle

struct Stack {
  std::uint8_t size = 0;
  std::array<LoopId, kMaxStack> loop;
};

enum class CarrierState : std::uint8_t { out, pending, in };

struct Carrier {
  CarrierState state = CarrierState::out;
  bool hooked = false;     // held by the yarn-inserting hook
  bool stitched = false;   // has made a stitch since it came in
  CarrierMask in_set = 0;  // the set it came in with (first use must match it)
  std::size_t in_line = 0;
  std::uint32_t piece = 0;
};

// A carriage pass: consecutive stitch ops in one direction with the same carriers and rack,
// each further along than the last; or consecutive transfers/drops at one rack.
struct PassTracker {
  bool open = false, transfer = false;
  Direction dir = Direction::none;
  CarrierMask carriers = 0;
  std::int32_t rack = 0, first = 0, last = 0;
};

class VirtualBed {
 public:
  VirtualBed(const std::string& file, const MachineProfile& profile, std::string_view text,
             ReplayOptions options)
      : file_(file),
        p_(profile),
        options_(options),
        text_(text),
        lines_(header_lines(text)),
        line_count_(count_lines(text)) {
    n_ = static_cast<std::int32_t>(p_.needles);
    for (std::size_t r = 0; r < severity_.size(); ++r)
      severity_[r] = rule_severity(static_cast<Rule>(r), p_, options_.strict);
  }

  Replay run() {
    r_.header = parse_header(lines_, file_);
    check_header();
    keep_ = r_.header.position.empty() || r_.header.position == "Keep";
    // Strict, with Keep, the bed is exactly 0..n-1; otherwise the back end places the design,
    // and any n needles in a row may be used: the v-bed keeps room for them.
    bool exact = keep_ && severity(Rule::needle_off_bed) == Severity::error;
    lo_ = exact ? 0 : -2 * n_;
    hi_ = exact ? n_ : 3 * n_;
    for (auto& bed : beds_) bed.assign(static_cast<std::size_t>(hi_ - lo_), Stack{});
    carriers_.assign(r_.header.carriers.size(), Carrier{});
    r_.fabric.by_carrier.assign(r_.header.carriers.size(), {});
    r_.fabric.loops.reserve(line_count_);  // at most one loop a line: no regrowth
    r_.fabric.parents.reserve(line_count_);
    r_.stats.min_needle = std::numeric_limits<std::int32_t>::max();
    r_.stats.max_needle = std::numeric_limits<std::int32_t>::min();
    last_slot_.assign(r_.header.carriers.size(), kNoSlot);
    std::string error;
    Op op;
    // Operations are read straight from the text, a line at a time.
    std::size_t pos = 0;
    for (std::size_t skip = 1; skip < r_.header.first_op_line && pos < text_.size(); ++skip)
      pos = next_line(pos);
    for (line_ = r_.header.first_op_line; pos < text_.size(); ++line_) {
      std::size_t next = next_line(pos);
      std::string_view text = current_ = text_.substr(pos, next - pos - 1);
      if (next > text_.size()) text = last_line_ = std::string(text) + '\n';  // see parse_op
      pos = next;
      if (!parse_op(text, r_.header, op, error)) {
        if (!error.empty()) fail(error);
        continue;
      }
      ++r_.stats.operations;
      last_op_line_ = line_;
      last_op_ = current_;
      apply(op);
    }
    finish();
    return std::move(r_);
  }

 private:
  [[noreturn]] void fail(const std::string& why) const {
    throw ParseError(file_, line_, std::string(current_), why);
  }

  Severity severity(Rule rule) const { return severity_[static_cast<std::size_t>(rule)]; }

  // Breaks `rule` at the current line: an error stops the replay; a warning or a note is kept
  // (its first message and a count) and the replay goes on. The message is made at most once.
  template <typename Message>
  void breaks(Rule rule, Message&& message) {
    Severity s = severity(rule);
    if (s == Severity::off) return;
    if (s == Severity::error) fail(message());
    record(rule, s, line_, message);
  }
  template <typename Message>
  void breaks_header(std::size_t line, Rule rule, Message&& message) {
    Severity s = severity(rule);
    if (s == Severity::off) return;
    if (s == Severity::error) fail_header(line, message());
    record(rule, s, line, message);
  }
  template <typename Message>
  void record(Rule rule, Severity s, std::size_t line, Message& message) {
    Finding& f = found_[static_cast<std::size_t>(rule)];
    if (f.count++ > 0) return;
    f.rule = rule;
    f.severity = s;
    f.line = line;
    f.message = message();
  }

  // Sums of at most 255 per block fit a byte, so the compiler can count 16 or 32 bytes an
  // instruction (std::count widens every byte to 64 bits: 6% of a replay).
  static std::size_t count_lines(std::string_view text) {
    constexpr std::size_t kBlock = 255;
    std::size_t lines = 1;
    for (std::size_t at = 0; at < text.size(); at += kBlock) {
      std::uint8_t newlines = 0;
      for (char c : text.substr(at, kBlock)) newlines += c == '\n';
      lines += newlines;
    }
    return lines;
  }

  std::size_t next_line(std::size_t pos) const {
    const void* end = std::memchr(text_.data() + pos, '\n', text_.size() - pos);
    return end ? static_cast<std::size_t>(static_cast<const char*>(end) - text_.data()) + 1
               : text_.size() + 1;
  }

  [[noreturn]] void fail_header(std::size_t line, const std::string& why) const {
    throw ParseError(file_, line,
                     line && line <= lines_.size() ? std::string(lines_[line - 1]) : "", why);
  }

  void check_header() {
    const Header& h = r_.header;
    if (!h.has_carriers)
      fail_header(h.first_op_line - 1,
                  fmt::format("missing the ;;Carriers: header ({} needs ';;Carriers: {}')", p_.name,
                              p_.carriers_line()));
    if (h.carriers != p_.carriers)
      breaks_header(h.carriers_line, Rule::carriers_line, [&] {
        return fmt::format("{} needs ';;Carriers: {}'", p_.name, p_.carriers_line());
      });
    auto header_line = [&](std::string_view key) {
      for (std::size_t i = 1; i < h.first_op_line - 1; ++i)
        if (lines_[i].starts_with(fmt::format(";;{}:", key))) return i + 1;
      return std::size_t{1};
    };
    if (options_.check_machine && !h.machine.empty() && !p_.is_machine(h.machine))
      breaks_header(header_line("Machine"), Rule::machine_header, [&] {
        return fmt::format("the file is for machine '{}', profile {} is '{}'", h.machine, p_.name,
                           p_.machine);
      });
    if (options_.check_machine && !h.gauge.empty() &&
        std::strtod(h.gauge.c_str(), nullptr) != p_.gauge)
      breaks_header(header_line("Gauge"), Rule::gauge_header, [&] {
        return fmt::format("the file is for gauge {}, {} is gauge {}", h.gauge, p_.name, p_.gauge);
      });
    if (!h.width.empty() && std::stoul(h.width) > p_.needles)
      breaks_header(header_line("Width"), Rule::width_header, [&] {
        return fmt::format("the file asks for {} needles, {} has {}", h.width, p_.name, p_.needles);
      });
  }

  // ---- needles ----
  Stack& at(Needle n) {
    if (is_slider(n.bed) && !p_.sliders)
      breaks(Rule::no_sliders, [&] {
        return fmt::format("{} is a slider, and {} has no sliders", needle_name(n), p_.name);
      });
    if (keep_ && (n.index < 0 || n.index >= n_))
      breaks(Rule::needle_off_bed, [&] {
        return fmt::format("needle {} is outside the bed: {} has needles 0..{}", needle_name(n),
                           p_.name, n_ - 1);
      });
    if (n.index < lo_ || n.index >= hi_)
      fail(fmt::format("needle {} is further from 0 than the v-bed tracks on {} ({}..{})",
                       needle_name(n), p_.name, lo_, hi_ - 1));
    ShopStats& s = r_.stats;
    s.min_needle = std::min(s.min_needle, n.index);
    s.max_needle = std::max(s.max_needle, n.index);
    if (s.max_needle - s.min_needle >= n_)
      breaks(Rule::needle_span, [&] {
        return fmt::format("the needles used span {}..{} ({} needles), {} has {}", s.min_needle,
                           s.max_needle, s.max_needle - s.min_needle + 1, p_.name, n_);
      });
    return beds_[static_cast<int>(n.bed)][static_cast<std::size_t>(n.index - lo_)];
  }

  void push(Stack& s, Needle n, LoopId loop) {
    if (s.size >= p_.max_loops_per_needle)
      breaks(Rule::loops_per_needle, [&] {
        return fmt::format("{} would hold {} loops, {} allows {} per needle", needle_name(n),
                           s.size + 1, p_.name, p_.max_loops_per_needle);
      });
    if (s.size >= kMaxStack)
      breaks(Rule::needle_overfull, [&] {
        return fmt::format("{} would hold {} loops, more than the v-bed tracks", needle_name(n),
                           s.size + 1);
      });
    s.loop[s.size++] = loop;
  }

  // ---- carriers ----
  std::string names(CarrierMask mask) const { return carrier_names(r_.header, mask); }

  template <typename F>
  void each(CarrierMask mask, F f) {
    for (; mask; mask &= mask - 1) {  // straight to each set bit: a high carrier costs no more
      auto c = static_cast<std::size_t>(std::countr_zero(mask));
      f(carriers_[c], c);
    }
  }

  void use_carriers(const Op& op) {
    if ((op.carriers & ~carriers_in_) == 0) return;  // all in and stitched: nothing to check
    CarrierMask pending = 0;
    each(op.carriers, [&](Carrier& c, std::size_t i) {
      if (c.state == CarrierState::out)
        breaks(Rule::carrier_not_in, [&] {
          return fmt::format("carrier {} is not in (bring it in with {} first)",
                             r_.header.carriers[i], p_.hook == YarnHook::inhook ? "inhook" : "in");
        });
      if (c.state == CarrierState::pending) pending |= c.in_set;
    });
    if (pending) {
      if (pending != op.carriers)
        breaks(Rule::first_use_set, [&] {
          return fmt::format(
              "the first use of carriers {} must use exactly the set brought in together ({})",
              names(op.carriers), names(pending));
        });
      if (op.dir != p_.first_pass)
        breaks(Rule::first_pass_direction, [&] {
          return fmt::format(
              "the first pass after bringing in carrier {} must go {} on {}, found {}",
              names(op.carriers), direction_char(p_.first_pass), p_.name, direction_char(op.dir));
        });
    }
    // The hook holds the yarn's end beside the first stitch, on the side the carrier came from.
    if ((pending & hook_) && p_.hook == YarnHook::inhook) {
      hook_edge_ = op.a.index;
      hook_side_ = opposite(op.dir);
    }
    each(op.carriers, [&](Carrier& c, std::size_t) {
      c.state = CarrierState::in;
      c.stitched = true;
    });
    carriers_in_ |= op.carriers;
  }

  // Until releasehook, the needles beyond the first stitch on the hook's side are in its way.
  void check_hook_clear(Needle n) {
    bool beyond = hook_side_ == Direction::plus ? n.index > hook_edge_ : n.index < hook_edge_;
    if (beyond)
      breaks(Rule::hook_blocks, [&] {
        return fmt::format(
            "{} is blocked by the yarn-inserting hook, which holds carrier {} {} of needle {} "
            "until releasehook",
            needle_name(n), names(hook_), hook_side_ == Direction::plus ? "right" : "left",
            hook_edge_);
      });
  }
  void check_hook_clear(const Op& op) {
    switch (op.code) {
      case OpCode::split:
      case OpCode::xfer:
        check_hook_clear(op.b);
        [[fallthrough]];
      case OpCode::knit:
      case OpCode::tuck:
      case OpCode::miss:
      case OpCode::drop:
      case OpCode::amiss:
        return check_hook_clear(op.a);
      default:
        return;
    }
  }

  void bring_in(const Op& op) {
    bool hook = op.code == OpCode::inhook;
    if (hook) check_has_hook("in");
    if (hook && hook_)
      breaks(Rule::hook_busy, [&] {
        return fmt::format("the yarn-inserting hook still holds carrier {}: releasehook it first",
                           names(hook_));
      });
    each(op.carriers, [&](Carrier& c, std::size_t i) {
      if (c.state != CarrierState::out)
        breaks(Rule::carrier_already_in,
               [&] { return fmt::format("carrier {} is already in", r_.header.carriers[i]); });
      c = Carrier{CarrierState::pending, hook, false, op.carriers, line_, ++pieces_};
      ++r_.stats.yarn_pieces;
    });
    if (hook) hook_ = op.carriers;
  }

  // An inhook, releasehook or outhook on a machine without a hook: its back end uses in / out.
  void check_has_hook(const char* instead) {
    if (p_.hook == YarnHook::inhook) return;
    breaks(Rule::no_hook, [&] {
      return severity(Rule::no_hook) == Severity::error
                 ? fmt::format("{} has no yarn-inserting hook{}", p_.name,
                               *instead ? fmt::format(": use '{}'", instead) : " to release")
                 : fmt::format(
                       "{} has no yarn-inserting hook: its back end knits inhook as in, "
                       "outhook as out",
                       p_.name);
    });
  }

  void release_hook(const Op& op) {
    check_has_hook("");
    if (hook_ != op.carriers)
      breaks(Rule::releasehook_mismatch, [&] {
        return hook_
                   ? fmt::format("the hook holds carrier {}, not {}", names(hook_),
                                 names(op.carriers))
                   : fmt::format("releasehook {}, but the hook holds nothing", names(op.carriers));
      });
    each(op.carriers, [&](Carrier& c, std::size_t i) {
      if (!c.stitched)
        breaks(Rule::releasehook_early, [&] {
          return fmt::format("releasehook before carrier {} has made a stitch",
                             r_.header.carriers[i]);
        });
      c.hooked = false;
    });
    hook_ = 0;
    hook_side_ = Direction::none;
  }

  void take_out(const Op& op) {
    bool hook = op.code == OpCode::outhook;
    if (hook) check_has_hook("out");
    if (hook && hook_)
      breaks(Rule::hook_busy, [&] {
        return fmt::format("outhook while the hook still holds carrier {}: releasehook it first",
                           names(hook_));
      });
    each(op.carriers, [&](Carrier& c, std::size_t i) {
      const std::string& name = r_.header.carriers[i];
      if (c.state == CarrierState::out)
        breaks(Rule::out_not_in, [&] { return fmt::format("carrier {} is not in", name); });
      if (!c.stitched)
        breaks(Rule::out_without_stitch, [&] {
          return fmt::format("carrier {} is taken out without having made a stitch", name);
        });
      if (c.hooked)
        breaks(Rule::out_while_hooked, [&] {
          return fmt::format("carrier {} is still held by the hook: releasehook {} first", name,
                             name);
        });
      c.state = CarrierState::out;
      last_slot_[i] = kNoSlot;
    });
    carriers_in_ &= ~op.carriers;
  }

  // ---- racking and alignment ----
  void set_rack(std::int32_t quarters) {
    if (std::abs(quarters) > p_.max_rack * 4)
      breaks(Rule::rack_limit, [&] {
        return fmt::format("rack {} is beyond the racking limit of {} (±{})", quarters / 4.0,
                           p_.name, p_.max_rack);
      });
    if (!p_.rack_fraction_allowed(quarters))
      breaks(Rule::rack_fraction, [&] {
        return fmt::format("rack {} has a fraction {} does not allow", quarters / 4.0, p_.name);
      });
    if (quarters != rack_) ++r_.stats.racks;
    rack_ = quarters;
  }

  void check_transfer(const Op& op) {
    const char* what = op.code == OpCode::split ? "split" : "xfer";
    if (is_slider(op.a.bed) && is_slider(op.b.bed))
      breaks(Rule::transfer_slider_slider, [&] {
        return fmt::format("{} {} {} moves from slider to slider", what, needle_name(op.a),
                           needle_name(op.b));
      });
    if (is_front(op.a.bed) == is_front(op.b.bed))
      breaks(Rule::transfer_same_bed, [&] {
        return fmt::format("{} {} {} stays on one bed: loops move only between front and back",
                           what, needle_name(op.a), needle_name(op.b));
      });
    Needle front = is_front(op.a.bed) ? op.a : op.b, back = is_front(op.a.bed) ? op.b : op.a;
    if (rack_ % 4 != 0 || front.index * 4 != back.index * 4 + rack_)
      breaks(Rule::transfer_misaligned, [&] {
        return fmt::format("{} and {} are not aligned at rack {} ({} faces f{})", needle_name(op.a),
                           needle_name(op.b), rack_ / 4.0, needle_name(back),
                           rack_ % 4 ? fmt::format("{}", back.index + rack_ / 4.0)
                                     : fmt::format("{}", back.index + rack_ / 4));
      });
    if (std::abs(rack_) > p_.max_transfer_stretch * 4)
      breaks(Rule::transfer_stretch, [&] {
        return fmt::format("{} at rack {} stretches a loop {} needles, {} allows {}", what,
                           rack_ / 4, std::abs(rack_ / 4), p_.name, p_.max_transfer_stretch);
      });
  }

  // ---- loops ----
  LoopId new_loop(OpCode by, Direction dir, Needle n, CarrierMask yarn,
                  std::span<const LoopId> through) {
    LoopId id = static_cast<LoopId>(r_.fabric.loops.size());
    FabricLoop l;
    l.first_parent = static_cast<std::uint32_t>(r_.fabric.parents.size());
    l.parent_count = static_cast<std::uint8_t>(through.size());
    l.made_by = by;
    l.front = is_front(n.bed);
    l.dir = dir;
    l.yarn = yarn;
    l.line = static_cast<std::uint32_t>(line_);
    l.needle = n.index;
    std::size_t lowest = static_cast<std::size_t>(std::countr_zero(yarn));
    l.piece = carriers_[lowest].piece;
    for (LoopId parent : through) {
      r_.fabric.parents.push_back(parent);
      auto& children = r_.fabric.loops[parent].children;
      if (children < 255) ++children;
    }
    r_.fabric.loops.push_back(l);
    each(yarn, [&](Carrier&, std::size_t c) {
      count_float(c, n.index);
      std::vector<LoopId>& along = r_.fabric.by_carrier[c];
      if (along.empty()) along.reserve(line_count_);
      along.push_back(id);
    });
    return id;
  }

  // The yarn from a carrier's last loop to this one floats across the needles between.
  void count_float(std::size_t carrier, std::int32_t needle) {
    std::int32_t& last = last_slot_[carrier];
    if (last != kNoSlot && p_.max_float && std::abs(needle - last) > std::int32_t(p_.max_float))
      ++r_.stats.long_floats;
    last = needle;
  }

  void stitch_op(const Op& op) {
    if (op.code == OpCode::split && is_slider(op.a.bed))
      breaks(Rule::split_from_slider, [&] {
        return fmt::format("split cannot start from a slider ({})", needle_name(op.a));
      });
    else if (is_slider(op.a.bed))
      breaks(Rule::stitch_on_slider, [&] {
        return fmt::format("{} on a slider ({}): sliders only hold loops moved there",
                           op_name(op.code), needle_name(op.a));
      });
    if (op.code == OpCode::miss) {
      if (!op.carriers)
        breaks(Rule::miss_without_carriers, [] {
          return std::string("miss needs carriers (a miss without yarn does nothing)");
        });
      use_carriers(op);
      count_pass(op, false);
      ++r_.stats.misses;
      return;
    }
    Stack& s = at(op.a);
    if (!op.carriers)
      return op.code == OpCode::knit    ? drop(op.a)
             : op.code == OpCode::split ? transfer(op)
                                        : void(at(op.a));
    if (op.code == OpCode::split) check_transfer(op);
    if (s.size == 0 && op.code != OpCode::tuck) {
      ++r_.stats.empty_knits;
      breaks(Rule::knit_empty_needle, [&] {
        return severity(Rule::knit_empty_needle) == Severity::error
                   ? fmt::format(
                         "{} on {}, which holds no loop ({} treats knitting an empty "
                         "needle as an error)",
                         op_name(op.code), needle_name(op.a), p_.name)
                   : fmt::format("{} on {}, which holds no loop: a new loop held by nothing",
                                 op_name(op.code), needle_name(op.a));
      });
    }
    use_carriers(op);
    count_pass(op, false);
    if (op.code == OpCode::tuck) {
      ++r_.stats.tucks;
      push(s, op.a, new_loop(OpCode::tuck, op.dir, op.a, op.carriers, {}));
      return;
    }
    LoopId made = new_loop(op.code, op.dir, op.a, op.carriers, {s.loop.data(), s.size});
    if (op.code == OpCode::split) {
      ++r_.stats.splits;
      Stack& to = at(op.b);
      for (std::uint8_t i = 0; i < s.size; ++i) push(to, op.b, s.loop[i]);
    } else {
      ++r_.stats.knits;
    }
    s.size = 0;
    s.loop[s.size++] = made;
  }

  void drop(Needle n) {
    Stack& s = at(n);
    Op op;
    op.code = OpCode::drop;
    op.a = n;
    count_pass(op, true);
    for (std::uint8_t i = 0; i < s.size; ++i)
      if (r_.fabric.loops[s.loop[i]].children == 0) r_.fabric.loops[s.loop[i]].dropped = true;
    r_.stats.loops_dropped += s.size;
    s.size = 0;
  }

  void transfer(const Op& op) {
    check_transfer(op);
    Stack& from = at(op.a);
    Stack& to = at(op.b);
    count_pass(op, true);
    ++r_.stats.transfers;
    for (std::uint8_t i = 0; i < from.size; ++i) push(to, op.b, from.loop[i]);
    from.size = 0;
  }

  void count_pass(const Op& op, bool transfer) {
    ShopStats& s = r_.stats;
    std::int32_t slot = op.a.index + (is_front(op.a.bed) ? 0 : rack_ / 4);
    PassTracker& t = pass_;
    bool continues = t.open && t.transfer == transfer && t.rack == rack_;
    if (continues && !transfer)
      continues = t.dir == op.dir && t.carriers == op.carriers &&
                  (op.dir == Direction::plus ? slot >= t.last : slot <= t.last);
    if (!continues) {
      close_pass();
      t = PassTracker{true, transfer, op.dir, op.carriers, rack_, slot, slot};
      ++(transfer ? s.transfer_passes : s.stitch_passes);
    }
    t.first = std::min(t.first, slot);
    t.last = transfer ? std::max(t.last, slot) : slot;
    span_lo_ = continues ? std::min(span_lo_, slot) : slot;
    span_hi_ = continues ? std::max(span_hi_, slot) : slot;
  }
  void close_pass() {
    if (pass_.open) r_.stats.needles_crossed += static_cast<std::uint64_t>(span_hi_ - span_lo_ + 1);
    pass_.open = false;
  }

  void apply(const Op& op) {
    if (hook_side_ != Direction::none) check_hook_clear(op);
    switch (op.code) {
      case OpCode::in:
      case OpCode::inhook:
        return bring_in(op);
      case OpCode::releasehook:
        return release_hook(op);
      case OpCode::out:
      case OpCode::outhook:
        return take_out(op);
      case OpCode::knit:
      case OpCode::tuck:
      case OpCode::split:
      case OpCode::miss:
        return stitch_op(op);
      case OpCode::drop:
        return drop(op.a);
      case OpCode::amiss:
        if (is_slider(op.a.bed))
          breaks(Rule::stitch_on_slider,
                 [&] { return fmt::format("amiss on a slider ({})", needle_name(op.a)); });
        at(op.a);
        return;
      case OpCode::xfer:
        return transfer(op);
      case OpCode::rack:
        return set_rack(op.rack_quarters);
      case OpCode::stitch:
      case OpCode::pause:
      case OpCode::extension:
        return;
    }
  }

  void finish() {
    close_pass();
    line_ = last_op_line_ ? last_op_line_ : lines_.size();
    current_ = last_op_line_ ? last_op_ : lines_.back();
    for (std::size_t c = 0; c < carriers_.size(); ++c)
      if (carriers_[c].state != CarrierState::out)
        breaks(Rule::carrier_left_in, [&] {
          return fmt::format("carrier {} is still in at the end of the file (take it out with {})",
                             r_.header.carriers[c],
                             p_.hook == YarnHook::inhook ? "outhook" : "out");
        });
    for (const Finding& f : found_)
      if (f.count) r_.findings.push_back(f);
    for (const auto& bed : beds_)
      for (const Stack& s : bed) r_.stats.loops_left += s.size;
    ShopStats& s = r_.stats;
    if (s.max_needle < s.min_needle) s.min_needle = s.max_needle = 0;
    s.seconds = static_cast<double>(s.stitch_passes + s.transfer_passes) * p_.seconds_per_pass +
                static_cast<double>(s.needles_crossed) * p_.seconds_per_needle +
                static_cast<double>(s.racks) * p_.seconds_per_rack;
  }

  static constexpr std::int32_t kNoSlot = std::numeric_limits<std::int32_t>::min();

  std::string file_;
  const MachineProfile& p_;
  ReplayOptions options_;
  std::array<Severity, static_cast<std::size_t>(Rule::count)> severity_{};
  std::array<Finding, static_cast<std::size_t>(Rule::count)> found_{};
  std::vector<std::int32_t> last_slot_;  // per carrier: where its last loop was (for floats)
  std::string_view text_;
  std::vector<std::string_view> lines_;  // the header's lines only
  // Counted, not bounded by bytes / 8: that reserved twice the memory, and past glibc's largest
  // mmap threshold (32 MB), so each replay in a process faulted every page in again.
  std::size_t line_count_;
  std::string_view current_, last_op_;  // the line being replayed, the last operation's
  std::string last_line_;               // the last line with a '\n', if the file has none
  Replay r_;
  std::array<std::vector<Stack>, 4> beds_;
  std::vector<Carrier> carriers_;
  CarrierMask hook_ = 0;
  CarrierMask carriers_in_ = 0;            // the carriers in state `in` (which have made a stitch)
  std::int32_t hook_edge_ = 0;             // the needle of the hooked yarn's first stitch
  Direction hook_side_ = Direction::none;  // the side of it the hook blocks (none: no hook)
  std::uint32_t pieces_ = 0;
  std::int32_t rack_ = 0, n_ = 0, lo_ = 0, hi_ = 0, span_lo_ = 0, span_hi_ = 0;
  bool keep_ = true;
  PassTracker pass_;
  std::size_t line_ = 0, last_op_line_ = 0;
};

}  // namespace

Header read_header(std::string_view text, const std::string& file) {
  return parse_header(header_lines(text), file);
}

ProfileChoice choose_profile(std::string_view text, const std::string& file,
                             const std::string& machine, bool strict) {
  ProfileChoice c;
  c.options.strict = strict;
  if (!machine.empty()) {
    c.profile = load_machine_profile(machine);
    return c;
  }
  std::string named = read_header(text, file).machine;
  if (auto known = profile_for_machine(named)) {
    c.profile = std::move(*known);
    c.how = fmt::format(" (the file's ;;Machine: {})", named);
    return c;
  }
  c.profile = load_machine_profile("generic");
  c.options.check_machine = false;
  c.how =
      named.empty()
          ? " (note: the file names no ;;Machine:; give --machine to replay it on one)"
          : fmt::format(" (note: no profile knows ;;Machine: {}; give --machine for one)", named);
  return c;
}

Replay replay_knitout(std::string_view text, const std::string& file, const MachineProfile& profile,
                      ReplayOptions options) {
  return VirtualBed(file, profile, text, options).run();
}

std::string shop_summary(const Replay& r, const MachineProfile& p) {
  const ShopStats& s = r.stats;
  auto minutes = static_cast<int>(s.seconds / 60);
  return fmt::format(
      "  machine: {} ({}), needles {}..{} used\n"
      "  carriage passes: {} ({} knitting, {} transfer)\n"
      "  stitches: {} knit, {} tuck, {} split, {} miss\n"
      "  transfers: {}, rack changes: {}, loops dropped: {}, loops left on the needles: {}\n"
      "  yarn pieces: {}{}\n"
      "  estimated knitting time: {}:{:02d} (min:s)",
      p.name, p.description, s.min_needle, s.max_needle, s.stitch_passes + s.transfer_passes,
      s.stitch_passes, s.transfer_passes, s.knits, s.tucks, s.splits, s.misses, s.transfers,
      s.racks, s.loops_dropped, s.loops_left, s.yarn_pieces,
      s.empty_knits ? fmt::format(", knits on empty needles: {}", s.empty_knits) : "", minutes,
      static_cast<int>(s.seconds - minutes * 60));
}

}  // namespace skein::knitout
