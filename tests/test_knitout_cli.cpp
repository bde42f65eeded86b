// `skein compile --target knitout --machine P` and `skein verify FILE.k` as a user meets them.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

#include "cli_runner.hpp"

namespace skein {
namespace {

namespace fs = std::filesystem;

class KnitoutCli : public testing::SkeinCliTest {};

TEST_F(KnitoutCli, CompilesVerifiesAndProvesTheHat) {
  std::string k = (dir_ / "hat.k").string();
  testing::CliRun compiled = skein(
      "compile samples/hat/hat.obj --target knitout --machine swg091n2 -o " + k + " --verify");
  EXPECT_EQ(compiled.exit_code, 0) << compiled.err;
  EXPECT_NE(compiled.out.find("proven against samples/hat/hat.obj: all 2048 stitches are there"),
            std::string::npos)
      << compiled.out;
  testing::CliRun replayed = skein("verify " + k + " --machine swg091n2");
  EXPECT_EQ(replayed.exit_code, 0);  // valid: all a file can be checked for without a model
  EXPECT_NE(replayed.out.find("every operation is valid on swg091n2"), std::string::npos)
      << replayed.out;
  EXPECT_NE(replayed.out.find("estimated knitting time"), std::string::npos) << replayed.out;
  testing::CliRun proven =
      skein("verify " + k + " --machine swg091n2 --against samples/hat/hat.obj");
  EXPECT_EQ(proven.exit_code, 0) << proven.out << proven.err;
}

// Third-party files as their authors would run them: no --machine, no --target.
TEST_F(KnitoutCli, AForeignFileIsReplayedOnTheMachineItNames) {
  const std::string dir = "tests/data/knitout-foreign/knitout-examples/";
  testing::CliRun named = skein("verify " + dir + "icord-cast-on.k");
  EXPECT_EQ(named.exit_code, 0) << named.err;  // valid; nothing to prove it against
  EXPECT_NE(named.out.find("every operation is valid on swg091n2 (the file's ;;Machine: SWGN2)"),
            std::string::npos)
      << named.out;
  EXPECT_NE(named.out.find("note: line 613: needle f-1 is outside the bed: swg091n2 has needles "
                           "0..539 [needle-off-bed: knitout-to-dat] (98 times)"),
            std::string::npos)
      << named.out;
  EXPECT_NE(named.out.find("fabric: 1 piece; 530 knit on the front bed, 110 on the back, 30 tuck"),
            std::string::npos)
      << named.out;
  std::string svg = (dir_ / "rectangle.svg").string();
  testing::CliRun unnamed = skein("verify " + dir + "rectangle.knitout --picture " + svg);
  EXPECT_TRUE(fs::exists(svg)) << unnamed.out << unnamed.err;
  EXPECT_EQ(unnamed.exit_code, 0) << unnamed.err;
  EXPECT_NE(unnamed.out.find("every operation is valid on generic (note: the file names no "
                             ";;Machine:; give --machine to replay it on one)"),
            std::string::npos)
      << unnamed.out;
  testing::CliRun strict = skein("verify " + dir + "icord-cast-on.k --strict");
  EXPECT_EQ(strict.exit_code, 2);
  EXPECT_NE(strict.err.find("needle f-1 is outside the bed"), std::string::npos) << strict.err;
  testing::CliRun autoknit = skein("verify tests/data/knitout-foreign/autoknit-knitout/test-A.k");
  EXPECT_EQ(autoknit.exit_code, 2);
  EXPECT_NE(autoknit.err.find("test-A.k:162: carrier '0' is not named in the ;;Carriers: header"),
            std::string::npos)
      << autoknit.err;
}

// The sock's short-row heel on the Kniterate, and the sweater refused in words (exit 3: valid
// input the target cannot knit; no file).
TEST_F(KnitoutCli, TheSockIsProvenAndTheSweaterRefused) {
  std::string k = (dir_ / "sock.k").string();
  testing::CliRun sock =
      skein("compile samples/sock/sock.yaml -t knitout -m kniterate -o " + k + " --verify");
  EXPECT_EQ(sock.exit_code, 0) << sock.err;
  EXPECT_NE(sock.out.find("proven against samples/sock/sock.yaml: all 4606 stitches are there"),
            std::string::npos)
      << sock.out;
  std::string sweater_k = (dir_ / "sweater.k").string();
  testing::CliRun sweater =
      skein("compile samples/sweater/sweater.yaml -t knitout -m swg091n2 -o " + sweater_k);
  EXPECT_EQ(sweater.exit_code, 3);
  EXPECT_NE(sweater.err.find("not yet supported by the knitout target"), std::string::npos)
      << sweater.err;
  EXPECT_FALSE(fs::exists(sweater_k));
}

TEST_F(KnitoutCli, ABadProfileOrFileExitsTwoAndWritesNothing) {
  std::string k = (dir_ / "swatch.k").string();
  testing::CliRun unknown =
      skein("compile samples/rib-swatch/rib-swatch.obj -t knitout -m swg999 -o " + k);
  EXPECT_EQ(unknown.exit_code, 2);
  EXPECT_NE(unknown.err.find("no machine profile 'swg999'"), std::string::npos) << unknown.err;
  EXPECT_FALSE(fs::exists(k));
  testing::CliRun on_generic =
      skein("compile samples/rib-swatch/rib-swatch.obj -t knitout -m generic -o " + k);
  ASSERT_EQ(on_generic.exit_code, 0) << on_generic.err;
  testing::CliRun wrong_machine = skein("verify " + k + " --machine kniterate");
  EXPECT_EQ(wrong_machine.exit_code, 2);
  EXPECT_NE(wrong_machine.err.find("swatch.k:4: kniterate needs ';;Carriers: 1 2 3 4 5 6'"),
            std::string::npos)
      << wrong_machine.err;
}

}  // namespace
}  // namespace skein
