// Where a command writes: a regular file, replaced atomically, or standard output. The path is
// checked before any work is done, so that a command never replaces one of its inputs, a
// device, FIFO or folder, or (without --force) an existing file or a symbolic link's target.
#pragma once

#include <functional>
#include <iosfwd>
#include <string>
#include <vector>

namespace skein {

struct OutputRules {
  bool force = false;               // --force: an existing regular file (or link target) may go
  std::vector<std::string> inputs;  // files the command reads: never replaced, even with force
};

class OutputFile {
 public:
  // `path` "-" is standard output. Throws UsageError naming the path when the rules forbid
  // writing it: an input, a non-regular file, or without force an existing file or a link.
  OutputFile(std::string path, OutputRules rules);

  bool is_standard_output() const { return path_ == "-"; }
  // For messages: the path as given, or "standard output".
  std::string name() const;

  // Checks the path again, then writes what `write` produces: through a temporary file renamed
  // into place (beside a symbolic link's target when --force allowed it), or held until
  // `write` returns and then put on standard output, so an error never leaves partial output.
  void write(const std::function<void(std::ostream&)>& write) const;
  void write_text(const std::string& text) const;

 private:
  std::string path_;  // as given
  OutputRules rules_;
};

}  // namespace skein
