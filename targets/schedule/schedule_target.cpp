#include "schedule/schedule_target.hpp"

#include <fmt/format.h>

#include <boost/range/iterator_range.hpp>
#include <charconv>
#include <ostream>
#include <string_view>

#include "common/error.hpp"
#include "driver/pipeline.hpp"

namespace skein {
namespace {

constexpr std::string_view kMagic = ";!skein-schedule 1";

std::string event_line(const KnitGraph& g, const Event& e) {
  switch (e.kind) {
    case EventKind::yarn_start:
      return fmt::format("yarn {} start", e.yarn + 1);
    case EventKind::yarn_end:
      return fmt::format("yarn {} end", e.yarn + 1);
    case EventKind::row_start:
      return fmt::format("  row {} ({})", g.row[e.stitch] + 1,
                         row_shape_name(g.row_shape[g.row[e.stitch]]));
    case EventKind::turn:
      return "  turn";
    case EventKind::marker:
      return fmt::format("  marker {}", marker_name(e.marker));
    case EventKind::hold:
      return fmt::format("yarn {} hold at {}: waits for {}", e.yarn + 1, e.stitch + 1,
                         e.waits_for + 1);
    case EventKind::resume:
      return fmt::format("yarn {} resume at {}", e.yarn + 1, e.stitch + 1);
    case EventKind::stitch:
      return fmt::format("    {} {}", e.stitch + 1, abbreviation(g.type[e.stitch]));
  }
  return {};
}

class ScheduleTarget : public Target {
 public:
  std::string name() const override { return "schedule"; }
  std::string description() const override {
    return "Algorithm 1's knitting order as text: one stitch a line, with yarn, row, turn, "
           "marker and hold events";
  }
  std::string default_extension() const override { return ".schedule"; }
  void emit(const Compilation& c, const TargetOptions&, std::ostream& out) const override {
    const KnitGraph& g = c.knit;
    out << kMagic << '\n'
        << fmt::format("; source: {} (stitch numbers are {} numbers{})\n", c.input, g.element,
                       g.first_extruded < g.size() ? "; extruded stitches follow the last" : "")
        << fmt::format("; {} stitches, {} yarn pieces, {} holds\n", g.size(), c.yarns.size(),
                       c.schedule.holds);
    std::string buffer;
    for (const Event& e : c.schedule.events) {
      buffer += event_line(g, e);
      buffer += '\n';
      if (buffer.size() > (1u << 16)) {
        out << buffer;
        buffer.clear();
      }
    }
    out << buffer;
  }
};

// Replays a schedule text: each stitch line works one stitch of the current yarn.
class ScheduleReplay {
 public:
  ScheduleReplay(const std::string& file, const Compilation* against) : file_(file), c_(against) {
    if (c_) {
      done_.assign(c_->knit.size(), 0);
      last_.assign(c_->yarns.size(), kNoStitch);
    }
  }

  VerifyReport run(std::string_view text) try {
    std::size_t line_no = 0;
    for (std::size_t pos = 0; pos < text.size();) {
      std::size_t end = text.find('\n', pos);
      if (end == std::string_view::npos) end = text.size();
      std::string_view line = text.substr(pos, end - pos);
      pos = end + 1;
      ++line_no;
      if (line_no == 1 && line != kMagic) fail(line_no, line, fmt::format("expected '{}'", kMagic));
      replay_line(line_no, line);
    }
    return finish();
  } catch (const Mismatch& m) {
    return {false, m.what};
  }

 private:
  // A well-formed schedule that is not the model's: not proven, as opposed to a malformed one.
  struct Mismatch {
    std::string what;
  };

  [[noreturn]] void fail(std::size_t line_no, std::string_view line, const std::string& why) {
    throw ParseError(file_, line_no, std::string(line), why);
  }
  [[noreturn]] void differs(std::size_t line_no, std::string_view line, const std::string& why) {
    throw Mismatch{fmt::format("{}:{}: {}\n  {:>5} | {}", file_, line_no, why, line_no, line)};
  }

  static std::string_view trim(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\r')) s.remove_suffix(1);
    return s;
  }

  void replay_line(std::size_t line_no, std::string_view raw) {
    std::string_view line = trim(raw);
    if (line.empty() || line.front() == ';') return;
    if (line.starts_with("yarn ")) return replay_yarn(line_no, raw, line.substr(5));
    if (line.starts_with("row ") || line == "turn" || line.starts_with("marker ")) return;
    std::uint32_t number = 0;
    auto [end, ec] = std::from_chars(line.data(), line.data() + line.size(), number);
    if (ec != std::errc() || number == 0 || end == line.data() + line.size() || *end != ' ')
      fail(line_no, raw,
           "expected a stitch line '<number> <stitch>', a 'yarn', 'row', 'turn' or "
           "'marker' line");
    replay_stitch(line_no, raw, number - 1, trim(std::string_view(end, line.data() + line.size())));
  }

