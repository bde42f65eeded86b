#include "hand/loop_places.hpp"

#include <algorithm>

namespace skein::hand {

void LoopPlaces::set(std::span<const std::uint32_t> loops, LoopAt where) {
  for (std::uint32_t loop : loops) at_[loop] = where;
}

std::uint32_t LoopPlaces::hold(std::span<const std::uint32_t> loops, std::uint32_t section) {
  holders_.emplace_back(loops.begin(), loops.end());
  holder_section_.push_back(section);
  auto number = static_cast<std::uint32_t>(holders_.size());
  set(loops, {Place::holder, number});
  return number;
}

void LoopPlaces::hold_onto(std::uint32_t holder, std::span<const std::uint32_t> loops) {
  holders_[holder - 1].insert(holders_[holder - 1].end(), loops.begin(), loops.end());
  set(loops, {Place::holder, holder});
}

void LoopPlaces::leave(std::uint32_t section, Place place, std::vector<std::uint32_t> loops) {
  auto& lists = place == Place::chain ? chains_ : spares_;
  if (lists.size() <= section) lists.resize(section + 1);
  set(loops, {place, section});
  if (place == Place::spare)
    for (std::uint32_t i = 0; i < loops.size(); ++i) counted_at_[loops[i]] = i + 1;
  lists[section] = std::move(loops);
}

void LoopPlaces::add(std::uint32_t section, Place place, std::uint32_t loop) {
  auto& lists = place == Place::chain ? chains_ : spares_;
  if (lists.size() <= section) lists.resize(section + 1);
  lists[section].push_back(loop);
  at_[loop] = {place, section};
  if (place == Place::spare) counted_at_[loop] = static_cast<std::uint32_t>(lists[section].size());
}

void LoopPlaces::take_off_spare(std::uint32_t section, std::span<const std::uint32_t> loops) {
  std::vector<std::uint32_t>& spare = spares_[section];
  for (std::uint32_t loop : loops) at_[loop] = {};
  std::erase_if(spare, [&](std::uint32_t loop) { return at_[loop].place != Place::spare; });
}

std::uint32_t LoopPlaces::spare_needles_holding_sts() const {
  auto holds_sts = [&](const std::vector<std::uint32_t>& loops) {
    return std::any_of(loops.begin(), loops.end(),
                       [&](std::uint32_t loop) { return at_[loop].place == Place::spare; });
  };
  return static_cast<std::uint32_t>(std::count_if(spares_.begin(), spares_.end(), holds_sts));
}

const std::vector<std::uint32_t>& LoopPlaces::loops_of(LoopAt source) const {
  static const std::vector<std::uint32_t> kNone;
  const std::vector<std::vector<std::uint32_t>>* lists = nullptr;
  std::uint32_t i = source.index;
  if (source.place == Place::holder) lists = &holders_, i = source.index - 1;
  if (source.place == Place::spare) lists = &spares_;
  if (source.place == Place::chain) lists = &chains_;
  return lists && i < lists->size() ? (*lists)[i] : kNone;
}

std::optional<Lie> LoopPlaces::lie(LoopAt source, std::span<const std::uint32_t> met) const {
  const std::vector<std::uint32_t>& on = loops_of(source);
  const std::size_t n = on.size();
  auto first = std::find(on.begin(), on.end(), met.empty() ? 0u : met.front());
  if (met.size() != n || n == 0 || first == on.end()) return std::nullopt;
  auto k = static_cast<std::size_t>(first - on.begin());
  std::optional<Lie> found;
  for (bool down : {false, true}) {
    bool same = true;
    for (std::size_t i = 0; i < n && same; ++i) same = met[i] == on[(down ? k + n - i : k + i) % n];
    if (!same) continue;
    std::size_t tip = down ? n - 1 : 0;
    Lie lie{down, k == tip ? 0u : static_cast<std::uint32_t>(k + 1)};
    // Two loops lie both ways: from the end the knitter takes first, rather than round.
    if (!found || (found->at != 0 && lie.at == 0)) found = lie;
  }
  return found;
}

}  // namespace skein::hand
