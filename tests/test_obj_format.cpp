#include "mesh/obj_format.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>

#include "common/error.hpp"
#include "mesh/generate.hpp"

#ifndef SKEIN_SOURCE_DIR
#define SKEIN_SOURCE_DIR "."
#endif

namespace skein {
namespace {

using Kind = MismatchYarn::Kind;

std::string written(const StitchMesh& mesh) {
  std::ostringstream out;
  write_stitch_mesh(mesh, out);
  return out.str();
}

std::string corners(const StitchMesh& mesh, Face f) {
  std::string s;
  for (Halfedge h : mesh.halfedges(f)) s += std::to_string(mesh.tail(h).index() + 1) + " ";
  return s;
}

std::string roles(const StitchMesh& mesh, Face f) {
  std::string s;
  for (Halfedge h : mesh.halfedges(f)) s += role_letter(mesh.role[h]);
  return s;
}

bool same_bits(const Vec3& a, const Vec3& b) {
  return std::bit_cast<std::uint32_t>(a.x) == std::bit_cast<std::uint32_t>(b.x) &&
         std::bit_cast<std::uint32_t>(a.y) == std::bit_cast<std::uint32_t>(b.y) &&
         std::bit_cast<std::uint32_t>(a.z) == std::bit_cast<std::uint32_t>(b.z);
}

// Names the first difference between two meshes, down to the bits of the positions.
testing::AssertionResult same_mesh(const StitchMesh& a, const StitchMesh& b) {
  if (a.num_vertices() != b.num_vertices() || a.num_faces() != b.num_faces() ||
      a.num_edges() != b.num_edges())
    return testing::AssertionFailure()
           << "sizes differ: " << a.num_vertices() << "/" << a.num_faces() << "/" << a.num_edges()
           << " vs " << b.num_vertices() << "/" << b.num_faces() << "/" << b.num_edges();
  for (Vertex v : a.vertices())
    if (!same_bits(a.position[v], b.position[v]))
      return testing::AssertionFailure() << "position of vertex " << v.index() + 1;
  for (Face f : a.faces())
    if (a.stitch[f] != b.stitch[f] || corners(a, f) != corners(b, f) || roles(a, f) != roles(b, f))
      return testing::AssertionFailure()
             << "face " << f.index() + 1 << ": " << abbreviation(a.stitch[f]) << " " << roles(a, f)
             << " " << corners(a, f) << "vs " << abbreviation(b.stitch[f]) << " " << roles(b, f)
             << " " << corners(b, f);
  for (Edge e : a.edges()) {
    if (a.tail(a.halfedge(e)) != b.tail(b.halfedge(e)) ||
        a.head(a.halfedge(e)) != b.head(b.halfedge(e)))
      return testing::AssertionFailure() << "ends of edge " << e.index();
    if (a.shift_path[e] != b.shift_path[e])
      return testing::AssertionFailure() << "shift mark of " << describe(a, e);
    if (a.mismatch_yarn[e] != b.mismatch_yarn[e])
      return testing::AssertionFailure() << "yarn choice of " << describe(a, e);
  }
  return testing::AssertionSuccess();
}

// Writes, parses back, and checks the mesh and the re-written bytes are unchanged.
void expect_round_trip(const StitchMesh& mesh) {
  std::string text = written(mesh);
  StitchMesh parsed = parse_stitch_mesh(text, "round-trip.obj");
  EXPECT_TRUE(same_mesh(mesh, parsed));
  EXPECT_EQ(written(parsed), text);
}

std::uint32_t count_shift_marks(const StitchMesh& mesh) {
  std::uint32_t n = 0;
  for (Edge e : mesh.edges()) n += mesh.shift_path[e];
  return n;
}

// Passes when parsing `text` throws a ParseError on `line` whose message contains `message`.
testing::AssertionResult fails_at(std::string_view text, std::size_t line,
                                  std::string_view message) {
  try {
    parse_stitch_mesh(text, "bad.obj");
  } catch (const ParseError& e) {
    if (e.line() == line && e.expected().find(message) != std::string::npos &&
        e.file() == "bad.obj")
      return testing::AssertionSuccess();
    return testing::AssertionFailure() << "wrong error, line " << e.line() << ": " << e.what();
  }
  return testing::AssertionFailure() << "parsed without a ParseError";
}

// A tube of three stitches: a cast-on round and a bind-off round, with its seam marked.
constexpr std::string_view kTube = R"(#~skein-stitch-mesh 1
# a tube of three stitches
v 2 0 0
v -1 0 -2
v -1 0 2
v 2 1 0
v -1 1 -2
v -1 1 2
v 2 2 0
v -1 2 -2
v -1 2 2
f 1 2 5 4
#~s co boti
f 2 3 6 5
#~s co boti
f 3 1 4 6
#~s co boti
f 4 5 8 7
#~s bo boti
f 5 6 9 8
#~s bo boti
f 6 4 7 9
#~s bo boti
#~shift 4 1
#~shift 7 4
)";

// Two cast-on faces whose tops meet along 3-4: a joining edge, knit with face 1's yarn.
constexpr std::string_view kJoin = R"(#~skein-stitch-mesh 1
v 0 0 0
v 1 0 0
v 1 1 0
v 0 1 0
v 0 2 0
v 1 2 0
f 1 2 3 4
#~s co boti
f 4 3 6 5
#~s co tobi
#~yarn 3 4 own 1
)";

