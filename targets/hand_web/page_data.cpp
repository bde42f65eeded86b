#include "hand_web/page_data.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <map>
#include <sstream>
#include <string_view>
#include <tuple>

#include "common/error.hpp"
#include "driver/pipeline.hpp"
#include "hand/chart.hpp"
#include "hand/hand_target.hpp"
#include "hand/needle_sim.hpp"
#include "hand/pattern_model.hpp"
#include "hand/pattern_reader.hpp"
#include "hand_web/row_spans.hpp"
#include "yarn/build.hpp"
#include "yarn/layout.hpp"

namespace skein::hand_web {
namespace {

using hand::Fabric;
using hand::HandOp;

constexpr const char* kPatternName = "the page's pattern";

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

// "**Rnd 25:** *K to ..." as a knitter reads it: "Rnd 25: *K to ...".
std::string without_markup(std::string line) {
  for (std::size_t at; (at = line.find("**")) != std::string::npos;) line.erase(at, 2);
  return line;
}

// Per fabric stitch, the model stitch the judge pairs it with: the yarns in the order the
// schedule starts them, each followed stitch by stitch (hand/fabric_compare.hpp).
std::vector<StitchId> model_of(const Fabric& f, const Compilation& c) {
  std::vector<StitchId> model(f.size(), kNoStitch);
  std::size_t piece = 0;
  for (const Event& e : c.schedule.events) {
    if (e.kind != EventKind::yarn_start) continue;
    SKEIN_ASSERT(piece < f.piece_first.size(), "a proven pattern knits every yarn");
    std::uint32_t x = f.piece_first[piece++];
    for (StitchId s = c.yarns.first[e.yarn]; s != kNoStitch; s = c.knit.yarn_next[s]) {
      model[x] = s;
      x = f.yarn_next[x];
    }
  }
  return model;
}

// A stitch of the fabric is made by each operation that takes or makes a loop, except a
// make-one, which belongs to the stitch beside it.
bool makes_a_stitch(HandOp op) {
  const hand::HandOpInfo& i = hand::info(op);
  return !hand::is_make_one(op) && (i.takes > 0 || i.makes > 0);
}

bool marks(HandOp op) {
  return op == HandOp::pm || op == HandOp::sm;
}

// The page's script indexes text by UTF-16 code units ("Rows 2–16: ..." has an en dash
// before the tokens): the offset of byte `at` of UTF-8 `text` in those units.
std::uint32_t utf16_offset(std::string_view text, std::uint32_t at) {
  std::uint32_t units = 0;
  for (std::uint32_t i = 0; i < at; ++i) {
    auto byte = static_cast<unsigned char>(text[i]);
    if ((byte & 0xc0) != 0x80) units += byte >= 0xf0 ? 2 : 1;  // a lead byte: one code point
  }
  return units;
}

struct RowText {
  std::vector<OpSpan> spans;  // per stitch of the row, in the order worked
  std::vector<std::uint8_t> marker;
};

// Does the stitch the simulator knitted look like what operation `op` makes? Checked for the
// plain stitches and decreases that nothing beside them changes (a make-one after one forms one
// stitch with it; a German short row's turn after one, the end of its row, or a DS before can
// make it the turn's), so that a row whose operations do not line up with its stitches marks no
// token.
bool looks_like(const Fabric& f, std::uint32_t x, std::span<const HandOp> ops, std::size_t i) {
  HandOp op = ops[i];
  bool simple = op == HandOp::k || op == HandOp::p || op == HandOp::k2tog || op == HandOp::ssk ||
                op == HandOp::p2tog || op == HandOp::ssp;
  bool changed = i + 1 == ops.size() || hand::is_make_one(ops[i + 1]) ||
                 hand::ends_row(ops[i + 1]) || (i > 0 && ops[i - 1] == HandOp::ds);
  if (!simple || changed) return true;
  std::optional<StitchType> face = hand::rs_face(op, f.facing[x]);
  return !face || *face == f.type[x];
}

// The written row's operations against its text and the stitches the simulator knitted for it
// (`count` of them from fabric stitch `first` on): per stitch the token that names it. Empty when
// the text does not read back as these operations, or they do not line up with the stitches (then
// the whole line is shown).
RowText row_text(const hand::HandPattern& p, const hand::PatternRow& row, const std::string& text,
                 const Fabric& f, std::uint32_t first, std::uint32_t count) {
  std::size_t colon = text.find(": ");
  if (colon == std::string::npos) return {};
  std::size_t from = colon + 2;
  std::size_t to = text.rfind(" \u2014 ");
  if (to == std::string::npos || to < from) to = text.size() - (text.ends_with('.') ? 1 : 0);
  std::span<const HandOp> ops = p.ops_of(row);
  auto spans = op_spans(std::string_view(text).substr(from, to - from), ops);
  if (!spans) return {};
  RowText out;
  bool marked = false;
  for (std::size_t i = 0; i < ops.size(); ++i) {
    marked = marked || marks(ops[i]);
    if (!makes_a_stitch(ops[i])) continue;
    std::size_t n = out.spans.size();
    if (n >= count || !looks_like(f, first + static_cast<std::uint32_t>(n), ops, i)) return {};
    OpSpan s = (*spans)[i];
    s.begin = utf16_offset(text, s.begin + static_cast<std::uint32_t>(from));
    s.end = utf16_offset(text, s.end + static_cast<std::uint32_t>(from));
    out.spans.push_back(s);
    out.marker.push_back(marked);
    marked = false;
  }
  if (out.spans.size() != count) return {};
  return out;
}

class Builder {
 public:
  Builder(const Compilation& c, const std::string& pattern, const hand::HandPattern& written)
      : c_(c), written_(written), lines_(lines_of(pattern)) {
    out_.source = c.input;
    out_.pattern = pattern;
    out_.title = lines_.empty() ? c.input : lines_[0].substr(lines_[0].find_first_not_of("# "));
  }

