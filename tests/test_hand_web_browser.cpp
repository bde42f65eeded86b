// The knitting page in a real browser: Debian's headless Chromium opens the hat's page and runs
// the page's own self-tests (stepping through every stitch; progress across a reload), which
// report into the DOM that `--dump-dom` prints; screenshots at phone and desktop sizes show the
// model drawn. Skipped where /usr/bin/chromium is not installed.
#include <gtest/gtest.h>
#include <png.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <future>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "builtin_targets.hpp"
#include "driver/pipeline.hpp"
#include "driver/registry.hpp"

namespace skein {
namespace {

namespace fs = std::filesystem;

constexpr const char* kChromium = "/usr/bin/chromium";

std::string read_file(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

class HandWebBrowser : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!fs::exists(kChromium)) GTEST_SKIP() << kChromium << " is not installed";
    dir_ = fs::temp_directory_path() /
           ("skein-page-" +
            std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) + "-" +
            std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    Registry registry;
    register_builtin_targets(registry);
    for (auto [model, page] : {std::pair{"hat/hat.obj", "hat.html"},
                               std::pair{"rib-swatch/rib-swatch.obj", "rib-swatch.html"}}) {
      Compilation c = compile_model(std::string(SKEIN_SOURCE_DIR "/samples/") + model);
      std::ofstream out(dir_ / page, std::ios::binary);
      registry.target("hand-web")->emit(c, {}, out);
    }
  }
  void TearDown() override {
    if (!dir_.empty()) fs::remove_all(dir_);
  }

  // Runs headless Chromium (software WebGL) on `page` (the hat's) with `query`; returns stdout.
  // Each `run` has a profile and output files of its own, so that runs may go at once.
  std::string chromium(const std::string& args, const std::string& query,
                       const std::string& run = "run", const std::string& page = "hat.html") const {
    fs::path out = dir_ / (run + ".out"), err = dir_ / (run + ".err");
    std::string command = std::string(kChromium) +
                          " --headless --no-sandbox --use-angle=swiftshader "
                          "--enable-unsafe-swiftshader --hide-scrollbars --user-data-dir=" +
                          (dir_ / (run + ".profile")).string() + " " + args + " 'file://" +
                          (dir_ / page).string() + query + "' >" + out.string() + " 2>" +
                          err.string();
    int status = std::system(("timeout 240 " + command).c_str());
    EXPECT_EQ(status, 0) << command << "\n" << read_file(err);
    return read_file(out);
  }

  // The self-test's report, from the page's <pre id="selftest">.
  std::string self_test(const std::string& args, const std::string& query,
                        const std::string& page = "hat.html") const {
    std::string dom = chromium("--dump-dom " + args, query, "run", page);
    std::size_t at = dom.find("<pre id=\"selftest\">");
    if (at == std::string::npos) return "no report in:\n" + dom.substr(0, 2000);
    at += 19;
    return dom.substr(at, dom.find("</pre>", at) - at);
  }

  fs::path dir_;
};

TEST_F(HandWebBrowser, StepsThroughEveryStitchWithTextCountsAndModelAgreeing) {
  // At a phone's size: the page also checks that nothing is wider than the window.
  std::string report = self_test("--window-size=390,844", "?selftest=1");
  EXPECT_EQ(
      report.rfind("selftest: ok 2048 stitches, 39 rows checked, 3D checked, click checked", 0), 0u)
      << report;
  std::cout << report << "\n";  // the timings
}

TEST_F(HandWebBrowser, ShowsTheChartOfAChartedPieceWithTheCurrentRowAndStitchMarked) {
  // The rib swatch's piece has a chart: at each stitch of each of its rows but the bind-off the
  // page shows it, that row and that stitch's square marked (the hat's page, above, none).
  std::string report = self_test("--window-size=390,844", "?selftest=1", "rib-swatch.html");
  EXPECT_EQ(report.rfind("selftest: ok 360 stitches", 0), 0u) << report;
  EXPECT_NE(report.find(" chart rows checked"), std::string::npos) << report;
}

TEST_F(HandWebBrowser, ProgressSurvivesAReload) {
  // The page saves its place, reloads itself (its address without the #s= part), and checks
  // that it comes back there from localStorage; virtual time lets the reload finish.
  std::string report =
      self_test("--window-size=800,600 --virtual-time-budget=10000", "?selftest=reload");
  EXPECT_EQ(report, "reload: ok restored stitch 37");
}

struct Picture {
  std::uint32_t width = 0, height = 0;
  std::vector<std::uint8_t> rgba;
};

Picture read_png(const fs::path& path) {
  Picture p;
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&image, path.c_str())) return p;
  image.format = PNG_FORMAT_RGBA;
  p.rgba.resize(PNG_IMAGE_SIZE(image));
  if (!png_image_finish_read(&image, nullptr, p.rgba.data(), 0, nullptr)) return {};
  p.width = image.width;
  p.height = image.height;
  return p;
}

// Pixels the shaded "done" green takes (green well above red and blue), and how many colours
// the picture has in all (a blank or failed page has a handful).
struct Census {
  std::size_t green = 0, colours = 0;
};

Census census(const Picture& p) {
  Census c;
  std::vector<bool> seen(1 << 15, false);
  for (std::size_t i = 0; i + 3 < p.rgba.size(); i += 4) {
    int r = p.rgba[i], g = p.rgba[i + 1], b = p.rgba[i + 2];
    if (g > r + 40 && g > b + 40) ++c.green;
    std::size_t key = static_cast<std::size_t>(((r >> 3) << 10) | ((g >> 3) << 5) | (b >> 3));
    if (!seen[key]) ++c.colours;
    seen[key] = true;
  }
  return c;
}

TEST_F(HandWebBrowser, ScreenshotsShowTheModelAtPhoneAndDesktopSizes) {
  std::vector<std::pair<int, int>> sizes = {{390, 844}, {1280, 800}};
  std::vector<std::future<void>> shots;  // both at once: a browser mostly waits to start
  for (auto [width, height] : sizes) {
    std::string name = "hat-" + std::to_string(width);
    shots.push_back(std::async(std::launch::async, [this, name, w = width, h = height] {
      chromium("--window-size=" + std::to_string(w) + "," + std::to_string(h) +
                   " --virtual-time-budget=3000 --screenshot=" + (dir_ / (name + ".png")).string(),
               "#s=1630", name);  // 80% knitted: most of the hat is done (green)
    }));
  }
  for (auto& shot : shots) shot.get();
  for (auto [width, height] : sizes) {
    fs::path shot = dir_ / ("hat-" + std::to_string(width) + ".png");
    Picture p = read_png(shot);
    ASSERT_EQ(p.width, static_cast<std::uint32_t>(width)) << shot;
    ASSERT_EQ(p.height, static_cast<std::uint32_t>(height));
    Census c = census(p);
    EXPECT_GT(c.green, p.width * p.height / 50) << "the 3D model is not drawn: " << shot;
    EXPECT_GT(c.colours, 50u) << "a blank page: " << shot;
  }
}

}  // namespace
}  // namespace skein
