#include "knitout/fabric_picture.hpp"

#include <fmt/format.h>
#include <fmt/ostream.h>

#include <algorithm>
#include <ostream>
#include <vector>

namespace skein::knitout {
namespace {

constexpr int kPitch = 6;  // px between needles and between heights

const char* yarn_colour(std::size_t carrier) {
  static const char* colours[] = {"#1f77b4", "#2ca02c", "#9467bd", "#ff7f0e",
                                  "#17becf", "#8c564b", "#e377c2", "#bcbd22"};
  return colours[carrier % std::size(colours)];
}

}  // namespace

std::vector<std::uint32_t> loop_heights(const Fabric& f) {
  std::vector<std::uint32_t> height(f.loops.size(), 0);
  std::vector<std::uint32_t> last_of_piece;
  for (LoopId l = 0; l < f.loops.size(); ++l) {
    std::uint32_t piece = f.loops[l].piece;
    if (piece >= last_of_piece.size()) last_of_piece.resize(piece + 1, 0);
    std::uint32_t h = 0;
    for (LoopId parent : f.parents_of(l)) h = std::max(h, height[parent] + 1);
    height[l] = f.loops[l].parent_count ? h : last_of_piece[piece];
    last_of_piece[piece] = height[l];
  }
  return height;
}

void write_fabric_svg(const Replay& r, const std::string& title, std::ostream& out) {
  const Fabric& f = r.fabric;
  std::vector<std::uint32_t> height = loop_heights(f);
  std::int32_t lo = 0, hi = 0;
  std::uint32_t top = 0;
  for (LoopId l = 0; l < f.loops.size(); ++l) {
    lo = l ? std::min(lo, f.loops[l].needle) : f.loops[l].needle;
    hi = l ? std::max(hi, f.loops[l].needle) : f.loops[l].needle;
    top = std::max(top, height[l]);
  }
  auto x = [&](LoopId l) { return (f.loops[l].needle - lo + 1) * kPitch; };
  auto y = [&](LoopId l) { return static_cast<int>(top - height[l] + 1) * kPitch; };
  fmt::print(out,
             "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{}\" height=\"{}\">\n"
             "<title>{}</title>\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
             "<g stroke=\"#bbb\" stroke-width=\"0.8\">\n",
             (hi - lo + 2) * kPitch, (top + 2) * kPitch, title);
  for (LoopId l = 0; l < f.loops.size(); ++l)
    for (LoopId parent : f.parents_of(l))
      fmt::print(out, "<line x1=\"{}\" y1=\"{}\" x2=\"{}\" y2=\"{}\"/>\n", x(l), y(l), x(parent),
                 y(parent));
  fmt::print(out, "</g>\n<g fill=\"none\" stroke-width=\"0.6\">\n");
  for (std::size_t c = 0; c < f.by_carrier.size(); ++c) {
    const std::vector<LoopId>& along = f.by_carrier[c];
    for (std::size_t i = 1; i < along.size(); ++i)
      if (f.loops[along[i]].piece == f.loops[along[i - 1]].piece)
        fmt::print(out, "<line x1=\"{}\" y1=\"{}\" x2=\"{}\" y2=\"{}\" stroke=\"{}\"/>\n",
                   x(along[i - 1]), y(along[i - 1]), x(along[i]), y(along[i]), yarn_colour(c));
  }
  fmt::print(out, "</g>\n<g>\n");
  for (LoopId l = 0; l < f.loops.size(); ++l) {
    const FabricLoop& loop = f.loops[l];
    const char* colour = loop.dropped ? "#d62728" : loop.front ? "#333" : "#999";
    if (loop.made_by == OpCode::tuck)
      fmt::print(out, "<circle cx=\"{}\" cy=\"{}\" r=\"1.8\" fill=\"none\" stroke=\"{}\"/>\n", x(l),
                 y(l), colour);
    else
      fmt::print(out, "<circle cx=\"{}\" cy=\"{}\" r=\"1.8\" fill=\"{}\"/>\n", x(l), y(l), colour);
  }
  fmt::print(out, "</g>\n</svg>\n");
}

}  // namespace skein::knitout
