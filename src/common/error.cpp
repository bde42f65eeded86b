#include "common/error.hpp"

#include <fmt/format.h>
#include <yaml-cpp/exceptions.h>

#include <exception>
#include <filesystem>
#include <new>

namespace skein {

ParseError::ParseError(std::string file, std::size_t line, std::string quoted, std::string expected)
    : Error(fmt::format("{}:{}: {}\n  {:>5} | {}", file, line, expected, line, quoted)),
      file_(std::move(file)),
      line_(line),
      expected_(std::move(expected)) {}

Failure describe_current_exception(const std::string& doing) {
  try {
    throw;
  } catch (const UnsupportedError& e) {
    return {kUnsupported, fmt::format("unsupported: {}", e.what())};
  } catch (const Error& e) {
    return {kBadInput, fmt::format("error: {}", e.what())};
  } catch (const std::filesystem::filesystem_error& e) {
    return {kBadInput,
            fmt::format("error while {}: {}: {}", doing, e.path1().string(), e.code().message())};
  } catch (const YAML::Exception& e) {
    return {kBadInput, fmt::format("error while {}: {}", doing, e.what())};
  } catch (const std::bad_alloc&) {
    return {kInternal, fmt::format("out of memory while {}", doing)};
  } catch (const InternalError& e) {
    return {kInternal, fmt::format("{} (while {})", e.what(), doing)};
  } catch (const std::exception& e) {
    return {kInternal,
            fmt::format("internal error while {}: {}; please report this", doing, e.what())};
  } catch (...) {
    return {kInternal, fmt::format("internal error while {}; please report this", doing)};
  }
}

void assertion_failed(const char* condition, const char* file, int line,
                      const std::string& message) {
  throw InternalError(fmt::format("internal error at {}:{}: {} ({}); please report this", file,
                                  line, message, condition));
}

}  // namespace skein
