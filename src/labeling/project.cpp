#include "labeling/project.hpp"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <charconv>
#include <filesystem>
#include <optional>

#include "common/atomic_file.hpp"
#include "common/error.hpp"
#include "common/yaml_source.hpp"
#include "labeling/coarse_mesh.hpp"

namespace skein {
namespace {

using Names = std::vector<std::string_view>;

constexpr std::pair<std::string_view, double> kUnitsPerCm[] = {
    {"mm", 10}, {"cm", 1}, {"m", 0.01}, {"in", 1 / 2.54}};
constexpr std::string_view kPatterns[] = {"knit", "purl", "k1p1", "k2p2"};
constexpr std::string_view kWeights[] = {"lace", "fingering", "sport",       "dk",   "worsted",
                                         "aran", "bulky",     "super-bulky", "jumbo"};

// The usual weight for a gauge (the Craft Yarn Council's ranges of stitches per 10 cm, where
// two overlap the finer) and the usual needle for each weight.
struct WeightDefault {
  double from_sts;  // this weight from this many stitches per 10 cm (up to the finer one's)
  YarnWeight weight;
  double needle_mm;
};
constexpr WeightDefault kWeightDefaults[] = {
    {33, YarnWeight::lace, 2},    {27, YarnWeight::fingering, 2.75}, {24, YarnWeight::sport, 3.5},
    {21, YarnWeight::dk, 4},      {16, YarnWeight::worsted, 4.5},    {14, YarnWeight::aran, 5},
    {12, YarnWeight::bulky, 6.5}, {7, YarnWeight::super_bulky, 10},  {0, YarnWeight::jumbo, 15}};

// Reads YAML nodes and turns every problem into a ParseError on the node's line.
class Reader : public YamlSource {
 public:
  using YamlSource::YamlSource;

  int line(const YAML::Node& node) const { return node.Mark().line + 1; }

  // Calls visit(key, value) for each field; an unknown key names the nearest known one.
  template <class Visit>
  void fields(const YAML::Node& map, const Names& known, std::string_view what, Visit visit) const {
    if (!map.IsMap()) fail(map, fmt::format("expected the fields of {} (key: value)", what));
    check_unique_keys(map);
    for (const auto& item : map) {
      std::string key = text(item.first, "a field name");
      if (std::find(known.begin(), known.end(), key) == known.end())
        unknown_field(item.first, what, known);
      visit(key, item.second);
    }
  }