  PageData run(std::string proof) && {
    out_.proof = std::move(proof);
    hand::Script script = hand::read_pattern(out_.pattern, kPatternName);
    hand::Replay r = hand::replay(script, kPatternName);
    SKEIN_ASSERT(r.ok, "a proven pattern replays");
    const Fabric& f = r.fabric;
    add_rows(f, lines_starting_pieces(script));
    add_row_spans(f);
    add_charts();
    std::vector<StitchId> model = model_of(f, c_);
    std::vector<std::uint32_t> fabric_of(c_.knit.size(), kNone);
    for (std::uint32_t x = 0; x < f.size(); ++x) fabric_of[model[x]] = x;
    add_order(f, model, fabric_of);
    add_geometry();
    out_.key = key_of();
    return std::move(out_);
  }

 private:
  // The lines of the steps that start a piece's stitches without a row (the simulator's rows
  // numbered 0), in order: cast-ons, pick-ups, joins of a new yarn, three-needle bind-offs.
  static std::vector<std::size_t> lines_starting_pieces(const hand::Script& script) {
    using K = hand::Step::Kind;
    std::vector<std::size_t> lines;
    for (const hand::Step& s : script.steps)
      if (s.kind == K::cast_on || s.kind == K::join_spare || s.kind == K::three_needle_bind_off ||
          (s.kind == K::pick_up && !s.into_rnd))
        lines.push_back(s.line);
    return lines;
  }

  // The pattern's rows as the simulator worked them, with the text that says each.
  void add_rows(const Fabric& f, const std::vector<std::size_t>& starts) {
    std::size_t unnumbered = 0, next_start = 0;
    for (const Fabric::RowWorked& w : f.rows) unnumbered += w.line == 0 ? 1 : 0;
    auto line_of = [&](const Fabric::RowWorked& w) -> std::size_t {
      if (w.line != 0) return w.line;
      return unnumbered == starts.size() ? starts[next_start++] : 0;
    };
    std::vector<std::string> heading_at(lines_.size() + 1);  // by 1-based line
    for (std::size_t i = 0, h = 0; i < lines_.size(); ++i) {
      if (lines_[i].starts_with("#")) h = i;
      heading_at[i + 1] = lines_[h].starts_with("### ") ? lines_[h].substr(4) : "";
    }
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> written_at;  // piece, no.
    std::vector<std::uint32_t> sts(f.rows.size(), 0);
    for (std::uint32_t x = 0; x < f.size(); ++x) ++sts[f.row[x]];
    for (std::uint32_t r = 0; r < f.rows.size(); ++r) {
      const Fabric::RowWorked& w = f.rows[r];
      std::size_t line = line_of(w);
      PageRow row{
          heading_at[line], f.row_label(r), line ? without_markup(lines_[line - 1]) : "", "",
          sts[r],           w.piece};
      if (w.repeat_of) {
        row.said_by = row.text;
        row.text = out_.rows[written_at.at({w.piece, w.repeat_of})].text;
      } else {
        written_at[{w.piece, w.number}] = r;
        worked_as_before(row, w.number, written_at);
      }
      piece_named_[row.heading.substr(0, row.heading.find(" ("))] = w.piece;
      out_.rows.push_back(std::move(row));
    }
  }

