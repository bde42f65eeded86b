// The state of the virtual v-bed while it replays a file (vbed_simulator.hpp says what it
// does): the loops on every needle, the carriers, the pass being knitted, the rules broken so
// far. Its work is split by job: vbed_simulator.cpp replays the operations on the needles,
// vbed_carriers.cpp brings the yarn in and out (and the hook), vbed_header.cpp reads the
// header and sums up the shop's figures.
#pragma once

#include <array>
#include <bit>
#include <cstdint>
#include <limits>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "common/error.hpp"
#include "knitout/vbed_simulator.hpp"

namespace skein::knitout::vbed {

// The magic line, the header and the line after it: all that is ever quoted by number.
std::vector<std::string_view> header_lines(std::string_view text);

constexpr std::uint32_t kMaxStack = 15;  // the most loops a profile may allow on one needle

struct Stack {
  std::uint8_t size = 0;
  std::array<LoopId, kMaxStack> loop;
};

// Every needle's stack of one bed, all empty at first, in memory the system hands out zeroed a
// page at a time as it is first touched: the v-bed keeps room for thousands of needles a file
// may use (five beds' widths when the back end places the design), a file uses a few hundred,
// and zeroing them all was a tenth of a replay (page faults in a virtual machine).
class Needles {
 public:
  Needles() = default;
  explicit Needles(std::size_t count);
  Needles(const Needles&) = delete;
  Needles& operator=(const Needles&) = delete;
  Needles(Needles&& other) noexcept { *this = std::move(other); }
  Needles& operator=(Needles&& other) noexcept;
  ~Needles() { release(); }
  Stack& operator[](std::size_t i) { return stacks_[i]; }
  const Stack& operator[](std::size_t i) const { return stacks_[i]; }

 private:
  void release();
  Stack* stacks_ = nullptr;
  std::size_t count_ = 0;
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
             ReplayOptions options);
  Replay run();

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

  // ---- the text and its header (vbed_header.cpp) ----
  static std::size_t count_lines(std::string_view text);
  std::size_t next_line(std::size_t pos) const;
  [[noreturn]] void fail_header(std::size_t line, const std::string& why) const;
  void check_header();

  // ---- needles and loops (vbed_simulator.cpp) ----
  void apply(const Op& op);
  Stack& at(Needle n);
  void push(Stack& s, Needle n, LoopId loop);
  void set_rack(std::int32_t quarters);
  void check_transfer(const Op& op);
  LoopId new_loop(OpCode by, Direction dir, Needle n, CarrierMask yarn,
                  std::span<const LoopId> through);
  void count_float(std::size_t carrier, std::int32_t needle);
  void stitch_op(const Op& op);
  void drop(Needle n);
  void transfer(const Op& op);
  void count_pass(const Op& op, bool transfer);
  void close_pass();
  void finish();

  // ---- carriers and the hook (vbed_carriers.cpp) ----
  std::string names(CarrierMask mask) const;
  template <typename F>
  void each(CarrierMask mask, F f) {
    for (; mask; mask &= mask - 1) {  // straight to each set bit: a high carrier costs no more
      auto c = static_cast<std::size_t>(std::countr_zero(mask));
      f(carriers_[c], c);
    }
  }
  void use_carriers(const Op& op) {
    if ((op.carriers & ~carriers_in_) == 0) return;  // all in and stitched: nothing to check
    start_carriers(op);
  }
  void start_carriers(const Op& op);
  void check_hook_clear(Needle n);
  void check_hook_clear(const Op& op);
  void bring_in(const Op& op);
  void check_has_hook(const char* instead);
  // inhook / outhook: `instead` names the op a hookless machine's back end uses, `busy` says
  // what finds the hook still holding a carrier.
  void take_hook(const char* instead, const char* busy);
  void release_hook(const Op& op);
  void take_out(const Op& op);

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
  std::array<Needles, 4> beds_;
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

}  // namespace skein::knitout::vbed
