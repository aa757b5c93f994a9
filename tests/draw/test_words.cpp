// Text fitted to the room the window has for it (draw/words.h): a script's path in the menu
// bar, shortened in its middle; the status line, cut between words. Measured in the window's
// own font, as a frame at 1280 × 720 has it. A script's names in the class's words are tested
// with their unit, tests/lessons/test_class_words.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

#include "draw/words.h"
#include "tests/rendering.h"

namespace frictionlab::draw {
namespace {

// A script's path in the room the menu bar has: whole, else whole folders from its start and the
// whole file name, else the file name with its middle left out; never wider than the room.
TEST(WordsThatFit, APathIsShortenedInTheMiddleToFitNeverCut) {
  FontsForLayout& fonts = measuring();
  ImGui::GetIO().DisplaySize = ImVec2(1280.0f, 720.0f);
  fonts.host.begin_frame();  // the window's font, as the menu bar has it
  const auto width = [](const std::string& text) { return ImGui::CalcTextSize(text.c_str()).x; };
  const std::string path = "/home/ann/physics/week_7/file.lua";
  EXPECT_EQ(path_that_fits(path, width(path)), path);
  EXPECT_EQ(path_that_fits(path, width(path) - 1.0f), "/home/ann/physics/\u2026/file.lua");
  EXPECT_EQ(path_that_fits(path, width("/home/ann/\u2026/file.lua") + 1.0f), "/home/ann/\u2026/file.lua");
  EXPECT_EQ(path_that_fits(path, width("/\u2026/file.lua")), "/\u2026/file.lua");
  EXPECT_EQ(path_that_fits(path, width("fil\u2026lua")), "fil\u2026lua");
  EXPECT_EQ(path_that_fits(path, width("\u2026")), "\u2026");
  EXPECT_EQ(path_that_fits(path, 0.0f), "");
  for (float room = 0.0f; room < width(path) + 10.0f; room += 3.0f) {
    EXPECT_LE(width(path_that_fits(path, room)), room) << "in " << room << " points";
  }
  ImGui::EndFrame();
}

// The status line's words in the room beside the time bar: whole, else cut between words with
// " … " (the trial read "Kept from the last sessio…sion start" and "The run ends here: Spac…"),
// a saved file's path at the end kept as far as it fits; never wider than the room.
TEST(WordsThatFit, AStatusLineIsCutBetweenWordsNeverInsideOne) {
  FontsForLayout& fonts = measuring();
  ImGui::GetIO().DisplaySize = ImVec2(1280.0f, 720.0f);
  fonts.host.begin_frame();
  const auto width = [](const std::string& text) { return ImGui::CalcTextSize(text.c_str()).x; };
  const std::string line =
      "Kept from the last session: dark theme, projector mode. Speed \u00d71 and the tools off, as every session starts.  "
      "The run ends here: Space plays on.";
  EXPECT_EQ(words_that_fit(line, width(line)), line);
  std::istringstream split(line);
  std::vector<std::string> words;
  for (std::string word; split >> word;) words.push_back(word);
  int shortened = 0;
  for (float room = width("Kept \u2026"); room < width(line); room += 7.0f) {
    const std::string shown = words_that_fit(line, room);
    EXPECT_LE(width(shown), room) << "in " << room << " points: " << shown;
    // Every piece of what is shown is one of the line's words, or the "…" where words were left out.
    std::istringstream pieces(shown);
    for (std::string piece; pieces >> piece;) {
      EXPECT_TRUE(piece == "\u2026" || std::find(words.begin(), words.end(), piece) != words.end())
          << "in " << room << " points, \"" << piece << "\" is a cut word: " << shown;
    }
    EXPECT_EQ(shown.rfind("Kept ", 0), 0u) << shown;
    shortened += shown != line;
  }
  EXPECT_GT(shortened, 10);
  // A saved file's name is the news: kept whole, its folders shortened first.
  const std::string saved = "History saved to /home/ann/physics/week_7/tipping_box_history.csv";
  EXPECT_EQ(words_that_fit(saved, width("History saved to /home/ann/\u2026/tipping_box_history.csv")),
            "History saved to /home/ann/\u2026/tipping_box_history.csv");
  EXPECT_EQ(words_that_fit(saved, width("History \u2026 /\u2026/tipping_box_history.csv")), "History \u2026 /\u2026/tipping_box_history.csv");
  // A single word wider than the room: cut at characters (one in three from its end), as nothing
  // else fits.
  EXPECT_EQ(words_that_fit("Unbreakable", width("Unbrea\u2026le")), "Unbrea\u2026le");
  ImGui::EndFrame();
}

// The status line on the lines the bar's height holds: each line as many of the words as fit,
// broken between words, none wider than the room; the words all there, in order, where they fit
// on the lines; the last line cut as words_that_fit cuts where they do not.
TEST(LinesThatFit, ALineIsBrokenBetweenWordsOntoAtMostTheLinesGiven) {
  FontsForLayout& fonts = measuring();
  ImGui::GetIO().DisplaySize = ImVec2(1280.0f, 720.0f);
  fonts.host.begin_frame();
  const auto width = [](const std::string& text) { return ImGui::CalcTextSize(text.c_str()).x; };
  const auto joined = [](const std::vector<std::string>& lines) {
    std::string all;
    for (const std::string& line : lines) all += (all.empty() ? "" : " ") + line;
    return all;
  };
  const std::string notice = "As last time: dark theme, projector mode, no help, predictions.";
  EXPECT_EQ(lines_that_fit(notice, width(notice), 2), std::vector<std::string>{notice}) << "it fits on one line";
  EXPECT_TRUE(lines_that_fit("", 100.0f, 2).empty());
  // Room for the longer of two halves: the first line as many words as fit, the second the rest.
  const std::string first = "As last time: dark theme, projector", second = "mode, no help, predictions.";
  EXPECT_EQ(lines_that_fit(notice, std::max(width(first), width(second)) + 1.0f, 2), (std::vector<std::string>{first, second}));
  EXPECT_EQ(lines_that_fit(notice, width(first), 1).size(), 1u) << "one line given, one line";
  int broken = 0;
  for (float room = width("predictions."); room < width(notice); room += 5.0f) {
    const std::vector<std::string> lines = lines_that_fit(notice, room, 2);
    ASSERT_FALSE(lines.empty());
    EXPECT_LE(lines.size(), 2u) << "in " << room << " points";
    for (const std::string& line : lines) EXPECT_LE(width(line), room) << "in " << room << " points: " << line;
    // The first line takes as many words as fit: the next word would not.
    if (lines.size() == 2 && joined(lines) == notice) {
      const std::string next = notice.substr(lines[0].size() + 1, notice.find(' ', lines[0].size() + 1) - lines[0].size() - 1);
      EXPECT_GT(width(lines[0] + " " + next), room) << "in " << room << " points, \"" << next << "\" fitted on the first line";
      ++broken;
    }
    if (joined(lines) != notice) {
      EXPECT_NE(lines.back().find("\u2026"), std::string::npos) << "in " << room << " points, cut without saying so";
    }
  }
  EXPECT_GT(broken, 3);
  ImGui::EndFrame();
}

}  // namespace
}  // namespace frictionlab::draw
