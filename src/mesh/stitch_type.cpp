#include "mesh/stitch_type.hpp"

#include <array>

#include "common/error.hpp"

namespace skein {
namespace {

using T = StitchType;
using S = LoopStack;
// clang-format off
constexpr bool R = true, K = false;  // mirroring reverses its loops / keeps their order
constexpr std::array kCatalogue{
  //            type         abbr        name                            bot top in out adj  var    stack            mirror       rev:taken made purl worked_by
  StitchTypeInfo{T::k,        "k",        "knit",                          1, 1, 1, 1, false, false, S::single,        T::k,        R, R, false, by_both},
  StitchTypeInfo{T::p,        "p",        "purl",                          1, 1, 1, 1, false, false, S::single,        T::p,        R, R, true, by_both},
  StitchTypeInfo{T::co,       "co",       "cast-on",                       1, 1, 0, 1, false, false, S::single,        T::co,       R, R, false, by_both},
  StitchTypeInfo{T::bo,       "bo",       "bind-off",                      1, 1, 1, 0, false, false, S::single,        T::bo,       R, R, false, by_both},
  StitchTypeInfo{T::kfb,      "kfb",      "knit front and back",           1, 2, 1, 2, false, false, S::single,        T::kfb,      R, R, false, by_both},
  StitchTypeInfo{T::m1l,      "m1l",      "make 1 left",                   1, 2, 1, 2, false, false, S::single,        T::m1r,      R, R, false, by_both},
  StitchTypeInfo{T::m1r,      "m1r",      "make 1 right",                  1, 2, 1, 2, false, false, S::single,        T::m1l,      R, R, false, by_both},
  StitchTypeInfo{T::yo,       "yo",       "yarn over",                     1, 2, 1, 2, false, false, S::single,        T::yo,       R, R, false, by_both},
  StitchTypeInfo{T::k2tog,    "k2tog",    "knit 2 together",               2, 1, 2, 1, false, false, S::left_on_top,   T::ssk,      R, R, false, by_both},
  StitchTypeInfo{T::ssk,      "ssk",      "slip, slip, knit",              2, 1, 2, 1, false, false, S::right_on_top,  T::k2tog,    R, R, false, by_both},
  StitchTypeInfo{T::p2tog,    "p2tog",    "purl 2 together",               2, 1, 2, 1, false, false, S::left_on_top,   T::p2tog,    R, R, true, by_both},
  StitchTypeInfo{T::s2kp,     "s2kp",     "centred double decrease",       3, 1, 3, 1, false, false, S::centre_on_top, T::s2kp,     R, R, false, by_both},
  StitchTypeInfo{T::sr4,      "sr4",      "short-row end (4 edges)",       1, 1, 1, 1, true,  false, S::single,        T::sr4,      R, R, false, by_both},
  StitchTypeInfo{T::sr5,      "sr5",      "short-row end (5 edges)",       1, 2, 1, 2, true,  false, S::single,        T::sr5,      R, R, false, by_both},
  StitchTypeInfo{T::srn,      "srn",      "short-row end (collapsed edges)", 1, 2, 1, 2, true, true, S::single,        T::srn,      R, R, false, by_none},
  StitchTypeInfo{T::tnbo,     "3nbo",     "three-needle bind-off",         2, 1, 2, 0, false, false, S::by_side,       T::tnbo,     K, R, false, by_both},
  StitchTypeInfo{T::sco,      "sco",      "cast-on along a split",         1, 2, 0, 2, false, false, S::single,        T::sco,      R, K, false, by_both},
  StitchTypeInfo{T::sl,       "sl",       "slip",                          1, 1, 1, 1, false, false, S::single,        T::sl,       R, R, false, by_both},
  StitchTypeInfo{T::tuck,     "tuck",     "tuck",                          1, 1, 1, 1, false, false, S::single,        T::tuck,     R, R, false, by_both},
  StitchTypeInfo{T::k2tog_bo, "k2tog-bo", "knit 2 together and bind off",  2, 1, 2, 0, false, false, S::left_on_top,   T::k2tog_bo, R, R, false, by_none},
};
// clang-format on

constexpr bool catalogue_is_indexed_by_type() {
  for (std::size_t i = 0; i < kCatalogue.size(); ++i)
    if (static_cast<std::size_t>(kCatalogue[i].type) != i) return false;
  return true;
}
static_assert(catalogue_is_indexed_by_type());

// A mirror's mirror is the stitch itself.
constexpr bool mirror_is_an_involution() {
  for (const StitchTypeInfo& entry : kCatalogue)
    if (kCatalogue[static_cast<std::size_t>(entry.mirror)].mirror != entry.type) return false;
  return true;
}
static_assert(mirror_is_an_involution());

}  // namespace

const StitchTypeInfo& info(StitchType type) {
  auto index = static_cast<std::size_t>(type);
  SKEIN_ASSERT(index < kCatalogue.size(), "stitch type out of range");
  return kCatalogue[index];
}

float stack_position(StitchType type, std::uint32_t slot, std::uint32_t loops) {
  const float middle = static_cast<float>(loops - 1) / 2;
  const float from_left = static_cast<float>(slot) - middle;
  switch (info(type).stack) {
    case LoopStack::single:
      return 0;
    case LoopStack::left_on_top:
      return -from_left;
    case LoopStack::right_on_top:
    case LoopStack::by_side:
      return from_left;
    case LoopStack::centre_on_top:  // in front; the others behind it as right_on_top
      if (2 * slot + 1 == loops) return middle;
      return from_left - (2 * slot > loops ? 1.0f : 0.0f);
  }
  return 0;
}

std::span<const std::uint8_t> stacking_order(StitchType type) {
  static constexpr std::uint8_t kLeftOnTop[] = {1, 0}, kRightOnTop[] = {0, 1},
                                kCentreOnTop[] = {0, 2, 1}, kSingle[] = {0};
  switch (info(type).stack) {
    case LoopStack::single:
      return kSingle;
    case LoopStack::left_on_top:
      return kLeftOnTop;
    case LoopStack::right_on_top:
    case LoopStack::by_side:  // the second needle's loop on the first's
      return kRightOnTop;
    case LoopStack::centre_on_top:
      return kCentreOnTop;
  }
  return kSingle;
}

std::span<const StitchTypeInfo> stitch_catalogue() {
  return kCatalogue;
}

std::optional<StitchType> stitch_type_from_abbreviation(std::string_view abbreviation) {
  for (const auto& entry : kCatalogue)
    if (entry.abbreviation == abbreviation) return entry.type;
  return std::nullopt;
}

}  // namespace skein
