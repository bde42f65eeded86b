#include "common/atomic_file.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>

#include "common/error.hpp"

namespace skein {

void write_file_atomically(const std::string& path,
                           const std::function<void(std::ostream&)>& write) {
  std::error_code ec;
  std::filesystem::file_type type = std::filesystem::symlink_status(path, ec).type();
  if (type != std::filesystem::file_type::not_found && type != std::filesystem::file_type::none &&
      type != std::filesystem::file_type::regular)
    throw IoError(fmt::format("cannot write {}: it is not a regular file", path));
  std::string temp = fmt::format("{}.tmp{}", path, ::getpid());
  try {
    {
      std::ofstream out(temp, std::ios::binary);
      if (!out) throw IoError(fmt::format("cannot write {}: {}", path, std::strerror(errno)));
      write(out);
      out.flush();
      if (!out) throw IoError(fmt::format("cannot write {}: {}", path, std::strerror(errno)));
    }
    std::filesystem::rename(temp, path, ec);
    if (ec) throw IoError(fmt::format("cannot write {}: {}", path, ec.message()));
  } catch (...) {
    std::error_code ignored;
    std::filesystem::remove(temp, ignored);
    throw;
  }
}

namespace {

// A reader given a directory, a FIFO or a device (`mesh: /dev/zero`) would fail obscurely,
// block or read forever: only regular files are read.
void check_regular_file(const std::string& path) {
  std::error_code error;
  std::filesystem::file_status status = std::filesystem::status(path, error);
  if (error || status.type() == std::filesystem::file_type::regular) return;  // fopen says why
  const char* what = status.type() == std::filesystem::file_type::directory ? "a directory"
                     : status.type() == std::filesystem::file_type::fifo    ? "a FIFO"
                                                                            : "a device or socket";
  throw IoError(fmt::format("cannot read '{}': it is {}; expected a regular file", path, what));
}

}  // namespace

std::string read_file(const std::string& path) {
  check_regular_file(path);
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "rb"),
                                                       &std::fclose);
  if (!file) throw IoError(fmt::format("cannot open '{}': {}", path, std::strerror(errno)));
  std::string text;
  std::error_code size_unknown;
  std::uintmax_t size = std::filesystem::file_size(path, size_unknown);
  if (!size_unknown) text.reserve(size);
  std::array<char, 1 << 16> block;
  while (std::size_t got = std::fread(block.data(), 1, block.size(), file.get()))
    text.append(block.data(), got);
  if (std::ferror(file.get()))
    throw IoError(fmt::format("cannot read '{}': {}", path, std::strerror(errno)));
  return text;
}

}  // namespace skein
