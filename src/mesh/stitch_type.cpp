#include "mesh/stitch_type.hpp"

#include <array>

#include "common/error.hpp"

namespace skein {
namespace {

using T = StitchType;
// clang-format off
constexpr std::array kCatalogue{
  //            type      abbr     name                                bot top in out adj  var
  StitchTypeInfo{T::k,     "k",     "knit",                              1,  1,  1, 1, false, false},
  StitchTypeInfo{T::p,     "p",     "purl",                              1,  1,  1, 1, false, false},
  StitchTypeInfo{T::co,    "co",    "cast-on",                           1,  1,  0, 1, false, false},
  StitchTypeInfo{T::bo,    "bo",    "bind-off",                          1,  1,  1, 0, false, false},
  StitchTypeInfo{T::kfb,   "kfb",   "knit front and back",               1,  2,  1, 2, false, false},
  StitchTypeInfo{T::m1l,   "m1l",   "make 1 left",                       1,  2,  1, 2, false, false},
  StitchTypeInfo{T::m1r,   "m1r",   "make 1 right",                      1,  2,  1, 2, false, false},
  StitchTypeInfo{T::yo,    "yo",    "yarn over",                         1,  2,  1, 2, false, false},
  StitchTypeInfo{T::k2tog, "k2tog", "knit 2 together",                   2,  1,  2, 1, false, false},
  StitchTypeInfo{T::ssk,   "ssk",   "slip, slip, knit",                  2,  1,  2, 1, false, false},
  StitchTypeInfo{T::p2tog, "p2tog", "purl 2 together",                   2,  1,  2, 1, false, false},
  StitchTypeInfo{T::s2kp,  "s2kp",  "centred double decrease",           3,  1,  3, 1, false, false},
  StitchTypeInfo{T::sr4,   "sr4",   "short-row end (4 edges)",           1,  1,  1, 1, true,  false},
  StitchTypeInfo{T::sr5,   "sr5",   "short-row end (5 edges)",           1,  2,  1, 2, true,  false},
  StitchTypeInfo{T::srn,   "srn",   "short-row end (collapsed edges)",   1,  2,  1, 2, true,  true},
  StitchTypeInfo{T::tnbo,  "3nbo",  "three-needle bind-off",             2,  1,  2, 0, false, false},
  StitchTypeInfo{T::sco,   "sco",   "cast-on along a split",             1,  2,  0, 2, false, false},
  StitchTypeInfo{T::sl,    "sl",    "slip",                              1,  1,  1, 1, false, false},
  StitchTypeInfo{T::tuck,  "tuck",  "tuck",                              1,  1,  1, 1, false, false},
  StitchTypeInfo{T::k2tog_bo, "k2tog-bo", "knit 2 together and bind off",   2,  1,  2, 0, false, false},
};
// clang-format on

constexpr bool catalogue_is_indexed_by_type() {
  for (std::size_t i = 0; i < kCatalogue.size(); ++i)
    if (static_cast<std::size_t>(kCatalogue[i].type) != i) return false;
  return true;
}
static_assert(catalogue_is_indexed_by_type());

}  // namespace

const StitchTypeInfo& info(StitchType type) {
  auto index = static_cast<std::size_t>(type);
  SKEIN_ASSERT(index < kCatalogue.size(), "stitch type out of range");
  return kCatalogue[index];
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
