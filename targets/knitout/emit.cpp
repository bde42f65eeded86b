#include "knitout/emit.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <deque>
#include <ostream>

#include "common/error.hpp"
#include "knitout/course_layout.hpp"
#include "knitout/emitter.hpp"
#include "knitout/knitout_writer.hpp"

namespace skein::knitout {
namespace emit {

void Emitter::run() {
  const Course& first = l_.courses.front();
  carrier_ = carriers_[first.yarn];
  plan_course(first, true);
  cast_on(first);
  for (std::size_t i = 1; i < l_.courses.size(); ++i) {
    const Course& course = l_.courses[i];
    carrier_ = carriers_[course.yarn];
    if (course.along_split) {  // the crotch between two branches of the tube
      cast_on_along_split(course);
      continue;
    }
    if (course.cast_on) {  // a sheet beside the loops on the bed, its yarn and border its own
      plan_beside(course);
      cast_on(course);
      continue;
    }
    plan_course(course, false);
    transition(course);
    // A yarn that starts on loops on the bed comes in for its first course: the hook (if
    // any) lets go once that course holds it.
    if (course.first_of_yarn) bring_in(course);
    if (chained_off(g_.type[l_.order[course.begin]])) {
      bind_off(course, course.last_of_yarn);  // lets the hook go after its first st
      continue;
    }
    knit_course(course);
    wrap_turn(course);
    if (course.last_of_yarn) leave_loops(course);
    if (course.first_of_yarn) release(carrier_);
  }
}

void Emitter::source(const Course& c, const char* what) {
  StitchId a = l_.order[c.begin], b = l_.order[c.end - 1];
  w_.note(fmt::format(";!source: row {} {}: {}s {}..{} ({})", c.row + 1, what, g_.element,
                      g_.source[a] + 1, g_.source[b] + 1,
                      c.left_to_right ? "left to right" : "right to left"));
}

}  // namespace emit

namespace {

// "46 rows: a sheet", "107 rounds and 20 short rows: a tube in half gauge".
std::string describe(const CourseLayout& l) {
  auto partial = static_cast<std::size_t>(
      std::count_if(l.courses.begin(), l.courses.end(), [](const Course& c) { return c.partial; }));
  return fmt::format("{} {}{}: {}", l.courses.size() - partial, l.tube ? "rounds" : "rows",
                     partial ? fmt::format(" and {} short rows", partial) : "",
                     l.tube ? "a tube in half gauge" : "a sheet");
}

void write_header(KnitoutWriter& w, const Compilation& c, const MachineProfile& p,
                  const std::vector<CourseLayout>& pieces) {
  w.line(";!knitout-2");
  w.line(fmt::format(";;Machine: {}", p.machine));
  w.line(fmt::format(";;Gauge: {}", p.gauge));
  if (p.width_header) w.line(fmt::format(";;Width: {}", p.needles));
  w.line(fmt::format(";;Carriers: {}", p.carriers_line()));
  w.line(fmt::format(";;Position: {}", p.position));
  std::string what = pieces.size() == 1
                         ? describe(pieces[0])
                         : fmt::format("{} yarn pieces knit one after another", pieces.size());
  w.line(fmt::format(";!source: {} ({} stitches, {}), knit by skein for {}", c.input, c.knit.size(),
                     what, p.name));
  if (p.stitch_number) w.line(fmt::format("x-stitch-number {}", p.stitch_number));
  if (p.speed_number) w.line(fmt::format("x-speed-number {}", p.speed_number));
}

// The carriers for the model's yarns: the profile's yarn carrier, then the others in the
// header's order, never the waste yarn's or the draw thread's.
std::vector<std::string> yarn_carrier_names(const MachineProfile& p) {
  std::vector<std::string> carriers{p.yarn_carrier};
  for (const std::string& name : p.carriers)
    if (name != p.yarn_carrier && name != p.waste_carrier && name != p.draw_carrier)
      carriers.push_back(name);
  return carriers;
}

[[noreturn]] void too_few_carriers(const Compilation& c, const MachineProfile& p,
                                   std::size_t carriers, std::size_t in, StitchId at) {
  throw UnsupportedError(fmt::format(
      "{} has {} yarn pieces in at once (at {}), one carrier each, and {} has only {} carriers "
      "for them{}",
      c.input, in, c.knit.describe(at), p.name, carriers,
      p.waste_carrier.empty()  ? ""
      : p.draw_carrier.empty() ? " besides the waste yarn's"
                               : " besides the waste yarn's and the draw thread's"));
}

}  // namespace

// Per yarn piece its carrier, in the order the layouts bring the yarns in: a carrier not used
// yet while the profile has one, then one that a yarn knit before has taken out (its piece
// bound off, or its loops left to another yarn), the first taken out first. A machine with few
// carriers (kniterate's 4) so knits a model of more yarn pieces, as long as no more are in at
// once.
std::vector<std::string> yarn_carriers(const Compilation& c, const MachineProfile& p,
                                       const std::vector<CourseLayout>& pieces) {
  std::vector<std::string> names = yarn_carrier_names(p), carriers(c.yarns.size());
  std::deque<std::string> out;  // carriers taken out, to be brought in again
  std::size_t next = 0, in = 0;
  for (const CourseLayout& l : pieces)
    for (const Course& course : l.courses) {
      if (course.first_of_yarn) {
        ++in;
        if (next == names.size() && out.empty())
          too_few_carriers(c, p, names.size(), in, l.order[course.begin]);
        if (next < names.size()) {
          carriers[course.yarn] = names[next++];
        } else {
          carriers[course.yarn] = out.front();
          out.pop_front();
        }
      }
      // A cast-on never takes its yarn out; any other last course does (Emitter::run).
      if (course.last_of_yarn && !course.cast_on) {
        --in;
        out.push_back(carriers[course.yarn]);
      }
    }
  return carriers;
}

// "carrier 3", "carriers 3, 4".
std::string carriers_of(const CourseLayout& l, const std::vector<std::string>& carriers) {
  std::vector<std::string> used;
  for (const Course& course : l.courses)
    if (course.first_of_yarn &&
        std::find(used.begin(), used.end(), carriers[course.yarn]) == used.end())
      used.push_back(carriers[course.yarn]);
  return fmt::format("carrier{} {}", used.size() > 1 ? "s" : "", fmt::join(used, ", "));
}

void emit_knitout(const Compilation& c, const MachineProfile& p, std::ostream& out) {
  std::vector<CourseLayout> pieces = lay_out_pieces(c);
  std::vector<std::string> carriers = yarn_carriers(c, p, pieces);
  KnitoutWriter w(out);
  write_header(w, c, p, pieces);
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    if (pieces.size() > 1)
      w.line(fmt::format(";!source: yarn piece {} ({}): {}", i + 1,
                         carriers_of(pieces[i], carriers), describe(pieces[i])));
    emit::Emitter(c, p, pieces[i], w, carriers).run();  // one piece's state at a time
  }
}

}  // namespace skein::knitout
