#include <fmt/format.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <new>
#include <utility>

#ifdef __linux__
#include <sys/mman.h>
#endif

#include "knitout/vbed_bed.hpp"

namespace skein::knitout {
namespace vbed {
namespace {

// Asks for 2 MB pages under a large reserved buffer (Linux's transparent huge pages, where they
// are given on request): a replay writes each page of its fabric once, and a page fault costs
// more than filling the page (in a virtual machine, 4 KB page faults were a quarter of a
// replay's time).
template <typename T>
void advise_huge_pages(std::vector<T>& v) {
#ifdef __linux__
  constexpr std::uintptr_t kHuge = std::uintptr_t{2} << 20;
  auto begin = reinterpret_cast<std::uintptr_t>(v.data());
  std::uintptr_t from = (begin + kHuge - 1) & ~(kHuge - 1);
  std::uintptr_t to = (begin + v.capacity() * sizeof(T)) & ~(kHuge - 1);
  if (from < to) madvise(reinterpret_cast<void*>(from), to - from, MADV_HUGEPAGE);
#else
  (void)v;
#endif
}

}  // namespace

// Linux maps anonymous memory as zero pages, given out on first touch; elsewhere calloc zeroes.
Needles::Needles(std::size_t count) : count_(count) {
  std::size_t bytes = count * sizeof(Stack);
#ifdef __linux__
  void* p = mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (p == MAP_FAILED) throw std::bad_alloc();
#else
  void* p = std::calloc(count, sizeof(Stack));
  if (!p) throw std::bad_alloc();
#endif
  stacks_ = static_cast<Stack*>(p);
}

Needles& Needles::operator=(Needles&& other) noexcept {
  release();
  stacks_ = std::exchange(other.stacks_, nullptr);
  count_ = std::exchange(other.count_, 0);
  return *this;
}

void Needles::release() {
  if (!stacks_) return;
#ifdef __linux__
  munmap(stacks_, count_ * sizeof(Stack));
#else
  std::free(stacks_);
#endif
  stacks_ = nullptr;
}

std::size_t VirtualBed::next_line(std::size_t pos) const {
  const void* end = std::memchr(text_.data() + pos, '\n', text_.size() - pos);
  return end ? static_cast<std::size_t>(static_cast<const char*>(end) - text_.data()) + 1
             : text_.size() + 1;
}

Replay VirtualBed::run() {
  r_.header = parse_header(lines_, file_);
  check_header();
  keep_ = r_.header.position.empty() || r_.header.position == "Keep";
  // Strict, with Keep, the bed is exactly 0..n-1; otherwise the back end places the design,
  // and any n needles in a row may be used: the v-bed keeps room for them.
  bool exact = keep_ && severity(Rule::needle_off_bed) == Severity::error;
  lo_ = exact ? 0 : -2 * n_;
  hi_ = exact ? n_ : 3 * n_;
  for (auto& bed : beds_) bed = Needles(static_cast<std::size_t>(hi_ - lo_));
  carriers_.assign(r_.header.carriers.size(), Carrier{});
  r_.fabric.by_carrier.assign(r_.header.carriers.size(), {});
  r_.fabric.loops.reserve(line_count_);  // at most one loop a line: no regrowth
  r_.fabric.parents.reserve(line_count_);
  advise_huge_pages(r_.fabric.loops);
  advise_huge_pages(r_.fabric.parents);
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
    std::size_t next = 0;
    bool plain = parse_plain_op(text_, pos, r_.header, op, next);  // most lines: one scan
    if (!plain) next = next_line(pos);
    std::string_view text = current_ = text_.substr(pos, next - pos - 1);
    if (next > text_.size()) text = last_line_ = std::string(text) + '\n';  // see parse_op
    pos = next;
    if (!plain && !parse_op(text, r_.header, op, error)) {
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

void VirtualBed::apply(const Op& op) {
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

Stack& VirtualBed::at(Needle n) {
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

void VirtualBed::push(Stack& s, Needle n, LoopId loop) {
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

void VirtualBed::set_rack(std::int32_t quarters) {
  if (std::abs(quarters) > p_.max_rack * 4)
    breaks(Rule::rack_limit, [&] {
      return fmt::format("rack {} is beyond the racking limit of {} (±{})", quarters / 4.0, p_.name,
                         p_.max_rack);
    });
  if (!p_.rack_fraction_allowed(quarters))
    breaks(Rule::rack_fraction, [&] {
      return fmt::format("rack {} has a fraction {} does not allow", quarters / 4.0, p_.name);
    });
  if (quarters != rack_) ++r_.stats.racks;
  rack_ = quarters;
}

void VirtualBed::check_transfer(const Op& op) {
  const char* what = op.code == OpCode::split ? "split" : "xfer";
  if (is_slider(op.a.bed) && is_slider(op.b.bed))
    breaks(Rule::transfer_slider_slider, [&] {
      return fmt::format("{} {} {} moves from slider to slider", what, needle_name(op.a),
                         needle_name(op.b));
    });
  if (is_front(op.a.bed) == is_front(op.b.bed))
    breaks(Rule::transfer_same_bed, [&] {
      return fmt::format("{} {} {} stays on one bed: loops move only between front and back", what,
                         needle_name(op.a), needle_name(op.b));
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
      return fmt::format("{} at rack {} stretches a loop {} needles, {} allows {}", what, rack_ / 4,
                         std::abs(rack_ / 4), p_.name, p_.max_transfer_stretch);
    });
}

LoopId VirtualBed::new_loop(OpCode by, Direction dir, Needle n, CarrierMask yarn,
                            std::span<const LoopId> through) {
  LoopId id = static_cast<LoopId>(r_.fabric.loops.size());
  FabricLoop l;
  l.first_parent =
      through.size() == 1 ? through[0] : static_cast<std::uint32_t>(r_.fabric.parents.size());
  l.parent_count = static_cast<std::uint8_t>(through.size());
  l.made_by = by;
  l.front = is_front(n.bed);
  l.dir = dir;
  l.yarn = yarn;
  l.line = static_cast<std::uint32_t>(line_);
  l.needle = n.index;
  std::size_t lowest = static_cast<std::size_t>(std::countr_zero(yarn));
  l.piece = carriers_[lowest].piece;
  if (through.size() > 1)
    r_.fabric.parents.insert(r_.fabric.parents.end(), through.begin(), through.end());
  for (LoopId parent : through) {
    auto& children = r_.fabric.loops[parent].children;
    if (children < 255) ++children;
  }
  r_.fabric.loops.push_back(l);
  each(yarn, [&](Carrier&, std::size_t c) {
    count_float(c, n.index);
    std::vector<LoopId>& along = r_.fabric.by_carrier[c];
    if (along.empty()) {
      along.reserve(line_count_);
      advise_huge_pages(along);
    }
    along.push_back(id);
  });
  return id;
}

// The yarn from a carrier's last loop to this one floats across the needles between.
void VirtualBed::count_float(std::size_t carrier, std::int32_t needle) {
  std::int32_t& last = last_slot_[carrier];
  if (last != kNoSlot && p_.max_float && std::abs(needle - last) > std::int32_t(p_.max_float))
    ++r_.stats.long_floats;
  last = needle;
}

void VirtualBed::stitch_op(const Op& op) {
  if (op.code == OpCode::split && is_slider(op.a.bed))
    breaks(Rule::split_from_slider,
           [&] { return fmt::format("split cannot start from a slider ({})", needle_name(op.a)); });
  else if (is_slider(op.a.bed))
    breaks(Rule::stitch_on_slider, [&] {
      return fmt::format("{} on a slider ({}): sliders only hold loops moved there",
                         op_name(op.code), needle_name(op.a));
    });
  if (op.code == OpCode::miss) {
    if (!op.carriers)
      breaks(Rule::miss_without_carriers,
             [] { return std::string("miss needs carriers (a miss without yarn does nothing)"); });
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
    LoopId tuck = new_loop(OpCode::tuck, op.dir, op.a, op.carriers, {});
    r_.fabric.loops[tuck].over_nothing = s.size == 0;
    push(s, op.a, tuck);
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

void VirtualBed::drop(Needle n) {
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

void VirtualBed::transfer(const Op& op) {
  check_transfer(op);
  Stack& from = at(op.a);
  Stack& to = at(op.b);
  count_pass(op, true);
  ++r_.stats.transfers;
  for (std::uint8_t i = 0; i < from.size; ++i) push(to, op.b, from.loop[i]);
  from.size = 0;
}

void VirtualBed::count_pass(const Op& op, bool transfer) {
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

void VirtualBed::close_pass() {
  if (pass_.open) r_.stats.needles_crossed += static_cast<std::uint64_t>(span_hi_ - span_lo_ + 1);
  pass_.open = false;
}

void VirtualBed::finish() {
  close_pass();
  line_ = last_op_line_ ? last_op_line_ : lines_.size();
  current_ = last_op_line_ ? last_op_ : lines_.back();
  for (std::size_t c = 0; c < carriers_.size(); ++c)
    if (carriers_[c].state != CarrierState::out)
      breaks(Rule::carrier_left_in, [&] {
        return fmt::format("carrier {} is still in at the end of the file (take it out with {})",
                           r_.header.carriers[c], p_.hook == YarnHook::inhook ? "outhook" : "out");
      });
  for (const Finding& f : found_)
    if (f.count) r_.findings.push_back(f);
  ShopStats& s = r_.stats;
  if (s.max_needle < s.min_needle) s.min_needle = s.max_needle = 0;
  for (const auto& bed : beds_)  // only the needles used hold loops (untouched pages stay so)
    for (std::int32_t n = s.min_needle; n <= s.max_needle; ++n)
      s.loops_left += bed[static_cast<std::size_t>(n - lo_)].size;
  s.seconds = static_cast<double>(s.stitch_passes + s.transfer_passes) * p_.seconds_per_pass +
              static_cast<double>(s.needles_crossed) * p_.seconds_per_needle +
              static_cast<double>(s.racks) * p_.seconds_per_rack;
}

}  // namespace vbed

Replay replay_knitout(std::string_view text, const std::string& file, const MachineProfile& profile,
                      ReplayOptions options) {
  return vbed::VirtualBed(file, profile, text, options).run();
}

}  // namespace skein::knitout
