// A YAML file's text kept line by line, so that a problem at any node becomes a ParseError
// quoting the file's line: the strict readers of project files and machine profiles share it.
#pragma once

#include <yaml-cpp/yaml.h>

#include <string>
#include <string_view>
#include <vector>

namespace skein {

class YamlSource {
 public:
  YamlSource(std::string file, const std::string& text);

  [[noreturn]] void fail(const YAML::Mark& mark, const std::string& expected) const;
  [[noreturn]] void fail(const YAML::Node& node, const std::string& expected) const {
    fail(node.Mark(), expected);
  }
  // "unknown field 'KEY' in WHERE; did you mean 'NEAREST'? (known: A, B, ...)"
  // YAML keeps the last of two equal keys and says nothing: the first would be ignored.
  // Fails on the second, naming the line of the first. `map` must be a map.
  void check_unique_keys(const YAML::Node& map) const;
  [[noreturn]] void unknown_field(const YAML::Node& key, std::string_view where,
                                  const std::vector<std::string_view>& known) const;

 private:
  std::string file_;
  std::vector<std::string> lines_;
};

// The name in `names` (not empty) closest to `word` by edit distance, ignoring case.
std::string nearest_name(std::string_view word, const std::vector<std::string_view>& names);

}  // namespace skein
