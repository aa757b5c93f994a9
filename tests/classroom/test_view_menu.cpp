// The View menu (classroom/view_menu.h) in the window, clicked as a teacher clicks it: each item
// changes what its key changes (D, P, F1, F11, B), and says nothing else.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "tests/classroom_hands.h"

namespace frictionlab::classroom {
namespace {

// The View menu opened and one of its items clicked.
void choose(ClassroomHands& hands, const std::string& item) {
  hands.frame();
  hands.click("View menu");
  hands.click(item);
  hands.frame();
}

TEST(ViewMenu, EachItemChangesWhatItsKeyChanges) {
  ClassroomOptions options;
  options.lesson = "incline";
  ClassroomHands hands(options);
  const WindowSettings& window = hands.classroom().window_settings();
  ASSERT_EQ(window.theme, draw::ThemeName::light);
  ASSERT_FALSE(window.projector);
  ASSERT_FALSE(window.help);  // the hands open without the help panel

  choose(hands, "Dark theme");
  EXPECT_EQ(window.theme, draw::ThemeName::dark);
  choose(hands, "Projector mode");
  EXPECT_TRUE(window.projector);
  EXPECT_EQ(window.theme, draw::ThemeName::dark) << "the theme kept";
  EXPECT_FALSE(hands.classroom().take_full_screen_toggle()) << "nothing asked of the host yet";
  choose(hands, "Full screen");
  EXPECT_TRUE(hands.classroom().take_full_screen_toggle());

  // And back, each as it was.
  choose(hands, "Dark theme");
  EXPECT_EQ(window.theme, draw::ThemeName::light);
  choose(hands, "Projector mode");
  EXPECT_FALSE(window.projector);
  EXPECT_FALSE(window.help);
  choose(hands, "Help");
  EXPECT_TRUE(window.help);
  EXPECT_TRUE(window.predictions) << "the predictions item untouched";
}


// Whose forces the world draws (View > Forces on, B): on stacked_blocks five arrows start where
// the blocks touch, and three teacher's trials in a row called that knot the picture's blocker
// (issue 31). B shows the top block's forces alone, then the bottom block's, then every body's
// again, as a textbook draws each block's free-body diagram apart; the world's corner says whose
// forces are drawn, and nothing else in the window moves.

ClassroomOptions lesson_options(const std::string& lesson) {
  ClassroomOptions options;
  options.lesson = lesson;
  options.window.predictions = false;
  return options;
}

// What the world drew in a frame: the bodies its forces' values act on, whether a lane's caption
// names the top or the bottom block, and the first lane's view.
struct WorldDrawn {
  std::set<std::string> bodies;
  std::size_t forces = 0;
  bool names_top = false, names_bottom = false;
  draw::Camera camera;
};

WorldDrawn world_drawn(ClassroomHands& hands) {
  hands.frame();
  draw::FrameRecord record;
  hands.frame(0.0, &record);
  WorldDrawn drawn;
  const Scene& scene = hands.lesson().scene();
  for (const draw::FrameRecord::Lane& lane : record.lanes) {
    drawn.names_top = drawn.names_top || lane.caption == "forces on top only (B: next)";
    drawn.names_bottom = drawn.names_bottom || lane.caption == "forces on bottom only (B: next)";
    for (const draw::LabelPlacer::ForceLabel& force : lane.forces) {
      drawn.bodies.insert(scene.name_of(force.body));
      ++drawn.forces;
    }
  }
  drawn.camera = record.lanes.at(0).camera;
  return drawn;
}

// Played to 3 s, where the bottom block slides on the floor and the top one rides on it: every
// force of the lesson is drawn, the friction between the blocks among them.
void play_to_three_seconds(ClassroomHands& hands) {
  hands.key(Key::space);
  // (At most 4 s of frames: a run that ends sooner pauses there.)
  for (int frame = 0; frame < 240 && hands.lesson().scene().time() < 3.0; ++frame) hands.frame(1.0 / 60.0);
  hands.key(Key::space);
}

TEST(ViewMenuForcesOn, BShowsEachBlocksForcesAloneThenEveryBodysAgain) {
  ClassroomHands hands(lesson_options("stacked_blocks"));
  hands.frame();
  play_to_three_seconds(hands);
  const ImRect play_before = hands.control("play");
  const WorldDrawn every = world_drawn(hands);
  EXPECT_EQ(every.bodies, (std::set<std::string>{"bottom", "top"}));
  EXPECT_FALSE(every.names_top || every.names_bottom) << "every body's forces: no caption";

  // The top block: its weight, the bottom block's normal force and friction on it, nothing else.
  hands.key(Key::b);
  const WorldDrawn top = world_drawn(hands);
  EXPECT_EQ(top.bodies, std::set<std::string>{"top"});
  EXPECT_EQ(top.forces, 3u) << "weight, normal force and friction on the top block";
  EXPECT_TRUE(top.names_top) << "the world's corner says whose forces these are";
  // The bottom block: its weight, the floor's normal force and friction, the top block's normal
  // force and friction on it, and the pull.
  hands.key(Key::b);
  const WorldDrawn bottom = world_drawn(hands);
  EXPECT_EQ(bottom.bodies, std::set<std::string>{"bottom"});
  EXPECT_EQ(bottom.forces, 6u) << "weight, the floor's normal force and friction, the top's two, the pull";
  EXPECT_TRUE(bottom.names_bottom);
  EXPECT_EQ(top.forces + bottom.forces, every.forces) << "the two blocks' forces are every force drawn";
  // And every body again.
  hands.key(Key::b);
  const WorldDrawn again = world_drawn(hands);
  EXPECT_EQ(again.bodies, every.bodies);
  EXPECT_EQ(again.forces, every.forces);
  EXPECT_FALSE(again.names_top || again.names_bottom);

  // Nothing moved: the world's view is the same, the transport bar's buttons too.
  for (const WorldDrawn* drawn : {&top, &bottom, &again}) {
    EXPECT_EQ(drawn->camera.origin.x, every.camera.origin.x);
    EXPECT_EQ(drawn->camera.origin.y, every.camera.origin.y);
    EXPECT_EQ(drawn->camera.pixels_per_metre, every.camera.pixels_per_metre);
  }
  const ImRect play_after = hands.control("play");
  EXPECT_EQ(play_after.Min.x, play_before.Min.x);
  EXPECT_EQ(play_after.Min.y, play_before.Min.y);
}

TEST(ViewMenuForcesOn, TheViewMenuPicksABodyAndEveryLessonOpensWithEveryBodys) {
  ClassroomHands hands(lesson_options("stacked_blocks"));
  hands.frame();
  play_to_three_seconds(hands);
  hands.click("View menu");
  hands.mouse_at(hands.control("Forces on").GetCenter());  // the submenu opens under the pointer
  hands.click("Forces on bottom");
  EXPECT_EQ(world_drawn(hands).bodies, std::set<std::string>{"bottom"});
  // R rebuilds the world, with new bodies of the same names: still the bottom block's.
  hands.key(Key::r);
  play_to_three_seconds(hands);
  EXPECT_EQ(world_drawn(hands).bodies, std::set<std::string>{"bottom"});
  // Another lesson, and this one again: every body's, as a lesson opens.
  ASSERT_EQ(hands.classroom().open("push"), "");
  ASSERT_EQ(hands.classroom().open("stacked_blocks"), "");
  play_to_three_seconds(hands);
  EXPECT_EQ(world_drawn(hands).bodies, (std::set<std::string>{"bottom", "top"}));
}

// In lanes the caption is short, for a lane may be a third of the world wide: friction_models'
// lanes are named after their blocks, and "coulomb: forces on coulomb only" ran past the edge
// of its lane on a projector. The lane that draws the block says so; the others keep their names.
TEST(ViewMenuForcesOn, ALanesCaptionSaysItsBodysForcesAloneInFewWords) {
  ClassroomHands hands(lesson_options("friction_models"));
  hands.frame();
  play_to_three_seconds(hands);
  hands.key(Key::b);
  hands.key(Key::b);
  hands.frame();
  draw::FrameRecord record;
  hands.frame(0.0, &record);
  ASSERT_EQ(record.lanes.size(), 3u);
  EXPECT_EQ(record.lanes[0].caption, "coulomb");
  EXPECT_EQ(record.lanes[1].caption, "engineering only (B: next)");
  EXPECT_EQ(record.lanes[2].caption, "quadratic");
  const Scene& scene = hands.lesson().scene();
  for (const draw::FrameRecord::Lane& lane : record.lanes) {
    for (const draw::LabelPlacer::ForceLabel& force : lane.forces) EXPECT_EQ(scene.name_of(force.body), "engineering");
  }
}

// push has one moving body: its forces are every force, and B changes nothing.
TEST(ViewMenuForcesOn, BChangesNothingWhereOneBodyMoves) {
  ClassroomHands hands(lesson_options("push"));
  hands.frame();
  play_to_three_seconds(hands);
  const WorldDrawn before = world_drawn(hands);
  hands.key(Key::b);
  const WorldDrawn after = world_drawn(hands);
  EXPECT_EQ(after.bodies, before.bodies);
  EXPECT_EQ(after.forces, before.forces);
  EXPECT_EQ(before.bodies, std::set<std::string>{"block"});
}

}  // namespace
}  // namespace frictionlab::classroom
