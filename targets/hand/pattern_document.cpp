#include "hand/pattern_document.hpp"

#include <fmt/format.h>

#include <cctype>
#include <cmath>
#include <filesystem>

#include "hand/pattern_wording.hpp"

namespace skein::hand {
namespace {

std::string title_of(const std::string& source) {
  std::string title = std::filesystem::path(source).stem().string();
  bool start = true;
  for (char& ch : title) {
    if (ch == '-' || ch == '_') ch = ' ';
    if (start) ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
    start = ch == ' ';
  }
  return title.empty() ? "Pattern" : title;
}

}  // namespace

double Gauge::yarn_cm_per_stitch() const {
  double per_cm2 = sts_per_10cm / 10 * rows_per_10cm / 10;
  return std::sqrt(19.0 / per_cm2) * 1.1;
}

PatternDocument make_document(const HandPattern& pattern, Dialect dialect, const Gauge& gauge) {
  PatternDocument doc;
  doc.title = title_of(pattern.source);
  std::uint64_t stitches = 0;
  for (const PatternSection& s : pattern.sections) stitches += s.stitches;
  doc.subtitle = fmt::format(
      "A hand-knitting pattern written by skein from {} ({} stitches). Prove it with `skein "
      "verify` against the same model.",
      pattern.source, document::with_commas(stitches));
  doc.instructions = document::instructions(pattern, dialect);
  doc.front = document::front_matter(pattern, gauge, doc.instructions);
  doc.finishing = {"Weave in the ends. Block lightly to the measurements."};
  return doc;
}

}  // namespace skein::hand
