// The window's history export (classroom/exports.h, Ctrl+E and the Lesson menu's item), against
// the command line's `run --csv` of the same lesson.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "lessons/runtime/history_csv.h"
#include "tests/classroom_hands.h"

namespace frictionlab::classroom {
namespace {

// One CSV format for every export (the teacher's trial: the window's had no byte-order mark,
// "t" and a "#" line; run --csv had "t (s)"). The window's export (Ctrl+E) of tipping_box after
// 12 steps and `frictionlab run tipping_box --csv` over the same 12 steps are the same file,
// byte for byte: the mark, the header with its units as the very first line, the same rows (no
// hand pulled, so hand_pulled 0 and no gauge reading). Beside each, the settings file says which
// lesson and values made the run.
TEST(HistoryExport, IsTheFileRunCsvWrites) {
  ClassroomHands hands(gauge_options("tipping_box"));
  hands.frame();
  for (int i = 0; i < 12; ++i) hands.lesson().step();
  const std::string window_path = hands.classroom().export_history();
  const std::string window = read_file(window_path);

  const std::filesystem::path folder = std::filesystem::path(window_path).parent_path();
  const std::string run_path = (folder / "run.csv").string();
  const std::string command = std::string("'") + FRICTIONLAB_PROGRAM + "' run tipping_box --duration 0.05 --csv '" + run_path + "' > /dev/null";
  ASSERT_EQ(std::system(command.c_str()), 0) << command;
  const std::string run = read_file(run_path);

  const std::string header = "\xEF\xBB\xBFt (s),push (N),tilt (\u00b0),slide (m),friction_force (N),back_load (N),front_load (N),"
                             "slipping,contact_points,any_contact_slipping,hand_pulled,gauge (N)\n";
  EXPECT_EQ(window.substr(0, window.find('\n') + 1), header);
  EXPECT_EQ(run.substr(0, run.find('\n') + 1), header);
  EXPECT_EQ(std::count(window.begin(), window.end(), '\n'), 13);
  EXPECT_EQ(window, run);

  for (const std::string& csv : {window_path, run_path}) {
    const std::string settings = read_file(lessons::settings_path_for(csv));
    EXPECT_EQ(settings.rfind("FrictionLab run of ", 0), 0u) << csv << ":\n" << settings;
    EXPECT_NE(settings.find("tipping_box.lua\n240 Hz, 1 sub-step(s), stick-slip friction\n"), std::string::npos) << settings;
    EXPECT_NE(settings.find("\npush_height = 0.7 m\n"), std::string::npos) << settings;
  }
}

}  // namespace
}  // namespace frictionlab::classroom
