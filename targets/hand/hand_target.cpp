#include "hand/hand_target.hpp"

#include <fmt/format.h>

#include <ostream>

#include "common/error.hpp"
#include "driver/pipeline.hpp"
#include "hand/fabric_compare.hpp"
#include "hand/needle_sim.hpp"
#include "hand/pattern_reader.hpp"
#include "hand/pattern_writers.hpp"
#include "hand/program_pattern.hpp"

namespace skein {
namespace hand {
namespace {

enum class Format : std::uint8_t { markdown, html, knitspeak };

struct FormatInfo {
  Format format;
  const char* target;
  const char* extension;
  const char* description;
};

constexpr FormatInfo kFormats[] = {
    {Format::markdown, "hand", ".md",
     "a printable hand-knitting pattern (markdown): materials, gauge, abbreviations, rows and "
     "rounds with repeats and stitch counts"},
    {Format::html, "hand-html", ".html",
     "the hand-knitting pattern as a self-contained printable page with a schematic and charts"},
    {Format::knitspeak, "hand-knitspeak", ".knitspeak",
     "the hand-knitting pattern's rows in Stitch-Maps' KnitSpeak"},
};

// `--set short-rows=...`, else the project file's, else German.
TurnMethod turn_method_of(const TargetOptions& options) {
  auto set = options.settings.find("short-rows");
  bool wrapped = set != options.settings.end() && set->second == "wrap-and-turn";
  return wrapped ? TurnMethod::wrap_and_turn : TurnMethod::german;
}

// The project's gauge, yarn and needle; a stitch mesh or stitch graph does not say them.
Gauge gauge_of(const Compilation& c) {
  if (!c.gauge) return {};
  return {c.gauge->stitches_per_10cm, c.gauge->rows_per_10cm,
          std::string(yarn_weight_name(c.gauge->weight)), c.gauge->needle_mm, false};
}

Rounds rounds_of(const TargetOptions& options) {
  auto set = options.settings.find("rounds");
  bool inside_out = set != options.settings.end() && set->second == "inside-out";
  return inside_out ? Rounds::ws_facing : Rounds::mirror_most;
}

}  // namespace

HandPattern build_pattern(const Compilation& c, const TargetOptions& options) {
  return build_hand_pattern(c, turn_method_of(options), rounds_of(options));
}

namespace {

class HandTarget : public Target {
 public:
  explicit HandTarget(const FormatInfo& f) : f_(f) {}
  std::string name() const override { return f_.target; }
  std::string description() const override { return f_.description; }
  std::string default_extension() const override { return f_.extension; }
  std::vector<std::string> dialects() const override { return {"standard", "knitspeak"}; }
  std::vector<TargetSetting> settings() const override {
    return {{"short-rows",
             {"german", "wrap-and-turn"},
             "how short rows turn (default: the project's short_rows: hand:)"},
            {"rounds",
             {"mirror", "inside-out"},
             "rnds run left to right: mirror the model if most do, or work them WS facing"}};
  }
  void emit(const Compilation& c, const TargetOptions& options, std::ostream& out) const override {
    HandPattern pattern = build_pattern(c, options);
    PatternDocument doc = make_document(pattern, dialect_of(options), gauge_of(c));
    // `--target hand --dialect knitspeak` writes what hand-knitspeak writes; the page stays a
    // page, with its rows in KnitSpeak.
    bool rows_only = f_.format == Format::markdown && options.dialect == "knitspeak";
    Format format = rows_only ? Format::knitspeak : f_.format;
    switch (format) {
      case Format::markdown:
        write_markdown(doc, out);
        break;
      case Format::html: {
        std::optional<CellPicture> picture = picture_of_pieces(c);
        write_html(doc, pattern, picture ? &*picture : nullptr, out);
        break;
      }
      case Format::knitspeak:
        write_knitspeak(doc, out);
        break;
    }
  }

