// Where each operation of a row is named in the row's printed instructions: "*K to 2 sts
// before m, ssk, sm; rep from * to end" read back against the operations it was written from,
// so that the page can point at "ssk" (repeat 3 of 8) while the knitter works that stitch. The
// text is the proven pattern's own; this reads it, never rewrites it.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "hand/hand_ops.hpp"

namespace skein::hand_web {

// One operation's place in the text: the characters [begin, end) of the token that names it
// ("k8" for each of eight knits), and which time round the innermost repeat around it this
// is (1-based; repeats 0 when it is in no repeat).
struct OpSpan {
  std::uint32_t begin = 0, end = 0;
  std::uint32_t repeat = 0, repeats = 0;
};

// Per operation of `ops`, its span in `text` (the instructions after the row's label, as the
// hand target writes them in its standard dialect); nullopt when the text does not read back as
// exactly these operations (a sentence such as "Knit every rnd until 23 rnds in all.").
std::optional<std::vector<OpSpan>> op_spans(std::string_view text,
                                            std::span<const hand::HandOp> ops);

}  // namespace skein::hand_web