  void replay_yarn(std::size_t line_no, std::string_view raw, std::string_view rest) {
    std::uint32_t number = 0;
    auto [end, ec] = std::from_chars(rest.data(), rest.data() + rest.size(), number);
    if (ec != std::errc() || number == 0) fail(line_no, raw, "expected a yarn number after 'yarn'");
    std::string_view what = trim(std::string_view(end, rest.data() + rest.size()));
    yarn_ = number - 1;
    active_ = !what.starts_with("end") && !what.starts_with("hold");
    if (!c_) return;
    if (yarn_ >= c_->yarns.size())
      differs(line_no, raw, fmt::format("the model has {} yarn pieces", c_->yarns.size()));
  }

  void replay_stitch(std::size_t line_no, std::string_view raw, StitchId s, std::string_view abbr) {
    ++stitches_;
    if (!active_) fail(line_no, raw, "a stitch is worked while no yarn is started or resumed");
    if (!c_) return;
    const KnitGraph& g = c_->knit;
    if (s >= g.size()) differs(line_no, raw, fmt::format("the model has {} stitches", g.size()));
    if (abbr != abbreviation(g.type[s]))
      differs(line_no, raw,
              fmt::format("{} is a {}, not a {}", g.describe(s), abbreviation(g.type[s]), abbr));
    if (done_[s]) differs(line_no, raw, fmt::format("{} is worked a second time", g.describe(s)));
    for (auto e : boost::make_iterator_range(in_edges(s, c_->deps))) {
      StitchId before = static_cast<StitchId>(source(e, c_->deps));
      if (!done_[before])
        differs(line_no, raw,
                fmt::format("{} is worked before {}, which it waits for: {}", g.describe(s),
                            g.describe(before), explain(c_->deps[e].reason)));
    }
    if (c_->yarns.piece_of[s] != yarn_)
      differs(line_no, raw,
              fmt::format("{} belongs to yarn {}, not yarn {}", g.describe(s),
                          c_->yarns.piece_of[s] + 1, yarn_ + 1));
    StitchId previous = last_[yarn_];
    bool follows = previous == kNoStitch ? c_->yarns.first[yarn_] == s : g.yarn_next[previous] == s;
    if (!follows)
      differs(line_no, raw,
              fmt::format("{} does not come next along yarn {}", g.describe(s), yarn_ + 1));
    done_[s] = 1;
    last_[yarn_] = s;
  }

  VerifyReport finish() const {
    VerifyReport report;
    if (!c_) {
      report.summary = fmt::format("{}: {} stitch lines read; give --against INPUT to prove them",
                                   file_, stitches_);
      report.valid = true;
      return report;
    }
    for (StitchId s = 0; s < c_->knit.size(); ++s)
      if (!done_[s]) {
        report.summary = fmt::format("{}: {} is never worked", file_, c_->knit.describe(s));
        return report;
      }
    report.proven = true;
    report.summary = fmt::format(
        "{}: proven against {}: all {} stitches worked once, each along its yarn and after "
        "everything it depends on",
        file_, c_->input, c_->knit.size());
    return report;
  }

  std::string file_;
  const Compilation* c_;
  std::vector<std::uint8_t> done_;
  std::vector<StitchId> last_;  // per yarn piece: the last stitch worked
  std::uint32_t yarn_ = 0;
  bool active_ = false;
  std::uint64_t stitches_ = 0;
};

class ScheduleSimulator : public Simulator {
 public:
  std::string name() const override { return "schedule-replay"; }
  std::string target() const override { return "schedule"; }
  std::string description() const override {
    return "replays a schedule and proves every stitch is worked once, in a valid order";
  }
  VerifyReport verify(const std::string& text, const std::string& file, const Compilation* against,
                      const TargetOptions&) const override {
    if (against && !against->knittability.knittable)
      throw Error(
          fmt::format("{} is not knittable, so no schedule of it can be proven", against->input));
    return ScheduleReplay(file, against).run(text);
  }
};

}  // namespace

void register_schedule_target(Registry& registry) {
  registry.add(std::make_unique<ScheduleTarget>());
  registry.add(std::make_unique<ScheduleSimulator>());
}

}  // namespace skein
