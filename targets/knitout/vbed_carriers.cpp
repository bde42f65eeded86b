#include <fmt/format.h>

#include "knitout/vbed_bed.hpp"

namespace skein::knitout::vbed {

std::string VirtualBed::names(CarrierMask mask) const {
  return carrier_names(r_.header, mask);
}

// The first use of carriers brought in (or of one not in at all).
void VirtualBed::start_carriers(const Op& op) {
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
        return fmt::format("the first pass after bringing in carrier {} must go {} on {}, found {}",
                           names(op.carriers), direction_char(p_.first_pass), p_.name,
                           direction_char(op.dir));
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
void VirtualBed::check_hook_clear(Needle n) {
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

void VirtualBed::check_hook_clear(const Op& op) {
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

void VirtualBed::bring_in(const Op& op) {
  bool hook = op.code == OpCode::inhook;
  if (hook) take_hook("in", "the yarn-inserting hook");
  each(op.carriers, [&](Carrier& c, std::size_t i) {
    if (c.state != CarrierState::out)
      breaks(Rule::carrier_already_in,
             [&] { return fmt::format("carrier {} is already in", r_.header.carriers[i]); });
    c = Carrier{CarrierState::pending, hook, false, op.carriers, line_, ++pieces_};
    ++r_.stats.yarn_pieces;
  });
  if (hook) hook_ = op.carriers;
}

// inhook and outhook use the hook: the machine must have one, and it must have been released.
void VirtualBed::take_hook(const char* instead, const char* busy) {
  check_has_hook(instead);
  if (hook_)
    breaks(Rule::hook_busy, [&] {
      return fmt::format("{} still holds carrier {}: releasehook it first", busy, names(hook_));
    });
}

// An inhook, releasehook or outhook on a machine without a hook: its back end uses in / out.
void VirtualBed::check_has_hook(const char* instead) {
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

void VirtualBed::release_hook(const Op& op) {
  check_has_hook("");
  if (hook_ != op.carriers)
    breaks(Rule::releasehook_mismatch, [&] {
      return hook_ ? fmt::format("the hook holds carrier {}, not {}", names(hook_),
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

void VirtualBed::take_out(const Op& op) {
  bool hook = op.code == OpCode::outhook;
  if (hook) take_hook("out", "outhook while the hook");
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

}  // namespace skein::knitout::vbed
