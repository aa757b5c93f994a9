// frictionlab bench: how many times faster than real time each built-in lesson runs headless,
// and the share of it spent in the script's Lua (lesson_speed.csv).
// Figures are measured here and reported, never asserted: the machines are shared.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

#include "app/table.h"
#include "bench/problems.h"
#include "bench/reports/reports.h"
#include "lessons/runtime/catalog.h"
#include "lessons/runtime/lesson.h"

namespace frictionlab {

// How many times faster than real time each built-in lesson runs headless at 240 Hz, and the
// share of the stepping spent inside the script's Lua (hands, forces, probes, every_step).
// A lesson's run takes a few milliseconds, while this shared machine's speed wanders: so the
// lessons take turns, a run each per round, and every lesson is timed over the same stretch of
// the machine's moods. Run one lesson's repeats after another's and two lessons of equal cost
// could differ by a third, the one timed in a slow spell.
// Two figures per lesson. On this shared machine the same run takes either its usual time or
// about half as long again, the core switching between the two at random (often within a
// second, more often after it has idled). A round can only be slowed by that, never sped up:
// the fastest round is the code at the core's full pace, the median what this machine gave.
//
// The step that reaches a lesson's end also works out its table's rows once (Lesson keeps them,
// so that a run played on past the end shows what it ended with), and a lesson whose theory
// solves a reduced model or follows the world's record does most of its script's work there: a
// few milliseconds once a run, where its steps cost microseconds. Counted into the steps, it
// made wedge read 1 100× real time where its steps run at 3 300×. So the two are timed apart:
// the steps up to the last one (× real time, and the script's share of them), and the last step
// with the rows (ms, once a run): what one frame of the window takes as a run ends.
std::string lesson_speed(bool quick, std::ostream& out) {
  const std::vector<std::string> names = lessons::builtin_lessons();
  // 61 rounds of about 0.2 s: twelve seconds, longer than the slow spells, which last a second or two.
  const int rounds = quick ? 1 : 61;
  std::vector<std::vector<double>> costs(names.size()), shares(names.size()), ends(names.size());
  std::vector<double> simulated(names.size(), 0.0);
  for (int round = 0; round < rounds; ++round) {
    // The first pass of a round times the speed alone; the second also clocks every call into
    // Lua for the share (reading the clock costs time of its own).
    for (const bool share_pass : {false, true}) {
      for (std::size_t i = 0; i < names.size(); ++i) {
        lessons::Lesson lesson(lessons::resolve_lesson(names[i]));
        // The duration first: a script may work it out at length (stacked_blocks integrates
        // the slip), and that is not stepping.
        simulated[i] = lesson.duration();
        lesson.time_script(share_pass);
        const auto wall_start = std::chrono::steady_clock::now();
        const double cpu_start = thread_cpu_seconds();
        lesson.step_to(simulated[i] - lesson.scene().frame_step());  // every step but the last
        const double cpu = thread_cpu_seconds() - cpu_start;
        const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
        const double stepped = lesson.scene().time();
        const double script = lesson.seconds_in_script();
        const double end_start = thread_cpu_seconds();
        lesson.step_to(simulated[i]);  // the last step, and the rows
        const double end_cpu = thread_cpu_seconds() - end_start;
        if (share_pass) {
          shares[i].push_back(script / wall);
        } else {
          costs[i].push_back(cpu / stepped);
          ends[i].push_back(end_cpu);
        }
      }
    }
  }
  std::ostringstream csv;
  // The fastest round's column comes last but one, so a reader of the older columns by position
  // still finds them where they were; the rows' time, added later, after it.
  csv << "lesson,hz,simulated_s,cpu_ms_per_simulated_s,times_real_time,script_share,times_real_time_fastest_round,"
         "last_step_and_rows_ms\n";
  std::vector<std::vector<std::string>> table{{"lesson", "simulated (s)", "CPU ms per simulated s", "× real time (median)",
                                               "fastest round", "script share of step time", "last step and rows (ms)"}};
  for (std::size_t i = 0; i < names.size(); ++i) {
    const double cost = median(costs[i]), share = median(shares[i]), end = median(ends[i]);
    const double fastest = *std::min_element(costs[i].begin(), costs[i].end());
    csv << names[i] << ",240," << simulated[i] << ',' << cost * 1e3 << ',' << 1.0 / cost << ',' << share << ','
        << 1.0 / fastest << ',' << end * 1e3 << '\n';
    table.push_back({names[i], format_number(simulated[i]), format_number(cost * 1e3, 3),
                     format_number(std::round(1.0 / cost), 6),  // "3124", not "3.12e+03"
                     format_number(std::round(1.0 / fastest), 6), format_number(share * 100.0, 2) + " %",
                     format_number(end * 1e3, 3)});
  }
  out << "\nBuilt-in lessons, headless at 240 Hz (median and fastest of " << rounds
      << " runs each, the lessons taking turns)\n";
  print_table(out, table);
  return csv.str();
}

}  // namespace frictionlab
