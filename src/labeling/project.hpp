// The project file (YAML): the coarse mesh and every choice a designer makes between it and the
// stitch mesh. Every field has a default, so the smallest project is one line, `mesh: hat.obj`.
// docs/formats.md ("Project files") documents each field with an example.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace skein {

enum class StitchPattern : std::uint8_t { knit, purl, k1p1, k2p2 };
enum class ShortRowMethod : std::uint8_t { sr4, sr5 };
enum class YarnHandling : std::uint8_t { by_default, extra, own };

// An edge of the coarse mesh named by its two vertices (0-based here, 1-based in the file).
struct CoarseEdgeRef {
  std::uint32_t a = 0, b = 0;
  int line = 0;  // where the file names it, for messages
};

struct StartSeed {
  enum class Kind : std::uint8_t { edge, vertex, lowest } kind = Kind::edge;
  CoarseEdgeRef edge;  // with `vertex`, only edge.a is used; with `lowest`, none
};

struct ShortRowFaceMark {
  std::uint32_t face = 0;                  // 0-based
  std::optional<CoarseEdgeRef> wide_edge;  // the side with the extra rows (default: the longer)
  int line = 0;
};

// Fig. 3's shift operations, as the stitch mesh stores them (ShiftOption: 1 up-right ... 4
// down-left).
struct ShiftPathMark {
  CoarseEdgeRef edge;
  std::uint8_t option = 1;
};

struct YarnMark {
  CoarseEdgeRef edge;
  YarnHandling use = YarnHandling::extra;
  std::optional<std::uint32_t> face;  // with `own`: whose yarn (0-based; default: labelled first)
};

struct GroupPattern {
  StitchPattern pattern = StitchPattern::knit;
  int line = 0;  // where the file names the group, for messages
};

// Yarn weights as the Craft Yarn Council names them, finest first.
enum class YarnWeight : std::uint8_t {
  lace,
  fingering,
  sport,
  dk,
  worsted,
  aran,
  bulky,
  super_bulky,
  jumbo
};

// What a knitter matches with a swatch: stitches and rows per 10 cm in stockinette, with this
// yarn on this needle. The hand target's gauge, measurements, yarn amounts and needles.
struct YarnGauge {
  double stitches_per_10cm = 20;
  double rows_per_10cm = 28;
  YarnWeight weight = YarnWeight::worsted;
  double needle_mm = 4.5;
};

// Limits the project reader enforces (docs/formats.md, "Limits").
inline constexpr double kMinGauge = 1, kMaxGauge = 100;  // stitches or rows per 10 cm
inline constexpr double kMinNeedleMm = 1, kMaxNeedleMm = 30;

struct Project {
  std::string file;  // the project file, for messages
  std::string mesh;  // path of the coarse OBJ (resolved against the project file's folder)

  // Size of one stitch in mesh units: from the gauge (per 10 cm) and the mesh unit, unless
  // stitch_size gives it directly.
  std::string unit = "cm";
  double stitches_per_10cm = 22;
  double rows_per_10cm = 30;
  std::optional<double> stitch_width, stitch_height;  // mesh units
  double stitch_width_in_units() const;
  double stitch_height_in_units() const;
  std::optional<YarnWeight> yarn_weight;  // default: the usual weight for the gauge
  std::optional<double> needle_mm;        // default: the weight's usual needle
  // The gauge in stitches and rows per 10 cm (from stitch_size too), with the yarn and needle
  // given or the defaults for that gauge.
  YarnGauge yarn_gauge() const;

  std::vector<StartSeed> start;  // empty: the lowest boundary loop (as `auto`)
  StitchPattern pattern = StitchPattern::knit;
  std::map<std::string, GroupPattern> group_patterns;  // OBJ group name -> pattern
  ShortRowMethod short_row_method = ShortRowMethod::sr4;
  std::vector<ShortRowFaceMark> short_row_faces;
  std::vector<CoarseEdgeRef> mismatch_edges;  // rows stop here (perpendicular mismatches)
  YarnHandling default_yarn = YarnHandling::by_default;
  std::vector<YarnMark> yarn_marks;
  std::vector<ShiftPathMark> shift_paths;  // coarse side edges a tube's shift-path follows
  std::uint8_t shift_option = 1;           // for paths skein places (default up-right)
  // Target settings, passed through to targets (`target:`; `short_rows: {hand: M}` is the hand
  // target's short-rows setting unless `target:` sets it).
  std::map<std::string, std::string> target;
};

// Parses project text; `file` names it in messages and resolves `mesh`. Throws ParseError
// naming the line: unknown fields (with the nearest valid name), wrong types, bad values.
Project parse_project(const std::string& text, const std::string& file);
Project read_project(const std::string& path);

bool is_project_file(const std::string& path);  // .yaml or .yml

// The project's `target:` option `key` ("" when `path` is not a project or does not set it):
// what the command line uses when its own option is not given.
std::string project_target_option(const std::string& path, const std::string& key);

std::string_view pattern_name(StitchPattern pattern);
std::string_view yarn_weight_name(YarnWeight weight);  // "worsted", "super-bulky"

}  // namespace skein
