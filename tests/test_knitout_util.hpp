// Helpers shared by the knitout tests: profiles by name, emitting, replaying and proving.
#pragma once

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "common/error.hpp"
#include "driver/pipeline.hpp"
#include "golden.hpp"
#include "knitout/emit.hpp"
#include "knitout/machine_profile.hpp"
#include "knitout/vbed_simulator.hpp"
#include "knitout/whole_file_proof.hpp"
#include "labeling/shapes.hpp"
#include "mesh/autoknit_st.hpp"

namespace skein::testing {

inline knitout::MachineProfile shipped_profile(const std::string& name) {
  return knitout::read_machine_profile(source_path("machine_profiles/" + name + ".yaml"));
}

// A shape from `skein new` at `size`, with the yarn its project picks for a crotch (extra, own),
// compiled from files written under the test's temporary directory.
inline Compilation compile_new_shape(const std::string& kind, const ShapeSize& size,
                                     const std::string& yarn) {
  Shape shape = make_shape(kind, size, kind);
  shape.project += fmt::format("yarn: {{default: {}}}\n", yarn);
  std::string dir = ::testing::TempDir() + kind + "-" + yarn;
  std::filesystem::create_directories(dir);
  return compile_model(write_shape(shape, dir + "/" + kind));
}

inline std::string emit_knitout_text(const Compilation& c, const knitout::MachineProfile& p) {
  std::ostringstream out;
  knitout::emit_knitout(c, p, out);
  return out.str();
}

// Replays `text` and proves it against `c` (throws ParseError on an invalid operation).
inline knitout::ProofResult replay_and_prove(const std::string& text, const Compilation& c,
                                             const knitout::MachineProfile& p) {
  knitout::Replay replay = knitout::replay_knitout(text, "out.k", p);
  return knitout::prove_whole_file(replay, text, c);
}

// Emits `c` on `p` and expects the file proven (`what` names it in a failure); returns the
// target's message when it refuses `c` by name before writing, empty when it wrote the file.
inline std::string prove_unless_refused(const Compilation& c, const knitout::MachineProfile& p,
                                        const std::string& what) {
  std::string text;
  try {
    text = emit_knitout_text(c, p);
  } catch (const UnsupportedError& e) {
    return e.what();
  }
  knitout::ProofResult proof = replay_and_prove(text, c, p);
  EXPECT_TRUE(proof.proven) << what << " on " << p.name << ": " << proof.summary;
  return "";
}

// A stitch graph in AutoKnit's format, one yarn: s cast-on, k knit, i increase, d decrease,
// t tuck, m miss (slip), e bind-off; '|' turns the yarn back (AutoKnit's dir flips). The loops
// on the needles are kept in order along the fabric: each stitch takes the next ones the yarn
// meets and leaves its own in their place; past either end the yarn comes round to the other
// (a tube, cut again where the yarn is), which a sheet's letters never ask for. A tube parts
// into legs with '(' before a leg's first stitch and ')' after its last: the yarn comes round
// the leg, back to the loop that first stitch made (the other loops wait). '/' cuts the yarn: the
// stitches after it are a yarn of their own (AutoKnit's next yarn id), going on where it was.
inline std::string stitch_graph_st(const std::string& letters) {
  struct Line {
    char letter;
    bool forward;
    int in[2] = {-1, -1}, out[2] = {-1, -1};
    int yarn = 0;
  };
  std::vector<Line> lines;
  std::vector<std::pair<int, int>> fabric;  // (stitch, out slot), left to right
  std::size_t yarn = 0;                     // the loops left of the yarn: fabric[0, yarn)
  bool forward = true, leg_starts = false;
  std::size_t leg = 0;  // where the leg's first loop lies in the fabric
  int yarn_id = 0;
  for (char letter : letters) {
    if (letter == '/') {
      ++yarn_id;
      continue;
    }
    if (letter == '|' || letter == '(' || letter == ')') {
      forward = forward != (letter == '|');
      leg_starts = letter == '(';
      if (letter == ')') yarn = leg;
      continue;
    }
    int s = static_cast<int>(lines.size());
    lines.push_back({letter, forward, {-1, -1}, {-1, -1}, yarn_id});
    std::size_t takes = letter == 's' ? 0 : letter == 'd' ? 2 : 1;
    int makes = letter == 'e' ? 0 : letter == 'i' ? 2 : 1;
    if (forward ? yarn + takes > fabric.size() : yarn < takes) {  // round the tube: cut it
      std::rotate(fabric.begin(), fabric.begin() + static_cast<std::ptrdiff_t>(yarn), fabric.end());
      yarn = forward ? 0 : fabric.size();
    }
    std::size_t first = forward ? yarn : yarn - takes;
    if (leg_starts) leg = first, leg_starts = false;
    for (std::size_t i = 0; i < takes; ++i) {
      auto [maker, slot] = fabric[first + i];
      lines[static_cast<std::size_t>(s)].in[i] = maker;
      lines[static_cast<std::size_t>(maker)].out[slot] = s;
    }
    auto at = fabric.erase(fabric.begin() + static_cast<std::ptrdiff_t>(first),
                           fabric.begin() + static_cast<std::ptrdiff_t>(first + takes));
    for (int i = makes; i-- > 0;) at = fabric.insert(at, {s, i});
    yarn = forward ? first + static_cast<std::size_t>(makes) : first;
  }
  // `.st` lists two ins or outs in the order the stitch's yarn meets them: going back, right
  // to left.
  std::string text;
  for (Line& l : lines) {
    if (!l.forward && l.in[1] != -1) std::swap(l.in[0], l.in[1]);
    if (!l.forward && l.out[1] != -1) std::swap(l.out[0], l.out[1]);
    text += fmt::format("{} {} {} {} {} {} {} 0 0 0\n", l.yarn, l.letter, l.forward ? 'a' : 'c',
                        l.in[0], l.in[1], l.out[0], l.out[1]);
  }
  return text;
}

// Shaping inside a short row, as AutoKnit's stitch graphs have it. The tube (10 round): a short
// row from the round's start across the front and into the back with a kfb on the back, so
// that the two loops waiting beyond its turn (on lower back needles) move down to make room;
// the short row back with a k2tog, so that they move up again; then two rounds that start at
// that turn (elsewhere than the round below), knit where their loops wait, and the bind-off.
// The sheet (8 wide): a short row from the right edge with a kfb, so that the loops waiting
// left of it move left; one from the left edge with a k2tog, which closes its gap.
inline const char* const kShapedShortRowTube =
    "ssssssssss"
    "kkkkkkkkkk"
    "kkkkkkik|"
    "kkdk|"
    "kkkkkkkkkk"
    "kkkkkkkkkk"
    "eeeeeeeeee";
inline const char* const kShapedShortRowSheet =
    "ssssssss|"
    "kkkkkkkk|"
    "kkkkkkkk|"
    "kikk|"
    "kkkkk|"
    "kkkkkkkkk|"
    "kkdk|"
    "kkkk|"
    "kkkkkkkk|"
    "eeeeeeee";

// A tube left lopsided by shaping inside short rows: its bind-off, which starts at a turn,
// crosses from one bed's left end to the other's further than swg091n2's transfers stretch.
inline const char* const kLeftFoldHopTube = "ssssssssdkkdkikdkikkkdkd|id|dkttkkkkkdikk|d|kiieeeee";

// A tube (8 around) parting into two legs, as AutoKnit's test-B does: a short round of 6 from
// the round's start (its last 4 stitches the first leg's, across the right fold, 2 on each
// bed), the first leg knit round once more and bound off while the other 4 loops wait; the
// yarn goes on to the second leg, knit round once and bound off.
inline const char* const kPartedTube =
    "ssssssss"
    "kkkkkkkk"
    "kk(kkkk)"
    "kkkk)"
    "eeee"
    "kkkk"
    "eeee";
// A tube (8 around) whose first half (its front) is bound off; the yarn goes on to knit the
// other half (the back) round twice, re-spaced over both beds, and binds it off.
inline const char* const kHalfBoundOffTube =
    "ssssssss"
    "kkkkkkkk"
    "eeee"
    "kkkk"
    "kkkk"
    "eeee";

inline Compilation compile_letters(const char* letters, const char* name) {
  return compile_knit_graph(parse_autoknit_st(stitch_graph_st(letters), name), name);
}

// A stitch graph's letters compiled and emitted for a shipped profile.
struct EmittedLetters {
  Compilation c;
  knitout::MachineProfile p;
  std::string text;
};
inline EmittedLetters emit_letters(const char* letters, const char* name,
                                   const std::string& profile) {
  EmittedLetters e{compile_letters(letters, name), shipped_profile(profile), ""};
  e.text = emit_knitout_text(e.c, e.p);
  return e;
}

// The lines of `text` from the first that starts with `from` up to the next that starts with
// `to` ("" when `from` is not there).
inline std::string section(const std::string& text, const std::string& from,
                           const std::string& to) {
  std::size_t begin = text.find(from);
  if (begin == std::string::npos) return "";
  return text.substr(begin, text.find(to, begin) - begin);
}

// Random letters taking exactly `loops` loops: knits, kfbs, k2togs, tucks and slips.
inline std::string random_run(std::mt19937_64& rng, std::size_t loops, std::size_t& made) {
  std::string run;
  for (std::size_t left = loops; left > 0;) {
    std::uint64_t r = rng() % 12;
    char letter = r < 7 ? 'k' : r < 9 ? 'i' : r < 11 && left > 1 ? 'd' : r == 11 ? 't' : 'k';
    run += letter;
    left -= letter == 'd' ? 2 : 1;
    made += letter == 'i' ? 2 : letter == 'd' ? 0 : 1;
    if (letter == 'd') ++made;
  }
  return run;
}

// Emits and proves random letters on every shipped profile: each proves (counted in `proven`)
// or is refused because a needle would gather more loops than the profile allows (`refused`).
inline void prove_or_refuse_gathering(const std::string& letters, int& proven, int& refused) {
  Compilation c = compile_letters(letters.c_str(), "random.st");
  ASSERT_TRUE(c.knittability.knittable) << letters;
  for (const char* name : {"swg091n2", "kniterate", "generic"}) {
    knitout::MachineProfile p = shipped_profile(name);
    std::string text;
    try {
      text = emit_knitout_text(c, p);
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("would gather"), std::string::npos)
          << letters << " on " << name << ": " << e.what();
      ++refused;
      continue;
    }
    knitout::ProofResult proof = replay_and_prove(text, c, p);
    EXPECT_TRUE(proof.proven) << letters << " on " << name << ": " << proof.summary;
    proven += proof.proven;
  }
}

}  // namespace skein::testing