  // A piece written "Work as Sleeve 1." shows, row by row, the row of that piece it works
  // again.
  void worked_as_before(
      PageRow& row, std::uint32_t number,
      const std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t>& written_at) const {
    constexpr std::string_view kWorkAs = "Work as ";
    if (!row.text.starts_with(kWorkAs) || !row.text.ends_with(".")) return;
    auto piece =
        piece_named_.find(row.text.substr(kWorkAs.size(), row.text.size() - kWorkAs.size() - 1));
    if (piece == piece_named_.end()) return;
    auto same = written_at.find({piece->second, number});
    if (same == written_at.end()) return;
    row.said_by = row.text;
    row.text = out_.rows[same->second].text;
  }

  // Per worked row, its tokens: the written rows follow the worked ones in order (a cast-on is
  // not a row); a row's stitches are consecutive in the fabric.
  void add_row_spans(const Fabric& f) {
    std::vector<std::uint32_t> first(f.rows.size(), 0);
    for (std::uint32_t x = f.size(); x-- > 0;) first[f.row[x]] = x;
    std::size_t next_written = 0;
    for (std::uint32_t r = 0; r < f.rows.size(); ++r) {
      const Fabric::RowWorked& w = f.rows[r];
      std::uint32_t n = out_.rows[r].stitches;
      bool written = w.number != 0 && !w.join && next_written < written_.rows.size();
      bool consecutive =
          n == 0 || (f.row[first[r] + n - 1] == r && f.position[first[r] + n - 1] == n);
      spans_.push_back(written && consecutive ? row_text(written_, written_.rows[next_written],
                                                         out_.rows[r].text, f, first[r], n)
                                              : RowText{});
      written_row_.push_back(written ? static_cast<std::uint32_t>(next_written) : kNone);
      next_written += written ? 1 : 0;
    }
  }

  // The charts of the pieces that have one, and per worked row its row of its piece's chart.
  void add_charts() {
    std::vector<std::pair<std::uint32_t, std::uint32_t>> chart_at(written_.rows.size(), {kNone, 0});
    for (const hand::PatternSection& s : written_.sections) {
      std::vector<hand::ChartRow> rows = hand::chart_rows(written_, s);
      if (rows.empty()) continue;
      auto chart = static_cast<std::uint32_t>(out_.charts.size());
      PageChart& c = out_.charts.emplace_back();
      for (const hand::ChartRow& row : rows) {
        chart_at[row.row] = {chart, static_cast<std::uint32_t>(c.cells.size())};
        std::string& squares = c.cells.emplace_back();
        for (StitchType t : row.cells) squares += t == StitchType::p ? 'p' : 'k';
        c.number.push_back(written_.rows[row.row].number);
        c.leftward.push_back(written_.rows[row.row].side == hand::Side::rs);
      }
    }
    // A worked row whose stitches are not its chart row's squares (none seen) shows no chart:
    // its current square would be a guess.
    for (std::size_t r = 0; r < out_.rows.size(); ++r) {
      if (written_row_[r] == kNone) continue;
      auto [chart, row] = chart_at[written_row_[r]];
      if (chart != kNone && out_.charts[chart].cells[row].size() == out_.rows[r].stitches)
        std::tie(out_.rows[r].chart, out_.rows[r].chart_row) = std::tie(chart, row);
    }
  }