// The header and a quad, for error tests that append lines below it (line 7 is next).
constexpr std::string_view kQuad = R"(#~skein-stitch-mesh 1
v 0 0 0
v 1 0 0
v 1 1 0
v 0 1 0
f 1 2 3 4
)";

std::string quad_then(std::string_view lines) {
  return std::string(kQuad) + std::string(lines);
}

TEST(ObjFormat, ParsesHandWrittenTube) {
  StitchMesh mesh = parse_stitch_mesh(kTube, "tube.obj");
  ASSERT_EQ(mesh.num_vertices(), 9u);
  ASSERT_EQ(mesh.num_faces(), 6u);
  EXPECT_EQ(mesh.position[Vertex(1)], (Vec3{-1, 0, -2}));
  EXPECT_EQ(mesh.position[Vertex(8)], (Vec3{-1, 2, 2}));
  EXPECT_EQ(mesh.stitch[Face(2)], StitchType::co);
  EXPECT_EQ(mesh.stitch[Face(3)], StitchType::bo);
  EXPECT_EQ(corners(mesh, Face(2)), "3 1 4 6 ");
  EXPECT_EQ(roles(mesh, Face(5)), "boti");
  EXPECT_EQ(mesh.num_edges(), 15u);
  EXPECT_EQ(count_shift_marks(mesh), 2u);
  EXPECT_TRUE(mesh.shift_path[mesh.find_edge(Vertex(0), Vertex(3))]);
  EXPECT_TRUE(mesh.shift_path[mesh.find_edge(Vertex(3), Vertex(6))]);
  EXPECT_EQ(mesh.row[Face(0)], 0u);
  EXPECT_EQ(mesh.row[Face(5)], 1u);
  EXPECT_NO_THROW(validate(mesh));
}

TEST(ObjFormat, WritesTubeAsDocumented) {
  StitchMesh mesh = parse_stitch_mesh(kTube, "tube.obj");
  std::string expected(kTube);
  expected.erase(expected.find("# a tube"),
                 std::string_view("# a tube of three stitches\n").size());
  EXPECT_EQ(written(mesh), expected);
}

TEST(ObjFormat, ParsesYarnChoiceOnJoin) {
  StitchMesh mesh = parse_stitch_mesh(kJoin, "join.obj");
  Edge join = mesh.find_edge(Vertex(2), Vertex(3));
  ASSERT_TRUE(join.valid());
  EXPECT_EQ(mesh.kind(join), EdgeKind::join);
  EXPECT_EQ(mesh.mismatch_yarn[join], (MismatchYarn{Kind::own, Face(0)}));
  EXPECT_NO_THROW(validate(mesh));
  expect_round_trip(mesh);

  std::string extra(kJoin);
  extra.replace(extra.find("own 1"), 5, "extra");
  StitchMesh with_extra = parse_stitch_mesh(extra, "join.obj");
  EXPECT_EQ(with_extra.mismatch_yarn[join], (MismatchYarn{Kind::extra, Face()}));
}

