// What the command line says about each kind of exception, and its exit code: no library's raw
// message without what skein was doing.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <functional>
#include <new>
#include <stdexcept>
#include <system_error>

#include "common/error.hpp"

namespace skein {
namespace {

Failure failure_of(const std::function<void()>& command) {
  try {
    command();
  } catch (...) {
    return describe_current_exception("compiling hat.obj for the hand target");
  }
  ADD_FAILURE() << "nothing thrown";
  return {kDone, ""};
}

void expect_failure(const std::function<void()>& command, ExitCode code,
                    const std::string& message) {
  Failure f = failure_of(command);
  EXPECT_EQ(f.exit_code, code) << f.message;
  EXPECT_EQ(f.message, message);
}

TEST(ErrorReport, AnErrorIsBadInputInItsOwnWords) {
  expect_failure([] { throw ParseError("hat.obj", 3, "v 0 0", "expected 3 coordinates"); },
                 kBadInput, "error: hat.obj:3: expected 3 coordinates\n      3 | v 0 0");
  expect_failure([] { throw UsageError("unknown target 'loom'"); }, kBadInput,
                 "error: unknown target 'loom'");
}

TEST(ErrorReport, AnUnsupportedStructureExitsThree) {
  expect_failure([] { throw UnsupportedError("hand target: face 3 (sr5, row 2) is ..."); },
                 kUnsupported, "unsupported: hand target: face 3 (sr5, row 2) is ...");
}

TEST(ErrorReport, LibraryErrorsSayWhatSkeinWasDoing) {
  expect_failure(
      [] {
        throw std::filesystem::filesystem_error("cannot open", "/a/b",
                                                std::make_error_code(std::errc::filename_too_long));
      },
      kBadInput, "error while compiling hat.obj for the hand target: /a/b: File name too long");
  expect_failure(
      [] {
        YAML::Mark at;
        at.line = 2;
        at.column = 4;
        throw YAML::ParserException(at, "bad key");
      },
      kBadInput,
      "error while compiling hat.obj for the hand target: yaml-cpp: error at line 3, column 5: "
      "bad key");
}

TEST(ErrorReport, NoMemoryAndBugsExitFour) {
  expect_failure([] { throw std::bad_alloc(); }, kInternal,
                 "out of memory while compiling hat.obj for the hand target");
  int line = 0;
  Failure bug = failure_of([&] {
    line = __LINE__ + 1;
    SKEIN_ASSERT(1 + 1 == 3, "arithmetic");
  });
  EXPECT_EQ(bug.exit_code, kInternal);
  EXPECT_EQ(bug.message, fmt::format("internal error at {}:{}: arithmetic (1 + 1 == 3); please "
                                     "report this (while compiling hat.obj for the hand target)",
                                     __FILE__, line));
  expect_failure([] { throw std::out_of_range("vector::_M_range_check"); }, kInternal,
                 "internal error while compiling hat.obj for the hand target: "
                 "vector::_M_range_check; please report this");
  expect_failure([] { throw 42; }, kInternal,
                 "internal error while compiling hat.obj for the hand target; please report this");
}

}  // namespace
}  // namespace skein
