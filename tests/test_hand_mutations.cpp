// Mutation tests of the hand simulator: many single edits of each pattern's text (drop or swap
// an instruction, change a stitch, a count, a repeat, a side, add a marker, delete or repeat a
// line). Every edit must be rejected unless the fabric it knits is the same as the original's
// (those are undetectable by design: the knitter makes the same thing).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <random>
#include <regex>
#include <sstream>

#include "builtin_targets.hpp"
#include "common/error.hpp"
#include "driver/pipeline.hpp"
#include "fixtures.hpp"
#include "hand/hand_target.hpp"
#include "hand/needle_sim.hpp"
#include "hand/pattern_document.hpp"
#include "hand/pattern_model.hpp"
#include "hand/pattern_writers.hpp"
#include "hand/program_pattern.hpp"
#include "mesh/generate.hpp"
#include "test_hand_plans.hpp"

namespace skein {
namespace {

struct Mutant {
  std::string kind;
  std::string text;
};

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::string joined(const std::vector<std::string>& lines) {
  std::string out;
  for (const std::string& l : lines) out += l + "\n";
  return out;
}

// The row text's items, split at top-level commas (not inside brackets).
std::vector<std::string> items_of(const std::string& text) {
  std::vector<std::string> items(1);
  int depth = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    depth += text[i] == '[' ? 1 : text[i] == ']' ? -1 : 0;
    if (depth == 0 && text.compare(i, 2, ", ") == 0) {
      items.emplace_back();
      ++i;
    } else {
      items.back() += text[i];
    }
  }
  return items;
}

std::string items_text(const std::vector<std::string>& items) {
  std::string out;
  for (const std::string& item : items) out += (out.empty() ? "" : ", ") + item;
  return out;
}

class Mutator {
 public:
  // With `near_pieces`, only the lines within 4 instructions of a piece heading (where pieces
  // start, wait, are taken up and join): for large patterns.
  explicit Mutator(const std::string& pattern, bool near_pieces = false)
      : lines_(lines_of(pattern)), near_pieces_(near_pieces) {
    for (std::size_t i = 0; i < lines_.size(); ++i) {
      if (lines_[i] == "## Instructions") begin_ = i + 1;
      if (begin_ && i > begin_ && lines_[i].rfind("## ", 0) == 0 && !end_) end_ = i;
    }
    if (!end_) end_ = lines_.size();
  }

  std::vector<Mutant> all() {
    for (std::size_t i = begin_; i < end_; ++i) {
      if (lines_[i].empty() || (near_pieces_ && !near_a_piece_heading(i))) continue;
      line_edits(i);
      word_edits(i);
      item_edits(i);
    }
    return std::move(out_);
  }

 private:
  void add(const char* kind, std::size_t i, const std::string& line) {
    if (line == lines_[i]) return;
    std::vector<std::string> copy = lines_;
    copy[i] = line;
    out_.push_back({kind, joined(copy)});
  }

  void line_edits(std::size_t i) {
    std::vector<std::string> copy = lines_;
    copy.erase(copy.begin() + static_cast<std::ptrdiff_t>(i));
    out_.push_back({"delete a line", joined(copy)});
    copy = lines_;
    copy.insert(copy.begin() + static_cast<std::ptrdiff_t>(i), lines_[i]);
    out_.push_back({"repeat a line", joined(copy)});
    if (lines_[i].find("Pm and join") != std::string::npos)
      add("remove the marker", i, std::regex_replace(lines_[i], std::regex("Pm and join"), "Join"));
    static const std::regex kMarkerOp(R"(, [psr]m\b|\b[psr]m, )");
    for (auto it = std::sregex_iterator(lines_[i].begin(), lines_[i].end(), kMarkerOp);
         it != std::sregex_iterator(); ++it)
      add("drop a marker", i,
          lines_[i].substr(0, it->position()) + lines_[i].substr(it->position() + it->length()));
  }