TEST(ObjFormat, RoundTripsGeneratedSheets) {
  expect_round_trip(
      build_from_rows(ribbed_rows(7, 5, {StitchType::k, StitchType::p}), Layout::sheet));
  for (std::uint64_t seed = 1; seed <= 5; ++seed)
    expect_round_trip(build_from_rows(random_rows(12, 20, {}, seed), Layout::sheet));
}

TEST(ObjFormat, RoundTripsGeneratedTubes) {
  StitchMesh hat = build_from_rows(hat_rows(24, 6, 4), Layout::tube);
  ASSERT_GT(count_shift_marks(hat), 0u);
  expect_round_trip(hat);
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    StitchMesh tube = build_from_rows(random_rows(30, 25, {}, seed), Layout::tube);
    expect_round_trip(tube);
  }
}

TEST(ObjFormat, RoundTripsYarnChoices) {
  // The writer and parser do not validate, so any edge can carry a choice here.
  StitchMesh mesh = build_from_rows(random_rows(10, 8, {}, 3), Layout::tube);
  mesh.mismatch_yarn[Edge(5)] = {Kind::extra, Face()};
  mesh.mismatch_yarn[Edge(17)] = {Kind::own, mesh.face(mesh.halfedge(Edge(17)))};
  mesh.mismatch_yarn[Edge(30)] = {Kind::own, Face(mesh.num_faces() - 1)};
  expect_round_trip(mesh);
}

TEST(ObjFormat, RoundTripsExtremeCoordinatesBitForBit) {
  StitchMesh mesh = parse_stitch_mesh(R"(#~skein-stitch-mesh 1
v 0.1 -0 1e-45
v 3.4028235e+38 -3.4028235e+38 0.33333334
v 1.1754944e-38 123456.79 -7
v 0 1 0
f 1 2 3 4
#~s k boti
)",
                                      "extreme.obj");
  EXPECT_EQ(std::bit_cast<std::uint32_t>(mesh.position[Vertex(0)].y), 0x80000000u);  // -0
  EXPECT_EQ(mesh.position[Vertex(0)].z, std::numeric_limits<float>::denorm_min());
  EXPECT_EQ(mesh.position[Vertex(1)].x, std::numeric_limits<float>::max());
  expect_round_trip(mesh);
}

TEST(ObjFormat, AcceptsObjCornerFormsAndRelativeIndices) {
  // The back of the quad: every edge again, the other way round.
  StitchMesh mesh =
      parse_stitch_mesh(quad_then("#~s k boti\nf -1 3//3 2/2/2 1/1\n#~s k boti\n"), "forms.obj");
  ASSERT_EQ(mesh.num_faces(), 2u);
  EXPECT_EQ(corners(mesh, Face(1)), "4 3 2 1 ");
  StitchMesh relative =
      parse_stitch_mesh(quad_then("#~s k boti\nv 2 0 0\nf -4 -1 -3\n#~s sr4 bti\n"), "rel.obj");
  EXPECT_EQ(corners(relative, Face(1)), "2 5 3 ");
}

TEST(ObjFormat, IgnoresOtherObjStatementsAndAcceptsTabsAndCrlf) {
  std::string text =
      "\r\n#~skein-stitch-mesh\t1\r\n# from a modeller\r\nmtllib a.mtl\r\no swatch\r\n"
      "g front\r\ns off\r\nusemtl wool\r\nvn 0 0 1\r\nvt 0 0\r\n  v\t0 0 0\r\nv 1 0 0  \r\n"
      "v 1 1 0\r\nv 0 1 0\r\nl 1 2\r\n#comment\r\nf 1 2 3 4\r\n#~s\tk  boti";  // no final break
  StitchMesh mesh = parse_stitch_mesh(text, "crlf.obj");
  ASSERT_EQ(mesh.num_faces(), 1u);
  EXPECT_EQ(mesh.position[Vertex(1)], (Vec3{1, 0, 0}));
  EXPECT_EQ(roles(mesh, Face(0)), "boti");
}