  // The program's stitches in its order; where the lowering stopped early, the stitches it did
  // not reach follow in the order the proven pattern works them (the page says so).
  void add_order(const Fabric& f, const std::vector<StitchId>& model,
                 const std::vector<std::uint32_t>& fabric_of) {
    const Program& p = c_.program;
    out_.order.reserve(c_.knit.size());
    std::vector<std::uint8_t> stepped(c_.knit.size(), 0);
    for (std::uint32_t step = 0; step < p.steps.size(); ++step)
      for (std::uint32_t i = p.steps[step].stitches.begin; i < p.steps[step].stitches.end; ++i) {
        StitchId s = p.stitches[i].stitch;
        add_stitch(f, s, step, fabric_of[s]);
        stepped[s] = 1;
      }
    if (p.complete()) return;
    out_.note = fmt::format(
        "The lowering stopped at {}: {}. From stitch {} on, this page follows the order the "
        "pattern works the stitches in.",
        c_.knit.describe(p.gap->stitch), p.gap->why, out_.order.size() + 1);
    for (std::uint32_t x = 0; x < f.size(); ++x)
      if (!stepped[model[x]]) add_stitch(f, model[x], kNone, x);
  }

  void add_stitch(const Fabric& f, StitchId s, std::uint32_t step, std::uint32_t x) {
    SKEIN_ASSERT(x != kNone, "the pattern knits every stitch of the program");
    PageStitch st{s, step, f.row[x], f.position[x]};
    const RowText& t = spans_[st.row];
    if (!t.spans.empty()) {
      const OpSpan& span = t.spans[st.position - 1];
      st.begin = span.begin;
      st.end = span.end;
      st.repeat = span.repeat;
      st.repeats = span.repeats;
      st.marker = t.marker[st.position - 1];
    }
    out_.order.push_back(st);
  }

  // Each stitch's cell from the layout the yarn stage uses: the stitch mesh's faces, or a
  // stitch graph's positions.
  void add_geometry() {
    const KnitGraph& g = c_.knit;
    std::optional<StitchLayout> layout;
    if (c_.mesh) {
      std::vector<Point3> at;
      for (Vertex v : c_.mesh->vertices()) {
        Vec3 p = c_.mesh->position[v];
        at.emplace_back(p.x, p.y, p.z);
      }
      layout = layout_from_mesh(*c_.mesh, at, g);
    } else if (c_.input.ends_with(".st") && std::filesystem::exists(c_.input)) {
      layout = layout_from_positions(g, read_stitch_positions(c_.input));
    }
    out_.yarn_piece.assign(g.size(), 0);
    for (std::uint32_t y = 0; y < c_.yarns.size(); ++y)
      for (StitchId s = c_.yarns.first[y]; s != kNoStitch; s = g.yarn_next[s]) {
        out_.yarn_piece[s] = y;
        if (g.yarn_next[s] != kNoStitch) out_.yarn.insert(out_.yarn.end(), {s, g.yarn_next[s]});
      }
    if (!layout) return;
    static constexpr float kCorner[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    out_.cells.resize(g.size());
    for (StitchId s = 0; s < g.size(); ++s)
      for (int k = 0; k < 4; ++k) {
        Point3 p = layout->frame[s].at(kCorner[k][0], kCorner[k][1], 0);
        for (int d = 0; d < 3; ++d) out_.cells[s][3 * k + d] = p[d];
      }
  }

  // FNV-1a over the pattern and the stitch order: progress kept for one model is not restored
  // for another.
  std::string key_of() const {
    std::uint64_t h = 14695981039346656037ull;
    auto add = [&](std::string_view bytes) {
      for (unsigned char b : bytes) h = (h ^ b) * 1099511628211ull;
    };
    add(out_.pattern);
    for (const PageStitch& s : out_.order)
      add(std::string_view(reinterpret_cast<const char*>(&s.stitch), sizeof s.stitch));
    return fmt::format("{:016x}", h);
  }

  const Compilation& c_;
  const hand::HandPattern& written_;
  std::vector<std::string> lines_;
  std::map<std::string, std::uint32_t> piece_named_;  // a heading's name: its piece
  std::vector<RowText> spans_;                        // per page row
  std::vector<std::uint32_t> written_row_;  // per page row: into written_.rows (kNone: none)
  PageData out_;
};

}  // namespace

PageData build_page_data(const Compilation& c, const std::string& pattern,
                         const hand::HandPattern& written) {
  VerifyReport proof = hand::verify_pattern(pattern, kPatternName, &c);
  if (!proof.proven)
    throw UnsupportedError(
        fmt::format("{}: the hand pattern is not proven, so no knitting page is written: {}",
                    c.input, proof.summary));
  return Builder(c, pattern, written).run(proof.summary);
}

}  // namespace skein::hand_web
