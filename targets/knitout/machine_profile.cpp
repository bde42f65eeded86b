#include "knitout/machine_profile.hpp"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <map>
#include <optional>

#include "common/atomic_file.hpp"
#include "common/error.hpp"
#include "common/yaml_source.hpp"

namespace skein::knitout {
namespace {

namespace fs = std::filesystem;

// Reads one profile strictly: every field known, typed and in range, else a ParseError that
// names the file, the line and the field.
class ProfileReader : public YamlSource {
 public:
  using YamlSource::YamlSource;

  // A map whose keys must all be in `fields` (each with what reads it); required ones must be
  // present.
  struct Field {
    const char* name;
    bool required;
    std::function<void(const YAML::Node&, const std::string& path)> read;
  };
  void read_map(const YAML::Node& map, const std::string& where, const std::vector<Field>& fields) {
    if (!map.IsMap())
      fail(map.Mark(),
           fmt::format("expected {} to be a map of fields", where.empty() ? "the profile" : where));
    check_unique_keys(map);
    for (const auto& entry : map) {
      std::string key = text(entry.first, "a field name");
      auto it =
          std::find_if(fields.begin(), fields.end(), [&](const Field& f) { return key == f.name; });
      if (it == fields.end()) {
        std::vector<std::string_view> known;
        for (const Field& f : fields) known.emplace_back(f.name);
        unknown_field(entry.first, where.empty() ? "the profile" : "'" + where + "'", known);
      }
      it->read(entry.second, prefix(where) + key);
    }
    for (const Field& f : fields)
      if (f.required && !map[f.name])
        fail(map.Mark(), fmt::format("missing field '{}{}'", prefix(where), f.name));
  }

  std::string text(const YAML::Node& n, const std::string& field) const {
    if (!n.IsScalar()) fail(n.Mark(), fmt::format("field '{}' must be a single value", field));
    return n.Scalar();
  }
  double number(const YAML::Node& n, const std::string& field, double low, double high) const {
    std::string s = text(n, field);
    char* end = nullptr;
    double value = std::strtod(s.c_str(), &end);
    if (s.empty() || *end != '\0' || !(value >= low && value <= high))
      fail(n.Mark(), fmt::format("field '{}' must be a number from {} to {}, found '{}'", field,
                                 low, high, s));
    return value;
  }
  std::uint32_t whole(const YAML::Node& n, const std::string& field, std::uint32_t low,
                      std::uint32_t high) const {
    double value = number(n, field, low, high);
    if (value != std::floor(value))
      fail(n.Mark(),
           fmt::format("field '{}' must be a whole number, found '{}'", field, n.Scalar()));
    return static_cast<std::uint32_t>(value);
  }
  bool flag(const YAML::Node& n, const std::string& field) const {
    std::string s = text(n, field);
    if (s == "true") return true;
    if (s == "false") return false;
    fail(n.Mark(), fmt::format("field '{}' must be true or false, found '{}'", field, s));
  }
  std::string choice(const YAML::Node& n, const std::string& field,
                     std::initializer_list<const char*> allowed) const {
    std::string s = text(n, field);
    std::string list;
    for (const char* a : allowed) {
      if (s == a) return s;
      list += (list.empty() ? "" : ", ") + std::string(a);
    }
    fail(n.Mark(), fmt::format("field '{}' must be one of {}, found '{}'", field, list, s));
  }

