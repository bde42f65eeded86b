// Errors a user can cause are typed exceptions that say where (file, line, face, edge),
// what was expected and what was found. Broken internal invariants use SKEIN_ASSERT.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>

namespace skein {

// Base of every error a user can cause; the CLI prints what() and exits 2 (3 for
// UnsupportedError).
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A malformed input file: names the file, the 1-based line, quotes the line, says what was
// expected.
class ParseError : public Error {
 public:
  ParseError(std::string file, std::size_t line, std::string quoted, std::string expected);
  const std::string& file() const { return file_; }
  std::size_t line() const { return line_; }
  const std::string& expected() const { return expected_; }

 private:
  std::string file_;
  std::size_t line_;
  std::string expected_;
};

// A structurally invalid stitch mesh (found by validate()): names the face or edge.
class MeshError : public Error {
 public:
  using Error::Error;
};

// A file that could not be opened, read or written.
class IoError : public Error {
 public:
  using Error::Error;
};

// A command-line request that does not make sense (unknown target, missing option, ...).
class UsageError : public Error {
 public:
  using Error::Error;
};

// A valid input that this target cannot express (yet, or on this machine): names the structure
// (stitch, row, piece) and what the target lacks. The CLI exits 3, not 2: the input is fine.
class UnsupportedError : public Error {
 public:
  using Error::Error;
};

// An internal invariant broke: a bug in skein, not in the input.
class InternalError : public std::logic_error {
 public:
  using std::logic_error::logic_error;
};

// The exit codes of every command.
enum ExitCode : int {
  kDone = 0,          // knittable, written, proven
  kNotKnittable = 1,  // valid input that is not knittable, or a file that does not prove
  kBadInput = 2,      // bad input or usage: an Error
  kUnsupported = 3,   // valid input that this target cannot do: an UnsupportedError
  kInternal = 4,      // a bug in skein, or no memory left
};

// What to tell the user about an exception that escaped a command.
struct Failure {
  ExitCode exit_code;
  std::string message;  // one or more lines, without the trailing newline
};

// Call in a catch block: the exception being handled, said in words. An Error's own message is
// enough; a library's (filesystem, YAML, bad_alloc, ...) is said with what skein was `doing`
// ("compiling hat.obj for the hand target"), since it does not say it.
Failure describe_current_exception(const std::string& doing);

[[noreturn]] void assertion_failed(const char* condition, const char* file, int line,
                                   const std::string& message);

}  // namespace skein

#define SKEIN_ASSERT(condition, message)                                                    \
  do {                                                                                      \
    if (!(condition)) ::skein::assertion_failed(#condition, __FILE__, __LINE__, (message)); \
  } while (false)
