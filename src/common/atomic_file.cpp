#include "common/atomic_file.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "common/error.hpp"

namespace skein {

void write_file_atomically(const std::string& path,
                           const std::function<void(std::ostream&)>& write) {
  std::string temp = fmt::format("{}.tmp{}", path, ::getpid());
  try {
    {
      std::ofstream out(temp, std::ios::binary);
      if (!out) throw IoError(fmt::format("cannot write {}: {}", path, std::strerror(errno)));
      write(out);
      out.flush();
      if (!out) throw IoError(fmt::format("cannot write {}: {}", path, std::strerror(errno)));
    }
    std::filesystem::rename(temp, path);
  } catch (...) {
    std::error_code ignored;
    std::filesystem::remove(temp, ignored);
    throw;
  }
}

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw IoError(fmt::format("cannot read {}: {}", path, std::strerror(errno)));
  in.seekg(0, std::ios::end);
  std::string text(static_cast<std::size_t>(in.tellg()), '\0');
  in.seekg(0);
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  if (!in) throw IoError(fmt::format("cannot read {}: read error", path));
  return text;
}

}  // namespace skein
