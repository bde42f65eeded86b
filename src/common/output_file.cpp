#include "common/output_file.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <iostream>
#include <sstream>

#include "common/atomic_file.hpp"
#include "common/error.hpp"

namespace skein {
namespace {

namespace fs = std::filesystem;

// "a folder", "a FIFO", ...: what a non-regular file is, for messages; empty for a regular
// file, a symbolic link or nothing at all.
std::string non_regular_kind(fs::file_type type) {
  switch (type) {
    case fs::file_type::directory:
      return "a folder";
    case fs::file_type::character:
      return "a character device";
    case fs::file_type::block:
      return "a block device";
    case fs::file_type::fifo:
      return "a FIFO";
    case fs::file_type::socket:
      return "a socket";
    default:
      return "";
  }
}

void refuse_non_regular(const std::string& path, fs::file_type type) {
  std::string kind = non_regular_kind(type);
  if (kind.empty()) return;
  throw UsageError(
      fmt::format("cannot write {}: it is {}, not a regular file{}", path, kind,
                  type == fs::file_type::directory ? "" : " (-o - writes to standard output)"));
}

void refuse_inputs(const std::string& path, const std::vector<std::string>& inputs) {
  for (const std::string& input : inputs) {
    std::error_code ec;
    if (!fs::equivalent(path, input, ec) || ec) continue;
    throw UsageError(fmt::format("cannot write {}: it is an input of this command{}", path,
                                 input == path ? "" : fmt::format(" ({})", input)));
  }
}

// The file to write for `path` under `rules`: `path` itself, or the target of the symbolic link
// it names. Throws UsageError when the rules forbid it.
std::string file_to_write(const std::string& path, const OutputRules& rules) {
  if (path.empty()) throw UsageError("the output path is empty");
  std::error_code ec;
  fs::file_type own = fs::symlink_status(path, ec).type();
  refuse_non_regular(path, own);
  if (own == fs::file_type::not_found || own == fs::file_type::none) return path;
  refuse_inputs(path, rules.inputs);
  if (own != fs::file_type::symlink) {
    if (!rules.force)
      throw UsageError(fmt::format("{} already exists; pass --force to replace it", path));
    return path;
  }
  std::string target = fs::weakly_canonical(path, ec).string();
  if (ec) throw IoError(fmt::format("cannot write {}: {}", path, ec.message()));
  refuse_non_regular(target, fs::status(target, ec).type());
  if (!rules.force)
    throw UsageError(fmt::format("{} is a symbolic link to {}; pass --force to replace {}", path,
                                 target, target));
  return target;
}

}  // namespace

OutputFile::OutputFile(std::string path, OutputRules rules)
    : path_(std::move(path)), rules_(std::move(rules)) {
  if (!is_standard_output()) file_to_write(path_, rules_);
}

std::string OutputFile::name() const {
  return is_standard_output() ? "standard output" : path_;
}

void OutputFile::write(const std::function<void(std::ostream&)>& write) const {
  if (!is_standard_output()) return write_file_atomically(file_to_write(path_, rules_), write);
  std::ostringstream text;
  write(text);
  write_text(text.str());
}

void OutputFile::write_text(const std::string& text) const {
  if (!is_standard_output())
    return write_file_atomically(file_to_write(path_, rules_),
                                 [&](std::ostream& out) { out << text; });
  std::cout << text << std::flush;
  if (!std::cout) throw IoError("cannot write to standard output");
}

}  // namespace skein
