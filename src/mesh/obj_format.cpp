#include "mesh/obj_format.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <ostream>
#include <vector>

#include "common/atomic_file.hpp"
#include "common/error.hpp"

namespace skein {
namespace {

constexpr std::string_view kHeaderKeyword = "#~skein-stitch-mesh";
constexpr std::string_view kVersion = "1";
constexpr std::string_view kHeaderLine = "#~skein-stitch-mesh 1";
// OBJ statements that say nothing about a stitch mesh.
constexpr std::string_view kIgnoredKeywords[] = {"vn", "vt",     "o",      "g",
                                                 "s",  "usemtl", "mtllib", "l"};

bool is_blank(char c) {
  return c == ' ' || c == '\t';
}

// A word for an error message: quoted, or "the end of the line" when there is none.
std::string quote(std::string_view word) {
  return word.empty() ? std::string("the end of the line") : fmt::format("'{}'", word);
}

// Parses all of `word` as a number; a trailing character or an empty word is a failure.
template <class T>
std::errc parse_number(std::string_view word, T& value) {
  const char* end = word.data() + word.size();
  auto [stop, error] = std::from_chars(word.data(), end, value);
  if (error == std::errc{} && stop != end) return std::errc::invalid_argument;
  return error;
}

std::string stitch_type_list() {
  std::string list;
  for (const StitchTypeInfo& entry : stitch_catalogue())
    list += fmt::format("{}{}", list.empty() ? "" : ", ", entry.abbreviation);
  return list;
}

// One line of the file (without its line break), read word by word.
class Line {
 public:
  Line(std::string_view text, std::size_t number) : text_(text), rest_(text), number_(number) {}
  std::string_view text() const { return text_; }
  std::size_t number() const { return number_; }

  // The next word separated by spaces or tabs, or an empty view at the end of the line.
  std::string_view next_word() {
    std::size_t begin = 0;
    while (begin < rest_.size() && is_blank(rest_[begin])) ++begin;
    std::size_t end = begin;
    while (end < rest_.size() && !is_blank(rest_[end])) ++end;
    std::string_view word = rest_.substr(begin, end - begin);
    rest_.remove_prefix(end);
    return word;
  }

 private:
  std::string_view text_;
  std::string_view rest_;
  std::size_t number_;
};

// A '#~shift' or '#~yarn' line, kept until the mesh is built and its edges exist.
struct EdgeMark {
  Line line;
  Vertex a, b;
  std::optional<MismatchYarn> yarn;   // empty on a '#~shift' line
  ShiftOption shift = kShiftUpRight;  // on a '#~shift' line
  std::string_view directive() const { return yarn ? "#~yarn" : "#~shift"; }
};

class Parser {
 public:
  Parser(std::string_view text, const std::string& file_name)
      : text_(text), file_name_(file_name), builder_(file_name) {}
  StitchMesh parse() &&;

 private:
  [[noreturn]] void fail(const Line& line, std::string expected) const {
    throw ParseError(file_name_, line.number(), std::string(line.text()), std::move(expected));
  }
  void reserve_capacity();
  void parse_line(Line& line);
  void parse_header(Line& line, std::string_view keyword);
  void parse_statement(Line& line, std::string_view keyword);
  void parse_vertex(Line& line);
  float parse_coordinate(Line& line);
  void parse_face(Line& line);
  Vertex resolve_face_vertex(const Line& line, std::string_view word) const;
  void parse_stitch(Line& line);
  void parse_directive(Line& line, std::string_view keyword);
  void parse_edge_mark(Line& line, std::string_view directive);
  Vertex parse_vertex_number(Line& line, std::string_view directive) const;
  MismatchYarn parse_yarn_choice(Line& line) const;
  ShiftOption parse_shift_option(Line& line) const;
  void expect_end(Line& line, std::string_view after) const;
  void apply_edge_marks(StitchMesh& mesh) const;

