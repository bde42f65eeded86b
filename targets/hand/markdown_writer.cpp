#include <ostream>

#include "hand/pattern_writers.hpp"

namespace skein::hand {
namespace {

// One instruction per paragraph, so that each is one line of the file (the reader's unit).
std::string instruction_line(const InstructionLine& line, bool markdown) {
  switch (line.kind) {
    case InstructionLine::Kind::heading:
      return (markdown ? "### " : "") + line.text;
    case InstructionLine::Kind::row:
      return markdown ? "**" + line.label + ":** " + line.text : line.label + ": " + line.text;
    default:
      return line.text;
  }
}

}  // namespace

void write_markdown(const PatternDocument& doc, std::ostream& out) {
  out << "# " << doc.title << "\n\n" << doc.subtitle << "\n";
  for (const FrontSection& section : doc.front) {
    if (section.items.empty()) continue;
    out << "\n## " << section.heading << "\n\n";
    if (section.items.size() == 1) {
      out << section.items[0] << "\n";
      continue;
    }
    for (const std::string& item : section.items) out << "- " << item << "\n";
  }
  out << "\n## " << kInstructionsHeading << "\n";
  for (const InstructionLine& line : doc.instructions)
    out << "\n" << instruction_line(line, true) << "\n";
  out << "\n## " << kFinishingHeading << "\n\n";
  for (const std::string& item : doc.finishing) out << item << "\n";
}

void write_knitspeak(const PatternDocument& doc, std::ostream& out) {
  for (const InstructionLine& line : doc.instructions) out << instruction_line(line, false) << "\n";
}

}  // namespace skein::hand
