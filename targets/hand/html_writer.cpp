// A self-contained HTML page that prints well: the document, an SVG schematic of the model at
// the start of each piece with that piece highlighted, and a chart for pieces whose stitches
// form a pattern of knits and purls. Every instruction stays on one line of the file, so the
// hand simulator reads the page line for line as it reads the markdown.
#include <fmt/format.h>

#include <algorithm>
#include <ostream>

#include "hand/pattern_writers.hpp"

namespace skein::hand {
namespace {

constexpr double kSchematicPx = 280;  // the longer side of a schematic
constexpr std::uint32_t kChartWidest = 60;
constexpr std::uint32_t kChartRows = 80;
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

// Each piece drawn row by row, as wide as its stitches at the gauge; the piece being worked in
// colour, the others grey, rows that change the count darker.
class Schematic {
 public:
  Schematic(const HandPattern& p, const Gauge& gauge) : p_(p) {
    for (const PatternSection& s : p.sections) {
      std::uint32_t widest = s.cast_on;
      for (std::uint32_t r = s.first_row; r < s.end_row; ++r)
        widest = std::max(widest, p.rows[r].sts_before);
      width_cm_ += widest * 10.0 / gauge.sts_per_10cm + (width_cm_ > 0 ? gap_cm_ : 0);
      widest_.push_back(widest);
      height_cm_ = std::max(height_cm_, (s.end_row - s.first_row) * 10.0 / gauge.rows_per_10cm);
    }
    px_per_cm_ = kSchematicPx / std::max({width_cm_, height_cm_, 1.0});
    stitch_px_ = px_per_cm_ * 10.0 / gauge.sts_per_10cm;
    row_px_ = px_per_cm_ * 10.0 / gauge.rows_per_10cm;
  }

  std::string svg(std::uint32_t highlighted) const {
    double w = width_cm_ * px_per_cm_ + 20, h = height_cm_ * px_per_cm_ + 40;
    std::string out = fmt::format(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{:.0f}\" height=\"{:.0f}\" "
        "viewBox=\"0 0 {:.0f} {:.0f}\" role=\"img\">\n",
        w, h, w, h);
    double x = 10;
    for (std::uint32_t s = 0; s < p_.sections.size(); ++s) {
      out += piece(s, x, h - 25, s == highlighted);
      x += widest_[s] * stitch_px_ + gap_cm_ * px_per_cm_;
    }
    return out + "</svg>\n";
  }

 private:
  std::string piece(std::uint32_t s, double left, double bottom, bool lit) const {
    const PatternSection& sec = p_.sections[s];
    double centre = left + widest_[s] * stitch_px_ / 2;
    std::string out;
    for (std::uint32_t r = sec.first_row; r < sec.end_row; ++r) {
      const PatternRow& row = p_.rows[r];
      double y = bottom - (r - sec.first_row + 1) * row_px_;
      double w = row.sts_before * stitch_px_;
      bool shaping = row.sts_before != row.sts_after && !row.bind_off;
      const char* fill = lit ? (shaping ? "#2f6f73" : "#7fb8b2") : (shaping ? "#999" : "#ccc");
      out += fmt::format(
          "<rect x=\"{:.2f}\" y=\"{:.2f}\" width=\"{:.2f}\" height=\"{:.2f}\" "
          "fill=\"{}\"/>\n",
          centre - w / 2, y, w, row_px_ + 0.3, fill);
    }
    out += fmt::format(
        "<text x=\"{:.1f}\" y=\"{:.1f}\" font-size=\"11\" text-anchor=\"middle\">"
        "{} {} sts</text>\n",
        centre, bottom + 14, sec.in_round ? "CO (around)" : "CO", sec.cast_on);
    return out;
  }

  const HandPattern& p_;
  std::vector<std::uint32_t> widest_;
  double gap_cm_ = 4, width_cm_ = 0, height_cm_ = 0;
  double px_per_cm_ = 1, stitch_px_ = 1, row_px_ = 1;
};

// The RS view of a row's stitches, left to right, when every one is a knit or a purl.
std::optional<std::vector<StitchType>> plain_faces(const HandPattern& p, const PatternRow& row) {
  std::vector<StitchType> faces;
  for (HandOp op : p.ops_of(row)) {
    if (!is_plain(op)) return std::nullopt;
    faces.push_back(*rs_face(op, row.side));
  }
  if (row.side == Side::rs) std::reverse(faces.begin(), faces.end());  // worked right to left
  return faces;
}

// A chart of knits and purls for a piece without shaping: clearer than words for ribs and
// textures. Read RS rows (and every round) from right to left, WS rows from left to right.
std::string chart(const HandPattern& p, const PatternSection& s) {
  std::vector<std::vector<StitchType>> rows;
  bool purls = false, knits = false;
  for (std::uint32_t r = s.first_row; r < s.end_row; ++r) {
    if (p.rows[r].bind_off) continue;
    auto faces = plain_faces(p, p.rows[r]);
    if (!faces || faces->size() != s.cast_on) return "";
    for (StitchType t : *faces) (t == StitchType::p ? purls : knits) = true;
    rows.push_back(std::move(*faces));
  }
  if (!purls || !knits || s.cast_on > kChartWidest || rows.size() > kChartRows) return "";
  int w = static_cast<int>(s.cast_on) * kCellPx + 60,
      h = static_cast<int>(rows.size()) * kCellPx + 30;
  std::string out = fmt::format(
      "<figure><svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{}\" height=\"{}\" viewBox=\"0 0 "
      "{} {}\" role=\"img\">\n",
      w, h, w, h);
  for (std::size_t r = 0; r < rows.size(); ++r) {
    int y = h - 20 - static_cast<int>(r + 1) * kCellPx;
    const PatternRow& row = p.rows[s.first_row + r];
    for (std::size_t c = 0; c < rows[r].size(); ++c) {
      int x = 30 + static_cast<int>(c) * kCellPx;
      out += fmt::format(
          "<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"#fff\" "
          "stroke=\"#888\" stroke-width=\"0.6\"/>",
          x, y, kCellPx, kCellPx);
      if (rows[r][c] == StitchType::p)
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

}  // namespace

void write_html(const PatternDocument& doc, const HandPattern& pattern, const Gauge& gauge,
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
  Schematic schematic(pattern, gauge);
  for (const InstructionLine& line : doc.instructions) {
    instruction(line, out);
    if (line.kind != InstructionLine::Kind::setup) continue;
    const PatternSection& s = pattern.sections[line.section];
    out << "<figure>\n"
        << schematic.svg(line.section)
        << fmt::format(
               "<figcaption>Schematic{}: rows bottom to top, as wide as their stitches "
               "at the gauge{}; darker rows change the stitch count.</figcaption>\n",
               pattern.sections.size() > 1 ? fmt::format(" (piece {} highlighted)", s.piece) : "",
               s.in_round ? " (rounds drawn flat: the width is the circumference)" : "")
        << "</figure>\n"
        << chart(pattern, s);
  }
  out << "<h2>" << kFinishingHeading << "</h2>\n";
  for (const std::string& item : doc.finishing) out << "<p>" << inline_html(item) << "</p>\n";
  out << "</body>\n</html>\n";
}

}  // namespace skein::hand
