// A self-contained HTML page that prints well: the document, an SVG schematic of the model at
// the start of each piece with that piece in colour, and a chart for pieces whose stitches
// form a pattern of knits and purls. Every instruction stays on one line of the file, so the
// hand simulator reads the page line for line as it reads the markdown.
#include <fmt/format.h>

#include <algorithm>
#include <ostream>

#include "driver/pipeline.hpp"
#include "hand/chart.hpp"
#include "hand/pattern_writers.hpp"

namespace skein::hand {
namespace {

constexpr double kSchematicPx = 280;            // the longer side of a schematic
constexpr std::uint32_t kSchematicCells = 140;  // ... in cells of the model's picture
constexpr int kCellPx = 12;

constexpr const char* kStyle = R"(<style>
body{font:11pt/1.45 Georgia,"Times New Roman",serif;color:#222;max-width:46em;margin:2em auto;padding:0 1em}
h1{font-size:1.9em;margin:0 0 .2em}
h2{font-size:1.15em;border-bottom:1px solid #bbb;margin-top:1.6em;padding-bottom:.1em}
h3{font-size:1em;margin-top:1.2em}
.subtitle{color:#555;font-style:italic}
p.row,p.setup,p.repeat,p.finish{margin:.35em 0}
.label{font-weight:bold}
figure{margin:1em 0;text-align:center}
figcaption{font-size:.85em;color:#555}
svg text{font-family:Helvetica,Arial,sans-serif}
code{font-size:.95em}
@media print{body{margin:0;max-width:none;font-size:10pt}h2,h3{break-after:avoid}
p.row,figure,li{break-inside:avoid}}
</style>)";

std::string escaped(std::string_view text) {
  std::string out;
  for (char ch : text) {
    switch (ch) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      default:
        out += ch;
    }
  }
  return out;
}

// The document's only inline markup: **bold** and `code`.
std::string inline_html(std::string_view text) {
  std::string out, plain = escaped(text);
  bool bold = false, code = false;
  for (std::size_t i = 0; i < plain.size(); ++i) {
    if (plain.compare(i, 2, "**") == 0) {
      out += (bold = !bold) ? "<b>" : "</b>";
      ++i;
    } else if (plain[i] == '`') {
      out += (code = !code) ? "<code>" : "</code>";
    } else {
      out += plain[i];
    }
  }
  return out;
}

// The model as a grid of cells (cell_picture.hpp), drawn once in grey and used by every figure;
// each figure draws the cells of the piece being worked over it in colour, in three shades by
// how squarely the stitches face the viewer.
class Schematic {
 public:
  explicit Schematic(const CellPicture& picture)
      : pic_(picture), cell_px_(kSchematicPx / std::max({picture.columns, picture.rows, 1u})) {}

  template <class Shown>
  std::string svg(Shown shown, bool first) const {
    double w = pic_.columns * cell_px_, h = pic_.rows * cell_px_;
    std::string out = fmt::format(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{:.0f}\" height=\"{:.0f}\" "
        "viewBox=\"0 0 {:.0f} {:.0f}\" role=\"img\">\n",
        w, h, w, h);
    if (first)
      out += "<defs><g id=\"skein-model\">\n" + cells([](std::uint32_t) { return true; }, kGrey) +
             "</g></defs>\n";
    out += "<use href=\"#skein-model\"/>\n";
    out += cells(shown, kLit);
    return out + "</svg>\n";
  }

 private:
  static constexpr const char* kGrey[3] = {"#dedede", "#c8c8c8", "#ababab"};
  static constexpr const char* kLit[3] = {"#7fb8b2", "#4f9690", "#2f6f73"};

  // One rectangle per run of cells of one shade in a row of the grid.
  template <class Chosen>
  std::string cells(Chosen chosen, const char* const (&colours)[3]) const {
    std::string out;
    for (std::uint32_t r = 0; r < pic_.rows; ++r) {
      for (std::uint32_t c = 0; c < pic_.columns;) {
        std::size_t i = std::size_t{r} * pic_.columns + c;
        if (pic_.label[i] == CellPicture::kEmpty || !chosen(pic_.label[i])) {
          ++c;
          continue;
        }
        std::uint32_t end = c + 1;
        while (end < pic_.columns && pic_.label[i + end - c] != CellPicture::kEmpty &&
               chosen(pic_.label[i + end - c]) && pic_.shade[i + end - c] == pic_.shade[i])
          ++end;
        out += fmt::format(
            "<rect x=\"{:.1f}\" y=\"{:.1f}\" width=\"{:.1f}\" height=\"{:.1f}\" fill=\"{}\"/>\n",
            c * cell_px_, r * cell_px_, (end - c) * cell_px_ + 0.2, cell_px_ + 0.2,
            colours[pic_.shade[i]]);
        c = end;
      }
    }
    return out;
  }

  const CellPicture& pic_;
  double cell_px_;
};

// A chart of knits and purls for a piece without shaping: clearer than words for ribs and
// textures. Read RS rows (and every round) from right to left, WS rows from left to right.
std::string chart(const HandPattern& p, const PatternSection& s) {
  std::vector<ChartRow> rows = chart_rows(p, s);
  if (rows.empty()) return "";
  int w = static_cast<int>(s.cast_on) * kCellPx + 60,
      h = static_cast<int>(rows.size()) * kCellPx + 30;
  std::string out = fmt::format(
      "<figure><svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{}\" height=\"{}\" viewBox=\"0 0 "
      "{} {}\" role=\"img\">\n",
      w, h, w, h);
  for (std::size_t r = 0; r < rows.size(); ++r) {
    int y = h - 20 - static_cast<int>(r + 1) * kCellPx;
    const PatternRow& row = p.rows[rows[r].row];
    for (std::size_t c = 0; c < rows[r].cells.size(); ++c) {
      int x = 30 + static_cast<int>(c) * kCellPx;
      out += fmt::format(
          "<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"#fff\" "
          "stroke=\"#888\" stroke-width=\"0.6\"/>",
          x, y, kCellPx, kCellPx);
      if (rows[r].cells[c] == StitchType::p)
        out += fmt::format("<circle cx=\"{}\" cy=\"{}\" r=\"2\" fill=\"#222\"/>", x + kCellPx / 2,
                           y + kCellPx / 2);
    }
    bool right = row.round || row.side == Side::rs;
    out += fmt::format("<text x=\"{}\" y=\"{}\" font-size=\"9\" text-anchor=\"{}\">{}</text>\n",
                       right ? w - 27 : 27, y + kCellPx - 2, right ? "start" : "end", row.number);
  }
  return out + fmt::format(
                   "</svg><figcaption>Chart, as seen from the RS: a blank square is k on RS rows "
                   "and p on WS rows; a dot is p on RS rows and k on WS rows. Read RS rows{} from "
                   "right to left{}.</figcaption></figure>\n",
                   s.in_round ? " and rounds" : "",
                   s.in_round ? "" : ", WS rows from left to right");
}

void instruction(const InstructionLine& line, std::ostream& out) {
  switch (line.kind) {
    case InstructionLine::Kind::heading:
      out << "<h3>" << escaped(line.text) << "</h3>\n";
      return;
    case InstructionLine::Kind::row:
      out << "<p class=\"row\"><span class=\"label\">" << escaped(line.label) << ":</span> "
          << escaped(line.text) << "</p>\n";
      return;
    case InstructionLine::Kind::setup:
      out << "<p class=\"setup\">" << escaped(line.text) << "</p>\n";
      return;
    case InstructionLine::Kind::repeat:
      out << "<p class=\"repeat\">" << escaped(line.text) << "</p>\n";
      return;
    case InstructionLine::Kind::finish:
      out << "<p class=\"finish\">" << escaped(line.text) << "</p>\n";
      return;
  }
}

// Which part of its piece a stitch is in: before the piece is first set aside, or after (the
// section that takes it up again).
std::vector<std::uint8_t> after_first_hold(const Compilation& c) {
  std::vector<std::uint8_t> after(c.knit.size(), 0), held(c.yarns.size(), 0);
  for (const Event& e : c.schedule.events) {
    if (e.kind == EventKind::hold) held[e.yarn] = 1;
    if (e.kind == EventKind::stitch) after[e.stitch] = held[e.yarn];
  }
  return after;
}

// The cells of the section worked: its piece's, and of that piece only the part before or
// after it was set aside when it was.
auto cells_of_section(const HandPattern& p, const PatternSection& s) {
  bool taken_up = std::any_of(p.sections.begin(), p.sections.end(), [&](const PatternSection& o) {
    return o.yarn == s.yarn && o.resumed;
  });
  return [yarn = s.yarn, resumed = s.resumed, taken_up](std::uint32_t label) {
    return label / 2 == yarn && (!taken_up || (label % 2 == 1) == resumed);
  };
}

}  // namespace

std::optional<CellPicture> picture_of_pieces(const Compilation& c) {
  if (!c.mesh) return std::nullopt;
  const KnitGraph& g = c.knit;
  std::vector<std::uint8_t> after = after_first_hold(c);
  auto label = [&](StitchId s) { return 2 * c.yarns.piece_of[s] + after[s]; };
  std::vector<std::uint32_t> face_label(c.mesh->num_faces(), CellPicture::kEmpty);
  std::vector<LabelledPoint> on_edges;
  for (StitchId s = 0; s < g.size(); ++s) {
    if (s < g.first_extruded) {
      face_label[g.source[s]] = label(s);
      continue;
    }
    const MismatchEdge& e = g.mismatch_edges[g.extruded_at[s - g.first_extruded]];
    Vec3 a = c.mesh->position[Vertex(e.vertex[0])], b = c.mesh->position[Vertex(e.vertex[1])];
    on_edges.push_back({{(a.x + b.x) / 2, (a.y + b.y) / 2, (a.z + b.z) / 2}, label(s)});
  }
  return picture_cells(*c.mesh, face_label, on_edges, kSchematicCells);
}

void write_html(const PatternDocument& doc, const HandPattern& pattern, const CellPicture* picture,
                std::ostream& out) {
  out << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>"
      << escaped(doc.title) << "</title>\n"
      << kStyle << "\n</head>\n<body>\n<h1>" << escaped(doc.title)
      << "</h1>\n<p class=\"subtitle\">" << inline_html(doc.subtitle) << "</p>\n";
  for (const FrontSection& section : doc.front) {
    if (section.items.empty()) continue;
    out << "<h2>" << escaped(section.heading) << "</h2>\n<ul>\n";
    for (const std::string& item : section.items) out << "<li>" << inline_html(item) << "</li>\n";
    out << "</ul>\n";
  }
  out << "<h2>" << kInstructionsHeading << "</h2>\n";
  bool first_figure = true;
  for (const InstructionLine& line : doc.instructions) {
    instruction(line, out);
    if (line.kind != InstructionLine::Kind::setup) continue;
    const PatternSection& s = pattern.sections[line.section];
    if (picture) {
      out << "<figure>\n"
          << Schematic(*picture).svg(cells_of_section(pattern, s), first_figure)
          << fmt::format(
                 "<figcaption>Schematic: the model seen from the front and a little above{}."
                 "</figcaption>\n",
                 pattern.sections.size() > 1
                     ? fmt::format(", piece {} (this section) in colour", s.piece)
                     : "")
          << "</figure>\n";
      first_figure = false;
    }
    out << chart(pattern, s);
  }
  out << "<h2>" << kFinishingHeading << "</h2>\n";
  for (const std::string& item : doc.finishing) out << "<p>" << inline_html(item) << "</p>\n";
  out << "</body>\n</html>\n";
}

}  // namespace skein::hand