 private:
  static std::string prefix(const std::string& where) { return where.empty() ? "" : where + "."; }
};

using Field = ProfileReader::Field;

std::vector<std::string> split_words(const std::string& line) {
  std::vector<std::string> words;
  std::size_t start = 0;
  for (std::size_t i = 0; i <= line.size(); ++i)
    if (i == line.size() || line[i] == ' ') {
      if (i > start) words.push_back(line.substr(start, i - start));
      start = i + 1;
    }
  return words;
}

// Readers that store a field's value, for the field tables below.
using Read = std::function<void(const YAML::Node&, const std::string&)>;
Read text_to(const ProfileReader& r, std::string& out) {
  return [&r, &out](const YAML::Node& n, const std::string& f) { out = r.text(n, f); };
}
Read number_to(const ProfileReader& r, double& out, double low, double high) {
  return [&r, &out, low, high](const YAML::Node& n, const std::string& f) {
    out = r.number(n, f, low, high);
  };
}
template <typename T>
Read whole_to(const ProfileReader& r, T& out, std::uint32_t low, std::uint32_t high) {
  return [&r, &out, low, high](const YAML::Node& n, const std::string& f) {
    out = static_cast<T>(r.whole(n, f, low, high));
  };
}
Read flag_to(const ProfileReader& r, bool& out) {
  return [&r, &out](const YAML::Node& n, const std::string& f) { out = r.flag(n, f); };
}
Read map_of(ProfileReader& r, std::vector<Field> fields) {
  return [&r, fields = std::move(fields)](const YAML::Node& n, const std::string& where) {
    r.read_map(n, where, fields);
  };
}

MachineProfile parse_profile(const std::string& path, const std::string& text) {
  ProfileReader r(path, text);
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    r.fail(e.mark, fmt::format("not valid YAML: {}", e.msg));
  }
  MachineProfile p;
  p.file = path;
  std::string hook, first_pass, knit_empty, style;
  auto carriers = [&](const YAML::Node& n, const std::string& f) {
    p.carriers = split_words(r.text(n, f));
    if (p.carriers.empty() || p.carriers.size() > 32)
      r.fail(n.Mark(), fmt::format("field '{}' must name 1 to 32 carriers separated by spaces", f));
  };
  auto fractions = [&](const YAML::Node& n, const std::string& f) {
    if (!n.IsSequence())
      r.fail(n.Mark(), fmt::format("field '{}' must be a list such as [0, 0.25]", f));
    for (const auto& item : n) p.rack_fractions.push_back(r.number(item, f, 0, 0.75));
  };
  auto names = [&](const YAML::Node& n, const std::string& f) {
    if (!n.IsSequence())
      r.fail(n.Mark(), fmt::format("field '{}' must be a list such as [SWG091N2, SWGN2]", f));
    for (const auto& item : n) p.machine_names.push_back(r.text(item, f));
  };
  auto choice_to = [&](std::string& out, std::initializer_list<const char*> allowed) -> Read {
    return [&r, &out, allowed](const YAML::Node& n, const std::string& f) {
      out = r.choice(n, f, allowed);
    };
  };
  // clang-format off
  r.read_map(root, "", {
      {"name", true, text_to(r, p.name)},
      {"description", true, text_to(r, p.description)},
      {"machine", true, text_to(r, p.machine)},
      {"machine_names", false, names},
      {"back_end", false, text_to(r, p.back_end)},
      {"gauge", true, number_to(r, p.gauge, 1, 100)},
      {"needles", true, whole_to(r, p.needles, 8, 100000)},
      {"position", true, choice_to(p.position, {"Left", "Center", "Right", "Keep"})},
      {"width_header", true, flag_to(r, p.width_header)},
      {"carriers", true, carriers},
      {"racking", true, map_of(r, {
          {"max", true, whole_to(r, p.max_rack, 0, 64)},
          {"fractions", true, fractions},
          {"max_transfer_stretch", true, whole_to(r, p.max_transfer_stretch, 0, 64)}})},
      {"max_loops_per_needle", true, whole_to(r, p.max_loops_per_needle, 1, 15)},
      {"sliders", true, flag_to(r, p.sliders)},
      {"knit_empty_needle", true, choice_to(knit_empty, {"error", "allowed"})},
      {"yarn", true, map_of(r, {
          {"hook", true, choice_to(hook, {"inhook", "in"})},
          {"first_pass", true, choice_to(first_pass, {"+", "-"})},
          {"carrier", true, text_to(r, p.yarn_carrier)},
          {"waste_carrier", false, text_to(r, p.waste_carrier)},
          {"draw_carrier", false, text_to(r, p.draw_carrier)}})},
      {"stitch_number", false, whole_to(r, p.stitch_number, 1, 255)},
      {"speed_number", false, whole_to(r, p.speed_number, 1, 10000)},
      {"max_float", false, whole_to(r, p.max_float, 1, 10000)},
      {"cast_on", true, map_of(r, {
          {"style", true, choice_to(style, {"alternating-tuck"})},
          {"waste_rows", true, whole_to(r, p.waste_rows, 0, 200)}})},
      {"bind_off", true, map_of(r, {
          {"style", true, choice_to(style, {"chain"})},
          {"tag_rows", true, whole_to(r, p.tag_rows, 0, 50)}})},
      {"timing", true, map_of(r, {
          {"seconds_per_pass", true, number_to(r, p.seconds_per_pass, 0, 60)},
          {"seconds_per_needle", true, number_to(r, p.seconds_per_needle, 0, 10)},
          {"seconds_per_rack", true, number_to(r, p.seconds_per_rack, 0, 60)}})},
  });
  // clang-format on
  p.knit_empty_needle_is_error = knit_empty == "error";
  p.hook = hook == "inhook" ? YarnHook::inhook : YarnHook::in;
  p.first_pass = first_pass == "+" ? Direction::plus : Direction::minus;
  auto has_carrier = [&](const std::string& c) {
    return std::find(p.carriers.begin(), p.carriers.end(), c) != p.carriers.end();
  };
  if (!has_carrier(p.yarn_carrier))
    r.fail(root["yarn"]["carrier"].Mark(),
           fmt::format("field 'yarn.carrier' names carrier '{}', which is not in 'carriers'",
                       p.yarn_carrier));
  if (p.waste_rows > 0 && (p.waste_carrier.empty() || !has_carrier(p.waste_carrier) ||
                           p.waste_carrier == p.yarn_carrier))
    r.fail(root["cast_on"]["waste_rows"].Mark(),
           "field 'cast_on.waste_rows' needs 'yarn.waste_carrier': a carrier of 'carriers' other "
           "than 'yarn.carrier'");
  if (!p.draw_carrier.empty() &&
      (p.waste_rows == 0 || !has_carrier(p.draw_carrier) || p.draw_carrier == p.yarn_carrier ||
       p.draw_carrier == p.waste_carrier))
    r.fail(root["yarn"]["draw_carrier"].Mark(),
           "field 'yarn.draw_carrier' needs 'cast_on.waste_rows' and a carrier of 'carriers' other "
           "than 'yarn.carrier' and 'yarn.waste_carrier'");
  if (p.max_transfer_stretch > p.max_rack)
    r.fail(root["racking"]["max_transfer_stretch"].Mark(),
           "field 'racking.max_transfer_stretch' cannot exceed 'racking.max'");
  if (std::find(p.rack_fractions.begin(), p.rack_fractions.end(), 0.0) == p.rack_fractions.end())
    p.rack_fractions.push_back(0.0);
  for (double f : p.rack_fractions)
    if (f * 4 != std::floor(f * 4))
      r.fail(root["racking"]["fractions"].Mark(),
             "field 'racking.fractions' allows quarters only (0, 0.25, 0.5, 0.75)");
  return p;
}

// The user's own profiles: $XDG_DATA_HOME/skein/machine_profiles, else
// ~/.local/share/skein/machine_profiles (none when neither variable is set).
std::optional<fs::path> user_profile_directory() {
  const char* data = std::getenv("XDG_DATA_HOME");
  if (data && fs::path(data).is_absolute()) return fs::path(data) / "skein" / "machine_profiles";
  const char* home = std::getenv("HOME");
  if (home && *home) return fs::path(home) / ".local" / "share" / "skein" / "machine_profiles";
  return std::nullopt;
}

// Where a profile name is looked up, first match first: machine_profiles/ in the current
// directory, the user's folder, then beside the executable and in each folder above it both
// machine_profiles/ (build/skein in a checkout) and share/skein/machine_profiles/ (bin/skein
// installed under a prefix).
std::vector<fs::path> profile_directories() {
  std::vector<fs::path> dirs;
  std::error_code ec;
  fs::path here = fs::current_path(ec);
  if (!ec) dirs.push_back(here / "machine_profiles");
  if (std::optional<fs::path> user = user_profile_directory()) dirs.push_back(*user);
  fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec)
    for (fs::path dir = exe.parent_path(); !dir.empty(); dir = dir.parent_path()) {
      dirs.push_back(dir / "machine_profiles");
      dirs.push_back(dir / "share" / "skein" / "machine_profiles");
      if (dir == dir.root_path()) break;
    }
  return dirs;
}

}  // namespace