  std::string_view text_;
  const std::string& file_name_;
  StitchMeshBuilder builder_;
  bool seen_header_ = false;
  std::optional<Line> pending_face_;  // the 'f' line still waiting for its '#~s' line
  std::vector<Vertex> face_vertices_;
  std::vector<EdgeRole> face_roles_;
  std::vector<EdgeMark> edge_marks_;
};

StitchMesh Parser::parse() && {
  reserve_capacity();
  std::size_t number = 0;
  for (std::size_t begin = 0; begin < text_.size();) {
    std::size_t end = std::min(text_.find('\n', begin), text_.size());
    std::string_view text = text_.substr(begin, end - begin);
    if (text.ends_with('\r')) text.remove_suffix(1);
    begin = end + 1;
    Line line(text, ++number);
    parse_line(line);
  }
  if (!seen_header_)
    fail(Line("", 1), fmt::format("the file is empty; expected the header '{}'", kHeaderLine));
  if (pending_face_)
    fail(*pending_face_, fmt::format("face on line {} has no '#~s' line after it; expected "
                                     "'#~s TYPE ROLES', found the end of the file",
                                     pending_face_->number()));
  StitchMesh mesh = std::move(builder_).build();
  apply_edge_marks(mesh);
  return mesh;
}

// Counts 'v' and 'f' lines so that the builder allocates once.
void Parser::reserve_capacity() {
  std::size_t vertices = 0, faces = 0;
  for (std::size_t begin = 0; begin + 1 < text_.size();) {
    if (is_blank(text_[begin + 1])) {
      vertices += text_[begin] == 'v';
      faces += text_[begin] == 'f';
    }
    begin = text_.find('\n', begin);
    if (begin == std::string_view::npos) break;
    ++begin;
  }
  constexpr std::size_t kCornersPerFace = 4;  // most stitches are quads; only a hint
  builder_.reserve(vertices, faces, faces * kCornersPerFace);
}

void Parser::parse_line(Line& line) {
  std::string_view keyword = line.next_word();
  if (!seen_header_) {
    if (!keyword.empty()) parse_header(line, keyword);
    return;
  }
  if (pending_face_ && keyword != "#~s")
    fail(line,
         fmt::format("face on line {} has no '#~s' line after it; expected '#~s TYPE "
                     "ROLES' directly below the 'f' line, found {}",
                     pending_face_->number(), keyword.empty() ? "an empty line" : quote(keyword)));
  parse_statement(line, keyword);
}

void Parser::parse_header(Line& line, std::string_view keyword) {
  if (keyword != kHeaderKeyword)
    fail(line, fmt::format("expected the header '{}' on the first non-empty line", kHeaderLine));
  std::string_view version = line.next_word();
  if (version != kVersion)
    fail(line, fmt::format("expected format version {} after '{}', found {}", kVersion,
                           kHeaderKeyword, quote(version)));
  expect_end(line, "the format version");
  seen_header_ = true;
}

void Parser::parse_statement(Line& line, std::string_view keyword) {
  if (keyword.empty()) return;
  if (keyword == "v") return parse_vertex(line);
  if (keyword == "f") return parse_face(line);
  if (keyword.starts_with("#~")) return parse_directive(line, keyword);
  if (keyword.starts_with('#')) return;
  for (std::string_view ignored : kIgnoredKeywords)
    if (keyword == ignored) return;
  fail(line, fmt::format("unknown keyword '{}'; expected v, f, a comment (#), a skein line (#~) "
                         "or an ignored OBJ keyword (vn, vt, o, g, s, usemtl, mtllib, l)",
                         keyword));
}

void Parser::parse_vertex(Line& line) {
  Vec3 p;
  p.x = parse_coordinate(line);
  p.y = parse_coordinate(line);
  p.z = parse_coordinate(line);
  std::string_view extra = line.next_word();
  if (!extra.empty())
    fail(line, fmt::format("expected 3 numbers after 'v', found a 4th value '{}' (neither OBJ's "
                           "optional w nor vertex colours are supported)",
                           extra));
  builder_.add_vertex(p);
}

float Parser::parse_coordinate(Line& line) {
  std::string_view word = line.next_word();
  float value = 0;
  std::errc error = parse_number(word, value);
  if (error == std::errc::result_out_of_range)
    fail(line, fmt::format("expected 3 numbers after 'v', found '{}', which is out of range for "
                           "a float",
                           word));
  if (error != std::errc{})
    fail(line, fmt::format("expected 3 numbers after 'v', found {}", quote(word)));
  return value;
}

void Parser::parse_face(Line& line) {
  face_vertices_.clear();
  for (std::string_view word = line.next_word(); !word.empty(); word = line.next_word())
    face_vertices_.push_back(resolve_face_vertex(line, word));
  if (face_vertices_.size() < 3)
    fail(line,
         fmt::format("expected at least 3 vertices after 'f', found {}", face_vertices_.size()));
  pending_face_ = line;
}

// OBJ corners are 'v', 'v/vt', 'v/vt/vn' or 'v//vn'; only v matters. A negative v counts back
// from the last vertex so far (-1 is the last).
Vertex Parser::resolve_face_vertex(const Line& line, std::string_view word) const {
  std::int64_t number = 0;
  if (parse_number(word.substr(0, word.find('/')), number) != std::errc{})
    fail(line, fmt::format("expected vertex numbers after 'f' (such as 3, -1 or 3/1/2), found "
                           "'{}'",
                           word));
  const std::int64_t count = builder_.num_vertices();
  const std::int64_t index = number < 0 ? count + number : number - 1;
  if (number == 0 || index < 0 || index >= count)
    fail(line, fmt::format("vertex {} does not exist (the file has {} vertices so far){}", number,
                           count, number == 0 ? "; vertex numbers start at 1" : ""));
  return Vertex(static_cast<std::uint32_t>(index));
}

void Parser::parse_stitch(Line& line) {
  if (!pending_face_)
    fail(line, "expected '#~s' only directly below an 'f' line; the line above is not a face");
  std::string_view type_word = line.next_word();
  if (type_word.empty())
    fail(line,
         "expected a stitch type and edge roles after '#~s' (such as '#~s k boti'), found "
         "the end of the line");
  std::optional<StitchType> type = stitch_type_from_abbreviation(type_word);
  if (!type)
    fail(line, fmt::format("unknown stitch type '{}'; expected one of {}", type_word,
                           stitch_type_list()));
  std::string_view roles = line.next_word();
  if (roles.size() != face_vertices_.size())
    fail(line, fmt::format("expected {} edge roles (one per edge of the face on the previous "
                           "line), found {}",
                           face_vertices_.size(), roles.size()));
  face_roles_.clear();
  for (char letter : roles) {
    std::optional<EdgeRole> role = role_from_letter(letter);
    if (!role)
      fail(line, fmt::format("unknown edge role '{}' in '{}'; expected b (bottom), t (top), "
                             "i (yarn enters) or o (yarn leaves)",
                             letter, roles));
    face_roles_.push_back(*role);
  }
  expect_end(line, "the edge roles");
  builder_.add_face(face_vertices_, face_roles_, *type);
  pending_face_.reset();
}

void Parser::parse_directive(Line& line, std::string_view keyword) {
  if (keyword == "#~s") return parse_stitch(line);
  if (keyword == "#~shift" || keyword == "#~yarn") return parse_edge_mark(line, keyword);
  fail(line,
       fmt::format("unknown skein line '{}'; expected '#~s', '#~shift' or '#~yarn'", keyword));
}

void Parser::parse_edge_mark(Line& line, std::string_view directive) {
  Vertex a = parse_vertex_number(line, directive);
  Vertex b = parse_vertex_number(line, directive);
  EdgeMark mark{line, a, b, std::nullopt};
  if (directive == "#~yarn")
    mark.yarn = parse_yarn_choice(line);
  else
    mark.shift = parse_shift_option(line);
  expect_end(line, mark.yarn ? "the yarn choice" : "the shift option");
  edge_marks_.push_back(mark);
}

// An optional word after a '#~shift' edge: one of Fig. 3's four shift operations.
ShiftOption Parser::parse_shift_option(Line& line) const {
  std::string_view word = line.next_word();
  if (word.empty()) return kShiftUpRight;
  for (ShiftOption option : {kShiftUpRight, kShiftUpLeft, kShiftDownRight, kShiftDownLeft})
    if (word == shift_option_name(option)) return option;
  fail(line, fmt::format("expected a shift option (up-right, up-left, down-right or down-left) "
                         "after the two vertex numbers, found '{}'",
                         word));
}

// Vertex numbers on '#~' lines are 1-based and name vertices defined above the line.
Vertex Parser::parse_vertex_number(Line& line, std::string_view directive) const {
  std::string_view word = line.next_word();
  std::uint32_t number = 0;
  if (parse_number(word, number) != std::errc{})
    fail(line,
         fmt::format("expected two vertex numbers after '{}', found {}", directive, quote(word)));
  if (number == 0 || number > builder_.num_vertices())
    fail(line, fmt::format("vertex {} does not exist (the file has {} vertices so far)", number,
                           builder_.num_vertices()));
  return Vertex(number - 1);
}

MismatchYarn Parser::parse_yarn_choice(Line& line) const {
  std::string_view how = line.next_word();
  if (how == "extra") return {MismatchYarn::Kind::extra, Face()};
  if (how != "own")
    fail(line, fmt::format("expected 'extra' or 'own FACE' after the two vertex numbers, found {}",
                           quote(how)));
  std::string_view word = line.next_word();
  std::uint32_t number = 0;
  if (parse_number(word, number) != std::errc{})
    fail(line, fmt::format("expected a face number after 'own', found {}", quote(word)));
  if (number == 0 || number > builder_.num_faces())
    fail(line, fmt::format("face {} does not exist (the file has {} faces so far)", number,
                           builder_.num_faces()));
  return {MismatchYarn::Kind::own, Face(number - 1)};
}

void Parser::expect_end(Line& line, std::string_view after) const {
  std::string_view extra = line.next_word();
  if (!extra.empty())
    fail(line, fmt::format("expected nothing after {}, found '{}'", after, extra));
}

// Edges exist only once the builder has linked the faces, so marks are resolved last.
void Parser::apply_edge_marks(StitchMesh& mesh) const {
  for (const EdgeMark& mark : edge_marks_) {
    std::string what =
        fmt::format("{} {} {}", mark.directive(), mark.a.index() + 1, mark.b.index() + 1);
    Edge e = mesh.find_edge(mark.a, mark.b);
    if (!e.valid())
      fail(mark.line, fmt::format("{}: vertices {} and {} share no edge; expected the two ends "
                                  "of an edge of some face",
                                  what, mark.a.index() + 1, mark.b.index() + 1));
    if (!mark.yarn) {
      mesh.shift_path[e] = mark.shift;
      continue;
    }
    MismatchYarn& yarn = mesh.mismatch_yarn[e];
    if (yarn.kind != MismatchYarn::Kind::by_default && yarn != *mark.yarn)
      fail(mark.line, fmt::format("{}: the edge already has a different yarn choice from an "
                                  "earlier '#~yarn' line; expected one choice per edge",
                                  what));
    yarn = *mark.yarn;
  }
}

// Formats into one large buffer with std::to_chars and hands it to the stream in big blocks.
class BufferedWriter {
 public:
  explicit BufferedWriter(std::ostream& out) : out_(out) { buffer_.reserve(kBlockSize + 1024); }
  void text(std::string_view s) { buffer_.append(s); }
  void text(char c) { buffer_.push_back(c); }
  template <class T>
  void number(T value) {
    char digits[32];
    auto [end, error] = std::to_chars(digits, digits + sizeof digits, value);
    SKEIN_ASSERT(error == std::errc{}, "a number always fits in 32 characters");
    buffer_.append(digits, end);
  }
  void end_line() {
    buffer_.push_back('\n');
    if (buffer_.size() >= kBlockSize) flush();
  }
  void flush() {
    out_.write(buffer_.data(), static_cast<std::streamsize>(buffer_.size()));
    buffer_.clear();
  }

