// Import of AutoKnit stitch graphs (`.st`, textiles-lab/autoknit): one stitch per line,
// `yarn type dir in0 in1 out0 out1 x y z`, in construction order. The file already is a knit
// graph, so it becomes a KnitGraph directly, without a stitch mesh.
#pragma once

#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "knitgraph/knit_graph.hpp"

namespace skein {

// Parses the text of a `.st` file; stitch s is line s (0-based). Validates every field and
// every link as strictly as AutoKnit's own loader, and throws ParseError naming the first bad
// line. `file_name` is only used in messages and as the graph's source_name.
// When `positions` is given it receives each stitch's x y z (for the yarn model's layout).
KnitGraph parse_autoknit_st(std::string_view text, const std::string& file_name,
                            std::vector<std::array<double, 3>>* positions = nullptr);

// Reads and parses the file at `path`; throws IoError if it cannot be read.
KnitGraph read_autoknit_st(const std::string& path);

}  // namespace skein
