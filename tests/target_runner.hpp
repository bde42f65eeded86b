// Runs a registered target or its simulator on a compilation, as `skein compile` and
// `skein verify` do, for tests that check what a target writes or proves.
#pragma once

#include <sstream>
#include <string>

#include "builtin_targets.hpp"
#include "driver/pipeline.hpp"
#include "hand/hand_target.hpp"

namespace skein::testing {

inline std::string emit(const Compilation& c, const std::string& target,
                        const TargetOptions& options = {}) {
  Registry registry;
  register_builtin_targets(registry);
  std::ostringstream out;
  registry.target(target)->emit(c, options, out);
  return out.str();
}

inline VerifyReport verify(const Compilation& c, const std::string& target,
                           const std::string& text) {
  Registry registry;
  register_builtin_targets(registry);
  return registry.simulator_for(target)->verify(text, "pattern", &c, {});
}

// Each hand format (markdown, page, KnitSpeak) written (with the target's `options`) and
// proven: the failures, or "".
inline std::string unproven_hand_formats(const Compilation& c, const TargetOptions& options = {}) {
  std::string failures;
  for (const char* target : {"hand", "hand-html", "hand-knitspeak"}) {
    VerifyReport report = verify(c, target, emit(c, target, options));
    if (!report.proven) failures += std::string(target) + ": " + report.summary + "\n";
  }
  return failures;
}

// Works a hand pattern written by hand (no model to compare with): the failure, or "".
inline std::string failure_of(const std::string& pattern) {
  VerifyReport r = hand::verify_pattern(pattern, "p.md", nullptr);
  return r.summary.find("give --against") == std::string::npos ? r.summary : "";
}

}  // namespace skein::testing
