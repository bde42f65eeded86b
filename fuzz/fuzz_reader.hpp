// What every fuzz target shares: a reader may refuse its input with a typed error (the message
// a user sees) and nothing else; any other exception, crash, sanitizer report or hang is a
// finding for libFuzzer.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "common/error.hpp"

namespace skein::fuzz {

template <class Read>
int run_reader(const std::uint8_t* data, std::size_t size, Read read) {
  std::string text(reinterpret_cast<const char*>(data), size);
  try {
    read(text);
  } catch (const skein::Error&) {
    // Refused with a message naming the file and line: what the reader should do.
  }
  return 0;
}

}  // namespace skein::fuzz
