// Writes knitout text, one operation a line, keeping the racking so transfers can ask for the
// rack they need. Buffered: flushed to the stream in large blocks.
#pragma once

#include <fmt/compile.h>
#include <fmt/format.h>

#include <cstdint>
#include <ostream>
#include <string>
#include <string_view>

#include "knitout/knitout_ops.hpp"

namespace skein::knitout {

class KnitoutWriter {
 public:
  explicit KnitoutWriter(std::ostream& out) : out_(out) { buffer_.reserve(kFlushAt + 256); }
  ~KnitoutWriter() { flush(); }
  KnitoutWriter(const KnitoutWriter&) = delete;
  KnitoutWriter& operator=(const KnitoutWriter&) = delete;

  void line(std::string_view text) { append(FMT_COMPILE("{}\n"), text); }
  // A comment written just before the next operation, or never if none follows before the next
  // note (so an empty transfer plan leaves no trace).
  void note(std::string text) { note_ = std::move(text); }
  void carriers(const char* op, std::string_view carrier) {
    append(FMT_COMPILE("{} {}\n"), op, carrier);
  }
  std::int32_t racking() const { return rack_; }
  void rack(std::int32_t r) {
    if (r == rack_) return;
    rack_ = r;
    append(FMT_COMPILE("rack {}\n"), r);
  }
  void knit(Direction d, Needle n, std::string_view c) { stitch("knit", d, n, c); }
  void tuck(Direction d, Needle n, std::string_view c) { stitch("tuck", d, n, c); }
  void miss(Direction d, Needle n, std::string_view c) { stitch("miss", d, n, c); }
  void split(Direction d, Needle n, Needle to, std::string_view c) {
    append(FMT_COMPILE("split {} {}{} {}{} {}\n"), direction_char(d), bed_name(n.bed), n.index,
           bed_name(to.bed), to.index, c);
  }
  void drop(Needle n) { append(FMT_COMPILE("drop {}{}\n"), bed_name(n.bed), n.index); }
  // A front/back transfer at whatever rack aligns the two needles.
  void xfer(Needle from, Needle to) {
    Needle front = is_front(from.bed) ? from : to, back = is_front(from.bed) ? to : from;
    rack(front.index - back.index);
    append(FMT_COMPILE("xfer {}{} {}{}\n"), bed_name(from.bed), from.index, bed_name(to.bed),
           to.index);
  }

  void flush() {
    out_.write(buffer_.data(), static_cast<std::streamsize>(buffer_.size()));
    buffer_.clear();
  }

 private:
  static constexpr std::size_t kFlushAt = 1 << 20;

  void stitch(const char* op, Direction d, Needle n, std::string_view c) {
    append(FMT_COMPILE("{} {} {}{} {}\n"), op, direction_char(d), bed_name(n.bed), n.index, c);
  }
  // Formats compiled with FMT_COMPILE: parsing the format at run time, once per line, cost
  // a fifth to a half of the time of writing a file.
  template <typename Format, typename... Args>
  void append(const Format& format, const Args&... args) {
    if (!note_.empty()) {
      buffer_ += note_;
      buffer_ += '\n';
      note_.clear();
    }
    fmt::format_to(std::back_inserter(buffer_), format, args...);
    if (buffer_.size() >= kFlushAt) flush();
  }

  std::ostream& out_;
  std::string buffer_, note_;
  std::int32_t rack_ = 0;
};

}  // namespace skein::knitout
