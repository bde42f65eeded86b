#include "hand_web/hand_web_target.hpp"

#include <fmt/format.h>

#include <ostream>
#include <sstream>

#include "common/error.hpp"
#include "driver/pipeline.hpp"
#include "hand/hand_target.hpp"
#include "hand/pattern_model.hpp"
#include "hand_web/page_data.hpp"
#include "hand_web/page_writer.hpp"

namespace skein {
namespace {

constexpr const char* kName = "hand-web";

class HandWebTarget : public Target {
 public:
  explicit HandWebTarget(const Target& hand) : hand_(hand) {}
  std::string name() const override { return kName; }
  std::string description() const override {
    return fmt::format(
        "the knitting page: one self-contained HTML file that steps through the model stitch "
        "by stitch (the proven hand pattern's text beside the model in 3D, progress kept in "
        "the browser); three.js r111 is inlined from Debian's libjs-three ({})",
        hand_web::kThreeDir);
  }
  std::string default_extension() const override { return ".html"; }
  // The hand pattern's own: the page shows the text `--target hand` writes.
  std::vector<TargetSetting> settings() const override { return hand_.settings(); }

  void emit(const Compilation& c, const TargetOptions& options, std::ostream& out) const override {
    TargetOptions text_options = options;
    text_options.dialect = "standard";
    std::ostringstream pattern;
    hand_.emit(c, text_options, pattern);
    hand::HandPattern written = hand::build_pattern(c, options);
    hand_web::PageData data = hand_web::build_page_data(c, pattern.str(), written);
    std::optional<hand_web::ThreeJs> three = hand_web::find_three_js();
    hand_web::write_page(data, three ? &*three : nullptr, out);
  }

 private:
  const Target& hand_;
};

class HandWebSimulator : public Simulator {
 public:
  std::string name() const override { return "hand-web-knitter"; }
  std::string target() const override { return kName; }
  std::string description() const override {
    return "works the pattern the page embeds as a knitter would (the hand simulator) and "
           "proves it knits the input stitch for stitch";
  }
  VerifyReport verify(const std::string& text, const std::string& file, const Compilation* against,
                      const TargetOptions&) const override {
    std::optional<std::string> pattern = hand_web::embedded_pattern(text);
    if (!pattern)
      throw Error(
          fmt::format("{}: expected a knitting page written by skein (--target {}), "
                      "found no embedded pattern",
                      file, kName));
    return hand::verify_pattern(*pattern, file, against);
  }
};

}  // namespace

void register_hand_web_target(Registry& registry) {
  const Target* hand = registry.target("hand");
  SKEIN_ASSERT(hand != nullptr, "the hand target registers before the page built on it");
  registry.add(std::make_unique<HandWebTarget>(*hand));
  registry.add(std::make_unique<HandWebSimulator>());
}

}  // namespace skein