TEST(ObjFormat, WritesShiftMarksAfterFacesAndYarnLast) {
  StitchMesh mesh = parse_stitch_mesh(kJoin, "join.obj");
  mesh.shift_path[mesh.find_edge(Vertex(1), Vertex(2))] = 1;
  std::string text = written(mesh);
  EXPECT_EQ(text.substr(text.rfind("#~s co")), "#~s co tobi\n#~shift 2 3\n#~yarn 3 4 own 1\n");
}

TEST(ObjFormat, ErrorQuotesFileLineAndText) {
  try {
    parse_stitch_mesh(quad_then("#~s kk boti\n"), "swatch.obj");
    FAIL() << "parsed an unknown stitch type";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.file(), "swatch.obj");
    EXPECT_EQ(e.line(), 7u);
    EXPECT_NE(std::string(e.what()).find("swatch.obj:7:"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("#~s kk boti"), std::string::npos) << e.what();
  }
}

TEST(ObjFormat, RejectsEmptyFile) {
  EXPECT_TRUE(fails_at("", 1, "the file is empty; expected the header '#~skein-stitch-mesh 1'"));
  EXPECT_TRUE(fails_at(" \n\t\r\n", 1, "the file is empty"));
}

TEST(ObjFormat, RejectsMissingOrWrongHeader) {
  EXPECT_TRUE(fails_at("\nv 0 0 0\n", 2,
                       "expected the header '#~skein-stitch-mesh 1' on the first non-empty line"));
  EXPECT_TRUE(fails_at("# made by hand\n#~skein-stitch-mesh 1\n", 1, "expected the header"));
  EXPECT_TRUE(fails_at("#~skein-stitch-mesh 2\n", 1,
                       "expected format version 1 after '#~skein-stitch-mesh', found '2'"));
  EXPECT_TRUE(fails_at("#~skein-stitch-mesh\n", 1, "found the end of the line"));
  EXPECT_TRUE(fails_at("#~skein-stitch-mesh 1 beta\n", 1,
                       "expected nothing after the format version, found 'beta'"));
}

TEST(ObjFormat, RejectsMalformedVertices) {
  EXPECT_TRUE(
      fails_at("#~skein-stitch-mesh 1\nv 0 x 0\n", 2, "expected 3 numbers after 'v', found 'x'"));
  EXPECT_TRUE(fails_at("#~skein-stitch-mesh 1\nv 0 0\n", 2,
                       "expected 3 numbers after 'v', found the end of the line"));
  EXPECT_TRUE(fails_at("#~skein-stitch-mesh 1\nv 0 0 0 1\n", 2,
                       "expected 3 numbers after 'v', found a 4th value '1'"));
  EXPECT_TRUE(fails_at("#~skein-stitch-mesh 1\nv 0 1e99 0\n", 2,
                       "found '1e99', which is out of range for a float"));
  EXPECT_TRUE(fails_at("#~skein-stitch-mesh 1\nv 0 0 0.5.1\n", 2, "found '0.5.1'"));
}

TEST(ObjFormat, RejectsFacesWithTooFewVertices) {
  EXPECT_TRUE(fails_at(quad_then("#~s k boti\nf 1 2\n"), 8,
                       "expected at least 3 vertices after 'f', found 2"));
  EXPECT_TRUE(fails_at(quad_then("#~s k boti\nf\n"), 8, "found 0"));
}

