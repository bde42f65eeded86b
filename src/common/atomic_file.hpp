#pragma once

#include <functional>
#include <iosfwd>
#include <string>

namespace skein {

// Writes `path` through a temporary file beside it that is renamed into place only when
// `write` returns normally: an error never leaves a partial output file. Throws IoError, also
// when `path` is something else than a regular file (a link, folder, device or FIFO): the
// rename would replace it. OutputFile (output_file.hpp) decides what a command may replace.
void write_file_atomically(const std::string& path,
                           const std::function<void(std::ostream&)>& write);

// The whole file as a string; throws IoError naming the file when it cannot be read or is not
// a regular file (a directory, FIFO or device).
std::string read_file(const std::string& path);

}  // namespace skein
