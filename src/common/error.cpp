#include "common/error.hpp"

#include <fmt/format.h>

namespace skein {

ParseError::ParseError(std::string file, std::size_t line, std::string quoted, std::string expected)
    : Error(fmt::format("{}:{}: {}\n  {:>5} | {}", file, line, expected, line, quoted)),
      file_(std::move(file)),
      line_(line),
      expected_(std::move(expected)) {}

void assertion_failed(const char* condition, const char* file, int line,
                      const std::string& message) {
  throw InternalError(fmt::format("internal error at {}:{}: {} ({}); please report this", file,
                                  line, message, condition));
}

}  // namespace skein