TEST(ObjFormat, RejectsFacesNamingMissingVertices) {
  std::string ten_vertices = "#~skein-stitch-mesh 1\n";
  for (int i = 0; i < 10; ++i) ten_vertices += "v 0 0 0\n";
  EXPECT_TRUE(fails_at(ten_vertices + "f 1 2 12\n", 12,
                       "vertex 12 does not exist (the file has 10 vertices so far)"));
  EXPECT_TRUE(fails_at(ten_vertices + "f 1 2 -11\n", 12,
                       "vertex -11 does not exist (the file has 10 vertices so far)"));
  EXPECT_TRUE(fails_at(ten_vertices + "f 0 1 2\n", 12, "vertex numbers start at 1"));
  // Vertices defined below a face do not count.
  EXPECT_TRUE(
      fails_at("#~skein-stitch-mesh 1\nv 0 0 0\nv 1 0 0\nf 1 2 3\n#~s sr4 bti\n"
               "v 1 1 0\n",
               4, "vertex 3 does not exist (the file has 2 vertices so far)"));
  EXPECT_TRUE(fails_at(quad_then("").replace(kQuad.find("f 1 2 3 4"), 9, "f 1 2 x 4"), 6,
                       "expected vertex numbers after 'f' (such as 3, -1 or 3/1/2), found 'x'"));
}

TEST(ObjFormat, RejectsFaceWithoutStitchLine) {
  EXPECT_TRUE(fails_at(quad_then("v 0 2 0\n"), 7,
                       "face on line 6 has no '#~s' line after it; expected '#~s TYPE ROLES' "
                       "directly below the 'f' line, found 'v'"));
  EXPECT_TRUE(fails_at(quad_then("\n#~s k boti\n"), 7,
                       "face on line 6 has no '#~s' line after it; expected '#~s TYPE ROLES' "
                       "directly below the 'f' line, found an empty line"));
  EXPECT_TRUE(fails_at(quad_then(""), 6,
                       "face on line 6 has no '#~s' line after it; expected '#~s TYPE ROLES', "
                       "found the end of the file"));
}

TEST(ObjFormat, RejectsStitchLineWithoutFace) {
  EXPECT_TRUE(fails_at(quad_then("#~s k boti\n#~s k boti\n"), 8,
                       "expected '#~s' only directly below an 'f' line"));
}

TEST(ObjFormat, RejectsUnknownStitchType) {
  EXPECT_TRUE(fails_at(quad_then("#~s kk boti\n"), 7,
                       "unknown stitch type 'kk'; expected one of k, p, co, bo, kfb"));
  EXPECT_TRUE(fails_at(quad_then("#~s\n"), 7,
                       "expected a stitch type and edge roles after '#~s' (such as '#~s k boti'), "
                       "found the end of the line"));
}

TEST(ObjFormat, RejectsWrongNumberOfRoles) {
  EXPECT_TRUE(fails_at(quad_then("#~s k bot\n"), 7,
                       "expected 4 edge roles (one per edge of the face on the previous line), "
                       "found 3"));
  EXPECT_TRUE(fails_at(quad_then("#~s k\n"), 7, "expected 4 edge roles"));
}

TEST(ObjFormat, RejectsUnknownRoleLetter) {
  EXPECT_TRUE(fails_at(quad_then("#~s k boxi\n"), 7,
                       "unknown edge role 'x' in 'boxi'; expected b (bottom), t (top)"));
  EXPECT_TRUE(
      fails_at(quad_then("#~s k boti p\n"), 7, "expected nothing after the edge roles, found 'p'"));
}

TEST(ObjFormat, ShiftOptionsRoundTrip) {
  StitchMesh mesh = build_from_rows(ribbed_rows(6, 3, {StitchType::k}), Layout::tube);
  ShiftOption options[] = {kShiftUpRight, kShiftUpLeft, kShiftDownRight, kShiftDownLeft};
  int i = 0;
  for (Edge e : mesh.edges())
    if (mesh.shift_path[e]) mesh.shift_path[e] = options[i++ % 4];
  std::ostringstream out;
  write_stitch_mesh(mesh, out);
  EXPECT_NE(out.str().find(" down-left\n"), std::string::npos);
  StitchMesh back = parse_stitch_mesh(out.str(), "options.obj");
  for (Edge e : mesh.edges()) EXPECT_EQ(back.shift_path[e], mesh.shift_path[e]);
}

