// What `-o` may replace: never an input, a folder, device or FIFO; an existing file or a symbolic
// link's target only with --force; `-o -` is standard output. Every writer: compile, render,
// generate, new.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>

#include "cli_runner.hpp"

namespace skein {
namespace {

namespace fs = std::filesystem;
using testing::CliRun;

class CliOutputs : public testing::SkeinCliTest {
 protected:
  // A copy of samples/NAME/FILE in the test's folder; its path.
  std::string copy_sample(const std::string& name, const std::string& file) {
    fs::copy_file(fs::path("samples") / name / file, dir_ / file);
    return in_dir(file);
  }
  void write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name) << text;
  }
  void expect_refused(const CliRun& r, const std::string& message) {
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_EQ(r.err, "skein: error: " + message + "\n");
    EXPECT_EQ(r.out, "");
  }
};

TEST_F(CliOutputs, NoWriterReplacesItsInputEvenWithForce) {
  std::string hat = copy_sample("hat", "hat.obj");
  std::string text = read("hat.obj");
  for (const char* force : {"", " --force"}) {
    expect_refused(skein("compile " + hat + " -t hand -o " + hat + force),
                   "cannot write " + hat + ": it is an input of this command");
    expect_refused(skein("render " + hat + " -o " + hat + force),
                   "cannot write " + hat + ": it is an input of this command");
  }
  std::string project = copy_sample("sock", "sock.yaml"), mesh = copy_sample("sock", "sock.obj");
  expect_refused(skein("compile " + project + " -t knitout -m generic -o " + project),
                 "cannot write " + project + ": it is an input of this command");
  // The project's coarse mesh is an input too, however the path is spelled.
  std::string spelled = in_dir("./sock.obj");
  expect_refused(skein("generate " + project + " -o " + spelled + " --force"),
                 "cannot write " + spelled + ": it is an input of this command (" + mesh + ")");
  expect_refused(skein("render " + project + " --coarse -o " + mesh + " --force"),
                 "cannot write " + mesh + ": it is an input of this command");
  EXPECT_EQ(read("hat.obj"), text);
}

// verify's --picture and --fabric follow the same rules as -o, checked before the replay.
TEST_F(CliOutputs, VerifyDrawsOrWritesTheFabricOnlyWhereAnOutputMay) {
  std::string k = copy_sample("hat", "hat.generic.k");
  expect_refused(skein("verify " + k + " --fabric " + k + " --force"),
                 "cannot write " + k + ": it is an input of this command");
  write("f.st", "mine\n");
  expect_refused(skein("verify " + k + " --fabric " + in_dir("f.st")),
                 in_dir("f.st") + " already exists; pass --force to replace it");
  EXPECT_EQ(read("f.st"), "mine\n");
  CliRun forced = skein("verify " + k + " --fabric " + in_dir("f.st") + " --force");
  EXPECT_NE(read("f.st"), "mine\n") << forced.err;
  write("f.svg", "mine\n");
  expect_refused(skein("verify " + k + " --picture " + in_dir("f.svg")),
                 in_dir("f.svg") + " already exists; pass --force to replace it");
}

TEST_F(CliOutputs, AnExistingOutputIsReplacedOnlyWithForce) {
  write("hat.schedule", "mine\n");
  std::string out = in_dir("hat.schedule");
  expect_refused(skein("compile samples/hat/hat.obj -t schedule -o " + out),
                 out + " already exists; pass --force to replace it");
  EXPECT_EQ(read("hat.schedule"), "mine\n");
  CliRun forced = skein("compile samples/hat/hat.obj -t schedule -o " + out + " --force");
  EXPECT_EQ(forced.exit_code, 0) << forced.err;
  EXPECT_EQ(forced.out.rfind("wrote " + out + " (schedule target, 2048 stitches, 1 yarn piece)\n" +
                                 out + ": proven against samples/hat/hat.obj",
                             0),
            0u)
      << forced.out;
  EXPECT_EQ(read("hat.schedule").rfind(";!skein-schedule 1\n", 0), 0u);
  write("s.svg", "mine\n");
  expect_refused(skein("render samples/swatch/swatch.yaml -o " + in_dir("s.svg")),
                 in_dir("s.svg") + " already exists; pass --force to replace it");
  write("s.obj", "mine\n");
  expect_refused(skein("generate samples/swatch/swatch.yaml -o " + in_dir("s.obj")),
                 in_dir("s.obj") + " already exists; pass --force to replace it");
  EXPECT_EQ(read("s.svg"), "mine\n");
  EXPECT_EQ(read("s.obj"), "mine\n");
}