 private:
  static constexpr std::size_t kBlockSize = std::size_t{1} << 20;
  std::ostream& out_;
  std::string buffer_;
};

void write_vertices(const StitchMesh& mesh, BufferedWriter& w) {
  for (Vertex v : mesh.vertices()) {
    const Vec3& p = mesh.position[v];
    w.text("v ");
    w.number(p.x);
    w.text(' ');
    w.number(p.y);
    w.text(' ');
    w.number(p.z);
    w.end_line();
  }
}

void write_faces(const StitchMesh& mesh, BufferedWriter& w) {
  for (Face f : mesh.faces()) {
    w.text('f');
    for (Halfedge h : mesh.halfedges(f)) {
      w.text(' ');
      w.number(mesh.tail(h).index() + 1);
    }
    w.end_line();
    w.text("#~s ");
    w.text(abbreviation(mesh.stitch[f]));
    w.text(' ');
    for (Halfedge h : mesh.halfedges(f)) w.text(role_letter(mesh.role[h]));
    w.end_line();
  }
}

void write_edge_ends(const StitchMesh& mesh, Edge e, BufferedWriter& w) {
  Halfedge h = mesh.halfedge(e);
  w.text(' ');
  w.number(mesh.tail(h).index() + 1);
  w.text(' ');
  w.number(mesh.head(h).index() + 1);
}

void write_shift_marks(const StitchMesh& mesh, BufferedWriter& w) {
  for (Edge e : mesh.edges()) {
    if (!mesh.shift_path[e]) continue;
    w.text("#~shift");
    write_edge_ends(mesh, e, w);
    if (mesh.shift_path[e] != kShiftUpRight) {
      w.text(" ");
      w.text(shift_option_name(static_cast<ShiftOption>(mesh.shift_path[e])));
    }
    w.end_line();
  }
}

void write_yarn_choices(const StitchMesh& mesh, BufferedWriter& w) {
  for (Edge e : mesh.edges()) {
    const MismatchYarn& yarn = mesh.mismatch_yarn[e];
    if (yarn.kind == MismatchYarn::Kind::by_default) continue;
    w.text("#~yarn");
    write_edge_ends(mesh, e, w);
    if (yarn.kind == MismatchYarn::Kind::extra) {
      w.text(" extra");
    } else {
      SKEIN_ASSERT(yarn.side.valid() && yarn.side.index() < mesh.num_faces(),
                   "an 'own' yarn choice names one of the mesh's faces");
      w.text(" own ");
      w.number(yarn.side.index() + 1);
    }
    w.end_line();
  }
}

}  // namespace

StitchMesh parse_stitch_mesh(std::string_view text, const std::string& file_name) {
  return Parser(text, file_name).parse();
}

StitchMesh read_stitch_mesh(const std::string& path) {
  return parse_stitch_mesh(read_file(path), path);
}

void write_stitch_mesh(const StitchMesh& mesh, std::ostream& out) {
  BufferedWriter w(out);
  w.text(kHeaderLine);
  w.end_line();
  write_vertices(mesh, w);
  write_faces(mesh, w);
  write_shift_marks(mesh, w);
  write_yarn_choices(mesh, w);
  w.flush();
}

}  // namespace skein
