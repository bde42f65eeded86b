#include "hand/fabric_compare.hpp"

#include <fmt/format.h>

#include "driver/pipeline.hpp"
#include "knitgraph/worked_by_hand.hpp"

namespace skein::hand {
namespace {

const char* link_words(YarnLink link) {
  switch (link) {
    case YarnLink::none:
      return "ends its yarn";
    case YarnLink::course:
      return "goes on along the row";
    case YarnLink::shift:
      return "goes on into the next rnd";
    case YarnLink::turn:
      return "turns the work";
  }
  return "?";
}

std::string ordinal(std::size_t n) {
  static constexpr const char* kWords[] = {"1st", "2nd", "3rd"};
  return n < 3 ? kWords[n] : fmt::format("{}th", n + 1);
}

class Comparison {
 public:
  Comparison(const Fabric& f, const Compilation& c, bool mirror)
      : f_(f), g_(c.knit), c_(c), mirror_(mirror), model_of_(f.size(), kNoStitch) {}

  std::optional<Difference> run() {
    if (auto d = pair_yarns()) return d;
    for (std::uint32_t x = 0; x < f_.size(); ++x)
      if (auto d = compare_stitch(x)) return d;
    return std::nullopt;
  }

 private:
  // The model's yarn pieces in the order its schedule starts them.
  std::vector<std::uint32_t> model_yarn_order() const {
    std::vector<std::uint32_t> order;
    for (const Event& e : c_.schedule.events)
      if (e.kind == EventKind::yarn_start) order.push_back(e.yarn);
    return order;
  }

  std::optional<Difference> pair_yarns() {
    std::vector<std::uint32_t> order = model_yarn_order();
    if (order.size() != f_.piece_first.size())
      return Difference{0,
                        fmt::format("the pattern knits {} piece(s), one yarn each; the model has "
                                    "{} yarn pieces",
                                    f_.piece_first.size(), order.size())};
    for (std::size_t j = 0; j < order.size(); ++j) {
      std::uint32_t x = f_.piece_first[j], last = x;
      StitchId s = c_.yarns.first[order[j]];
      for (; x != kNoStitch && s != kNoStitch; last = x, x = f_.yarn_next[x], s = g_.yarn_next[s])
        model_of_[x] = s;
      if (x != kNoStitch)
        return Difference{x, fmt::format("{}: the model's yarn {} ended at the st before",
                                         f_.describe(x), order[j] + 1)};
      if (s != kNoStitch)
        return Difference{last,
                          fmt::format("{}: the pattern's yarn ends here, but the model's yarn "
                                      "{} goes on with {}",
                                      f_.describe(last), order[j] + 1, g_.describe(s))};
    }
    return std::nullopt;
  }

  std::optional<Difference> differ(std::uint32_t x, std::string what) const {
    return Difference{x,
                      fmt::format("{}: {} ({})", f_.describe(x), what, g_.describe(model_of_[x]))};
  }

  std::optional<Difference> compare_stitch(std::uint32_t x) {
    StitchId s = model_of_[x];
    if (f_.yarn_link[x] != g_.yarn_link[s])
      return differ(x, fmt::format("the pattern {} after it, the model {}",
                                   link_words(f_.yarn_link[x]), link_words(g_.yarn_link[s])));
    // The fabric a knitter makes for the model's stitch: the core's rule, which the pattern
    // builder reads too (the judge calls no builder code).
    StitchType worked = worked_by_hand(g_, s);
    StitchType want = mirror_ ? mirrored(worked) : worked;
    if (f_.type[x] != want) {
      std::optional<Difference> d = differ(
          x, fmt::format(
                 "the pattern makes {} (as seen from the RS) where the model has {}{}{}",
                 abbreviation(f_.type[x]), abbreviation(g_.type[s]),
                 worked != g_.type[s] ? fmt::format(" (worked by hand as {})", abbreviation(worked))
                                      : "",
                 mirror_ ? fmt::format(" ({} in its mirror image)", abbreviation(want)) : ""));
      d->type = true;
      return d;
    }
    std::size_t made = worked == g_.type[s] ? g_.loops_made_by(s).size() : info(worked).loops_out;
    if (f_.made[x] != made)
      return differ(x, fmt::format("it makes {} loop(s), the model's stitch {}", f_.made[x], made));
    std::vector<std::uint32_t> taken = f_.rs_taken(x);
    // The decrease that knits an sr5's two loops together takes them as the one loop of the DS
    // or wrap a knitter works (the sr4's).
    auto model_taken = g_.loops_taken_by(s);
    bool as_one = knits_an_sr5_as_one(g_, s);
    std::size_t model_count = as_one ? 1 : model_taken.size();
    if (taken.size() != model_count)
      return differ(
          x, fmt::format("it takes {} loop(s), the model's stitch {}", taken.size(), model_count));
    for (std::size_t i = 0; i < taken.size(); ++i) {
      bool flip_taken = mirror_ && info(g_.type[s]).mirror_reverses_taken;
      Loop want_loop = g_.loops[model_taken[flip_taken ? taken.size() - 1 - i : i]];
      if (as_one) want_loop.maker_slot = 0;
      std::uint32_t maker = f_.loop_maker[taken[i]];
      std::uint32_t slot = f_.rs_slot(taken[i]);
      if (mirror_ && !sides_of_a_split(f_.type[maker])) slot = f_.made[maker] - 1 - slot;
      if (model_of_[maker] != want_loop.maker || slot != want_loop.maker_slot)
        return differ(
            x, fmt::format("its {} loop from the left comes from {} (loop {}), the model's "
                           "from {} (loop {})",
                           ordinal(i), f_.describe(maker), slot + 1, g_.describe(want_loop.maker),
                           want_loop.maker_slot + 1));
    }
    return std::nullopt;
  }

  // A three-needle bind-off's loops are front and back, a provisional cast-on's the two sides
  // of its split: a mirror keeps them (it swaps left and right only).
  static bool sides_of_a_split(StitchType type) { return type == StitchType::sco; }

  const Fabric& f_;
  const KnitGraph& g_;
  const Compilation& c_;
  bool mirror_;
  std::vector<StitchId> model_of_;
};

}  // namespace

std::optional<Difference> first_difference(const Fabric& fabric, const Compilation& model,
                                           bool mirror) {
  return Comparison(fabric, model, mirror).run();
}

}  // namespace skein::hand