  // Numbers, count words, stitches and sides, one occurrence at a time.
  void word_edits(std::size_t i) {
    const std::string& line = lines_[i];
    static const std::regex kWord(R"(w&t|[A-Za-z0-9]+|\(RS\)|\(WS\))");
    for (auto it = std::sregex_iterator(line.begin(), line.end(), kWord);
         it != std::sregex_iterator(); ++it) {
      std::string word = it->str();
      auto replace = [&](const char* kind, const std::string& with) {
        add(kind, i,
            line.substr(0, it->position()) + with + line.substr(it->position() + word.size()));
      };
      if (std::isdigit(static_cast<unsigned char>(word[0]))) {
        int n = std::stoi(word);
        replace("change a number", std::to_string(n + 1));
        if (n > 0) replace("change a number", std::to_string(n - 1));
      }
      for (const auto& [from, tos] : kAlternatives)
        if (word == from)
          for (const char* to : tos) replace(kind_of(from), to);
      static const std::regex kPlainRun(R"([KkPp]\d+)");
      if (std::regex_match(word, kPlainRun)) replace("change a stitch", swapped_plain(word));
    }
  }

  // "k12" <-> "p12", keeping the case.
  static std::string swapped_plain(std::string word) {
    constexpr std::string_view kFrom = "kpKP", kTo = "pkPK";
    word[0] = kTo[kFrom.find(word[0])];
    return word;
  }

  static const char* kind_of(const std::string& word) {
    if (word == "(RS)" || word == "(WS)") return "flip a side";
    if (word == "once" || word == "twice" || word == "three" || word == "four" || word == "five" ||
        word == "six" || word == "fifteen")
      return "change a repeat count";
    if (word == "end" || word == "last") return "change a repeat form";
    return "change a stitch";
  }

  void item_edits(std::size_t i) {
    const std::string& line = lines_[i];
    std::size_t colon = line.find(":** ");
    if (colon == std::string::npos) return;
    std::string label = line.substr(0, colon + 4), body = line.substr(colon + 4), tail;
    std::size_t end = body.find(" \u2014");
    if (end == std::string::npos) end = body.size() - 1;  // the period
    tail = body.substr(end);
    std::vector<std::string> items = items_of(body.substr(0, end));
    for (std::size_t k = 0; k < items.size(); ++k) {
      std::vector<std::string> edited = items;
      edited.erase(edited.begin() + static_cast<std::ptrdiff_t>(k));
      if (!edited.empty()) add("drop an instruction", i, label + items_text(edited) + tail);
      edited = items;
      edited.insert(edited.begin() + static_cast<std::ptrdiff_t>(k + 1), "pm");
      add("place a marker", i, label + items_text(edited) + tail);
      if (k + 1 < items.size()) {
        edited = items;
        std::swap(edited[k], edited[k + 1]);
        add("swap two instructions", i, label + items_text(edited) + tail);
      }
    }
  }

  inline static const std::map<std::string, std::vector<const char*>> kAlternatives = {
      {"k2tog", {"ssk", "p2tog", "s2kp", "kfb"}},
      {"ssk", {"k2tog", "ssp", "s2kp"}},
      {"Ssk", {"K2tog", "S2kp"}},
      {"K2tog", {"Ssk", "P2tog"}},
      {"p2tog", {"k2tog", "ssp", "s2pp"}},
      {"ssp", {"p2tog", "ssk"}},
      {"s2kp", {"k2tog", "s2pp"}},
      {"s2pp", {"p2tog", "s2kp"}},
      {"kfb", {"pfb", "M1L", "yo"}},
      {"pfb", {"kfb", "M1PL"}},
      {"M1L", {"M1R", "M1PL", "yo"}},
      {"M1R", {"M1L", "M1PR"}},
      {"M1PL", {"M1PR", "M1L"}},
      {"M1PR", {"M1PL", "M1R"}},
      {"yo", {"M1L", "kfb"}},
      {"k", {"p"}},
      {"p", {"k"}},
      {"K", {"P"}},
      {"P", {"K"}},
      {"Knit", {"Purl"}},
      {"Purl", {"Knit"}},
      {"(RS)", {"(WS)"}},
      {"(WS)", {"(RS)"}},
      {"once", {"twice"}},
      {"twice", {"once", "three"}},
      {"three", {"twice", "four"}},
      {"four", {"three", "five"}},
      {"five", {"four", "six"}},
      {"fifteen", {"fourteen", "sixteen"}},
      {"end", {"last 1 st"}},
      {"last", {"end, and", "first"}},
      {"first", {"last"}},
      {"front", {"behind"}},
      {"behind", {"front"}},
      {"right", {"left"}},
      {"left", {"right"}},
      {"up", {"down"}},
      {"down", {"up"}},
      {"w&t", {"turn", "k1, turn"}},
      {"turn", {"w&t"}},
      {"DS", {"k", "sm"}},
      {"kw", {"k", "pw"}},
      {"pw", {"p", "kw"}},
      {"back", {"from spare"}},
      {"Rm", {"Sm"}},
      {"sl1yo", {"sl1", "k1", "turn"}},
      {"brk", {"k1", "brp", "sl1"}},
      {"Brk", {"K1", "Sl1"}},
      {"brp", {"p1", "brk"}},
  };

