#include "hand_web/page_writer.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <sstream>

namespace skein::hand_web {
namespace {

constexpr char kBase64[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
constexpr const char* kPatternTag =
    "<script type=\"application/octet-stream\" id=\"skein-pattern\">";

std::string base64(const void* data, std::size_t size) {
  const auto* b = static_cast<const unsigned char*>(data);
  std::string out;
  out.reserve((size + 2) / 3 * 4);
  for (std::size_t i = 0; i < size; i += 3) {
    std::uint32_t n = b[i] << 16;
    if (i + 1 < size) n |= b[i + 1] << 8;
    if (i + 2 < size) n |= b[i + 2];
    out += kBase64[(n >> 18) & 63];
    out += kBase64[(n >> 12) & 63];
    out += i + 1 < size ? kBase64[(n >> 6) & 63] : '=';
    out += i + 2 < size ? kBase64[n & 63] : '=';
  }
  return out;
}

std::optional<std::string> from_base64(std::string_view text) {
  std::string out;
  std::uint32_t bits = 0;
  int have = 0;
  for (char ch : text) {
    if (ch == '=') break;
    const char* at = std::strchr(kBase64, ch);
    if (!at || ch == '\0') return std::nullopt;
    bits = (bits << 6) | static_cast<std::uint32_t>(at - kBase64);
    have += 6;
    if (have >= 8) {
      have -= 8;
      out += static_cast<char>((bits >> have) & 0xff);
    }
  }
  return out;
}

// A JSON string safe inside a <script> element: `<` written \u003c, so no text ends it.
std::string json_string(std::string_view s) {
  std::string out = "\"";
  for (unsigned char ch : s) {
    switch (ch) {
      case '"':
        out += "\\\"";
        break;
      case '\\':
        out += "\\\\";
        break;
      case '\n':
        out += "\\n";
        break;
      case '<':
        out += "\\u003c";
        break;
      default:
        if (ch < 0x20)
          out += fmt::format("\\u{:04x}", ch);
        else
          out += static_cast<char>(ch);
    }
  }
  return out + "\"";
}

template <class F>
std::string json_array(const std::vector<PageStitch>& order, F field) {
  std::string out = "[";
  for (std::size_t i = 0; i < order.size(); ++i) {
    std::int64_t v = field(order[i]);
    out += fmt::format("{}{}", i ? "," : "", v);
  }
  return out + "]";
}

std::int64_t or_minus_one(std::uint32_t v) {
  return v == kNone ? -1 : static_cast<std::int64_t>(v);
}

std::string chart_json(const PageChart& c) {
  std::string out = "{\"cells\":[";
  for (std::size_t r = 0; r < c.cells.size(); ++r)
    out += fmt::format("{}\"{}\"", r ? "," : "", c.cells[r]);
  return out + fmt::format("],\"num\":[{}],\"left\":[{}]}}", fmt::join(c.number, ","),
                           fmt::join(c.leftward, ","));
}

std::string page_json(const PageData& d) {
  std::string out =
      fmt::format("{{\"title\":{},\"source\":{},\"proof\":{},\"note\":{},\"key\":{},\"rows\":[",
                  json_string(d.title), json_string(d.source), json_string(d.proof),
                  json_string(d.note), json_string(d.key));
  for (std::size_t r = 0; r < d.rows.size(); ++r) {
    const PageRow& row = d.rows[r];
    out += fmt::format(
        "{}{{\"h\":{},\"l\":{},\"t\":{},\"s\":{},\"n\":{},\"p\":{},\"c\":{},\"cr\":{}}}",
        r ? "," : "", json_string(row.heading), json_string(row.label), json_string(row.text),
        json_string(row.said_by), row.stitches, row.piece, or_minus_one(row.chart), row.chart_row);
  }
  out += "],\"charts\":[";
  for (std::size_t k = 0; k < d.charts.size(); ++k) {
    if (k) out += ',';
    out += chart_json(d.charts[k]);
  }
  const auto& o = d.order;
  out += "],\"order\":{";
  out += "\"stitch\":" + json_array(o, [](const PageStitch& s) { return s.stitch; });
  out += ",\"step\":" + json_array(o, [](const PageStitch& s) { return or_minus_one(s.step); });
  out += ",\"row\":" + json_array(o, [](const PageStitch& s) { return s.row; });
  out += ",\"pos\":" + json_array(o, [](const PageStitch& s) { return s.position; });
  out += ",\"b\":" + json_array(o, [](const PageStitch& s) { return or_minus_one(s.begin); });
  out += ",\"e\":" + json_array(o, [](const PageStitch& s) { return or_minus_one(s.end); });
  out += ",\"rep\":" + json_array(o, [](const PageStitch& s) { return s.repeat; });
  out += ",\"reps\":" + json_array(o, [](const PageStitch& s) { return s.repeats; });
  out += ",\"mark\":" + json_array(o, [](const PageStitch& s) { return s.marker ? 1 : 0; });
  out += fmt::format("}},\"stitches\":{}}}", d.yarn_piece.size());
  return out;
}

std::string html_text(std::string_view s) {
  std::string out;
  for (char ch : s) out += ch == '<' ? "&lt;" : ch == '&' ? "&amp;" : std::string(1, ch);
  return out;
}

std::optional<std::string> read_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

void data_script(std::ostream& out, const char* id, const std::string& base64_text) {
  out << "<script type=\"application/octet-stream\" id=\"" << id << "\">" << base64_text
      << "</script>\n";
}

}  // namespace

std::optional<ThreeJs> find_three_js() {
  const char* given = std::getenv("SKEIN_THREE_DIR");
  std::filesystem::path dir = given && *given ? given : kThreeDir;
  auto library = read_text(dir / "three.min.js");
  auto controls = read_text(dir / "examples/js/controls/OrbitControls.js");
  if (!library || !controls) return std::nullopt;
  // Pasted verbatim into a <script>: neither may end it early.
  if (library->find("</script") != std::string::npos ||
      controls->find("</script") != std::string::npos)
    return std::nullopt;
  return ThreeJs{std::move(*library), std::move(*controls), dir.string()};
}

void write_page(const PageData& d, const ThreeJs* three, std::ostream& out) {
  out << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n"
      << "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
      << "<meta name=\"generator\" content=\"skein compile --target hand-web\">\n"
      << "<title>" << html_text(d.title) << " \u2014 knitting</title>\n<style>" << kPageStyle
      << "</style></head>\n<body>\n"
      << "<script type=\"application/json\" id=\"skein-data\">" << page_json(d) << "</script>\n"
      << kPatternTag << base64(d.pattern.data(), d.pattern.size()) << "</script>\n";
  data_script(out, "skein-cells", base64(d.cells.data(), d.cells.size() * sizeof d.cells[0]));
  data_script(out, "skein-yarn", base64(d.yarn.data(), d.yarn.size() * sizeof d.yarn[0]));
  data_script(out, "skein-yarn-piece",
              base64(d.yarn_piece.data(), d.yarn_piece.size() * sizeof d.yarn_piece[0]));
  if (three) {
    out << "<!-- three.js r111 from Debian's libjs-three (" << three->from
        << "), MIT licence, verbatim -->\n<script>" << three->library << "</script>\n<script>"
        << three->orbit_controls << "</script>\n";
  }
  out << "<script>" << kPageScript << "</script>\n</body></html>\n";
}

std::optional<std::string> embedded_pattern(std::string_view html) {
  std::size_t at = html.find(kPatternTag);
  if (at == std::string_view::npos) return std::nullopt;
  at += std::strlen(kPatternTag);
  std::size_t end = html.find("</script>", at);
  if (end == std::string_view::npos) return std::nullopt;
  return from_base64(html.substr(at, end - at));
}

}  // namespace skein::hand_web