TEST_F(CliOutputs, FoldersDevicesAndFifosAreNeverReplaced) {
  fs::create_directory(dir_ / "folder");
  ASSERT_EQ(::mkfifo(in_dir("fifo").c_str(), 0600), 0);
  for (const char* force : {"", " --force"}) {
    expect_refused(skein("compile samples/hat/hat.obj -t schedule -o " + in_dir("folder") + force),
                   "cannot write " + in_dir("folder") + ": it is a folder, not a regular file");
    expect_refused(skein("render samples/hat/hat.obj -o " + in_dir("fifo") + force),
                   "cannot write " + in_dir("fifo") +
                       ": it is a FIFO, not a regular file (-o - writes to standard output)");
    expect_refused(skein("generate samples/swatch/swatch.yaml -o /dev/null" + std::string(force)),
                   "cannot write /dev/null: it is a character device, not a regular file (-o - "
                   "writes to standard output)");
  }
  EXPECT_TRUE(fs::is_fifo(dir_ / "fifo"));
  EXPECT_TRUE(fs::is_character_file("/dev/null"));
  EXPECT_TRUE(fs::is_empty(dir_ / "folder"));
}

TEST_F(CliOutputs, ASymbolicLinksTargetIsReplacedOnlyWithForceAndTheLinkStays) {
  write("target.svg", "mine\n");
  fs::create_symlink("target.svg", dir_ / "link.svg");
  std::string target = fs::canonical(dir_ / "target.svg").string();
  expect_refused(skein("render samples/hat/hat.obj -o " + in_dir("link.svg")),
                 in_dir("link.svg") + " is a symbolic link to " + target +
                     "; pass --force to replace " + target);
  EXPECT_EQ(read("target.svg"), "mine\n");
  CliRun forced = skein("render samples/hat/hat.obj -o " + in_dir("link.svg") + " --force");
  EXPECT_EQ(forced.exit_code, 0) << forced.err;
  EXPECT_TRUE(fs::is_symlink(dir_ / "link.svg"));
  EXPECT_EQ(read("target.svg").rfind("<svg", 0), 0u) << read("target.svg").substr(0, 80);
  // A link to an input is that input.
  std::string hat = copy_sample("hat", "hat.obj");
  fs::create_symlink("hat.obj", dir_ / "hat.md");
  expect_refused(
      skein("compile " + hat + " -t hand -o " + in_dir("hat.md") + " --force"),
      "cannot write " + in_dir("hat.md") + ": it is an input of this command (" + hat + ")");
  EXPECT_TRUE(fs::is_symlink(dir_ / "hat.md"));
}

TEST_F(CliOutputs, DashIsStandardOutputAndTheReportGoesToStandardError) {
  CliRun schedule = skein("compile samples/rib-swatch/rib-swatch.obj -t schedule -o - --verify");
  EXPECT_EQ(schedule.exit_code, 0) << schedule.err;
  EXPECT_EQ(schedule.out.rfind(";!skein-schedule 1\n", 0), 0u) << schedule.out.substr(0, 80);
  EXPECT_EQ(schedule.err,
            "wrote standard output (schedule target, 360 stitches, 1 yarn piece)\n"
            "standard output: proven against samples/rib-swatch/rib-swatch.obj: all 360 stitches "
            "worked once, each along its yarn and after everything it depends on\n");
  CliRun svg = skein("render samples/swatch/swatch.yaml -o -");
  EXPECT_EQ(svg.exit_code, 0) << svg.err;
  EXPECT_EQ(svg.out.rfind("<svg", 0), 0u) << svg.out.substr(0, 80);
  CliRun mesh = skein("generate samples/swatch/swatch.yaml -o -");
  EXPECT_EQ(mesh.exit_code, 0) << mesh.err;
  EXPECT_EQ(mesh.out.rfind("#~skein-stitch-mesh", 0), 0u) << mesh.out.substr(0, 80);
  expect_refused(skein("new sock -o -"),
                 "skein new writes two files (NAME.obj and NAME.yaml): -o - cannot hold them");
  EXPECT_TRUE(outputs().empty());
}