  bool near_a_piece_heading(std::size_t i) const {  // blank lines between instructions
    for (std::size_t j = i > 8 ? i - 8 : 0; j < std::min(i + 9, lines_.size()); ++j)
      if (lines_[j].rfind("### ", 0) == 0) return true;  // "### Sleeve 1 (yarn 3)"
    return false;
  }

  std::vector<std::string> lines_;
  bool near_pieces_ = false;
  std::size_t begin_ = 0, end_ = 0;
  std::vector<Mutant> out_;
};

bool same_fabric(const hand::Fabric& a, const hand::Fabric& b) {
  if (a.size() != b.size() || a.piece_first != b.piece_first) return false;
  for (std::uint32_t x = 0; x < a.size(); ++x) {
    if (a.type[x] != b.type[x] || a.yarn_next[x] != b.yarn_next[x] ||
        a.yarn_link[x] != b.yarn_link[x] || a.made[x] != b.made[x])
      return false;
    std::vector<std::uint32_t> ta = a.rs_taken(x), tb = b.rs_taken(x);
    if (ta.size() != tb.size()) return false;
    for (std::size_t i = 0; i < ta.size(); ++i)
      if (a.loop_maker[ta[i]] != b.loop_maker[tb[i]] || a.rs_slot(ta[i]) != b.rs_slot(tb[i]))
        return false;
  }
  return true;
}

hand::Replay knit(const std::string& text) {
  return hand::replay(hand::read_pattern(text, "p.md"), "p.md");
}

struct Tally {
  std::map<std::string, int> outcome;                         // by outcome
  std::map<std::string, std::map<std::string, int>> by_kind;  // kind -> outcome
  int total = 0;
  std::vector<std::string> missed;
};

void judge(const Compilation& c, const std::string& original, const Mutant& m, Tally& tally) {
  std::string outcome;
  try {
    VerifyReport r = hand::verify_pattern(m.text, "mutant.md", &c);
    if (r.proven) {
      bool same = same_fabric(knit(original).fabric, knit(m.text).fabric);
      outcome = same ? "same fabric: undetectable by design" : "MISSED";
      if (!same) tally.missed.push_back(m.kind + ":\n" + m.text);
    } else if (r.summary.find("not the model's fabric") != std::string::npos) {
      outcome = "rejected: a different fabric";
    } else if (r.summary.find("the pattern says") != std::string::npos) {
      outcome = "rejected: a printed stitch count";
    } else {
      outcome = "rejected: an impossible step";
    }
  } catch (const ParseError&) {
    outcome = "rejected: unreadable";
  }
  ++tally.total;
  ++tally.outcome[outcome];
  ++tally.by_kind[m.kind][outcome];
}

std::string report(const std::string& name, const Tally& t) {
  int same = t.outcome.count("same fabric: undetectable by design")
                 ? t.outcome.at("same fabric: undetectable by design")
                 : 0;
  int changing = t.total - same, rejected = changing - static_cast<int>(t.missed.size());
  std::string out = fmt::format(
      "{}: {} edits; {} change the fabric, {} of them rejected ({:.1f}%); "
      "{} knit the same fabric\n",
      name, t.total, changing, rejected, changing ? 100.0 * rejected / changing : 100.0, same);
  for (const auto& [outcome, n] : t.outcome) out += fmt::format("    {:<40} {}\n", outcome, n);
  for (const auto& [kind, outcomes] : t.by_kind) {
    out += fmt::format("  {:<24}", kind);
    for (const auto& [outcome, n] : outcomes) out += fmt::format(" {} {};", outcome, n);
    out += "\n";
  }
  return out;
}

std::string hand_pattern(const Compilation& c) {
  Registry registry;
  register_builtin_targets(registry);
  std::ostringstream out;
  registry.target("hand")->emit(c, {}, out);
  return out.str();
}

void mutate_and_judge(const std::string& name, const Compilation& c, const std::string& pattern,
                      bool near_pieces = false) {
  ASSERT_TRUE(hand::verify_pattern(pattern, name, &c).proven);
  Tally tally;
  for (const Mutant& m : Mutator(pattern, near_pieces).all()) judge(c, pattern, m, tally);
  std::cout << report(name, tally);
  EXPECT_GE(tally.total, 25) << name;
  EXPECT_TRUE(tally.missed.empty()) << name << ": an edit that changes the fabric was proven:\n"
                                    << tally.missed.front();
}

void mutate_and_judge(const std::string& name, const Compilation& c) {
  mutate_and_judge(name, c, hand_pattern(c));
}

TEST(HandMutations, SamplesRejectEveryEditThatChangesTheFabric) {
  std::filesystem::current_path(SKEIN_SOURCE_DIR);
  for (const char* sample :
       {"samples/rib-swatch/rib-swatch.obj", "samples/hat/hat.obj", "samples/sock/sock.yaml",
        "samples/short-row-wedge/short-row-wedge.yaml"})
    mutate_and_judge(sample, compile_model(sample));
}

std::string hand_pattern(const Compilation& c, hand::TurnMethod turns) {
  std::ostringstream out;
  hand::write_markdown(hand::make_document(hand::build_hand_pattern(c, turns)), out);
  return out.str();
}

// The same samples' short rows with wrap and turn (German short rows above).
TEST(HandMutations, WrapAndTurnShortRowsRejectEveryEditThatChangesTheFabric) {
  std::filesystem::current_path(SKEIN_SOURCE_DIR);
  for (const char* sample :
       {"samples/sock/sock.yaml", "samples/short-row-wedge/short-row-wedge.yaml"}) {
    Compilation c = compile_model(sample);
    mutate_and_judge(std::string(sample) + " (wrap and turn)", c,
                     hand_pattern(c, hand::TurnMethod::wrap_and_turn));
  }
}

// Short rows turning at sr5 faces, the DS or wrap worked as one st with the sr5's by the
// decrease above (k DS, kw), with either method: Fig. 9's fixture and the sock's project with
// `short_rows: {method: sr5}`; the wedge's purled (p DS over a p2tog seen from the RS).
TEST(HandMutations, Sr5TurnsRejectEveryEditThatChangesTheFabric) {
  Compilation fixture = compile_stitch_mesh(testing::short_row_mesh(StitchType::sr5), "fig. 9");
  Compilation sock = testing::sample_turning_at_sr5_faces("sock");
  for (hand::TurnMethod turns : {hand::TurnMethod::german, hand::TurnMethod::wrap_and_turn}) {
    const char* method = turns == hand::TurnMethod::german ? "German short rows" : "wrap and turn";
    mutate_and_judge(fmt::format("Fig. 9 with an sr5 ({})", method), fixture,
                     hand_pattern(fixture, turns));
    mutate_and_judge(fmt::format("sock with sr5 turns ({})", method), sock,
                     hand_pattern(sock, turns));
  }
  Compilation purled = testing::sample_turning_at_sr5_faces("short-row-wedge", "pattern: purl\n");
  mutate_and_judge("purled wedge with sr5 turns (p DS over a p2tog)", purled);
}

// Short rows that turn again at the st the last one turned at (`DS, k8, k DS, turn.`; with
// wrap and turn `K8, w&t.` at the wrapped st, which then has two wraps).
TEST(HandMutations, TurnsAtATurnedStRejectEveryEditThatChangesTheFabric) {
  Compilation c = testing::sock_turning_twice_at_a_st();
  mutate_and_judge("sock at 44 rows to 10 cm (k DS, turn)", c,
                   hand_pattern(c, hand::TurnMethod::german));
  mutate_and_judge("sock at 44 rows to 10 cm (w&t at a wrapped st)", c,
                   hand_pattern(c, hand::TurnMethod::wrap_and_turn));
}

// Rounds that run left to right worked with the WS facing (the tube inside out), not mirrored.
TEST(HandMutations, RndsWorkedWithTheWSFacingRejectEveryEditThatChangesTheFabric) {
  std::filesystem::current_path(SKEIN_SOURCE_DIR);
  auto inside_out = [](const Compilation& c) {
    std::ostringstream out;
    hand::write_markdown(hand::make_document(hand::build_hand_pattern(c, hand::TurnMethod::german,
                                                                      hand::Rounds::ws_facing)),
                         out);
    return out.str();
  };
  Compilation hat = compile_model("samples/hat/hat.obj");
  mutate_and_judge("hat (rnds with the WS facing)", hat, inside_out(hat));
  RandomShaping shaping;
  shaping.purl = 0.3;
  shaping.increase = shaping.decrease = 0.1;
  Compilation tube =
      compile_stitch_mesh(build_from_rows(random_rows(14, 6, shaping, 3), Layout::tube), "tube");
  mutate_and_judge("random tube (rnds with the WS facing)", tube, inside_out(tube));
}

TEST(HandMutations, SectionMarkerPatternsRejectEveryEditThatChangesTheFabric) {
  mutate_and_judge(
      "crown with section markers",
      compile_stitch_mesh(
          build_from_rows(testing::wedge_plan(6, 9, 3, 1, StitchType::k2tog), Layout::tube),
          "crown"));
  Compilation crown = compile_stitch_mesh(
      build_from_rows(testing::wedge_plan(6, 9, 3, 1, StitchType::k2tog), Layout::tube), "crown");
  std::ostringstream marked;
  hand::write_markdown(hand::make_document(testing::with_region_marks_in_a_crown(crown)), marked);
  mutate_and_judge("crown with section and region markers", crown, marked.str());
  mutate_and_judge(
      "flat wedges with section markers",
      compile_stitch_mesh(
          build_from_rows(testing::wedge_plan(3, 5, 3, 1, StitchType::yo), Layout::sheet),
          "wedges"));
}

TEST(HandMutations, SplitsRejectEveryEditThatChangesTheFabric) {
  mutate_and_judge("split fixture",
                   compile_stitch_mesh(testing::split_mesh(MismatchYarn::Kind::extra), "split"));
  mutate_and_judge(
      "split sheets (own yarn)",
      compile_stitch_mesh(meeting_sheets(Meeting::split, 5, 3, 4, MismatchYarn::Kind::own, true, 7),
                          "split sheets"));
}

TEST(HandMutations, ProvisionalCastOnsInARowRejectEveryEditThatChangesTheFabric) {
  for (bool rs_row : {false, true})
    mutate_and_judge(rs_row ? "cast-on in a RS row" : "cast-on in a WS row",
                     compile_stitch_mesh(testing::mid_row_split_mesh(rs_row), "mid-row split"));
  mutate_and_judge("cast-on in a rnd (mirrored)",
                   compile_stitch_mesh(testing::mid_round_split_mesh(), "mid-round split"));
}

TEST(HandMutations, ThreeNeedleBindOffsInARowRejectEveryEditThatChangesTheFabric) {
  mutate_and_judge("three-needle bind-off in a row",
                   compile_stitch_mesh(testing::mid_row_join_mesh(), "mid-row join"));
  std::filesystem::current_path(SKEIN_SOURCE_DIR);
  mutate_and_judge("three bars with their own yarns",
                   compile_model("samples/three-bars-own/three-bars-own.yaml"));
}

TEST(HandMutations, PickUpsRejectEveryEditThatChangesTheFabric) {
  mutate_and_judge("expanding fixture (pick-up)",
                   compile_stitch_mesh(testing::expanding_mesh(), "expanding"));
  mutate_and_judge("contracting fixture (sl1 from spare)",
                   compile_stitch_mesh(testing::contracting_mesh(), "contracting"));
  mutate_and_judge("knitted-on edging with markers",
                   compile_stitch_mesh(testing::edging_mesh(6, 4), "edging"));
}

TEST(HandMutations, DecreasesAcrossAGapRejectEveryEditThatChangesTheFabric) {
  mutate_and_judge("heel turn (decreases across a gap)",
                   compile_knit_graph(testing::heel_turn_graph(), "heel turn"));
  mutate_and_judge("heel turn on a new yarn (a row parted onto holders)",
                   compile_knit_graph(testing::heel_turn_on_new_yarn_graph(), "heel turn"));
  mutate_and_judge(
      "new yarn on a set-aside piece's sts (an earlier row's sts to a holder)",
      compile_knit_graph(testing::new_yarn_on_set_aside_needle_graph(), "set-aside needle"));
  mutate_and_judge(
      "flat piece taken up on a chain (a chain and a holder placed on its needle)",
      compile_knit_graph(testing::flat_piece_taken_up_on_a_chain_graph(), "flat piece on a chain"));
  mutate_and_judge("folded tube (three-needle bind-off of a rnd)",
                   compile_knit_graph(testing::folded_tube_graph(), "folded tube"));
  mutate_and_judge("gusset (a flap's edges picked up into the rnd)",
                   compile_knit_graph(testing::gusset_graph(), "gusset"));
  mutate_and_judge("gusset leg (the flap's sts to a holder, a new yarn)",
                   compile_knit_graph(testing::gusset_leg_graph(), "gusset leg"));
  mutate_and_judge("reversed gusset leg (a flap worked back from the end of the rnd)",
                   compile_knit_graph(testing::reversed_gusset_leg_graph(), "reversed gusset leg"));
  mutate_and_judge("strip joined in the rnd (its sts to a holder, its edges picked up)",
                   compile_knit_graph(testing::strip_joined_in_the_rnd_graph(), "strip"));
  mutate_and_judge("tube taken up after its flap (the flap's sts slipped as it is taken up)",
                   compile_knit_graph(testing::flap_and_strip_graph(), "flap and strip"));
  mutate_and_judge(
      "flap's last row round a corner in the rnd (do not turn, sts before the marker)",
      compile_knit_graph(testing::flap_and_strip_graph(true), "corner flap and strip"));
  mutate_and_judge("strip going round a corner into the rnd (do not turn, sts left)",
                   compile_knit_graph(testing::corner_strip_graph(), "corner strip"));
  mutate_and_judge("a new yarn joined in the rnd, another piece's sts placed",
                   compile_knit_graph(testing::strip_and_tube_joined_graph(), "strip and tube"));
  mutate_and_judge("strip's sts joined in the rnd with a new yarn",
                   compile_knit_graph(testing::strip_joined_in_the_rnd_graph(true), "strip leg"));
}

TEST(HandMutations, JoinsRejectEveryEditThatChangesTheFabric) {
  mutate_and_judge("join fixture",
                   compile_stitch_mesh(testing::join_mesh(MismatchYarn::Kind::extra), "join"));
  mutate_and_judge("join fixture (own yarn)",
                   compile_stitch_mesh(testing::join_mesh(MismatchYarn::Kind::own), "join own"));
  mutate_and_judge("joined sheets",
                   compile_stitch_mesh(
                       meeting_sheets(Meeting::join, 5, 4, 3, MismatchYarn::Kind::extra, false, 7),
                       "joined sheets"));
}

// The sweater's pieces: where the body waits, the sleeves are left on spare needles, and the
// body is taken up again with the sleeves placed into its rnd.
TEST(HandMutations, PiecesSetAsideAndTakenUpRejectEveryEditThatChangesTheFabric) {
  std::filesystem::current_path(SKEIN_SOURCE_DIR);
  Compilation c = compile_model("samples/sweater/sweater.yaml");
  mutate_and_judge("sweater (lines near the pieces)", c, hand_pattern(c), true);
}

// The three bars: sts slipped to holders, placed into other pieces' rnds (with a provisional
// cast-on's sts and chain) and bound off together from holders; the two bars: holders put on
// a spare needle for rows that take their sts one at a time, edges picked up into a rnd.
TEST(HandMutations, HoldersRejectEveryEditThatChangesTheFabric) {
  std::filesystem::current_path(SKEIN_SOURCE_DIR);
  mutate_and_judge("three bars", compile_model("samples/three-bars/three-bars.yaml"));
  mutate_and_judge("two bars", compile_model("samples/two-bars/two-bars.yaml"));
  mutate_and_judge("two bars at 28 sts/26 rows (a face's last row that does not turn)",
                   testing::sample_at_gauge("two-bars", 28, 26));
}

// The letter H: a band across gaps between the legs, and a fold whose pairs take held sts
// put back on its spare needle first.
TEST(HandMutations, TheLetterHRejectsEveryEditThatChangesTheFabric) {
  std::filesystem::current_path(SKEIN_SOURCE_DIR);
  mutate_and_judge("letter H", compile_model("samples/letter-h/letter-h.yaml"));
  mutate_and_judge("letter H at 13 sts/18 rows (a band's last row that does not turn)",
                   testing::sample_at_gauge("letter-h", 13, 18));
}

// The letter R: a three-needle bind-off said before a rnd in the middle of a piece's work,
// two spare needles at once, a last rnd bound off with two pieces held behind it.
TEST(HandMutations, TheLetterRRejectsEveryEditThatChangesTheFabric) {
  std::filesystem::current_path(SKEIN_SOURCE_DIR);
  mutate_and_judge("letter R", compile_model("samples/letter-r/letter-r.yaml"));
  mutate_and_judge("letter R at 27 sts/39 rows (two spare needles beside a piece's, an odd flap)",
                   testing::sample_at_gauge("letter-r", 27, 39));
}

// The teapot: strips parted from its body and joined in the rnd, a heel turn on a new yarn, an
// earlier row's sts slipped to two holders as a piece is set aside, a chain and a holder placed
// on a flat piece's needle as it is taken up again.
TEST(HandMutations, TheTeapotRejectsEveryEditThatChangesTheFabric) {
  std::filesystem::current_path(SKEIN_SOURCE_DIR);
  mutate_and_judge("teapot", compile_model("samples/teapot/teapot.yaml"));
}

// AutoKnit's tubes parted along their helix into two legs: the second leg's sts go to one
// holder (after the sts on it), then a new yarn is joined to them (test-C) or the first leg's
// yarn is carried on to them from its bind-off (test-B).
TEST(HandMutations, StitchGraphLegsRejectEveryEditThatChangesTheFabric) {
  std::filesystem::current_path(SKEIN_SOURCE_DIR);
  mutate_and_judge("AutoKnit test-B (the yarn carried on to a leg)",
                   compile_model("samples/autoknit/test-B.st"));
  mutate_and_judge("AutoKnit test-C (a new yarn joined to a leg)",
                   compile_model("samples/autoknit/test-C.st"));
}

// AutoKnit's short rows turned on a tuck (sl1yo, turn, sl1, later brk), going round past the
// beginning of the rnd, which then moves to where the rnd after them begins.
TEST(HandMutations, StitchGraphTuckTurnsRejectEveryEditThatChangesTheFabric) {
  std::filesystem::current_path(SKEIN_SOURCE_DIR);
  mutate_and_judge("AutoKnit test-A (short rows turned on a tuck)",
                   compile_model("samples/autoknit/test-A.st"));
}

TEST(HandMutations, ShapedSheetsAndTubesRejectEveryEditThatChangesTheFabric) {
  std::mt19937_64 rng(11);
  for (int trial = 0; trial < 6; ++trial) {
    RandomShaping shaping;
    shaping.purl = 0.3;
    shaping.increase = shaping.decrease = 0.1;
    Layout layout = trial % 2 ? Layout::tube : Layout::sheet;
    RowPlan plan = testing::without_edge_make_ones(
        random_rows(10 + static_cast<std::uint32_t>(rng() % 10), 6, shaping, rng()), layout);
    mutate_and_judge(fmt::format("random {} {}", layout == Layout::tube ? "tube" : "sheet", trial),
                     compile_stitch_mesh(build_from_rows(plan, layout), "random"));
  }
}

}  // namespace
}  // namespace skein