bool MachineProfile::rack_allowed(std::int32_t quarters) const {
  return std::abs(quarters) <= max_rack * 4 && rack_fraction_allowed(quarters);
}

bool MachineProfile::rack_fraction_allowed(std::int32_t quarters) const {
  int fraction = ((quarters % 4) + 4) % 4;
  return std::any_of(rack_fractions.begin(), rack_fractions.end(),
                     [&](double f) { return static_cast<int>(f * 4) == fraction; });
}

std::string MachineProfile::carriers_line() const {
  std::string line;
  for (const std::string& c : carriers) line += (line.empty() ? "" : " ") + c;
  return line;
}

bool MachineProfile::is_machine(const std::string& header) const {
  auto same = [&](const std::string& known) {
    return std::equal(known.begin(), known.end(), header.begin(), header.end(), [](char a, char b) {
      return std::tolower(static_cast<unsigned char>(a)) ==
             std::tolower(static_cast<unsigned char>(b));
    });
  };
  return same(machine) || std::any_of(machine_names.begin(), machine_names.end(), same);
}

MachineProfile read_machine_profile(const std::string& path) {
  return parse_profile(path, read_file(path));
}

MachineProfile load_machine_profile(const std::string& name_or_path) {
  if (name_or_path.empty()) {
    std::string names;
    for (const std::string& n : shipped_profile_names()) names += (names.empty() ? "" : ", ") + n;
    throw UsageError(
        fmt::format("the knitout target needs --machine: a profile name ({}) or the "
                    "path of a profile .yaml file",
                    names.empty() ? "none found in machine_profiles/" : names));
  }
  bool is_path = name_or_path.find('/') != std::string::npos || name_or_path.ends_with(".yaml");
  if (is_path) return read_machine_profile(name_or_path);
  std::vector<fs::path> dirs = profile_directories();
  for (const fs::path& dir : dirs) {
    fs::path candidate = dir / (name_or_path + ".yaml");
    std::error_code ec;
    if (fs::is_regular_file(candidate, ec)) return read_machine_profile(candidate.string());
  }
  std::string names;
  for (const std::string& n : shipped_profile_names()) names += (names.empty() ? "" : ", ") + n;
  throw UsageError(
      fmt::format("no machine profile '{}' (looked for machine_profiles/ in the current "
                  "directory, in $XDG_DATA_HOME/skein or ~/.local/share/skein, beside the skein "
                  "executable and in its prefix's share/skein); known profiles: {}",
                  name_or_path, names.empty() ? "none" : names));
}

std::optional<MachineProfile> profile_for_machine(const std::string& header) {
  if (header.empty()) return std::nullopt;
  for (const std::string& name : shipped_profile_names()) {
    MachineProfile p = load_machine_profile(name);
    if (p.is_machine(header)) return p;
  }
  return std::nullopt;
}

std::vector<std::string> shipped_profile_names() {
  std::vector<std::string> names;
  for (const fs::path& dir : profile_directories()) {
    std::error_code ec;
    if (!fs::is_directory(dir, ec)) continue;
    for (const auto& entry : fs::directory_iterator(dir, ec))
      if (entry.path().extension() == ".yaml") names.push_back(entry.path().stem().string());
  }
  std::sort(names.begin(), names.end());
  names.erase(std::unique(names.begin(), names.end()), names.end());
  return names;
}

}  // namespace skein::knitout