 private:
  // --dialect knitspeak writes KnitSpeak rows whatever the target's own format.
  Dialect dialect_of(const TargetOptions& options) const {
    if (options.dialect.empty())
      return f_.format == Format::knitspeak ? Dialect::knitspeak : Dialect::standard;
    return options.dialect == "knitspeak" ? Dialect::knitspeak : Dialect::standard;
  }

  const FormatInfo& f_;
};

class HandSimulator : public Simulator {
 public:
  explicit HandSimulator(const FormatInfo& f) : f_(f) {}
  std::string name() const override { return std::string(f_.target) + "-knitter"; }
  std::string target() const override { return f_.target; }
  std::string description() const override {
    return "works the pattern as a knitter would (needles, markers, yarn) and proves it knits "
           "the input stitch for stitch";
  }
  VerifyReport verify(const std::string& text, const std::string& file, const Compilation* against,
                      const TargetOptions&) const override {
    if (f_.format == Format::html) return verify_pattern(html_to_text(text), file, against);
    return verify_pattern(text, file, against);
  }

 private:
  const FormatInfo& f_;
};

std::string counted(std::uint32_t n, const char* one, const char* many) {
  return fmt::format("{} {}", n, n == 1 ? one : many);
}

// "38 rnds worked, 8 printed stitch counts checked".
std::string work_done(const Replay& r) {
  std::string rows;
  if (r.rows) rows = counted(r.rows, "row", "rows");
  if (r.rounds) rows += (rows.empty() ? "" : " and ") + counted(r.rounds, "rnd", "rnds");
  if (rows.empty()) rows = "no rows";
  return fmt::format("{} worked by the hand simulator, {} checked", rows,
                     counted(r.counts_checked, "printed stitch count", "printed stitch counts"));
}

VerifyReport proven(const Replay& r, const std::string& file, const Compilation& c, bool mirror) {
  return {true, fmt::format(
                    "{}: proven against {}: {}; the knitted fabric matches the model "
                    "stitch for stitch ({} stitches: their types, loops and yarn order){}",
                    file, c.input, work_done(r), r.fabric.size(),
                    mirror ? ", as its mirror image (the model's rounds run left to right)" : "")};
}

}  // namespace

VerifyReport verify_pattern(std::string_view text, const std::string& file,
                            const Compilation* against) {
  if (against && !against->knittability.knittable)
    throw Error(
        fmt::format("{} is not knittable, so no pattern of it can be proven", against->input));
  Replay r = replay(read_pattern(text, file), file);
  if (!r.ok) return {false, r.failure};
  if (!against)
    return {false,
            fmt::format("{}: {}, {} stitches knitted; give --against INPUT to compare "
                        "them with the model",
                        file, work_done(r), r.fabric.size()),
            true};
  std::optional<Difference> straight = first_difference(r.fabric, *against, false);
  if (!straight) return proven(r, file, *against, false);
  // Only rounds are written mirrored (when the model's run left to right): a flat pattern that
  // knits the mirror image knits another piece.
  if (r.rounds == 0)
    return {false, fmt::format("{}: not the model's fabric: {}", file, straight->what)};
  std::optional<Difference> mirror = first_difference(r.fabric, *against, true);
  if (!mirror) return proven(r, file, *against, true);
  // Report the comparison that got further (the pattern is most likely meant that way); at
  // the same stitch, a wrong stitch type says more than loops in another order.
  bool mirror_first = mirror->stitch != straight->stitch ? mirror->stitch > straight->stitch
                                                         : mirror->type && !straight->type;
  const Difference& d = mirror_first ? *mirror : *straight;
  return {false, fmt::format("{}: not the model's fabric: {}", file, d.what)};
}

}  // namespace hand

void register_hand_target(Registry& registry) {
  for (const hand::FormatInfo& f : hand::kFormats) {
    registry.add(std::make_unique<hand::HandTarget>(f));
    registry.add(std::make_unique<hand::HandSimulator>(f));
  }
}

}  // namespace skein
