// The window's menu bar (classroom/menu_bar.h), clicked as a teacher clicks it: what its menus
// chose is carried out before the running script's path is drawn at the bar's right, so a lesson
// opened from the Lesson menu names its own script in the very frame it opens, never the one it
// replaced.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "tests/classroom_hands.h"

namespace frictionlab::classroom {
namespace {

// The texts of a frame's record that name a script (end in ".lua").
std::vector<std::string> script_names(const draw::FrameRecord& record) {
  std::vector<std::string> names;
  for (const draw::ShownText& text : record.texts) {
    if (text.text.size() >= 4 && text.text.compare(text.text.size() - 4, 4, ".lua") == 0) names.push_back(text.text);
  }
  return names;
}

bool ends_with(const std::string& text, const std::string& end) {
  return text.size() >= end.size() && text.compare(text.size() - end.size(), end.size(), end) == 0;
}

TEST(MenuBar, ALessonOpenedFromTheLessonMenuNamesItsScriptInTheFrameItOpens) {
  ClassroomHands hands("incline");
  hands.frame();
  draw::FrameRecord before;
  hands.frame(0.0, &before);
  ASSERT_EQ(script_names(before).size(), 1u);
  EXPECT_TRUE(ends_with(script_names(before).front(), "/incline.lua")) << script_names(before).front();

  hands.click("Lesson menu");
  // The item pressed, then let go with the frame recorded: ImGui's menu item acts as it is let go.
  ImGuiIO& io = ImGui::GetIO();
  io.MousePos = hands.control("lesson wedge").GetCenter();
  hands.frame();
  io.MouseDown[0] = true;
  hands.frame();
  io.MouseDown[0] = false;
  draw::FrameRecord opened;
  hands.frame(0.0, &opened);
  ASSERT_TRUE(ends_with(hands.lesson().path(), "/wedge.lua")) << "the click opened " << hands.lesson().path();
  const std::vector<std::string> named = script_names(opened);
  ASSERT_EQ(named.size(), 1u) << "one path at the bar's right";
  EXPECT_TRUE(ends_with(named.front(), "/wedge.lua")) << "the frame that opened wedge names " << named.front();
}

}  // namespace
}  // namespace frictionlab::classroom