TEST(ObjFormat, RejectsShiftMarkOffTheMesh) {
  EXPECT_TRUE(fails_at(quad_then("#~s k boti\n#~shift 1 3\n"), 8,
                       "#~shift 1 3: vertices 1 and 3 share no edge"));
  EXPECT_TRUE(fails_at(quad_then("#~s k boti\n#~shift 1 9\n"), 8,
                       "vertex 9 does not exist (the file has 4 vertices so far)"));
  EXPECT_TRUE(fails_at(quad_then("#~s k boti\n#~shift 1\n"), 8,
                       "expected two vertex numbers after '#~shift', found the end of the line"));
  EXPECT_TRUE(fails_at(quad_then("#~s k boti\n#~shift 1 -2\n"), 8, "found '-2'"));
  EXPECT_TRUE(
      fails_at(quad_then("#~s k boti\n#~shift 1 2 3\n"), 8,
               "expected a shift option (up-right, up-left, down-right or down-left) after the two "
               "vertex numbers, found '3'"));
}

TEST(ObjFormat, RejectsMalformedYarnChoices) {
  EXPECT_TRUE(
      fails_at(quad_then("#~s k boti\n#~yarn 1 2 mine\n"), 8,
               "expected 'extra' or 'own FACE' after the two vertex numbers, found 'mine'"));
  EXPECT_TRUE(fails_at(quad_then("#~s k boti\n#~yarn 1 2\n"), 8, "found the end of the line"));
  EXPECT_TRUE(fails_at(quad_then("#~s k boti\n#~yarn 1 2 own 2\n"), 8,
                       "face 2 does not exist (the file has 1 faces so far)"));
  EXPECT_TRUE(fails_at(quad_then("#~s k boti\n#~yarn 1 2 own 0\n"), 8, "face 0 does not exist"));
  EXPECT_TRUE(fails_at(quad_then("#~s k boti\n#~yarn 1 2 own\n"), 8,
                       "expected a face number after 'own', found the end of the line"));
  EXPECT_TRUE(fails_at(quad_then("#~s k boti\n#~yarn 2 4 extra\n"), 8,
                       "#~yarn 2 4: vertices 2 and 4 share no edge"));
  EXPECT_TRUE(fails_at(quad_then("#~s k boti\n#~yarn 1 2 extra\n#~yarn 2 1 own 1\n"), 9,
                       "#~yarn 2 1: the edge already has a different yarn choice"));
  EXPECT_NO_THROW(parse_stitch_mesh(quad_then("#~s k boti\n#~yarn 1 2 extra\n#~yarn 2 1 extra\n"),
                                    "repeat.obj"));
}

TEST(ObjFormat, RejectsUnknownKeywordsAndSkeinLines) {
  EXPECT_TRUE(fails_at(quad_then("#~s k boti\nvp 0.5\n"), 8,
                       "unknown keyword 'vp'; expected v, f, a comment (#)"));
  EXPECT_TRUE(fails_at(quad_then("#~s k boti\n#~stitch k\n"), 8,
                       "unknown skein line '#~stitch'; expected '#~s', '#~shift' or '#~yarn'"));
  EXPECT_TRUE(fails_at(quad_then("#~s k boti\n#~skein-stitch-mesh 1\n"), 8,
                       "unknown skein line '#~skein-stitch-mesh'"));
}

TEST(ObjFormat, LetsMeshErrorsFromBuildThrough) {
  // Both faces run 2 -> 3: one of them is listed clockwise.
  EXPECT_THROW(
      parse_stitch_mesh(quad_then("#~s k boti\nv 2 0 0\nf 2 3 5\n#~s sr4 bti\n"), "flipped.obj"),
      MeshError);
}

TEST(ObjFormat, ReadsFixtureFile) {
  StitchMesh mesh = read_stitch_mesh(SKEIN_SOURCE_DIR "/tests/data/obj/join.obj");
  EXPECT_TRUE(same_mesh(mesh, parse_stitch_mesh(kJoin, "join.obj")));
}

TEST(ObjFormat, ReadingMissingFileThrowsIoError) {
  std::string path = (std::filesystem::path(testing::TempDir()) / "no-such-mesh.obj").string();
  try {
    read_stitch_mesh(path);
    FAIL() << "read a missing file";
  } catch (const IoError& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
  }
  EXPECT_THROW(read_stitch_mesh(testing::TempDir()), IoError);  // a directory
}

}  // namespace
}  // namespace skein
