// Prepared setups: saved from the window and opened again (in the window, by the API the
// --setup option uses) with the lesson, values, lock, mystery, step settings and the class's
// predictions as they were;
// a broken file says file:line: and leaves the running lesson alone; saving never writes over a
// script or anything but a setup file FrictionLab wrote, and leaves no temporary file behind.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "classroom_state/setup_file.h"
#include "classroom_state/user_lessons.h"
#include "tests/classroom_hands.h"

namespace frictionlab::classroom_state {
namespace {

namespace fs = std::filesystem;

void write_file(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

// The message parse_setup gives `text`, "" when it reads it.
std::string parse_error(const std::string& text) {
  try {
    parse_setup(text, "class.setup");
    return "";
  } catch (const InvalidInput& error) {
    return error.what();
  }
}

TEST(SetupFile, SavedFromTheWindowItOpensAgainAsItWasInTheWindowAndByTheCommandLinesPath) {
  classroom::ClassroomHands teacher(classroom::prepared_setup_options());
  teacher.classroom().playback().run_to(1.0);
  teacher.classroom().reveal_mystery();  // revealed at home: the class still gets it hidden
  const std::string path = teacher.folder() + "/class.setup";
  ASSERT_EQ(teacher.classroom().save_setup(path), "");
  const std::string text = classroom::read_file(path);
  EXPECT_EQ(text.rfind("# FrictionLab setup\n", 0), 0u) << text;
  EXPECT_NE(text.find("\nlesson spring_pull\n"), std::string::npos) << text;
  EXPECT_NE(text.find("\nset mass = 1.5\n"), std::string::npos) << text;
  EXPECT_NE(text.find("\nlock friction, k, mass\n"), std::string::npos) << text;
  EXPECT_NE(text.find("\nmystery plastic/wood seed 42\n"), std::string::npos) << text;
  EXPECT_NE(text.find("\nfriction threshold\n"), std::string::npos) << text;
  // The pair and seed, never the values.
  EXPECT_EQ(text.find("mu_s ="), std::string::npos) << text;
  EXPECT_EQ(text.find("mu_k ="), std::string::npos) << text;

  // In class: another lesson running, the setup opened in its place (the Lesson menu's dialog
  // does it so: tests/classroom/test_setup_dialog.cpp).
  classroom::ClassroomOptions plain;
  plain.lesson = "incline";
  classroom::ClassroomHands hands(plain);
  ASSERT_EQ(hands.classroom().open_setup(path), "");
  classroom::expect_prepared_setup(hands.classroom(), "opened in place of another lesson");

  // The --setup option's way: the options read and checked before the window is made.
  classroom::Classroom from_options(classroom::setup_options(path, classroom::ClassroomOptions{}));
  expect_prepared_setup(from_options, "opened by setup_options");
}

// A setup's lock greys the Lesson menu's lessons; the menu names the setup, and the line to
// delete, as the reason (not --lock, which the teacher never typed), by --setup's way and the
// menu's. A lesson opened from a setup without a lock is not locked.
TEST(SetupFile, ItsLockIsNamedInTheLessonMenu) {
  classroom::ClassroomHands teacher(classroom::prepared_setup_options());
  const std::string path = teacher.folder() + "/monday.setup";
  ASSERT_EQ(teacher.classroom().save_setup(path), "");
  classroom::Classroom opened(classroom::setup_options(path, classroom::ClassroomOptions{}));
  const std::string why = opened.lock_words();
  EXPECT_EQ(why.rfind("Locked by the setup monday.setup", 0), 0u) << why;
  EXPECT_NE(why.find("delete its lock line (in " + path + ")"), std::string::npos) << why;

  classroom::ClassroomOptions plain;
  plain.lesson = "incline";
  classroom::ClassroomHands hands(plain);
  EXPECT_EQ(hands.classroom().lock_words(), "");
  ASSERT_EQ(hands.classroom().open_setup(path), "");
  hands.frame();
  hands.click("Lesson menu");
  EXPECT_NE(hands.texts().find("Locked by the setup monday.setup"), std::string::npos) << "the open menu says it";

  const std::string unlocked = teacher.folder() + "/unlocked.setup";
  write_file(unlocked, "# FrictionLab setup\nlesson incline\n");
  ASSERT_EQ(hands.classroom().open_setup(unlocked), "") << "a locked window opens a setup by its API";
  EXPECT_EQ(hands.classroom().lock_words(), "");
}

TEST(SetupFile, AStudentsScriptIsNamedFromTheSetupsFolderAndFoundFromAnywhere) {
  classroom::ClassroomOptions options;
  options.lesson = "spring_pull";
  classroom::ClassroomHands scratch(options);
  const std::string folder = scratch.folder() + "/class";
  fs::create_directories(folder);
  fs::copy_file(lessons::resolve_lesson("spring_pull"), folder + "/my_pull.lua");
  classroom::ClassroomOptions own;
  own.lesson = folder + "/my_pull.lua";
  own.overrides = {{"k", "120"}};
  classroom::ClassroomHands hands(own);
  ASSERT_EQ(hands.classroom().save_setup(folder + "/my.setup"), "");
  EXPECT_EQ(read_setup(folder + "/my.setup").lesson, "my_pull.lua");
  classroom::ClassroomHands other(options);
  ASSERT_EQ(other.classroom().open_setup(folder + "/my.setup"), "");
  EXPECT_EQ(fs::path(other.lesson().path()).filename(), "my_pull.lua");
  EXPECT_EQ(other.lesson().parameter("k").value, 120.0);
}

TEST(SetupFile, ABrokenFileSaysWhichLineAndTheRunningLessonKeepsRunning) {
  EXPECT_EQ(parse_error("lesson incline\nsett angle = 3\n"),
            "class.setup:2: 'sett' is not a line a setup has; its lines: lesson, set, lock, mystery, hz, substeps, friction, "
            "predictions, predict, theory");
  EXPECT_EQ(parse_error("# only a comment\n"), "class.setup: no lesson line; a setup names the lesson it opens, as in: lesson spring_pull");
  EXPECT_EQ(parse_error("lesson incline\nlesson push\n"), "class.setup:2: lesson given twice (lines 1 and 2); a setup opens one lesson");
  EXPECT_EQ(parse_error("lesson incline\nset angle 30\n"), "class.setup:2: set angle 30: write it as set NAME = VALUE, as in set mass = 1.5");
  EXPECT_EQ(parse_error("lesson incline\nset angle = 30\nset angle = 20\n"),
            "class.setup:3: set angle given twice (lines 2 and 3); give each parameter once");
  EXPECT_EQ(parse_error("lesson incline\nlock mu_s,,mu_k\n"), "class.setup:2: lock mu_s,,mu_k: give names separated by commas, as in lock mu_s, mu_k");
  EXPECT_EQ(parse_error("lesson incline\n\nmystery block/slope 42\n"),
            "class.setup:3: mystery block/slope 42: write it as mystery MATERIAL/MATERIAL seed N, as in mystery aluminium/wood seed 42");
  EXPECT_EQ(parse_error("lesson incline\nmystery block/slope seed 1000000\n"),
            "class.setup:2: seed 1000000: outside the allowed range; give a whole number from 0 to 999999");
  EXPECT_EQ(parse_error("lesson incline\nhz fast\n"), "class.setup:2: hz fast: not a number");
  EXPECT_EQ(parse_error("lesson incline\nsubsteps 2.5\n"), "class.setup:2: substeps 2.5: a whole number from 1 to 1000");
  EXPECT_NE(parse_error("lesson incline\nfriction dry\n").find("class.setup:2: friction dry: unknown friction treatment 'dry'"), std::string::npos);
  EXPECT_EQ(parse_error("lesson\n"), "class.setup:1: lesson needs what it sets, as in: lesson spring_pull");
  // Comments, blank lines, a byte-order mark and Windows line ends are all fine.
  EXPECT_EQ(parse_error("\xEF\xBB\xBF# a class\r\n\r\n  lesson incline  \r\n# more\r\nset angle = 30\r\n"), "");
  // Found by the fuzzer: a line ending in two carriage returns reads, and writes back, as the same lesson.
  const PreparedSetup twice = parse_setup("lesson my.lua\r\r\nlock x,y\r\n", "class.setup");
  EXPECT_EQ(twice.lesson, "my.lua");
  EXPECT_EQ(parse_setup(setup_text(twice), "again.setup").lesson, "my.lua");
  EXPECT_EQ(twice.lock, (std::vector<std::string>{"x", "y"}));

  // Against the lesson: the value, the lock's name and the pair are checked where the file gives them.
  classroom::ClassroomOptions options;
  options.lesson = "spring_pull";
  classroom::ClassroomHands hands(options);
  hands.classroom().playback().run_to(0.5);
  const auto opened = [&](const std::string& text) {
    write_file(hands.folder() + "/broken.setup", text);
    return hands.classroom().open_setup(hands.folder() + "/broken.setup");
  };
  const std::string at = hands.folder() + "/broken.setup:";
  EXPECT_EQ(opened("lesson incline\nset angle = 95\n"), at + "2: angle = 95 \u00b0 is outside the allowed range [2, 60]");
  EXPECT_NE(opened("lesson incline\nset angel = 30\n").find(at + "2: no parameter 'angel' in "), std::string::npos);
  EXPECT_NE(opened("lesson incline\n# the lock\nlock mu_s, tilt\n").find(at + "3: lock tilt: "), std::string::npos);
  EXPECT_NE(opened("lesson incline\nmystery block/ice seed 4\n").find(at + "2: mystery block/ice: "), std::string::npos);
  EXPECT_EQ(opened("lesson incline\nmystery block/slope seed 4\nset mu_k = 0.1\n"),
            at + "3: set mu_k: mu_k is the mystery's (line 2); leave it out");
  EXPECT_NE(opened("lesson ramp\n").find(at + "1: unknown lesson 'ramp'"), std::string::npos);
  EXPECT_EQ(hands.classroom().open_setup(hands.folder() + "/absent.setup"), "setup " + hands.folder() + "/absent.setup: no such file");
  EXPECT_EQ(hands.classroom().open_setup(hands.folder()), "setup " + hands.folder() + ": that is a folder, not a setup file");
  // None of them stopped the lesson that was running.
  EXPECT_EQ(fs::path(hands.lesson().path()).filename(), "spring_pull.lua");
  EXPECT_NEAR(hands.lesson().scene().time(), 0.5, 1e-9);
}

// The class's predictions, typed and picked in the theory panel, and the reveal: saved, then
// opened into a window that had other answers, and by setup_options.
TEST(SetupFile, TheClassesPredictionsAndTheRevealAreSavedAndOpenAgain) {
  classroom::ClassroomOptions options;
  options.lesson = "incline";
  classroom::ClassroomHands teacher(options, ImVec2(1920.0f, 1080.0f));  // the questions whole, none a scroll away
  teacher.frame();
  teacher.frame();
  teacher.click("prediction mean acceleration down the slope");
  teacher.type("2.5");
  teacher.press_enter();
  teacher.click("prediction sticks or slides: slides");
  ASSERT_EQ(teacher.classroom().predictions().answers["mean acceleration down the slope"], "2.5");
  ASSERT_EQ(teacher.classroom().predictions().answers["sticks or slides"], "slides");
  ASSERT_TRUE(teacher.classroom().theory_hidden());
  teacher.click("reveal");
  ASSERT_FALSE(teacher.classroom().theory_hidden());
  const std::string path = teacher.folder() + "/predicted.setup";
  ASSERT_EQ(teacher.classroom().save_setup(path), "");
  const std::string text = classroom::read_file(path);
  EXPECT_NE(text.find("\npredictions on\npredict sticks or slides = slides\npredict mean acceleration down the slope = 2.5\n"
                      "theory revealed\n"),
            std::string::npos)
      << text;

  // Another window: another lesson's answers, hidden theory, predictions not asked.
  classroom::ClassroomOptions other;
  other.lesson = "tipping_box";
  other.window.predictions = false;
  classroom::ClassroomHands hands(other);
  hands.classroom().predictions().answers["tips or slides"] = "tips";
  ASSERT_EQ(hands.classroom().open_setup(path), "");
  const auto expect_predicted = [](classroom::Classroom& window, const std::string& where) {
    EXPECT_EQ(fs::path(window.playback().lesson().path()).filename(), "incline.lua") << where;
    EXPECT_EQ(window.predictions().answers,
              (std::map<std::string, std::string>{{"mean acceleration down the slope", "2.5"}, {"sticks or slides", "slides"}}))
        << where;
    EXPECT_TRUE(window.predictions().revealed) << where;
    EXPECT_TRUE(window.window_settings().predictions) << where << ": predictions on";
    EXPECT_FALSE(window.theory_hidden()) << where;
  };
  expect_predicted(hands.classroom(), "opened in the window");
  classroom::ClassroomOptions plain;
  plain.window.predictions = false;
  classroom::Classroom from_options(classroom::setup_options(path, plain));
  expect_predicted(from_options, "opened by setup_options");

  // Not yet revealed, and a teacher who takes none: saved so, and opened so.
  hands.classroom().predictions().revealed = false;
  hands.classroom().window_settings().predictions = false;
  hands.classroom().predictions().answers.erase("sticks or slides");
  ASSERT_EQ(hands.classroom().save_setup(path), "");
  const std::string quiet = classroom::read_file(path);
  EXPECT_NE(quiet.find("\npredictions off\npredict mean acceleration down the slope = 2.5\n"), std::string::npos) << quiet;
  EXPECT_EQ(quiet.find("theory"), std::string::npos) << quiet;
  EXPECT_EQ(quiet.find("sticks or slides"), std::string::npos) << quiet;
  ASSERT_EQ(teacher.classroom().open_setup(path), "");
  EXPECT_EQ(teacher.classroom().predictions().answers,
            (std::map<std::string, std::string>{{"mean acceleration down the slope", "2.5"}}));
  EXPECT_FALSE(teacher.classroom().predictions().revealed);
  EXPECT_FALSE(teacher.classroom().window_settings().predictions);
  // A setup that says nothing of predictions leaves the window's choice, and asks afresh.
  write_file(path, "lesson incline\n");
  teacher.classroom().window_settings().predictions = true;
  ASSERT_EQ(teacher.classroom().open_setup(path), "");
  EXPECT_TRUE(teacher.classroom().predictions().answers.empty());
  EXPECT_TRUE(teacher.classroom().window_settings().predictions);
  EXPECT_TRUE(teacher.classroom().theory_hidden());
}

// Row names hold spaces, '·', '(' and '=': a prediction's line is split at its last '='.
TEST(SetupFile, APredictionsRowNameMayHoldAnythingButALineBreak) {
  const PreparedSetup read = parse_setup(
      "lesson terrain\npredict hack box: speed at the end (drifts down a slope) = 0.25\npredict μk = tan θ · x =slides back\n"
      "predict ice box: then=stays\n",
      "class.setup");
  ASSERT_EQ(read.answers.size(), 3u);
  EXPECT_EQ(read.answers[0].row, "hack box: speed at the end (drifts down a slope)");
  EXPECT_EQ(read.answers[0].text, "0.25");
  EXPECT_EQ(read.answers[1].row, "μk = tan θ · x");
  EXPECT_EQ(read.answers[1].text, "slides back");
  EXPECT_EQ(read.answers[2].row, "ice box: then");
  EXPECT_EQ(read.answers[2].line, 4);
  const PreparedSetup again = parse_setup(setup_text(read), "again.setup");
  ASSERT_EQ(again.answers.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(again.answers[i].row, read.answers[i].row);
    EXPECT_EQ(again.answers[i].text, read.answers[i].text);
  }
  // What a line cannot hold as it is is refused when saving, not written to read back otherwise.
  PreparedSetup odd;
  odd.lesson = "terrain";
  odd.answers = {{"ice box: then", "a = b", 0}};
  classroom::ClassroomOptions options;
  options.lesson = "terrain";
  classroom::ClassroomHands hands(options);
  const std::string path = hands.folder() + "/odd.setup";
  try {
    write_setup(path, odd);
    ADD_FAILURE() << "an answer holding '=' was written";
  } catch (const InvalidInput& error) {
    EXPECT_NE(std::string(error.what()).find(path + ": the class's answer \"a = b\" to \"ice box: then\" cannot be written"),
              std::string::npos)
        << error.what();
  }
  odd.answers = {{" ice box: then", "stays", 0}};
  EXPECT_THROW(write_setup(path, odd), InvalidInput);
  EXPECT_FALSE(fs::exists(path));
}

TEST(SetupFile, ABrokenPredictionSaysWhichLineAndTheRunningLessonKeepsRunning) {
  EXPECT_EQ(parse_error("lesson incline\npredict sticks or slides = slides\n\npredict sticks or slides = sticks\n"),
            "class.setup:4: predict sticks or slides given twice (lines 2 and 4); give each prediction once");
  EXPECT_EQ(parse_error("lesson incline\npredict sticks or slides\n"),
            "class.setup:2: predict sticks or slides: write it as predict ROW = ANSWER, as in predict breakaway force = 4.5");
  EXPECT_EQ(parse_error("lesson incline\npredict sticks or slides =\n"),
            "class.setup:2: predict sticks or slides =: write it as predict ROW = ANSWER, as in predict breakaway force = 4.5");
  EXPECT_EQ(parse_error("lesson incline\npredict\n"), "class.setup:2: predict needs what it sets, as in: predict breakaway force = 4.5");
  EXPECT_EQ(parse_error("lesson incline\npredictions yes\n"),
            "class.setup:2: predictions yes: write predictions on (the class predicts before the theory shows) or predictions off");
  EXPECT_EQ(parse_error("lesson incline\npredictions on\npredictions off\n"),
            "class.setup:3: predictions given twice (lines 2 and 3); say once whether the class is asked");
  EXPECT_EQ(parse_error("lesson incline\ntheory shown\n"),
            "class.setup:2: theory shown: write theory revealed (the class's predictions are set beside it) or theory hidden");
  EXPECT_EQ(parse_error("lesson incline\ntheory revealed\ntheory revealed\n"),
            "class.setup:3: theory given twice (lines 2 and 3); say once whether the theory is shown");

  // Against the lesson, where the file gives each.
  classroom::ClassroomOptions options;
  options.lesson = "spring_pull";
  classroom::ClassroomHands hands(options);
  hands.classroom().playback().run_to(0.5);
  hands.classroom().predictions().answers["breakaway force"] = "4";
  const auto opened = [&](const std::string& text) {
    write_file(hands.folder() + "/broken.setup", text);
    return hands.classroom().open_setup(hands.folder() + "/broken.setup");
  };
  const std::string at = hands.folder() + "/broken.setup:";
  const std::string incline = lessons::resolve_lesson("incline");
  EXPECT_EQ(opened("lesson incline\npredictions on\npredict breakaway force = 4.5\n"),
            at + "3: predict breakaway force = 4.5: " + incline +
                " asks for no prediction of that name; its predictions: \"sticks or slides\", \"mean acceleration down the slope\"");
  EXPECT_EQ(opened("lesson incline\npredict mean acceleration down the slope = fast\n"),
            at + "2: predict mean acceleration down the slope = fast: not a number: type it as 2.5 or -0.3");
  EXPECT_EQ(opened("lesson incline\npredict mean acceleration down the slope = 2,5\n"),
            at + "2: predict mean acceleration down the slope = 2,5: not a number: write decimals with a point, as in 0.5");
  EXPECT_EQ(opened("lesson incline\npredict mean acceleration down the slope = 2e6\n"),
            at + "2: predict mean acceleration down the slope = 2e6: outside the range a prediction takes, from -1000000 to 1000000");
  EXPECT_EQ(opened("lesson incline\n# the class\npredict sticks or slides = falls over\n"),
            at + "3: predict sticks or slides = falls over: not one of its choices: \"sticks\", \"slides\"");
  EXPECT_EQ(opened("lesson incline\npredict sticks or slides = Slides\n"),
            at + "2: predict sticks or slides = Slides: not one of its choices: \"sticks\", \"slides\"");
  // None of them stopped the lesson that was running, nor took the class's answers.
  EXPECT_EQ(fs::path(hands.lesson().path()).filename(), "spring_pull.lua");
  EXPECT_NEAR(hands.lesson().scene().time(), 0.5, 1e-9);
  EXPECT_EQ(hands.classroom().predictions().answers, (std::map<std::string, std::string>{{"breakaway force", "4"}}));

  // A typed answer that is no number is not saved into a file that would not open.
  hands.classroom().predictions().answers["breakaway force"] = "about 3";
  const std::string path = hands.folder() + "/class.setup";
  EXPECT_EQ(hands.classroom().save_setup(path),
            path + ": the class's prediction of breakaway force is about 3: not a number: type it as 2.5 or -0.3; correct it "
                   "or clear it in the theory panel, then save");
  EXPECT_FALSE(fs::exists(path));
  // An emptied box is no answer: not written.
  hands.classroom().predictions().answers["breakaway force"] = "";
  ASSERT_EQ(hands.classroom().save_setup(path), "");
  EXPECT_EQ(read_setup(path).answers.size(), 0u);
}

TEST(SetupFile, SavingNeverWritesOverAScriptOrAnythingButASetupItWrote) {
  classroom::ClassroomOptions options;
  options.lesson = "incline";
  classroom::ClassroomHands hands(options);
  classroom::Classroom& window = hands.classroom();
  const std::string folder = hands.folder();
  write_file(folder + "/lesson.lua", "-- a student's lesson\n");
  EXPECT_NE(window.save_setup(folder + "/lesson.lua").find("that looks like a lesson script"), std::string::npos);
  EXPECT_EQ(classroom::read_file(folder + "/lesson.lua"), "-- a student's lesson\n");
  write_file(folder + "/notes.setup", "my notes\n");
  EXPECT_NE(window.save_setup(folder + "/notes.setup").find("a file FrictionLab did not write is there"), std::string::npos);
  EXPECT_EQ(classroom::read_file(folder + "/notes.setup"), "my notes\n");
  ASSERT_EQ(::mkfifo((folder + "/pipe.setup").c_str(), 0600), 0);
  EXPECT_NE(window.save_setup(folder + "/pipe.setup").find("a FIFO (named pipe) is there"), std::string::npos);
  fs::create_directory(folder + "/folder.setup");
  EXPECT_NE(window.save_setup(folder + "/folder.setup").find("a folder is there"), std::string::npos);
  fs::create_symlink(folder + "/notes.setup", folder + "/link.setup");
  EXPECT_NE(window.save_setup(folder + "/link.setup").find("a symbolic link is there"), std::string::npos);
  EXPECT_EQ(classroom::read_file(folder + "/notes.setup"), "my notes\n");
  // A setup it wrote is replaced, whole.
  ASSERT_EQ(window.save_setup(folder + "/class.setup"), "");
  window.playback().set_parameter("angle", "33");
  ASSERT_EQ(window.save_setup(folder + "/class.setup"), "");
  EXPECT_NE(classroom::read_file(folder + "/class.setup").find("\nset angle = 33\n"), std::string::npos);
  // No temporary file is left beside them.
  for (const fs::directory_entry& entry : fs::directory_iterator(folder)) {
    EXPECT_EQ(entry.path().filename().string().find(".partial"), std::string::npos) << entry.path();
  }
}

}  // namespace
}  // namespace frictionlab::classroom_state

namespace frictionlab::classroom_state {
namespace {

// A prepared setup with a mystery and predictions to take opens on what the class predicts. In
// projector mode the predictions share the column's tab bar with the Mystery tab: the Predict
// tab is the one shown, also when another tab was chosen before. At 1280 × 720 the answers at
// their tallest (revealed) have a panel of their own over the tabs, the Mystery tab shown under it.
// With no predictions taken the Mystery tab comes forward.
TEST(SetupFile, ASetupWithPredictionsOpensOnWhatTheClassPredicts) {
  classroom::ClassroomHands teacher(classroom::prepared_setup_options());
  // Not in a window's folder: each window below has that folder's name, and takes it away when it closes.
  const fs::path folder = fs::temp_directory_path() / ("frictionlab_predict_first_" + std::to_string(::getpid()));
  fs::create_directories(folder);
  const std::string path = (folder / "mystery.setup").string();
  ASSERT_EQ(teacher.classroom().save_setup(path), "");
  // The same setup for a teacher who takes no predictions: the theory shows from the start.
  const std::string quiet = (folder / "quiet.setup").string();
  teacher.classroom().window_settings().predictions = false;
  ASSERT_EQ(teacher.classroom().save_setup(quiet), "");
  const lessons::Prediction& first = teacher.lesson().predictions().at(0);
  const std::string predicted =
      "prediction " + first.expectation + (first.is_choice() ? ": " + first.choices.front() : std::string());
  const std::string mystery_heading = "Measure \u03bcs and \u03bck of the mystery plastic/wood surface";
  struct Screen {
    const char* name;
    ImVec2 size;
    bool projector, mystery_shown;
  };
  for (const Screen& screen : {Screen{"projector 1920x1080", ImVec2(1920.0f, 1080.0f), true, false},
                               // The column is planned for the answers at their tallest (after the
                               // reveal), without the theory table under them (issue 31): here they
                               // have a panel of their own, and the Mystery tab shows beneath it.
                               Screen{"1280x720", ImVec2(1280.0f, 720.0f), false, true}}) {
    classroom::ClassroomOptions options;
    options.lesson = "incline";
    options.window.projector = screen.projector;
    classroom::ClassroomHands hands(options, screen.size);
    hands.frame();
    hands.frame();
    hands.click_text("Energy###energy");  // the tab the last class left open
    ASSERT_EQ(hands.classroom().open_setup(path), "");
    std::string texts = hands.texts();
    EXPECT_TRUE(hands.classroom().control(predicted).has_value()) << screen.name << ": " << predicted << " not shown in\n" << texts;
    EXPECT_EQ(texts.find(mystery_heading) != std::string::npos, screen.mystery_shown) << screen.name << ":\n" << texts;
    // By the command line's --setup too.
    classroom::ClassroomOptions base;
    base.window.projector = screen.projector;
    classroom::ClassroomHands opened(setup_options(path, base), screen.size);
    texts = opened.texts();
    EXPECT_TRUE(opened.classroom().control(predicted).has_value()) << screen.name << ", --setup:\n" << texts;
    EXPECT_EQ(texts.find(mystery_heading) != std::string::npos, screen.mystery_shown) << screen.name << ", --setup:\n" << texts;
    // No predictions taken: the Mystery tab is what the class works in.
    ASSERT_EQ(hands.classroom().open_setup(quiet), "");
    EXPECT_NE(hands.texts().find(mystery_heading), std::string::npos) << screen.name << ", no predictions taken";
  }
  fs::remove_all(folder);
}

}  // namespace
}  // namespace frictionlab::classroom_state

namespace frictionlab::classroom_state {
namespace {

// A setup as a link to the web page (the teacher sends an address): the text comes back whole,
// every byte a setup can hold (spaces, '=', '#', '&', a line break, UTF-8's μ), encoded as the
// page's own encodeURIComponent does, and the link opens the setup as the file does.
TEST(SetupLink, HoldsTheWholeSetupAndOpensAsTheFileDoes) {
  const std::string text =
      "# FrictionLab setup\nlesson push\nset mass = 2.5\nlock mass, mu_s\nmystery wood/wood seed 42\n"
      "predict breakaway push = 7.5\n# μs & μk: #1\n";
  const std::string link = setup_link(text, "https://school.example/frictionlab/");
  EXPECT_EQ(link.rfind("https://school.example/frictionlab/#setup=%23%20FrictionLab%20setup%0Alesson%20push%0A", 0), 0u) << link;
  EXPECT_EQ(link.find_first_of(" \n#&=", link.find("#setup=") + 7), std::string::npos) << "unescaped in " << link;
  EXPECT_NE(link.find("%CE%BC"), std::string::npos) << "μ is two UTF-8 bytes, each escaped: " << link;
  EXPECT_EQ(setup_text_from_link(link), text);
  // As the page writes its own address after the fragment's other keys, and a mail program's '+'.
  EXPECT_EQ(setup_text_from_link("frictionlab.html#setup=lesson+push%0A&projector=1"), "lesson push\n");
  EXPECT_EQ(setup_text_from_link("setup=lesson%20incline"), "lesson incline");
  EXPECT_EQ(setup_text_from_link("/home/teacher/push.setup"), std::nullopt);
  // Anywhere among the fragment's parts, as the page reads them: after a lesson or projector part.
  EXPECT_EQ(setup_text_from_link("https://school.example/fl/#lesson=incline&setup=lesson%20push%0A"), "lesson push\n");
  EXPECT_EQ(setup_text_from_link("frictionlab.html#projector=1&at=2&setup=lesson+push&x=1"), "lesson push");
  EXPECT_EQ(setup_text_from_link("lesson=incline&setup=lesson%20push"), "lesson push");
  // A part that only ends in "setup=" is another part.
  EXPECT_EQ(setup_text_from_link("page.html#mysetup=lesson%20push"), std::nullopt);

  const PreparedSetup from_link = read_setup(link);
  EXPECT_EQ(from_link.lesson, "push");
  ASSERT_EQ(from_link.values.size(), 1u);
  EXPECT_EQ(from_link.values[0].text, "2.5");
  ASSERT_TRUE(from_link.mystery.has_value());
  EXPECT_EQ(from_link.mystery->seed, 42u);
  classroom::ClassroomOptions base;
  const classroom::ClassroomOptions options = classroom::setup_options(link, base);
  EXPECT_EQ(options.overrides.at("mass"), "2.5");
  EXPECT_EQ(options.lock, (std::vector<std::string>{"mass", "mu_s"}));
}

// A student's own lesson in a link (the page's Copy link adds &script=): opened on the desktop,
// the lesson is kept among the user's lessons as the page keeps it (never over a different one
// of that name, once for the same text) and the setup names it there; and a setup naming a
// script file makes a link that carries it.
// A data folder of the test's own as XDG_DATA_HOME, gone (and the variable unset) however the test ends.
struct OwnDataFolder {
  fs::path path;
  OwnDataFolder() {
    std::string name = (fs::temp_directory_path() / "frictionlab_link_XXXXXX").string();
    path = ::mkdtemp(name.data());
    ::setenv("XDG_DATA_HOME", path.c_str(), 1);
  }
  ~OwnDataFolder() {
    ::unsetenv("XDG_DATA_HOME");
    fs::remove_all(path);
  }
};

TEST(SetupLink, CarriesAStudentsOwnLessonAndKeepsItAsThePageDoes) {
  const OwnDataFolder own_data;
  const fs::path data = own_data.path;
  const fs::path lessons = data / "frictionlab" / "lessons";
  std::ifstream incline(lessons::resolve_lesson("incline"), std::ios::binary);
  const std::string script{std::istreambuf_iterator<char>(incline), std::istreambuf_iterator<char>()};
  ASSERT_FALSE(script.empty());
  // As the page writes it: the lesson line names the browser's own folder.
  const std::string setup = "# FrictionLab setup\nlesson /home/web_user/.local/share/frictionlab/lessons/my slope.lua\nset mass = 3\n";
  const std::string link = setup_link(setup, "https://school.example/fl/", script) + "&projector=1";
  EXPECT_EQ(script_text_from_link(link), script);
  EXPECT_EQ(setup_text_from_link(link), setup);

  std::string kept;
  const std::optional<std::string> received = received_setup_text(link, &kept);
  ASSERT_TRUE(received.has_value());
  EXPECT_EQ(kept, (lessons / "my_slope.lua").string());
  EXPECT_EQ(*received, "# FrictionLab setup\nlesson " + kept + "\nset mass = 3\n");
  std::ifstream file(kept, std::ios::binary);
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()), script);
  const classroom::ClassroomOptions options = classroom::setup_options(link, classroom::ClassroomOptions{});
  EXPECT_EQ(options.lesson, kept);
  EXPECT_EQ(options.overrides.at("mass"), "3");
  // The same link again: the same lesson, kept once. Another lesson of that name: beside it.
  EXPECT_EQ(*received_setup_text(link), *received);
  const std::string other = script + "\n-- changed by the student\n";
  received_setup_text(setup_link(setup, "", other), &kept);
  EXPECT_EQ(kept, (lessons / "my_slope_2.lua").string());
  std::ifstream first(lessons / "my_slope.lua", std::ios::binary);
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(first), std::istreambuf_iterator<char>()), script);

  // A setup file naming a script: its link carries the script; one naming a built-in does not.
  const fs::path folder = data / "class";
  fs::create_directories(folder);
  std::ofstream(folder / "own.setup") << "lesson " << (lessons / "my_slope.lua").string() << "\n";
  std::string left_out;
  EXPECT_EQ(script_text_from_link(setup_file_link((folder / "own.setup").string(), "", &left_out)), script);
  EXPECT_EQ(left_out, "");
  std::ofstream(folder / "builtin.setup") << "lesson push\n";
  EXPECT_EQ(script_text_from_link(setup_file_link((folder / "builtin.setup").string(), "")), std::nullopt);
  // Too long for a link: left out, and named.
  std::ofstream(lessons / "long.lua") << script << std::string(largest_linked_script, '-') << "\n";
  std::ofstream(folder / "long.setup") << "lesson ../frictionlab/lessons/long.lua\n";
  const std::string long_link = setup_file_link((folder / "long.setup").string(), "", &left_out);
  EXPECT_EQ(script_text_from_link(long_link), std::nullopt);
  EXPECT_EQ(left_out, (lessons / "long.lua").string());
  // Carried, the lesson is named by its file alone: the teacher's folders stay out of the link.
  EXPECT_EQ(setup_text_from_link(setup_file_link((folder / "own.setup").string(), "")), "lesson my_slope.lua\n");
  // A broken escape in the script part is named as the lesson's.
  try {
    received_setup_text("#setup=lesson%20x.lua&script=end%2");
    FAIL() << "a cut script was read";
  } catch (const InvalidInput& error) {
    EXPECT_NE(std::string(error.what()).find("setup link's lesson: '%2'"), std::string::npos) << error.what();
  }
  // An empty script is no lesson, and nothing is kept.
  EXPECT_THROW(received_setup_text("#setup=lesson%20empty.lua&script="), InvalidInput);
  EXPECT_FALSE(fs::exists(lessons / "empty.lua"));
  // Names as the page makes them: no hidden file, one '_' a character, at most 100 characters.
  EXPECT_EQ(lesson_file_stem("/home/web_user/x/.bashrc"), "bashrc");
  EXPECT_EQ(lesson_file_stem("pente_\u00e9t\u00e9.lua"), "pente__t_");
  EXPECT_EQ(lesson_file_stem(".lua"), "linked_lesson");
  EXPECT_EQ(lesson_file_stem(std::string(300, 'a')).size(), 100u);
  // A link placed in the folder under the lesson's name is not written through: the lesson
  // comes in beside it, and the file the link points at is untouched.
  const fs::path outside = data / "outside.txt";
  fs::create_symlink(outside, lessons / "linked.lua");
  received_setup_text(setup_link("lesson linked.lua\n", "", script), &kept);
  EXPECT_EQ(kept, (lessons / "linked_2.lua").string());
  EXPECT_FALSE(fs::exists(outside)) << "a lesson was written through a link in the lessons folder";
}

TEST(SetupLink, ACutOrChangedLinkSaysWhereAndWhat) {
  try {
    setup_text_from_link("page.html#setup=lesson%2");
    FAIL() << "a cut escape was read";
  } catch (const InvalidInput& error) {
    EXPECT_NE(std::string(error.what()).find("'%2' at character 23 is not a %-escape"), std::string::npos) << error.what();
  }
  EXPECT_THROW(setup_text_from_link("#setup=%zz"), InvalidInput);
  EXPECT_THROW(setup_text_from_link("#setup=" + std::string(70 * 1024, 'a')), InvalidInput);
  // A link whose setup has a mistake names the link and the line, as a file's would.
  try {
    read_setup(setup_link("lesson push\nhz fast\n", ""));
    FAIL() << "hz fast was read";
  } catch (const InvalidInput& error) {
    EXPECT_EQ(std::string(error.what()).rfind("setup link:2: ", 0), 0u) << error.what();
  }
}

}  // namespace
}  // namespace frictionlab::classroom_state
