#include <fmt/format.h>

#include <algorithm>
#include <cstdlib>

#include "knitout/vbed_bed.hpp"

namespace skein::knitout {
namespace vbed {

// The magic line, the header and the line after it: all that is ever quoted by number.
std::vector<std::string_view> header_lines(std::string_view text) {
  std::vector<std::string_view> lines;
  for (std::size_t pos = 0; pos < text.size();) {
    std::size_t end = std::min(text.find('\n', pos), text.size());
    lines.push_back(text.substr(pos, end - pos));
    if (lines.size() > 1 && !lines.back().starts_with(";;")) break;
    pos = end + 1;
  }
  return lines;
}

VirtualBed::VirtualBed(const std::string& file, const MachineProfile& profile,
                       std::string_view text, ReplayOptions options)
    : file_(file),
      p_(profile),
      options_(options),
      text_(text),
      lines_(header_lines(text)),
      line_count_(count_lines(text)) {
  n_ = static_cast<std::int32_t>(p_.needles);
  for (std::size_t r = 0; r < severity_.size(); ++r)
    severity_[r] = rule_severity(static_cast<Rule>(r), p_, options_.strict);
}

// Sums of at most 255 per block fit a byte, so the compiler can count 16 or 32 bytes an
// instruction (std::count widens every byte to 64 bits: 6% of a replay).
std::size_t VirtualBed::count_lines(std::string_view text) {
  constexpr std::size_t kBlock = 255;
  std::size_t lines = 1;
  for (std::size_t at = 0; at < text.size(); at += kBlock) {
    std::uint8_t newlines = 0;
    for (char c : text.substr(at, kBlock)) newlines += c == '\n';
    lines += newlines;
  }
  return lines;
}

void VirtualBed::fail_header(std::size_t line, const std::string& why) const {
  throw ParseError(file_, line, line && line <= lines_.size() ? std::string(lines_[line - 1]) : "",
                   why);
}

void VirtualBed::check_header() {
  const Header& h = r_.header;
  if (!h.has_carriers)
    fail_header(h.first_op_line - 1,
                fmt::format("missing the ;;Carriers: header ({} needs ';;Carriers: {}')", p_.name,
                            p_.carriers_line()));
  if (h.carriers != p_.carriers)
    breaks_header(h.carriers_line, Rule::carriers_line, [&] {
      return fmt::format("{} needs ';;Carriers: {}'", p_.name, p_.carriers_line());
    });
  auto header_line = [&](std::string_view key) {
    for (std::size_t i = 1; i < h.first_op_line - 1; ++i)
      if (lines_[i].starts_with(fmt::format(";;{}:", key))) return i + 1;
    return std::size_t{1};
  };
  if (options_.check_machine && !h.machine.empty() && !p_.is_machine(h.machine))
    breaks_header(header_line("Machine"), Rule::machine_header, [&] {
      return fmt::format("the file is for machine '{}', profile {} is '{}'", h.machine, p_.name,
                         p_.machine);
    });
  if (options_.check_machine && !h.gauge.empty() &&
      std::strtod(h.gauge.c_str(), nullptr) != p_.gauge)
    breaks_header(header_line("Gauge"), Rule::gauge_header, [&] {
      return fmt::format("the file is for gauge {}, {} is gauge {}", h.gauge, p_.name, p_.gauge);
    });
  if (!h.width.empty() && std::stoul(h.width) > p_.needles)
    breaks_header(header_line("Width"), Rule::width_header, [&] {
      return fmt::format("the file asks for {} needles, {} has {}", h.width, p_.name, p_.needles);
    });
}

}  // namespace vbed

Header read_header(std::string_view text, const std::string& file) {
  return parse_header(vbed::header_lines(text), file);
}

ProfileChoice choose_profile(std::string_view text, const std::string& file,
                             const std::string& machine, bool strict) {
  ProfileChoice c;
  c.options.strict = strict;
  if (!machine.empty()) {
    c.profile = load_machine_profile(machine);
    return c;
  }
  std::string named = read_header(text, file).machine;
  if (auto known = profile_for_machine(named)) {
    c.profile = std::move(*known);
    c.how = fmt::format(" (the file's ;;Machine: {})", named);
    return c;
  }
  c.profile = load_machine_profile("generic");
  c.options.check_machine = false;
  c.how =
      named.empty()
          ? " (note: the file names no ;;Machine:; give --machine to replay it on one)"
          : fmt::format(" (note: no profile knows ;;Machine: {}; give --machine for one)", named);
  return c;
}

std::string shop_summary(const Replay& r, const MachineProfile& p) {
  const ShopStats& s = r.stats;
  auto minutes = static_cast<int>(s.seconds / 60);
  return fmt::format(
      "  machine: {} ({}), needles {}..{} used\n"
      "  carriage passes: {} ({} knitting, {} transfer)\n"
      "  stitches: {} knit, {} tuck, {} split, {} miss\n"
      "  transfers: {}, rack changes: {}, loops dropped: {}, loops left on the needles: {}\n"
      "  yarn pieces: {}{}\n"
      "  estimated knitting time: {}:{:02d} (min:s)",
      p.name, p.description, s.min_needle, s.max_needle, s.stitch_passes + s.transfer_passes,
      s.stitch_passes, s.transfer_passes, s.knits, s.tucks, s.splits, s.misses, s.transfers,
      s.racks, s.loops_dropped, s.loops_left, s.yarn_pieces,
      s.empty_knits ? fmt::format(", knits on empty needles: {}", s.empty_knits) : "", minutes,
      static_cast<int>(s.seconds - minutes * 60));
}

}  // namespace skein::knitout