TEST_F(CliOutputs, NewNeverOverwritesAnEditedProjectWithoutForce) {
  std::string sock = in_dir("sock");
  CliRun made = skein("new sock --circumference 20cm --length 15cm -o " + sock);
  EXPECT_EQ(made.exit_code, 0) << made.err;
  EXPECT_EQ(made.out, "wrote " + sock + ".obj and " + sock + ".yaml\n");
  write("sock.yaml", read("sock.yaml") + "# edited\n");
  std::string edited = read("sock.yaml");
  expect_refused(skein("new sock -o " + sock),
                 sock + ".yaml already exists; pass --force to replace it");
  fs::remove(dir_ / "sock.yaml");  // the mesh alone is refused too: no half-replaced project
  expect_refused(skein("new sock -o " + sock),
                 sock + ".obj already exists; pass --force to replace it");
  EXPECT_FALSE(fs::exists(dir_ / "sock.yaml"));
  write("sock.yaml", edited);
  CliRun forced = skein("new sock -o " + sock + " --force");
  EXPECT_EQ(forced.exit_code, 0) << forced.err;
  EXPECT_EQ(read("sock.yaml").find("# edited"), std::string::npos);
}

TEST_F(CliOutputs, NewWithAYamlNameWritesThatProjectBesideItsMesh) {
  fs::create_directory(dir_ / "hats");
  std::string project = in_dir("hats/hat.yaml");
  CliRun r = skein("new hat --circumference 54cm -o " + project);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out, "wrote " + in_dir("hats/hat.obj") + " and " + project + "\n");
  EXPECT_EQ(outputs(), std::vector<std::string>{"hats"});
  EXPECT_TRUE(fs::exists(dir_ / "hats/hat.obj"));
  EXPECT_NE(read("hats/hat.yaml").find("hat.obj"), std::string::npos);
  EXPECT_EQ(skein("check " + project).exit_code, 0);
}

TEST_F(CliOutputs, RenderAndGenerateSayWhatTheyWrote) {
  CliRun svg = skein("render samples/swatch/swatch.yaml -o " + in_dir("s.svg"));
  EXPECT_EQ(svg.exit_code, 0) << svg.err;
  EXPECT_EQ(svg.out, "wrote " + in_dir("s.svg") +
                         " (the stitch mesh of samples/swatch/swatch.yaml, 2024 stitches)\n");
  CliRun coarse = skein("render samples/swatch/swatch.yaml --coarse -o " + in_dir("c.svg"));
  EXPECT_EQ(coarse.out, "wrote " + in_dir("c.svg") +
                            " (the labelled coarse mesh of samples/swatch/swatch.yaml, 4 faces)\n");
  CliRun mesh = skein("generate samples/swatch/swatch.yaml -o " + in_dir("s.obj"));
  EXPECT_EQ(mesh.exit_code, 0) << mesh.err;
  EXPECT_EQ(mesh.out, "wrote " + in_dir("s.obj") +
                          " (the stitch mesh of samples/swatch/swatch.yaml, 2024 stitches)\n");
}

// `skein yarn` on a target's output lays yarn along the fabric its simulator rebuilds; a
// simulator that rebuilds none is refused as "cannot do that yet" (exit 3).
TEST_F(CliOutputs, YarnOfAKnitoutFileIsTheFabricTheVbedRebuilds) {
  std::string out = in_dir("hat-k.obj");
  CliRun r = skein("yarn samples/hat/hat.generic.k --steps 0 -o " + out);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out.rfind("yarn: 2048 stitches, 1 yarn piece, ", 0), 0u) << r.out;
  EXPECT_NE(r.out.find("wrote " + out + "\n"), std::string::npos) << r.out;
  CliRun hand = skein("yarn samples/hat/hat.md --steps 0 -o " + in_dir("hat-md.obj"));
  EXPECT_EQ(hand.exit_code, 3) << hand.err;
  EXPECT_NE(hand.err.find("the hand simulator does not rebuild the fabric of samples/hat/hat.md"),
            std::string::npos)
      << hand.err;
  EXPECT_FALSE(fs::exists(dir_ / "hat-md.obj"));
}

// `skein yarn --check` reports the yarn's checks: loops held by the stitches the knit graph
// says, and yarns closer than the tests allow.
TEST_F(CliOutputs, YarnCheckReportsLoopsHeldAndClearance) {
  CliRun r =
      skein("yarn samples/rib-swatch/rib-swatch.obj --steps 0 --check -o " + in_dir("r.obj"));
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("checks: 340 loops, 0 not held, 0 held wrongly\n"), std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find(" segment pairs closer than 0.9 diameters (closest "), std::string::npos)
      << r.out;
}

}  // namespace
}  // namespace skein
