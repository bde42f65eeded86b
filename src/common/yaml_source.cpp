#include "common/yaml_source.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cctype>
#include <map>
#include <numeric>

#include "common/error.hpp"

namespace skein {

YamlSource::YamlSource(std::string file, const std::string& text) : file_(std::move(file)) {
  for (std::size_t start = 0; start <= text.size();) {
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    std::string line = text.substr(start, end - start);
    if (!line.empty() && line.back() == '\r') line.pop_back();
    lines_.push_back(std::move(line));
    start = end + 1;
  }
}

void YamlSource::fail(const YAML::Mark& mark, const std::string& expected) const {
  std::size_t line = mark.line < 0 ? 0 : static_cast<std::size_t>(mark.line);
  throw ParseError(file_, line + 1, line < lines_.size() ? lines_[line] : "", expected);
}

void YamlSource::check_unique_keys(const YAML::Node& map) const {
  std::map<std::string, int> first_line;
  for (const auto& item : map) {
    if (!item.first.IsScalar()) continue;  // the reader refuses a key that is not text
    auto [at, fresh] = first_line.try_emplace(item.first.Scalar(), item.first.Mark().line + 1);
    if (!fresh)
      fail(item.first, fmt::format("'{}' is given twice (first on line {}); expected each key once",
                                   item.first.Scalar(), at->second));
  }
}

void YamlSource::unknown_field(const YAML::Node& key, std::string_view where,
                               const std::vector<std::string_view>& known) const {
  std::string name = key.as<std::string>();
  fail(key, fmt::format("unknown field '{}' in {}; did you mean '{}'? (known: {})", name, where,
                        nearest_name(name, known), fmt::join(known, ", ")));
}

std::string nearest_name(std::string_view word, const std::vector<std::string_view>& names) {
  auto distance = [&](std::string_view name) {
    std::vector<std::size_t> row(name.size() + 1);
    std::iota(row.begin(), row.end(), 0u);
    for (std::size_t i = 1; i <= word.size(); ++i) {
      std::size_t diagonal = row[0];
      row[0] = i;
      for (std::size_t j = 1; j <= name.size(); ++j) {
        std::size_t up = row[j];
        row[j] =
            std::min({row[j] + 1, row[j - 1] + 1,
                      diagonal + (std::tolower(word[i - 1]) == std::tolower(name[j - 1]) ? 0 : 1)});
        diagonal = up;
      }
    }
    return row.back();
  };
  return std::string(*std::min_element(names.begin(), names.end(),
                                       [&](auto a, auto b) { return distance(a) < distance(b); }));
}

}  // namespace skein
