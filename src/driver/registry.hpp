// The one registry of back ends and their simulators. Each target folder exposes an explicit
// register function (no static-constructor tricks); `skein --help` lists what is registered.
#pragma once

#include <iosfwd>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace skein {

struct Compilation;

// Options a user can pass to a target or simulator (e.g. --machine).
struct TargetOptions {
  std::string machine;  // profile name or path, for machine targets
  std::string dialect;  // one of the target's dialects(); empty: its default
  // --set KEY=VALUE, then the project file's `target:` keys the target knows.
  std::map<std::string, std::string> settings;
  bool strict = false;  // simulators: the target's own strictest rules (compile --verify)
  std::string picture;  // simulators: an .svg to draw what the replayed file makes in
  std::string fabric;   // simulators: a stitch graph (.st) to write what the file makes in
};

// A choice a target offers (`--set rounds=inside-out`) and the values it may take.
struct TargetSetting {
  std::string key;
  std::vector<std::string> values;
  std::string help;
};

class Target {
 public:
  virtual ~Target() = default;
  virtual std::string name() const = 0;
  virtual std::string description() const = 0;
  virtual std::string default_extension() const = 0;  // ".txt", ".k", ".md"
  // Every extension its files are known by (`skein verify` finds the target by it).
  virtual std::vector<std::string> extensions() const { return {default_extension()}; }
  // The dialects --dialect may name (the hand target: "standard", "knitspeak"); none by default.
  virtual std::vector<std::string> dialects() const { return {}; }
  // The settings --set may give; none by default.
  virtual std::vector<TargetSetting> settings() const { return {}; }
  // Writes the compiled model; throws Error when this target cannot express it.
  virtual void emit(const Compilation& compilation, const TargetOptions& options,
                    std::ostream& out) const = 0;
};

// What a simulator found: proven, or the first impossible step and why.
struct VerifyReport {
  bool proven = false;
  std::string summary;  // what was replayed and checked, or the first failure
  // Without a model: every step replayed as written (all that can be checked then).
  bool valid = false;
};

class Simulator {
 public:
  virtual ~Simulator() = default;
  virtual std::string name() const = 0;
  virtual std::string target() const = 0;  // the target whose output it replays
  virtual std::string description() const = 0;
  // Replays `text` (read from `file`); with `against`, also compares the result with it.
  virtual VerifyReport verify(const std::string& text, const std::string& file,
                              const Compilation* against, const TargetOptions& options) const = 0;
  // The fabric `text` makes, as an AutoKnit stitch graph (.st text with stitch positions), for
  // the stages that take a stitch graph (the yarn model); nullopt when the simulator does not
  // rebuild one. Throws on a file it cannot replay.
  virtual std::optional<std::string> fabric_stitch_graph(const std::string& text,
                                                         const std::string& file,
                                                         const TargetOptions& options) const {
    (void)text, (void)file, (void)options;
    return std::nullopt;
  }
};

class Registry {
 public:
  void add(std::unique_ptr<Target> target);
  void add(std::unique_ptr<Simulator> simulator);
  const Target* target(const std::string& name) const;  // nullptr if unknown
  const Simulator* simulator_for(const std::string& target_name) const;
  std::vector<const Target*> targets() const;
  std::vector<const Simulator*> simulators() const;

 private:
  std::map<std::string, std::unique_ptr<Target>> targets_;
  std::map<std::string, std::unique_ptr<Simulator>> simulators_;  // by target name
};

}  // namespace skein