  std::string text(const YAML::Node& node, std::string_view what) const {
    if (!node.IsScalar()) fail(node, fmt::format("expected {} (a single value)", what));
    return node.Scalar();
  }
  // A finite number in [low, high].
  double number(const YAML::Node& node, std::string_view what, double low, double high) const {
    std::string s = text(node, what);
    double v = 0;
    auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (!s.empty() && ec == std::errc() && end == s.data() + s.size() && v >= low && v <= high)
      return v;
    fail(node,
         fmt::format("expected {} (a number from {:g} to {:g}), found '{}'", what, low, high, s));
  }
  std::uint32_t index(const YAML::Node& node, std::string_view what) const {
    std::string s = text(node, what);
    if (!s.empty() && std::all_of(s.begin(), s.end(), ::isdigit) && s.size() < 10 &&
        std::stoul(s) > 0)
      return static_cast<std::uint32_t>(std::stoul(s) - 1);
    fail(node,
         fmt::format("expected {} (a number from 1, as in the OBJ file), found '{}'", what, s));
  }
  CoarseEdgeRef edge(const YAML::Node& node) const {
    if (!node.IsSequence() || node.size() != 2)
      fail(node, "expected an edge as its two vertex numbers, e.g. [3, 4]");
    return {index(node[0], "a vertex number"), index(node[1], "a vertex number"), line(node)};
  }
  std::vector<CoarseEdgeRef> edges(const YAML::Node& node) const {
    if (!node.IsSequence()) fail(node, "expected a list of edges, e.g. [[3, 4], [4, 5]]");
    std::vector<CoarseEdgeRef> out;
    for (const auto& item : node) out.push_back(edge(item));
    return out;
  }
  template <std::size_t N>
  std::size_t choice(const YAML::Node& node, std::string_view what,
                     const std::string_view (&names)[N]) const {
    std::string s = text(node, what);
    for (std::size_t i = 0; i < N; ++i)
      if (names[i] == s) return i;
    Names known(std::begin(names), std::end(names));
    fail(node, fmt::format("unknown {} '{}'; did you mean '{}'? (known: {})", what, s,
                           nearest_name(s, known), fmt::join(known, ", ")));
  }
};

StitchPattern read_pattern(const Reader& r, const YAML::Node& node) {
  return static_cast<StitchPattern>(r.choice(node, "stitch pattern", kPatterns));
}

// "4.5mm", "4.5 mm": a needle's diameter, the unit required.
double read_needle(const Reader& r, const YAML::Node& node) {
  std::string s = r.text(node, "a needle size");
  std::size_t digits = s.find_first_not_of("0123456789.");
  double mm = 0;
  auto [end, ec] = std::from_chars(s.data(), s.data() + std::min(digits, s.size()), mm);
  std::string_view unit = std::string_view(s).substr(std::min(digits, s.size()));
  if (unit.starts_with(' ')) unit.remove_prefix(1);
  if (ec == std::errc() && end == s.data() + std::min(digits, s.size()) && unit == "mm" &&
      mm >= kMinNeedleMm && mm <= kMaxNeedleMm)
    return mm;
  r.fail(node, fmt::format("expected a needle size in mm from {:g} to {:g}, e.g. 4.5mm, found '{}'",
                           kMinNeedleMm, kMaxNeedleMm, s));
}

void read_gauge(const Reader& r, const YAML::Node& node, Project& p) {
  r.fields(node, {"stitches", "rows", "yarn", "needle"}, "gauge",
           [&](const std::string& key, const YAML::Node& v) {
             if (key == "yarn")
               p.yarn_weight = static_cast<YarnWeight>(r.choice(v, "yarn weight", kWeights));
             else if (key == "needle")
               p.needle_mm = read_needle(r, v);
             else
               (key == "stitches" ? p.stitches_per_10cm : p.rows_per_10cm) =
                   r.number(v, key == "stitches" ? "stitches per 10 cm" : "rows per 10 cm",
                            kMinGauge, kMaxGauge);
           });
}

void read_stitch_size(const Reader& r, const YAML::Node& node, Project& p) {
  r.fields(node, {"width", "height"}, "stitch_size",
           [&](const std::string& key, const YAML::Node& v) {
             (key == "width" ? p.stitch_width : p.stitch_height) =
                 r.number(v, "a size in mesh units", 1e-6, kMaxCoordinate);
           });
  if (!p.stitch_width || !p.stitch_height) r.fail(node, "expected both width and height");
}

void read_start(const Reader& r, const YAML::Node& node, Project& p) {
  if (node.IsScalar() && node.Scalar() == "auto") return;
  if (!node.IsSequence())
    r.fail(node, "expected 'auto' or a list of starts, e.g. [auto, {edge: [1, 2]}, {vertex: 5}]");
  for (const auto& item : node) {
    if (item.IsScalar() && item.Scalar() == "auto") {
      p.start.push_back({StartSeed::Kind::lowest, {0, 0, r.line(item)}});
      continue;
    }
    r.fields(item, {"edge", "vertex"}, "a start", [&](const std::string& key, const YAML::Node& v) {
      StartSeed seed;
      if (key == "edge") {
        seed.edge = r.edge(v);
      } else {
        seed.kind = StartSeed::Kind::vertex;
        seed.edge = {r.index(v, "a vertex number"), 0, r.line(v)};
      }
      p.start.push_back(seed);
    });
  }
}

void read_short_rows(const Reader& r, const YAML::Node& node, Project& p) {
  constexpr std::string_view kMethods[] = {"sr4", "sr5"};
  constexpr std::string_view kHandMethods[] = {"german", "wrap-and-turn"};
  r.fields(node, {"method", "hand", "faces"}, "short_rows",
           [&](const std::string& key, const YAML::Node& v) {
             if (key == "method") {
               p.short_row_method =
                   static_cast<ShortRowMethod>(r.choice(v, "short-row method", kMethods));
               return;
             }
             if (key == "hand") {
               p.target.try_emplace(
                   "short-rows", kHandMethods[r.choice(v, "hand short-row method", kHandMethods)]);
               return;
             }
             if (!v.IsSequence())
               r.fail(v, "expected a list of faces, e.g. [12, {face: 13, wide_edge: [4, 5]}]");
             for (const auto& item : v) {
               ShortRowFaceMark mark{0, std::nullopt, r.line(item)};
               if (item.IsScalar()) {
                 mark.face = r.index(item, "a face number");
               } else {
                 bool has_face = false;
                 r.fields(item, {"face", "wide_edge"}, "a short-row face",
                          [&](const std::string& k, const YAML::Node& w) {
                            if (k == "face") {
                              mark.face = r.index(w, "a face number");
                              has_face = true;
                            } else {
                              mark.wide_edge = r.edge(w);
                            }
                          });
                 if (!has_face) r.fail(item, "expected 'face: N'");
               }
               p.short_row_faces.push_back(mark);
             }
           });
}

void read_yarn(const Reader& r, const YAML::Node& node, Project& p) {
  constexpr std::string_view kUses[] = {"auto", "extra", "own"};
  r.fields(node, {"default", "edges"}, "yarn", [&](const std::string& key, const YAML::Node& v) {
    if (key == "default") {
      p.default_yarn = static_cast<YarnHandling>(r.choice(v, "yarn handling", kUses));
      return;
    }
    if (!v.IsSequence()) r.fail(v, "expected a list of {edge: [a, b], use: extra|own, face: N}");
    for (const auto& item : v) {
      YarnMark mark;
      bool has_edge = false;
      r.fields(item, {"edge", "use", "face"}, "a yarn choice",
               [&](const std::string& k, const YAML::Node& w) {
                 if (k == "edge") {
                   mark.edge = r.edge(w);
                   has_edge = true;
                 } else if (k == "use") {
                   mark.use = static_cast<YarnHandling>(r.choice(w, "yarn handling", kUses));
                 } else {
                   mark.face = r.index(w, "a face number");
                 }
               });
      if (!has_edge) r.fail(item, "expected 'edge: [a, b]'");
      p.yarn_marks.push_back(mark);
    }
  });
}

constexpr std::string_view kShiftOptions[] = {"up-right", "up-left", "down-right", "down-left"};

std::uint8_t read_shift_option(const Reader& r, const YAML::Node& node) {
  return static_cast<std::uint8_t>(r.choice(node, "shift option", kShiftOptions) + 1);
}

void read_shift_paths(const Reader& r, const YAML::Node& node, Project& p) {
  if (!node.IsSequence())
    r.fail(node, "expected a list of edges or {edge: [a, b], option: up-left}");
  for (const auto& item : node) {
    if (item.IsSequence()) {
      p.shift_paths.push_back({r.edge(item), p.shift_option});
      continue;
    }
    ShiftPathMark mark{{}, 0};
    r.fields(item, {"edge", "option"}, "a shift-path",
             [&](const std::string& key, const YAML::Node& v) {
               if (key == "edge")
                 mark.edge = r.edge(v);
               else
                 mark.option = read_shift_option(r, v);
             });
    if (mark.edge.line == 0) r.fail(item, "expected 'edge: [a, b]'");
    p.shift_paths.push_back(mark);
  }
}

void read_target(const Reader& r, const YAML::Node& node, Project& p) {
  if (!node.IsMap()) r.fail(node, "expected target options (key: value)");
  r.check_unique_keys(node);
  for (const auto& item : node)
    p.target[r.text(item.first, "a target option")] = r.text(item.second, "a target option value");
}

}  // namespace

double Project::stitch_width_in_units() const {
  if (stitch_width) return *stitch_width;
  auto it = std::find_if(std::begin(kUnitsPerCm), std::end(kUnitsPerCm),
                         [&](const auto& u) { return u.first == unit; });
  return 10.0 / stitches_per_10cm * it->second;
}

double Project::stitch_height_in_units() const {
  if (stitch_height) return *stitch_height;
  auto it = std::find_if(std::begin(kUnitsPerCm), std::end(kUnitsPerCm),
                         [&](const auto& u) { return u.first == unit; });
  return 10.0 / rows_per_10cm * it->second;
}

YarnGauge Project::yarn_gauge() const {
  auto per_cm = std::find_if(std::begin(kUnitsPerCm), std::end(kUnitsPerCm),
                             [&](const auto& u) { return u.first == unit; });
  YarnGauge g;
  g.stitches_per_10cm = 10 * per_cm->second / stitch_width_in_units();
  g.rows_per_10cm = 10 * per_cm->second / stitch_height_in_units();
  const WeightDefault* usual =
      std::find_if(std::begin(kWeightDefaults), std::end(kWeightDefaults) - 1,
                   [&](const WeightDefault& d) { return g.stitches_per_10cm >= d.from_sts; });
  g.weight = yarn_weight.value_or(usual->weight);
  auto of_weight = std::find_if(std::begin(kWeightDefaults), std::end(kWeightDefaults),
                                [&](const WeightDefault& d) { return d.weight == g.weight; });
  g.needle_mm = needle_mm.value_or(yarn_weight ? of_weight->needle_mm : usual->needle_mm);
  return g;
}

std::string_view yarn_weight_name(YarnWeight weight) {
  return kWeights[static_cast<std::size_t>(weight)];
}

std::string_view pattern_name(StitchPattern pattern) {
  return kPatterns[static_cast<std::size_t>(pattern)];
}

bool is_project_file(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  return ext == ".yaml" || ext == ".yml";
}

Project parse_project(const std::string& text, const std::string& file) {
  Reader r(file, text);
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    r.fail(e.mark, fmt::format("not valid YAML: {}", e.msg));
  }
  Project p;
  p.file = file;
  std::optional<YAML::Node> shift_paths;
  if (!root.IsMap()) r.fail(root, "expected a project: at least 'mesh: FILE.obj'");
  constexpr std::string_view kUnits[] = {"mm", "cm", "m", "in"};
  const Names known = {"mesh",        "unit",         "gauge",      "stitch_size", "start",
                       "pattern",     "patterns",     "short_rows", "mismatches",  "yarn",
                       "shift_paths", "shift_option", "target"};
  r.fields(root, known, "the project", [&](const std::string& key, const YAML::Node& v) {
    if (key == "mesh") {
      std::filesystem::path mesh = r.text(v, "the coarse mesh file");
      p.mesh = mesh.is_absolute() ? mesh.string()
                                  : (std::filesystem::path(file).parent_path() / mesh).string();
    } else if (key == "unit") {
      p.unit = std::string(kUnits[r.choice(v, "unit", kUnits)]);
    } else if (key == "gauge") {
      read_gauge(r, v, p);
    } else if (key == "stitch_size") {
      read_stitch_size(r, v, p);
    } else if (key == "start") {
      read_start(r, v, p);
    } else if (key == "pattern") {
      p.pattern = read_pattern(r, v);
    } else if (key == "patterns") {
      if (!v.IsMap()) r.fail(v, "expected OBJ group names with a pattern each, e.g. cuff: k2p2");
      r.check_unique_keys(v);
      for (const auto& item : v)
        p.group_patterns[r.text(item.first, "an OBJ group name")] = {read_pattern(r, item.second),
                                                                     r.line(item.first)};
    } else if (key == "short_rows") {
      read_short_rows(r, v, p);
    } else if (key == "mismatches") {
      p.mismatch_edges = r.edges(v);
    } else if (key == "yarn") {
      read_yarn(r, v, p);
    } else if (key == "shift_paths") {
      shift_paths = v;  // read last: plain edges take shift_option, wherever it is written
    } else if (key == "shift_option") {
      p.shift_option = read_shift_option(r, v);
    } else {
      read_target(r, v, p);
    }
  });
  if (shift_paths) read_shift_paths(r, *shift_paths, p);
  for (ShiftPathMark& mark : p.shift_paths)
    if (mark.option == 0) mark.option = p.shift_option;
  if (p.mesh.empty()) r.fail(root, "expected 'mesh: FILE.obj' (the coarse polygon mesh)");
  return p;
}

Project read_project(const std::string& path) {
  return parse_project(read_file(path), path);
}

std::string project_target_option(const std::string& path, const std::string& key) {
  if (!is_project_file(path)) return "";
  Project p = read_project(path);
  auto it = p.target.find(key);
  return it == p.target.end() ? "" : it->second;
}

}  // namespace skein
