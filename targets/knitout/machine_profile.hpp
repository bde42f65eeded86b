// Machine profiles: what one knitting machine (and its knitout back end) allows, read from a
// YAML file in machine_profiles/. Every field is documented in docs/knitout.md; a missing,
// unknown or malformed field is a ParseError naming the file, the line and the field.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace skein::knitout {

enum class Direction : std::int8_t { minus = -1, none = 0, plus = 1 };
inline Direction opposite(Direction d) {
  return static_cast<Direction>(-static_cast<int>(d));
}
inline char direction_char(Direction d) {
  return d == Direction::plus ? '+' : '-';
}

enum class YarnHook : std::uint8_t {
  inhook,  // inhook / releasehook / outhook (a yarn-inserting hook, e.g. Shima Seiki)
  in,      // plain in / out (no hook, e.g. Kniterate)
};

struct MachineProfile {
  std::string file;                        // where it was read from, for messages
  std::string name;                        // "swg091n2"
  std::string description;                 // one line for people
  std::string machine;                     // the ;;Machine: header value
  std::vector<std::string> machine_names;  // other ;;Machine: values meaning this machine
  std::string back_end;                    // "knitout-to-dat": what turns knitout into its files
  double gauge = 0;                        // needles per inch, the ;;Gauge: header value
  std::uint32_t needles = 0;               // needles per bed, numbered 0..needles-1
  std::string position;                    // the ;;Position: header value
  bool width_header = false;               // write ;;Width: <needles>
  std::vector<std::string> carriers;       // the ;;Carriers: header, in order
  std::string yarn_carrier;                // the carrier skein knits with
  std::string waste_carrier;               // the carrier for the waste section (if any)
  std::string draw_carrier;            // the draw thread's carrier between waste and piece (if any)
  std::int32_t max_rack = 0;           // |racking| limit, in needles
  std::vector<double> rack_fractions;  // allowed fractional parts of a rack (0 always)
  std::int32_t max_transfer_stretch = 0;  // |racking| limit for xfer/split
  std::uint32_t max_loops_per_needle = 0;
  bool sliders = false;
  YarnHook hook = YarnHook::in;
  Direction first_pass = Direction::minus;  // after bringing a yarn in
  bool knit_empty_needle_is_error = true;
  std::uint32_t stitch_number = 0;  // x-stitch-number to emit (0: none)
  std::uint32_t speed_number = 0;   // x-speed-number to emit (0: none)
  std::uint32_t waste_rows = 0;     // cast-on: rows of waste yarn before the piece (0: none)
  std::uint32_t tag_rows = 0;       // bind-off: rows of the tag knit on the last loop
  std::uint32_t max_float = 0;      // the longest float, in needles, not worth a mention
  // Estimated knitting time: per carriage pass, plus per needle it crosses, plus per rack.
  double seconds_per_pass = 0;
  double seconds_per_needle = 0;
  double seconds_per_rack = 0;

  bool rack_allowed(std::int32_t quarters) const;           // racking given in quarter needles
  bool rack_fraction_allowed(std::int32_t quarters) const;  // its fraction, whatever its size
  std::string carriers_line() const;                        // "1 2 3 ..."
  // Whether a ;;Machine: header names this machine: `machine` or one of `machine_names`,
  // in any case ("SWG091N2", "swgn2").
  bool is_machine(const std::string& header) const;
};

// Reads and checks the profile file at `path`.
MachineProfile read_machine_profile(const std::string& path);

// `name_or_path` is a shipped profile's name (looked up in machine_profiles/ in the current
// directory, then in the user's $XDG_DATA_HOME/skein or ~/.local/share/skein, then beside the
// executable, its parent folders and their share/skein) or the path of a .yaml file.
MachineProfile load_machine_profile(const std::string& name_or_path);

// The shipped profile whose machine a file's ;;Machine: header names; nullopt if none does.
std::optional<MachineProfile> profile_for_machine(const std::string& header);

// The names of the profiles that can be found in all those folders, sorted.
std::vector<std::string> shipped_profile_names();

}  // namespace skein::knitout
