// Mutation tests: single-operation edits of valid knitout (drop a line, swap two lines, change
// a needle, a direction, a rack, a carrier). Every edit that changes the fabric or breaks a rule
// must be rejected, by a rule of the virtual v-bed or by the proof. An edit that the proof
// accepts leaves every loop pulled through the same loops in the same yarn order: it is
// undetectable by design, and is classified to show why (commuting operations, a rack no
// transfer sees, a machine setting). Edits anywhere in the file count, the waste section, draw
// thread, cast-on border and tag included: the whole-file proof must still free the piece from
// what they change, and finds the border whole (each cast-on loop on a border loop of its own,
// the border's passes in order, no loop of it wrapped in its yarn). Of the 241 border and
// draw-thread edits accepted before the border was checked, 24 are left, none changing what
// comes off the machine: 12 in the draw thread (pulled out) and 12 moving releasehook.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <iostream>
#include <map>
#include <random>

#include "common/error.hpp"
#include "mesh/generate.hpp"
#include "test_knitout_util.hpp"

namespace skein {
namespace {

using T = StitchType;

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  for (std::string_view l : knitout::split_lines(text)) lines.emplace_back(l);
  return lines;
}
std::string join(const std::vector<std::string>& lines) {
  std::string out;
  for (const std::string& l : lines) out += l + '\n';
  return out;
}
std::vector<std::string> words(const std::string& line) {
  std::vector<std::string> w;
  std::size_t i = 0;
  while (i < line.size()) {
    std::size_t j = line.find(' ', i);
    if (j == std::string::npos) j = line.size();
    if (j > i) w.push_back(line.substr(i, j - i));
    i = j + 1;
  }
  return w;
}
bool is_op(const std::string& line) {
  return !line.empty() && line[0] != ';';
}
bool is_needle(const std::string& w) {
  return w.size() >= 2 && (w[0] == 'f' || w[0] == 'b') &&
         (std::isdigit(static_cast<unsigned char>(w.back())));
}

struct Mutant {
  std::string kind;                // drop, swap, needle, direction, rack, carrier
  std::vector<std::size_t> lines;  // 0-based lines edited
  std::vector<std::string> text;
};

// One edit of `kind` at op line `i` (0-based), or nothing when it does not apply there.
std::optional<Mutant> mutate(const std::vector<std::string>& lines, std::size_t i,
                             const std::string& kind, const knitout::MachineProfile& p) {
  Mutant m{kind, {i}, lines};
  std::vector<std::string> w = words(lines[i]);
  auto rebuild = [&] {
    std::string l;
    for (const std::string& x : w) l += (l.empty() ? "" : " ") + x;
    m.text[i] = l;
  };
  if (kind == "drop") {
    m.text.erase(m.text.begin() + static_cast<std::ptrdiff_t>(i));
  } else if (kind == "swap") {
    std::size_t j = i + 1;
    while (j < lines.size() && !is_op(lines[j])) ++j;
    if (j == lines.size() || lines[i] == lines[j]) return std::nullopt;
    std::swap(m.text[i], m.text[j]);
    m.lines.push_back(j);
  } else if (kind == "needle") {
    auto it = std::find_if(w.begin(), w.end(), is_needle);
    if (it == w.end()) return std::nullopt;
    std::size_t digits = (*it)[1] == 's' ? 2 : 1;
    *it = it->substr(0, digits) + std::to_string(std::stoi(it->substr(digits)) + 1);
    rebuild();
  } else if (kind == "direction") {
    if (w.size() < 2 || (w[1] != "+" && w[1] != "-")) return std::nullopt;
    w[1] = w[1] == "+" ? "-" : "+";
    rebuild();
  } else if (kind == "rack") {
    if (w.size() != 2 || w[0] != "rack") return std::nullopt;
    w[1] = std::to_string(std::stoi(w[1]) + 1);
    rebuild();
  } else if (kind == "carrier") {
    if (w.empty() || w.back() != p.yarn_carrier) return std::nullopt;
    w.back() = p.yarn_carrier == "2" ? "5" : "2";
    rebuild();
  }
  return m;
}

struct Tally {
  std::map<std::string, int> outcome;  // rejected by a rule, not proven, undetectable: <why>
  int total = 0;
  std::vector<std::string> unexplained;
};

std::vector<std::string> needles_of(const std::string& line) {
  std::vector<std::string> w = words(line), n;
  std::copy_if(w.begin(), w.end(), std::back_inserter(n), is_needle);
  return n;
}
bool disjoint_needles(const std::string& a, const std::string& b) {
  for (const std::string& x : needles_of(a))
    for (const std::string& y : needles_of(b))
      if (x == y) return false;
  return true;
}
// "xfer A B" at line i is followed by "xfer B A" before anything else touches A or B.
bool comes_straight_back(const std::vector<std::string>& lines, std::size_t i) {
  std::vector<std::string> ab = needles_of(lines[i]);
  for (std::size_t j = i + 1; j < lines.size(); ++j) {
    if (!is_op(lines[j])) continue;
    std::vector<std::string> n = needles_of(lines[j]);
    if (n == std::vector<std::string>{ab[1], ab[0]}) return words(lines[j]).front() == "xfer";
    if (!disjoint_needles(lines[i], lines[j])) return false;
  }
  return false;
}

// The needle number of a stitch line ("tuck + f272 3": 272).
int needle_number(const std::string& line) {
  std::string n = needles_of(line).front();
  return std::stoi(n.substr(n.find_first_of("-0123456789")));
}
bool makes_a_loop(const std::string& line) {
  std::string op = words(line).front();
  return op == "knit" || op == "tuck";
}
// The loop of line i is one the yarn turns at: the loops made before and after it (by its
// carrier) lie on one side of its needle.
bool yarn_turns_at(const std::vector<std::string>& lines, std::size_t i) {
  std::string carrier = words(lines[i]).back();
  auto neighbour = [&](int step) -> std::optional<int> {
    for (auto j = static_cast<std::ptrdiff_t>(i) + step;
         j >= 0 && j < static_cast<std::ptrdiff_t>(lines.size()); j += step)
      if (is_op(lines[j]) && makes_a_loop(lines[j]) && words(lines[j]).back() == carrier)
        return needle_number(lines[j]);
    return std::nullopt;
  };
  std::optional<int> before = neighbour(-1), after = neighbour(1);
  int here = needle_number(lines[i]);
  return before && after && (*before - here) * (*after - here) > 0;
}

// Why an accepted edit cannot change the fabric, or "" when there is no such reason.
std::string why_undetectable(const Mutant& m, const std::vector<std::string>& original,
                             const knitout::ProofResult& proof, const knitout::MachineProfile& p) {
  auto op = [&](std::size_t i) { return words(original[i]).front(); };
  auto carrier = [&](std::size_t i) { return is_op(original[i]) ? words(original[i]).back() : ""; };
  auto all = [&](auto f) { return std::all_of(m.lines.begin(), m.lines.end(), f); };
  // The whole-file proof accepted it, so the piece still comes free of what the edit changed.
  if (all([&](std::size_t i) { return i + 1 < proof.first_line && carrier(i) == p.waste_carrier; }))
    return "in the waste section, which the piece still comes free of";
  // The draw thread is pulled out: the whole-file proof checked that each cast-on loop still
  // hangs on a loop of it of its own, and that nothing else holds the piece.
  if (all([&](std::size_t i) { return i + 1 < proof.first_line && carrier(i) == p.draw_carrier; }))
    return "in the draw thread, which is pulled out: each cast-on loop still hangs on its own loop";
  auto border = [&](std::size_t i) {
    return i + 1 < proof.first_line && (carrier(i) == p.yarn_carrier || op(i) == "releasehook");
  };
  auto border_or_first = [&](std::size_t i) { return border(i) || i + 1 == proof.first_line; };
  if (m.kind == "swap" && all(border_or_first) &&
      (op(m.lines[0]) == "releasehook" || op(m.lines[1]) == "releasehook"))
    return "the hook lets go of the yarn's end a stitch earlier or later (the same loops)";
  if (m.kind == "direction" && all(border) && yarn_turns_at(original, m.lines[0]))
    return "a border loop the yarn turns at (it comes and goes on one side) made going the "
           "other way: the same turn";
  if (all([&](std::size_t i) { return i + 1 > proof.last_line; }))
    return "in the tag after the bind-off, which is dropped and unravels to the piece's last loop";
  // A short row's wrap is no st of the model: dropped, moved onto another waiting loop or made
  // going the other way, the file still knits the model's sts (the proof accepts a turn with or
  // without one, and checks a wrap it finds is pulled through by one st).
  auto wrap = [&](std::size_t i) {
    return std::find(proof.wrap_lines.begin(), proof.wrap_lines.end(), i + 1) !=
           proof.wrap_lines.end();
  };
  if (m.kind != "swap" && all(wrap)) return "a short row's wrap, which the model does not have";
  if (m.kind == "swap" && op(m.lines[0]) == "xfer" && op(m.lines[1]) == "xfer")
    return "two transfers in one transfer pass swapped (they commute)";
  auto moves = [&](std::size_t i) { return op(i) == "xfer" || op(i) == "drop"; };
  if (m.kind == "swap" && moves(m.lines[0]) != moves(m.lines[1]) &&
      disjoint_needles(original[m.lines[0]], original[m.lines[1]]))
    return "a transfer or drop and a stitch on other needles swapped (they commute)";
  if (m.kind == "drop" && op(m.lines[0]) == "xfer")
    return comes_straight_back(original, m.lines[0])
               ? "a transfer that a later one undoes before the loop is used (a redundant pair)"
               : "a transfer whose loop joins the same stack, in the same order, by a later one";
  auto in_or_out = [&](std::size_t i) {
    return op(i) == "in" || op(i) == "out" || op(i) == "inhook" || op(i) == "outhook";
  };
  if (m.kind == "swap" && in_or_out(m.lines[0]) && in_or_out(m.lines[1]) &&
      carrier(m.lines[0]) != carrier(m.lines[1]))
    return "one carrier going out and another coming in swapped (no stitch between them)";
  if (op(m.lines[0]).starts_with("x-")) return "a machine setting (stitch size, speed)";
  if (m.kind == "rack" || (m.kind == "drop" && op(m.lines[0]) == "rack") ||
      (m.kind == "swap" && (op(m.lines[0]) == "rack" || op(m.lines[1]) == "rack")))
    return "a rack that no transfer sees (knitting does not depend on the rack)";
  return "";
}

void run_mutants(const std::string& name, const Compilation& c, const knitout::MachineProfile& p,
                 std::size_t samples, Tally& tally) {
  std::string text = testing::emit_knitout_text(c, p);
  ASSERT_TRUE(testing::replay_and_prove(text, c, p).proven) << name;
  std::vector<std::string> lines = lines_of(text);
  std::vector<std::size_t> ops;
  for (std::size_t i = 0; i < lines.size(); ++i)
    if (is_op(lines[i])) ops.push_back(i);
  std::mt19937_64 rng(std::hash<std::string>()(name));
  const char* kinds[] = {"drop", "swap", "needle", "direction", "rack", "carrier"};
  for (std::size_t n = 0; n < samples; ++n) {
    std::size_t i = ops[rng() % ops.size()];
    for (const char* kind : kinds) {
      std::optional<Mutant> m = mutate(lines, i, kind, p);
      if (!m) continue;
      ++tally.total;
      std::string verdict;
      knitout::ProofResult proof;
      try {
        proof = testing::replay_and_prove(join(m->text), c, p);
        verdict = proof.proven ? "" : "rejected: not proven against the input";
      } catch (const ParseError&) {
        verdict = "rejected: breaks a rule of the v-bed";
      }
      if (verdict.empty()) {
        std::string why = why_undetectable(*m, lines, testing::replay_and_prove(text, c, p), p);
        verdict = "undetectable by design: " + (why.empty() ? "UNEXPLAINED" : why);
        if (why.empty())
          tally.unexplained.push_back(
              fmt::format("{} {} at line {}: '{}'{}", name, kind, i + 1, lines[i],
                          m->lines.size() > 1 ? " with '" + lines[m->lines[1]] + "'" : ""));
      }
      ++tally.outcome[verdict];
    }
  }
}

// A random short-row sheet that turns at both an sr4 (with its wrap) and an sr5.
Compilation sheet_with_both_turns() {
  auto has = [](const Compilation& c, StitchType t) {
    return std::count(c.knit.type.begin(), c.knit.type.end(), t) > 0;
  };
  for (std::uint64_t seed = 1;; ++seed) {
    Compilation c = compile_stitch_mesh(short_row_sheet(12, 12, seed), "short rows");
    if (has(c, T::sr4) && has(c, T::sr5)) return c;
  }
}

TEST(KnitoutMutation, EveryEditThatChangesTheFabricOrBreaksARuleIsRejected) {
  std::filesystem::current_path(SKEIN_SOURCE_DIR);
  Tally tally;
  run_mutants("rib swatch on swg091n2", compile_model("samples/rib-swatch/rib-swatch.obj"),
              testing::shipped_profile("swg091n2"), 150, tally);
  run_mutants("hat on kniterate", compile_model("samples/hat/hat.obj"),
              testing::shipped_profile("kniterate"), 150, tally);
  RowPlan sheet = {{T::co, T::co, T::co, T::co, T::co, T::co},
                   {T::k, T::kfb, T::p, T::yo, T::k, T::m1l},
                   {T::k, T::k2tog, T::p, T::ssk, T::m1r, T::k, T::p},
                   {T::k, T::p, T::s2kp, T::k, T::p2tog},
                   {T::bo, T::bo, T::bo, T::bo, T::bo}};
  run_mutants("shaped sheet on generic",
              compile_stitch_mesh(build_from_rows(sheet, Layout::sheet), "sheet"),
              testing::shipped_profile("generic"), 150, tally);
  RandomShaping shaping;
  run_mutants(
      "shaped tube on swg091n2",
      compile_stitch_mesh(build_from_rows(random_rows(20, 10, shaping, 7), Layout::tube), "tube"),
      testing::shipped_profile("swg091n2"), 150, tally);
  run_mutants("short-row sheet on kniterate", sheet_with_both_turns(),
              testing::shipped_profile("kniterate"), 150, tally);
  run_mutants("sock (short-row heel in a tube) on swg091n2",
              compile_model("samples/sock/sock.yaml"), testing::shipped_profile("swg091n2"), 150,
              tally);
  // Shaping inside short rows: AutoKnit's test-A (a kfb in a short row, tucks and slips, rounds
  // that start at a turn) and the two small stitch graphs of test_knitout_short_rows.cpp.
  run_mutants("AutoKnit test-A on generic", compile_model("samples/autoknit/test-A.st"),
              testing::shipped_profile("generic"), 150, tally);
  // A bind-off of part of the work: AutoKnit's test-B and two small tubes parted by one.
  run_mutants("AutoKnit test-B on generic", compile_model("samples/autoknit/test-B.st"),
              testing::shipped_profile("generic"), 150, tally);
  for (auto [letters, name] :
       {std::pair{testing::kShapedShortRowTube, "shaped short rows, tube"},
        std::pair{testing::kLeftFoldHopTube, "a tube whose bind-off hops over its left fold"},
        std::pair{testing::kShapedShortRowSheet, "shaped short rows, sheet"},
        std::pair{testing::kPartedTube, "a tube parted into two legs"},
        std::pair{testing::kHalfBoundOffTube, "a tube half bound off"}})
    run_mutants(fmt::format("{} on swg091n2", name), testing::compile_letters(letters, name),
                testing::shipped_profile("swg091n2"), 100, tally);
  int rejected = 0, undetectable = 0;
  std::cout << "knitout mutants: " << tally.total << "\n";
  for (const auto& [verdict, count] : tally.outcome) {
    std::cout << fmt::format("  {:5}  {}\n", count, verdict);
    (verdict.starts_with("rejected") ? rejected : undetectable) += count;
  }
  std::cout << fmt::format(
      "  detection rate of edits that change the fabric or break a rule: {}/{}\n", rejected,
      tally.total - undetectable);
  EXPECT_TRUE(tally.unexplained.empty())
      << fmt::format("{} accepted edits have no reason:\n  {}", tally.unexplained.size(),
                     fmt::join(tally.unexplained, "\n  "));
  EXPECT_GT(rejected, tally.total * 3 / 4);
}

}  // namespace
}  // namespace skein
