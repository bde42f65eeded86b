#include "hand/piece_names.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <map>

#include "mesh/stitch_mesh.hpp"

namespace skein::hand {
namespace {

// Per piece: the part most of its stitches belong to (kNoPart where none has one).
std::vector<std::uint32_t> main_parts(const KnitGraph& g, const YarnPieces& yarns,
                                      const std::vector<PatternSection>& sections,
                                      std::uint32_t pieces) {
  std::vector<std::uint32_t> piece_of_yarn(yarns.size(), 0);
  for (const PatternSection& s : sections) piece_of_yarn[s.yarn] = s.piece;
  std::vector<std::vector<std::uint32_t>> count(pieces,
                                                std::vector<std::uint32_t>(g.part_names.size()));
  for (StitchId s = 0; s < g.size(); ++s) {
    std::uint32_t piece = piece_of_yarn[yarns.piece_of[s]];
    if (piece != 0 && g.part[s] != kNoPart) ++count[piece - 1][g.part[s]];
  }
  std::vector<std::uint32_t> main(pieces, kNoPart);
  for (std::uint32_t p = 0; p < pieces; ++p) {
    auto most = std::max_element(count[p].begin(), count[p].end());
    if (most != count[p].end() && *most > 0)
      main[p] = static_cast<std::uint32_t>(most - count[p].begin());
  }
  return main;
}

// The pieces' names; empty where the model's parts tell no pieces apart.
std::vector<std::string> named_pieces(const KnitGraph& g, const YarnPieces& yarns,
                                      const std::vector<PatternSection>& sections) {
  std::uint32_t pieces = 0;
  for (const PatternSection& s : sections) pieces = std::max(pieces, s.piece);
  std::vector<std::string> names(pieces);
  if (g.part_names.empty()) return {};
  std::vector<std::uint32_t> main = main_parts(g, yarns, sections, pieces);
  // By name (an OBJ may give two groups one name): the pieces named so, and numbered so far.
  std::map<std::string, std::uint32_t> sharing, numbered;
  for (std::uint32_t part : main)
    if (part != kNoPart) ++sharing[g.part_names[part]];
  if (sharing.size() < 2) return {};  // one part throughout: its name tells no piece apart
  for (std::uint32_t p = 0; p < pieces; ++p) {
    if (main[p] == kNoPart) {
      names[p] = fmt::format("Piece {}", p + 1);
      continue;
    }
    const std::string& part = g.part_names[main[p]];
    names[p] = sharing[part] == 1 ? part : fmt::format("{} {}", part, ++numbered[part]);
  }
  return names;
}

// Sets each section's part: the one most of its stitches are in.
void name_section_parts(const KnitGraph& g, const YarnPieces& yarns,
                        std::vector<PatternSection>& sections) {
  std::vector<std::vector<std::uint32_t>> of_yarn(yarns.size());  // its sections, in order
  // A section that works no st (a piece taken up and set aside again) is in no part.
  for (std::uint32_t i = 0; i < sections.size(); ++i)
    if (sections[i].stitches > 0) of_yarn[sections[i].yarn].push_back(i);
  for (std::uint32_t y = 0; y < yarns.size(); ++y) {
    // Along the yarn, a section ends once both ends of its last row are passed.
    std::size_t k = 0;
    int ends_passed = 0;
    std::vector<std::uint32_t> count(g.part_names.size());
    auto close = [&] {
      if (k >= of_yarn[y].size()) return;
      auto most = std::max_element(count.begin(), count.end());
      if (*most > 0) sections[of_yarn[y][k]].part = g.part_names[most - count.begin()];
      std::fill(count.begin(), count.end(), 0);
      ++k, ends_passed = 0;
    };
    StitchId s = yarns.first[y];
    for (std::uint32_t i = 0; i < yarns.length[y]; ++i, s = g.yarn_next[s]) {
      if (g.part[s] != kNoPart) ++count[g.part[s]];
      if (k >= of_yarn[y].size()) continue;
      const PatternSection& sec = sections[of_yarn[y][k]];
      ends_passed += (s == sec.last_row_ends[0]) + (s == sec.last_row_ends[1]);
      if (ends_passed >= (sec.last_row_ends[0] == sec.last_row_ends[1] ? 1 : 2) &&
          k + 1 < of_yarn[y].size())
        close();
    }
    close();
  }
}

}  // namespace

void name_pieces(const KnitGraph& g, const YarnPieces& yarns, HandPattern& pattern) {
  pattern.piece_names = named_pieces(g, yarns, pattern.sections);
  if (!pattern.piece_names.empty()) {
    name_section_parts(g, yarns, pattern.sections);
    return;
  }
  std::uint32_t pieces = 0;
  for (const PatternSection& s : pattern.sections) pieces = std::max(pieces, s.piece);
  for (std::uint32_t p = 1; p <= pieces; ++p)
    pattern.piece_names.push_back(fmt::format("Piece {}", p));
}

}  // namespace skein::hand
