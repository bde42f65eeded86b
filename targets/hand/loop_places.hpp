// Where each live loop waits while a hand pattern is written from the live-loop program: on a
// piece's needle, on a holder, on the spare needle a piece was left on, or in the chain of a
// provisional cast-on, or along the edge of the piece whose edge st made it (to be picked up).
// Holders, spare needles and chains keep their loops in the order the knitter put them there,
// which is the order the pattern counts them in.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace skein::hand {

enum class Place : std::uint8_t { none, needle, holder, spare, chain, edge };

struct LoopAt {
  Place place = Place::none;
  std::uint32_t index = 0;  // needle: the piece's needle; holder: its number (1-based);
                            // spare, chain: the section left there; edge: the
                            // section whose row made it
  bool operator==(const LoopAt&) const = default;
};

// How a run of loops met by a course lies on a holder, spare needle or chain: all of them,
// going up it (from_last false) or down it, from its `at`-th loop (1-based in the order put
// there; 0 when it begins at the end the knitter takes first).
struct Lie {
  bool from_last = false;
  std::uint32_t at = 0;
};

class LoopPlaces {
 public:
  explicit LoopPlaces(std::size_t loops) : at_(loops), counted_at_(loops, 0) {}

  LoopAt at(std::uint32_t loop) const { return at_[loop]; }
  void set(std::span<const std::uint32_t> loops, LoopAt where);
  void take(std::uint32_t loop) { at_[loop] = {}; }

  // Slips `loops` (in that order) to a new holder, from section `section`; its number.
  std::uint32_t hold(std::span<const std::uint32_t> loops, std::uint32_t section);
  // Slips `loops` onto holder `holder` after those it holds.
  void hold_onto(std::uint32_t holder, std::span<const std::uint32_t> loops);
  std::uint32_t holders() const { return static_cast<std::uint32_t>(holders_.size()); }
  std::uint32_t holder_section(std::uint32_t holder) const { return holder_section_[holder - 1]; }
  // Leaves a section's loops on a spare needle (or its chain), in the order the pattern counts
  // them.
  void leave(std::uint32_t section, Place place, std::vector<std::uint32_t> loops);
  // Takes `loops` off a section's spare needle (the rest keep their order).
  void take_off_spare(std::uint32_t section, std::span<const std::uint32_t> loops);
  // One more loop at the end of a section's spare needle (or chain).
  void add(std::uint32_t section, Place place, std::uint32_t loop);
  // A loop's place (1-based) on the spare needle it was left on, counted as the pattern counts
  // them when it was left: it keeps its number when others are taken off before it.
  std::uint32_t counted_at(std::uint32_t loop) const { return counted_at_[loop]; }
  // How many sections' spare needles hold loops.
  std::uint32_t spare_needles_holding_sts() const;
  // The loops on a holder, spare needle or chain, in order.
  const std::vector<std::uint32_t>& loops_of(LoopAt source) const;

  // How `met` lies on `source`: every loop of it, up or down, round from one of them.
  std::optional<Lie> lie(LoopAt source, std::span<const std::uint32_t> met) const;

 private:
  std::vector<LoopAt> at_;
  std::vector<std::uint32_t> counted_at_;
  std::vector<std::vector<std::uint32_t>> holders_;
  std::vector<std::uint32_t> holder_section_;
  std::vector<std::vector<std::uint32_t>> spares_, chains_;  // per section
};

}  // namespace skein::hand
