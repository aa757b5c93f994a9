// The world's labels: every force's value beside its own arrow, in the world and in the
// free-body inset; names, the slope's angle and the tools' readings off the bodies and each
// other; every label inside what the world view shows.
#include <cstdlib>
#include <functional>
#include <limits>
#include <map>
#include <set>

#include "draw/close_up.h"
#include "lessons/runtime/class_words.h"
#include "tests/layout_checks.h"

namespace frictionlab::classroom {

// The screen-point arithmetic of draw/drawing.h, used throughout here.
using draw::add;
using draw::length;
using draw::mul;
using draw::sub;
namespace {
using namespace layout_checks;

// The world's words for the class too: the legend's materials and the free-body diagram's
// body in words (where_methods_fail's "soft_law_block" material, terrain's "asphalt_box").
TEST(WorldLabels, NameMaterialsAndBodiesInWords) {
  draw::HeadlessRenderer renderer(draw::frame_width, draw::frame_height);
  const auto texts_of = [&](const std::string& lesson, double t) {
    draw::LessonAt at(lesson, {}, t);
    draw::FrameRecord record;
    renderer.render(*at.lesson, at.framing, &record);
    std::string all;
    for (const draw::ShownText& text : record.texts) all += text.text + "\n";
    return all;
  };
  const std::string where_methods_fail = texts_of("where_methods_fail", 1.0);
  EXPECT_NE(where_methods_fail.find("\nsoft law block\n"), std::string::npos) << where_methods_fail;
  EXPECT_EQ(where_methods_fail.find("soft_law_block"), std::string::npos) << where_methods_fail;
  const std::string terrain = texts_of("terrain", 1.0);
  EXPECT_NE(terrain.find("Free-body diagram: asphalt box\n"), std::string::npos) << terrain;
}

// A teacher's trial (issue 31): driven_wheel's motor torque is a curved arrow in the applied
// forces' colour, and the legend had no key to it: the class did not know what it was. Where a
// torque acts, the legend keys it, "torque", in the strip (a screen's frame) and in the column (a
// projector's window); where none acts (push), it does not.
TEST(WorldLabels, TheLegendKeysATorquesCurvedArrow) {
  const auto keyed = [](const std::vector<draw::ShownText>& texts) {
    // The legend's own panel, or the world's whose strip it is (the torque's slider says "torque" too).
    return std::any_of(texts.begin(), texts.end(), [](const draw::ShownText& text) {
      return text.text == "torque" && (text.panel.ends_with("###legend") || text.panel.ends_with("###world"));
    });
  };
  draw::HeadlessRenderer renderer(draw::frame_width, draw::frame_height);
  for (const char* lesson : {"driven_wheel", "push"}) {
    draw::LessonAt at(lesson, {}, 1.0);
    draw::FrameRecord record;
    renderer.render(*at.lesson, at.framing, &record);
    EXPECT_EQ(keyed(record.texts), std::string(lesson) == "driven_wheel") << lesson << " in a frame";
  }
  const ImVec2 display(1920.0f, 1080.0f);
  draw::HeadlessContext gl;
  draw::ImGuiHost host(nullptr);
  for (const lessons::CatalogEntry& entry : lessons::catalog()) {
    if (entry.name != "driven_wheel" && entry.name != "push") continue;
    Classroom window(class_window(entry.path, {"1920x1080", 1920, 1080, true}));
    window.run_to(1.0);
    draw_window_frame(gl, host, window, display);
    draw::FrameRecord record;
    draw_window_frame(gl, host, window, display, 0.0, &record);
    EXPECT_EQ(keyed(record.texts), entry.name == "driven_wheel") << entry.name << " on a projector";
  }
}

// A teacher's projector trial (issue 31): incline's view, framed round the block to keep it
// min_body_pixels long, cut off the slope's foot and the angle's mark, with the tools on too.
// The lesson's view is now the whole slope: on a projector at 1920 x 1080, at the default 35 deg,
// at 10 deg and at 60 deg, tools off and all on (distance marks, speed, stopwatch), at the run's
// start and end, every corner of the slope is inside what the world shows, and so is the angle's
// label.
TEST(WorldLabels, InclinesWholeSlopeAndItsAngleAreInViewOnAProjector) {
  const ImVec2 display(1920.0f, 1080.0f);
  draw::HeadlessContext gl;
  draw::ImGuiHost host(nullptr);
  for (const char* angle : {"35", "10", "60"}) {
    for (const bool tools : {false, true}) {
      ClassroomOptions options = class_window(lessons::resolve_lesson("incline"), {"1920x1080", 1920, 1080, true});
      options.overrides["angle"] = angle;
      options.window.tools.distance_marks = options.window.tools.speed = options.window.tools.stopwatch = tools;
      Classroom window(options);
      draw_window_frame(gl, host, window, display);
      for (const double t : {0.2, 1.0}) {
        window.run_to(t);
        draw_window_frame(gl, host, window, display);
        draw::FrameRecord record;
        draw_window_frame(gl, host, window, display, 0.0, &record);
        const std::string where = std::string(angle) + " deg at " + std::to_string(t) + " s" + (tools ? ", tools on" : "");
        ASSERT_EQ(record.lanes.size(), 1u) << where;
        const draw::FrameRecord::Lane& lane = record.lanes.front();
        const auto inside = [&](ImVec2 p) {
          return p.x >= lane.shown.x - 0.5f && p.x <= lane.shown.z + 0.5f && p.y >= lane.shown.y - 0.5f && p.y <= lane.shown.w + 0.5f;
        };
        const b2Body* slope = window.playback().lesson().scene().body("slope");
        ASSERT_NE(slope, nullptr);
        for (const b2Fixture* fixture = slope->GetFixtureList(); fixture != nullptr; fixture = fixture->GetNext()) {
          ASSERT_EQ(fixture->GetType(), b2Shape::e_polygon);
          const auto* shape = static_cast<const b2PolygonShape*>(fixture->GetShape());
          for (int k = 0; k < shape->m_count; ++k) {
            const ImVec2 corner = lane.camera.to_screen(slope->GetWorldPoint(shape->m_vertices[k]));
            EXPECT_TRUE(inside(corner)) << where << ": the slope's corner at (" << corner.x << ", " << corner.y
                                        << ") px, the world shows " << lane.shown.x << " to " << lane.shown.z << " by "
                                        << lane.shown.y << " to " << lane.shown.w;
          }
        }
        bool angle_shown = false;
        for (std::size_t i = 0; i < lane.texts.size(); ++i) {
          if (lane.texts[i] != std::string(angle) + "\u00b0") continue;
          angle_shown = inside(ImVec2(lane.labels[i].x, lane.labels[i].y)) && inside(ImVec2(lane.labels[i].z, lane.labels[i].w));
        }
        EXPECT_TRUE(angle_shown) << where << ": the angle's label";
      }
    }
  }
}

// A teacher's trial (issue 31): pulley's wheel hung over empty space, nothing holding it. It is
// now held by an arm from the nearest fixed body, the table's corner, to its axle: half way
// along the line from the corner to the axle, the picture is the outline's ink, not the sky.
TEST(WorldLabels, APulleyIsHeldByAnArmFromTheTable) {
  draw::HeadlessRenderer renderer(draw::frame_width, draw::frame_height);
  draw::LessonAt at("pulley", {}, 0.5);
  draw::FrameRecord record;
  const draw::Image image = renderer.render(*at.lesson, at.framing, &record);
  ASSERT_EQ(at.scene().ropes().size(), 1u);
  const Rope& rope = at.scene().ropes().front();
  const b2Vec2 axle = 0.5f * (rope.pulley_a + rope.pulley_b);
  const b2AABB table = lessons::body_box(at.scene().body("table"));
  const b2Vec2 corner(table.upperBound.x, table.upperBound.y);
  ASSERT_GT(axle.x, corner.x) << "the pulley is past the table's edge";
  const draw::Camera& camera = record.lanes.front().camera;
  const ImVec2 half_way = camera.to_screen(0.5f * (corner + axle));
  const std::uint8_t* pixel = image.pixel(static_cast<int>(half_way.x), static_cast<int>(half_way.y));
  const draw::Theme& theme = draw::theme(draw::ThemeName::light);
  const ImVec4 outline = ImGui::ColorConvertU32ToFloat4(theme.outline), sky = ImGui::ColorConvertU32ToFloat4(theme.sky);
  const auto near = [&](const ImVec4& colour) {
    return std::abs(pixel[0] - 255.0f * colour.x) < 24.0f && std::abs(pixel[1] - 255.0f * colour.y) < 24.0f &&
           std::abs(pixel[2] - 255.0f * colour.z) < 24.0f;
  };
  EXPECT_TRUE(near(outline)) << "at (" << half_way.x << ", " << half_way.y << ") px: " << int(pixel[0]) << ", " << int(pixel[1])
                             << ", " << int(pixel[2]);
  EXPECT_FALSE(near(sky));
}

// Before the first step no contact has been solved: the free-body inset of a block resting on a
// floor showed its weight and no normal force, unbalanced. At t = 0 it draws the body with no
// arrows and says when the forces come; after a step, the forces and the net force.
TEST(FreeBodyInset, AtTheStartSaysTheForcesComeWithTheRunInsteadOfShowingTheWeightAlone) {
  for (const auto& [width, height] : {std::pair(1280, 720), std::pair(1920, 1080)}) {
    draw::HeadlessRenderer renderer(width, height);
    for (const char* lesson : {"push", "incline", "terrain"}) {
      for (const double t : {0.0, 0.5}) {
        draw::LessonAt at(lesson, {}, t);
        draw::FrameRecord record;
        renderer.render(*at.lesson, at.framing, &record);
        std::string all;
        for (const draw::ShownText& text : record.texts) all += text.text + "\n";
        const std::string where = std::string(lesson) + " at " + std::to_string(t) + " s, " + std::to_string(width);
        const bool said = all.find("forces appear once the run starts\n") != std::string::npos ||
                          all.find("forces appear once\nthe run starts\n") != std::string::npos;
        EXPECT_EQ(said, t == 0.0) << where << ": " << all;
        EXPECT_EQ(all.find("net force: ") != std::string::npos, t > 0.0) << where;
      }
    }
  }
}

// Whether a label's box lies on a moving body as drawn: its polygons and its circles.
bool on_body(const ImVec4& label, const b2Body* body, const draw::Camera& camera) {
  for (const b2Fixture* fixture = body->GetFixtureList(); fixture != nullptr; fixture = fixture->GetNext()) {
    if (fixture->GetType() == b2Shape::e_polygon) {
      const auto* shape = static_cast<const b2PolygonShape*>(fixture->GetShape());
      std::vector<ImVec2> polygon;
      for (int k = 0; k < shape->m_count; ++k) polygon.push_back(camera.to_screen(body->GetWorldPoint(shape->m_vertices[k])));
      if (overlaps_polygon(label, polygon)) return true;
    } else if (fixture->GetType() == b2Shape::e_circle) {
      const auto* shape = static_cast<const b2CircleShape*>(fixture->GetShape());
      const ImVec2 centre = camera.to_screen(body->GetWorldPoint(shape->m_p));
      const float radius = surface_radius(*shape) * camera.pixels_per_metre;  // as drawn
      // The box's point nearest the centre.
      const float x = std::clamp(centre.x, label.x, label.z), y = std::clamp(centre.y, label.y, label.w);
      if (std::hypot(x - centre.x, y - centre.y) < radius) return true;
    }
  }
  return false;
}

// The trial: a slope's angle drawn under the block, a driven plank's word under the block on
// it, forces' values on the bodies their arrows push (a wheel's normal force on the wheel, the
// top block's on the bottom block). In the lessons with slopes, driven bodies, wheels, stacks
// and ropes, at the start and as they run, at 1280 × 720 and with projector text: the slope's
// angle and the word "driven" are placed labels, and they lie on no moving body (only a
// contact's word goes into the body under it, and a force's value where only that is beside its
// arrow), nor on each other, nor on an arrow (with every other rule of check_layout).
TEST(WorldLabels, TheSlopesAngleTheDrivenWordAndTheForcesValuesKeepOffTheBodiesAndEachOther) {
  struct Expected {
    const char* lesson;
    bool slope_angle, driven;  // shown whenever its lane is: the slope's corner, the driven body
  };
  const Expected lessons_tried[] = {{"incline", true, false},        {"wedge", false, true},
                                    {"check_the_article", false, false}, {"driven_wheel", false, false},
                                    {"stacked_blocks", false, false}, {"pulley", false, false}};
  const double times[] = {0.0, 0.5, 1.5, 3.0};
  int checked = 0;
  for (const Screen& screen : {screens[0], screens[3], screens[4]}) {
    draw::HeadlessRenderer renderer(screen.width, screen.height, draw::ThemeName::light, screen.scale);
    for (const Expected& expected : lessons_tried) {
      for (const double t : times) {
        draw::LessonAt at(expected.lesson, {}, t);
        draw::FrameRecord record;
        renderer.render(*at.lesson, at.framing, &record);
        char when[32];
        std::snprintf(when, sizeof when, " at %.1f s, ", t);
        const std::string where = expected.lesson + std::string(when) + screen.name;
        check_layout(record, *at.lesson, where);
        int angles = 0, driven = 0;
        for (const draw::FrameRecord::Lane& lane : record.lanes) {
          ASSERT_EQ(lane.texts.size(), lane.labels.size()) << where;
          for (std::size_t i = 0; i < lane.labels.size(); ++i) {
            const std::string& text = lane.texts[i];
            const bool angle = text.size() > 2 && text.compare(text.size() - 2, 2, "\u00b0") == 0;
            angles += angle ? 1 : 0;
            driven += text == "driven" ? 1 : 0;
            ++checked;
            if (text.find("sticking") != std::string::npos || text.find("slipping") != std::string::npos) continue;
            // A force's value goes beside its arrow first (issue 31: kept off the bodies, stacked_blocks'
            // normal forces went lines away from theirs); on a body, in its opaque box, where only
            // that is near. ForceLabels.EveryForceWithAnArrowHasItsValueBesideIt checks where they go.
            const auto ends = [&](const std::string& tail) {
              return text.size() >= tail.size() && text.compare(text.size() - tail.size(), tail.size(), tail) == 0;
            };
            // (A friction between two moving bodies names the body it acts on: "2.20 N on top".)
            const bool names_its_body = text.find(" N on ") != std::string::npos;
            if (ends(" N") || ends(" N\u00b7m") || ends(" in all") || names_its_body) continue;
            const ImVec4 label = drawn(lane.labels[i]);
            for (const auto& [name, body] : at.lesson->scene().bodies()) {
              if (body->GetType() != b2_dynamicBody) continue;
              EXPECT_FALSE(on_body(label, body, lane.camera))
                  << where << ": \"" << text << "\" at " << text_of(label) << " lies on " << name;
            }
          }
        }
        EXPECT_TRUE(!expected.slope_angle || angles >= 1) << where << ": the slope's angle is not a placed label";
        EXPECT_TRUE(!expected.driven || driven >= 1) << where << ": the word \"driven\" is not a placed label";
      }
    }
  }
  EXPECT_GE(checked, 150);
}

// The distance from a label's box to an arrow's centre line, tail to tip (0 where they meet):
// the nearest of the box's corners to the segment and of the segment's ends to the box, which is
// exact for a segment that does not cross the box.
float box_to_arrow(const ImVec4& box, const draw::DrawnSegment& arrow) {
  if (overlaps(box, draw::DrawnSegment{arrow.from, arrow.to, 0.0f})) return 0.0f;
  const auto point_to_box = [&](ImVec2 p) {
    return std::hypot(std::max({box.x - p.x, 0.0f, p.x - box.z}), std::max({box.y - p.y, 0.0f, p.y - box.w}));
  };
  const auto point_to_segment = [&](ImVec2 p) {
    const ImVec2 d = sub(arrow.to, arrow.from);
    const float span = d.x * d.x + d.y * d.y;
    const float f = span > 0.0f ? std::clamp(((p.x - arrow.from.x) * d.x + (p.y - arrow.from.y) * d.y) / span, 0.0f, 1.0f) : 0.0f;
    return length(sub(p, add(arrow.from, mul(d, f))));
  };
  float nearest = std::min(point_to_box(arrow.from), point_to_box(arrow.to));
  for (const ImVec2 corner : {ImVec2(box.x, box.y), ImVec2(box.z, box.y), ImVec2(box.z, box.w), ImVec2(box.x, box.w)}) {
    nearest = std::min(nearest, point_to_segment(corner));
  }
  return nearest;
}

// What a reader needs of a value's leader (LabelPlacer::place_beside's fallback), measured from
// the leader's recorded ends against every arrow and box the frame drew, rather than trusted to
// the rules leader_line() keeps: no longer than longest_leader() (three lines of the
// value's text, its box's height without the placer's padding), starting on the value's own
// arrow and ending on its box (a pixel each way: the ends are floats on the padded box and the
// arrow's line), and crossing no other value's box as drawn and no other arrow's centre line
// (but within half a line of its start, where forces at one contact start together), each of
// which would join the value to another force. Empty when it meets every rule.
std::vector<std::string> leader_faults(const std::vector<draw::LabelPlacer::ForceLabel>& forces, std::size_t index) {
  std::vector<std::string> faults;
  const draw::LabelPlacer::ForceLabel& force = forces[index];
  if (!force.leader || !force.box) return faults;
  const draw::DrawnSegment& leader = *force.leader;
  const ImVec4& padded = *force.box;
  const ImVec2 size(padded.z - padded.x - 4.0f, padded.w - padded.y - 4.0f);  // the placer's 2 px of padding off
  const std::string name = force.text + " at " + text_of(drawn(padded));
  const float span = length(sub(leader.to, leader.from));
  if (span > draw::LabelPlacer::longest_leader(size) + 1e-3f) {
    faults.push_back(name + ": its leader is " + std::to_string(span) + " px, longer than three lines (" +
                     std::to_string(draw::LabelPlacer::longest_leader(size)) + " px)");
  }
  const float from_arrow = box_to_arrow(ImVec4(leader.from.x, leader.from.y, leader.from.x, leader.from.y), force.arrow);
  const float to_box = std::hypot(std::max({padded.x - leader.to.x, 0.0f, leader.to.x - padded.z}),
                                  std::max({padded.y - leader.to.y, 0.0f, leader.to.y - padded.w}));
  if (from_arrow > 1.0f) faults.push_back(name + ": its leader starts " + std::to_string(from_arrow) + " px off its own arrow");
  if (to_box > 1.0f) faults.push_back(name + ": its leader ends " + std::to_string(to_box) + " px off its value");
  const auto side = [](ImVec2 a, ImVec2 b, ImVec2 p) { return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x); };
  for (std::size_t j = 0; j < forces.size(); ++j) {
    if (j == index) continue;
    const draw::LabelPlacer::ForceLabel& other = forces[j];
    const std::string whose = other.text.empty() ? std::string("another force's") : other.text + "'s";
    if (other.box && overlaps(drawn(*other.box), draw::DrawnSegment{leader.from, leader.to, 0.0f})) {
      faults.push_back(name + ": its leader crosses the value " + other.text + " at " + text_of(drawn(*other.box)));
    }
    const draw::DrawnSegment& arrow = other.arrow;
    const bool crossing = side(leader.from, leader.to, arrow.from) * side(leader.from, leader.to, arrow.to) < 0.0f &&
                          side(arrow.from, arrow.to, leader.from) * side(arrow.from, arrow.to, leader.to) < 0.0f;
    if (!crossing) continue;
    // Where the forces at a contact start together another arrow may pass within half a line of
    // the value's own: a leader that crosses it there leaves from where they meet, and is read
    // from there. Further along it joins the value to that arrow too.
    const ImVec2 d = sub(leader.to, leader.from), e = sub(arrow.to, arrow.from), w = sub(arrow.from, leader.from);
    const float along = (w.x * e.y - w.y * e.x) / (d.x * e.y - d.y * e.x) * length(d);
    if (along > 0.5f * size.y) {
      faults.push_back(name + ": its leader crosses " + whose + " arrow " + std::to_string(along) + " px from its start");
    }
  }
  return faults;
}

// Every force with an arrow has its value drawn, beside its own arrow, in the world and in the
// free-body inset (issue 31, a teacher's trial in projector mode at 1920 × 1080): tipping_box at
// 2.487 s with the distance marks on lost its friction's 2.59 N in both themes; stacked_blocks'
// normal forces, driven_wheel's friction and a ladder's weight had theirs far from their arrows.
// "Beside" is the label placer's own search (LabelPlacer::place_beside): the value's box starts
// at most one and a half arrow widths past the tip (draw_force's reach), moved at most
// beside_reach() in x and y, so its box lies within that of the arrow.
TEST(ForceLabels, EveryForceWithAnArrowHasItsValueBesideItInTheWorldAndTheInset) {
  const ImVec2 display(1920.0f, 1080.0f);
  draw::HeadlessContext gl;
  draw::ImGuiHost host(nullptr);
  const std::pair<std::string, double> runs[] = {{"tipping_box", 2.487},
                                                 {"stacked_blocks", 2.487},
                                                 {"stacked_blocks", 1.0},
                                                 {"driven_wheel", 2.487},
                                                 {"driven_wheel", 0.5},
                                                 {std::string(FRICTIONLAB_STUDENT_TRIAL) + "/ladder.lua", 1.0},
                                                 {std::string(FRICTIONLAB_STUDENT_TRIAL) + "/ladder.lua", 1.9}};
  // The distance from a box to an arrow's line (0 when they meet).
  const auto distance = [](const ImVec4& box, const draw::DrawnSegment& arrow) {
    float nearest = 1e9f;
    for (int i = 0; i <= 200; ++i) {
      const float f = static_cast<float>(i) / 200.0f;
      const ImVec2 p(arrow.from.x + f * (arrow.to.x - arrow.from.x), arrow.from.y + f * (arrow.to.y - arrow.from.y));
      const float dx = std::max({box.x - p.x, 0.0f, p.x - box.z}), dy = std::max({box.y - p.y, 0.0f, p.y - box.w});
      nearest = std::min(nearest, std::hypot(dx, dy));
    }
    return nearest;
  };
  int leaders = 0;  // values joined to their arrows by a leader
  const auto check = [&](const std::vector<draw::LabelPlacer::ForceLabel>& forces, const std::string& where) -> int {
    int labelled = 0;
    for (std::size_t i = 0; i < forces.size(); ++i) {
      const draw::LabelPlacer::ForceLabel& force = forces[i];
      if (force.text.empty()) continue;  // a foot's share of a normal force labelled "in all" at the longest
      ++labelled;
      EXPECT_TRUE(force.box.has_value()) << where << ": the value " << force.text << " is not drawn";
      if (!force.box) continue;
      const ImVec4& box = *force.box;
      const ImVec2 size(box.z - box.x - 4.0f, box.w - box.y - 4.0f);  // the placer's 2 px of padding off
      if (force.leader) {
        // No free place beside its arrow: joined to it by a leader, which must meet a reader's
        // rules (leader_faults), and then the value is at most the leader's longest off its arrow.
        for (const std::string& fault : leader_faults(forces, i)) ADD_FAILURE() << where << ": " << fault;
        EXPECT_LE(distance(box, force.arrow), draw::LabelPlacer::longest_leader(size) + 1.0f)
            << where << ": " << force.text << " at " << text_of(box) << " is further from its arrow than its leader's longest";
        ++leaders;
        continue;
      }
      const ImVec2 reach = draw::LabelPlacer::beside_reach(size);
      const float thickness = 2.0f * force.arrow.half_width;
      const float allowed = 1.5f * thickness + std::hypot(reach.x, reach.y) + 1.0f;
      EXPECT_LE(distance(box, force.arrow), allowed)
          << where << ": " << force.text << " at " << text_of(box) << " is far from its arrow from (" << force.arrow.from.x
          << ", " << force.arrow.from.y << ") to (" << force.arrow.to.x << ", " << force.arrow.to.y << ")";
    }
    return labelled;
  };
  int worlds = 0, insets = 0;
  // On a projector the world alone (its inset cannot be read there, and is left out:
  // FreeBody.LeftOutWhereItsArrowsCannotBeRead); on the screen, the world and the inset.
  for (const bool projector : {true, false}) {
  for (const draw::ThemeName theme : {draw::ThemeName::light, draw::ThemeName::dark}) {
    for (const auto& [lesson, t] : runs) {
      ClassroomOptions options = class_window(lessons::resolve_lesson(lesson), {"1920x1080", 1920, 1080, projector});
      options.window.theme = theme;
      options.window.tools.distance_marks = true;
      Classroom window(options);
      draw_window_frame(gl, host, window, display);
      window.run_to(t);
      draw_window_frame(gl, host, window, display);
      draw::FrameRecord record;
      draw_window_frame(gl, host, window, display, 0.0, &record);
      const std::string where = std::filesystem::path(lesson).stem().string() + " at " + std::to_string(t) + " s" +
                                (theme == draw::ThemeName::dark ? ", dark" : "") + (projector ? ", projector" : "");
      for (const draw::FrameRecord::Lane& lane : record.lanes) worlds += check(lane.forces, where + ", world");
      ASSERT_EQ(record.free_body.drawn, !projector) << where;
      insets += check(record.free_body.forces, where + ", free-body inset");
    }
  }
  }
  EXPECT_GE(worlds, 40);
  EXPECT_GE(insets, 20);
  // The runs' crowded contacts (stacked_blocks' blocks, driven_wheel's wheel, the ladder's foot)
  // give values with a leader (30 of them when written), so the leader's rules above are tried.
  EXPECT_GE(leaders, 10);
}

// "Beside its own arrow" as a measured rule, in one picture (a lane of the world, or the inset):
// every value drawn, the gap between its box as drawn and its own arrow at most one line of its
// text (the box's height without the placer's padding: a reader looks one line away, not
// several), and every other arrow of the picture further from it than its own, so it cannot be
// read as another's. Returns how many values it checked; with a `broken` count, it counts the
// values that break the rule there instead of failing (the pictures not yet held to it).
//
// Short arrows too (issue 31: tipping_box's friction label sat 170 px from its short arrow,
// push's applied force 110 px). Where no free place is beside its arrow (a friction of a few
// pixels where a normal force starts), a value may stand further off with a leader: a thin line
// that starts on its own arrow and ends on its box, which says whose it is as well; it too is
// nearer its own arrow than any other.
int check_beside_own_arrow(const std::vector<draw::LabelPlacer::ForceLabel>& forces, const std::string& where,
                           int* broken = nullptr, int* nearer_another = nullptr) {
  int checked = 0;
  for (std::size_t i = 0; i < forces.size(); ++i) {
    const draw::LabelPlacer::ForceLabel& force = forces[i];
    if (force.text.empty()) continue;  // a foot's share of a normal force labelled "in all" at the longest
    if (broken != nullptr) {
      *broken += force.box.has_value() ? 0 : 1;
    } else {
      EXPECT_TRUE(force.box.has_value()) << where << ": the value " << force.text << " is not drawn";
    }
    if (!force.box) continue;
    const ImVec4 box = drawn(*force.box);
    const float line = box.w - box.y;
    ++checked;
    const float own = box_to_arrow(box, force.arrow);
    if (force.leader) {
      std::vector<std::string> faults = leader_faults(forces, i);
      // Its leader says whose it is, but a value nearer another arrow than its own is read as
      // that one's first (issue 31: stacked_blocks' pressing force, 9.81 N, by the bottom block's
      // weight, 27 px from it and 43 px from its own arrow, in projector mode).
      for (std::size_t j = 0; j < forces.size(); ++j) {
        if (j == i || box_to_arrow(box, forces[j].arrow) > own) continue;
        if (nearer_another != nullptr) {
          ++*nearer_another;
          continue;
        }
        faults.push_back(force.text + " at " + text_of(box) + " is " + std::to_string(own) + " px from its own arrow but " +
                         std::to_string(box_to_arrow(box, forces[j].arrow)) + " px from " +
                         (forces[j].text.empty() ? std::string("another") : forces[j].text + "'s") + " arrow");
      }
      if (broken != nullptr) {
        *broken += faults.empty() ? 0 : 1;
      } else {
        for (const std::string& fault : faults) ADD_FAILURE() << where << ": " << fault;
      }
      continue;
    }
    if (broken != nullptr) {
      bool nearest = true;
      for (std::size_t j = 0; j < forces.size(); ++j) nearest = nearest && (j == i || own < box_to_arrow(box, forces[j].arrow));
      *broken += (own <= line && nearest) ? 0 : 1;
      continue;
    }
    const auto arrow_text = [](const draw::DrawnSegment& arrow) {
      return text_of(ImVec4(arrow.from.x, arrow.from.y, arrow.to.x, arrow.to.y)) + " (tail–tip)";
    };
    EXPECT_LE(own, line) << where << ": " << force.text << " at " << text_of(box) << " is " << own
                         << " px from its arrow " << arrow_text(force.arrow) << ", more than a line (" << line << " px)";
    for (std::size_t j = 0; j < forces.size(); ++j) {
      if (j == i) continue;
      const float other = box_to_arrow(box, forces[j].arrow);
      EXPECT_LT(own, other) << where << ": " << force.text << " at " << text_of(box) << " is " << own
                            << " px from its arrow " << arrow_text(force.arrow) << " but " << other << " px from "
                            << (forces[j].text.empty() ? std::string("another") : forces[j].text + "'s") << " arrow "
                            << arrow_text(forces[j].arrow);
    }
  }
  return checked;
}

// The window run to `t` and drawn twice (the second frame sees the first's layout), the second's
// record.
draw::FrameRecord recorded_at(draw::HeadlessContext& gl, draw::ImGuiHost& host, Classroom& window, ImVec2 display, double t) {
  window.run_to(t);
  draw_window_frame(gl, host, window, display);
  draw::FrameRecord record;
  draw_window_frame(gl, host, window, display, 0.0, &record);
  return record;
}

// " at 1.73 s", for a failure's message.
std::string said_at(double t) {
  char when[48];
  std::snprintf(when, sizeof when, " at %.2f s", t);
  return when;
}

// Every built-in lesson at its defaults in the window at 1920 × 1080, in projector mode or not, in
// a theme, at its opening, half way and at its end: the frame's record, with the lesson's name,
// when (" at 1.73 s") and the lesson. `help`: with the help panel open (F1).
void each_lesson_frame(bool projector, draw::ThemeName theme,
                       const std::function<void(const std::string& lesson, const std::string& when,
                                                const draw::FrameRecord& record, const lessons::Lesson& at)>& check,
                       bool help = false) {
  const ImVec2 display(1920.0f, 1080.0f);
  draw::HeadlessContext gl;
  draw::ImGuiHost host(nullptr);
  for (const lessons::CatalogEntry& entry : lessons::catalog()) {
    ClassroomOptions options = class_window(entry.path, {"1920x1080", 1920, 1080, projector});
    options.window.theme = theme;
    options.window.help = help;
    Classroom window(options);
    draw_window_frame(gl, host, window, display);
    const double end = window.playback().lesson().duration();
    for (const double t : {0.2, 0.5 * end, end}) {
      const draw::FrameRecord record = recorded_at(gl, host, window, display, t);
      check(entry.name, said_at(t), record, window.playback().lesson());
    }
  }
}

// Every built-in lesson in the window at 1920 × 1080, in projector mode and not, light and dark,
// at its opening (a fifth of a second in: no arrows before the first step), half way and at its
// end: each force's value beside its own arrow by check_beside_own_arrow's rule, in the world and
// in the free-body inset, with every rule of check_layout (issue 31, item 6: stacked_blocks' "29.4 N"
// sat 150 px from its arrow, tipping_box's friction beside the push). Before LabelPlacer::place_beside
// looked beside the arrow itself, 1566 checks failed here, in every lesson.
//
// Not yet in the pictures below, where arrows crowd more than the placer's places beside them
// and its leaders of at most three lines allow (issue 31, item 6, left open; each still fails
// the rule, and the test fails when one comes to meet it, so the list only shrinks): the world's
// lanes of contact_area (both modes), and in projector mode those of friction_models and
// where_methods_fail. stacked_blocks, driven_wheel and tipping_box left it in projector mode
// when draw_world came to place a picture's values again with those that found no place
// first (tipping_box's friction of a few pixels, 24.7 N at 1.24 s, had been 96 px off), and
// friction_models on a screen when it tried the shortest arrow's value first too (its drags'
// values, 2.07 N and 0.856 N at 0.2 s, had been 96 and 108 px off).
//
// A value with a leader is also nearer its own arrow than any other (issue 31: stacked_blocks'
// pressing force, 9.81 N, sat by the bottom block's weight). driven_wheel in projector mode came
// to meet that when LabelPlacer::place_beside looked for such a place first and draw_world placed
// again, first, a value by another arrow; not yet, and held to still break it as above:
// stacked_blocks' world on a screen (its 9.81 N values by the friction between the blocks, no
// free place nearer their own arrows within a leader's reach), friction_models' world and wedge's
// inset on a screen. terrain's world on a screen came to meet it when a weight that met a
// contact's arrow came to slide back up its line rather than the contact's force past it, and
// left it again when the weight came to start at its centre of mass always (a textbook's weight
// outweighs a value 0.4 px nearer a friction's arrow than its own). stacked_blocks' world in
// projector mode came to meet it, and terrain's on a screen again, when LabelPlacer::places_by_arrow
// came to slide a value along each side of its arrow in quarter lines, past the tail and the tip
// (the top block's 9.81 N weight, 38–53 px off with a leader, found the free side of its tail),
// and draw_world to place the values before each contact's word by its dot in turn (the
// pressing force, 9.81 N at 2.12 s, 74 px off, took the gap "sticking" held by its tip).
//
// stacked_blocks' world in projector mode, and friction_models' on a screen, went back onto the
// first list when arrows under twice the legible length came to be lengthened in order
// (drawn_arrow_pixels) rather than all drawn the same: their short arrows grew, and at the run's
// end stacked_blocks' top block's 9.81 N weight (or, with a quarter's lengthening, the floor's
// 29.4 N), and friction_models' weights at 0.2 s, found no place beside their own arrows. A
// smaller force drawn longer than a larger one misleads a class more than a value 85 px off.
// It left that list again when draw_world came to place a picture's values before the contacts'
// words that stood away from their dots (ForceLabels.StackedBlocksFrictionsStandBesideTheir...);
// friction_models' on a screen left it when a value with no place beside its arrow off the
// bodies' outlines came to be sought, with a leader, at every place half a line apart within a
// leader's reach (LabelPlacer::place_with_leader), not only along the eight rays round its tip.
// stacked_blocks' world on a screen came to have every value nearer its own arrow when the
// contacts came to be drawn where the bodies touch at the step's end, not a step behind.
// When two arrows along one line came to move apart only until they stood a gap apart, not a
// whole gap more (tipping_box's normal force had been drawn near the box's far corner), wedge's
// inset on a screen came to meet it, and friction_models' world on a screen came back onto it:
// its weights' values at 0.2 s, 40 px off with leaders, stand 24 px from the normal forces'
// arrows, now that those are drawn where they act, a gap from the weights.
// stacked_blocks' world on a screen came back onto the second list when arrows of different
// bodies along one line came to be set side by side (set_apart_along_one_line): the top
// block's weight, hidden under the normal force it presses the bottom block with but for a
// stub, is drawn whole, and the normal forces stand a gap either side of it, so that at 2.12 s
// the friction on the bottom block, 1.57 N, has its value 57 px off with a leader that passes
// 55 px from the top block's normal force. Every arrow seen, and which block's it is, outweighs
// a leader 2 px nearer another arrow than its own.
// The pictures the test below does not yet hold to check_beside_own_arrow's rule, and those it
// holds to it but for a value's being nearer another arrow than its own (a leader's).
bool not_yet(const std::string& lesson, bool projector, bool inset) {
  if (lesson == "contact_area") return !inset;
  if (lesson == "where_methods_fail") return projector && !inset;
  if (lesson == "friction_models") return projector && !inset;
  return false;
}
bool nearer_another_not_yet(const std::string& lesson, bool projector, bool inset) {
  if (lesson == "friction_models" || lesson == "stacked_blocks") return !projector && !inset;
  return false;
}

TEST(ForceLabels, EachValueIsWithinALineOfItsOwnArrowAndNearerItThanAnyOther) {
  std::map<std::string, int> still_nearer_another;
  int worlds = 0, insets = 0;
  // The pictures not yet held to the rule, and how many of their values break it: a picture
  // that comes to meet the rule must leave the list, so that it is held to it from then on.
  std::map<std::string, int> still_broken;
  for (const bool projector : {true, false}) {
    for (const draw::ThemeName theme : {draw::ThemeName::light, draw::ThemeName::dark}) {
      each_lesson_frame(projector, theme, [&](const std::string& lesson, const std::string& when,
                                              const draw::FrameRecord& record, const lessons::Lesson& at) {
        const std::string where =
            lesson + when + (projector ? ", projector" : "") + (theme == draw::ThemeName::dark ? ", dark" : "");
        check_layout(record, at, where);
        const std::string world_key = lesson + (projector ? ", projector" : "") + ", world";
        const std::string inset_key = lesson + (projector ? ", projector" : "") + ", inset";
        for (const draw::FrameRecord::Lane& lane : record.lanes) {
          if (not_yet(lesson, projector, false)) {
            check_beside_own_arrow(lane.forces, where, &still_broken[world_key]);
          } else if (nearer_another_not_yet(lesson, projector, false)) {
            worlds += check_beside_own_arrow(lane.forces, where + ", world", nullptr, &still_nearer_another[world_key]);
          } else {
            worlds += check_beside_own_arrow(lane.forces, where + ", world");
          }
        }
        // A projector's inset cannot be read, and is left out (FreeBody.LeftOutWhereItsArrowsCannotBeRead).
        EXPECT_FALSE(projector && record.free_body.drawn) << where << ": the free-body inset is drawn on a projector";
        if (not_yet(lesson, projector, true)) {
          check_beside_own_arrow(record.free_body.forces, where, &still_broken[inset_key]);
        } else if (nearer_another_not_yet(lesson, projector, true)) {
          insets += check_beside_own_arrow(record.free_body.forces, where + ", free-body inset", nullptr,
                                           &still_nearer_another[inset_key]);
        } else {
          insets += check_beside_own_arrow(record.free_body.forces, where + ", free-body inset");
        }
      });
    }
  }
  EXPECT_GE(worlds, 300);
  EXPECT_GE(insets, 200);
  for (const auto& [picture, broken] : still_broken) {
    EXPECT_GT(broken, 0) << picture << " now meets the rule: take it off the not_yet list";
  }
  for (const auto& [picture, broken] : still_nearer_another) {
    EXPECT_GT(broken, 0) << picture << " now has every value nearer its own arrow: take it off nearer_another_not_yet";
  }
}

// With the help open on a projector the frame above the help's strip shrank, and the world and
// the plots' row with it: stacked_blocks' force labels crowded and its legend's scale bar was
// cut under "20 cm" (issue 31). The test above's rules in the window on a projector with the help
// open, each lesson at its opening, half way and at its end (its values beside their own arrows,
// with its pictures not yet held to that left out as there, and check_layout's: clear of each
// other, the arrows and the inset), and the world's and the legend's words whole, the scale bar's
// length among them (noted only where the bar under it is whole too). Light only: the labels are
// placed alike in both themes, and under ASan + UBSan this runs eight times slower.
TEST(ForceLabels, EveryValueStandsBesideItsArrowAndTheScaleBarIsWholeWithTheHelpOpenOnAProjector) {
  int values = 0, scale_bars = 0;
  each_lesson_frame(true, draw::ThemeName::light, [&](const std::string& lesson, const std::string& when,
                                                       const draw::FrameRecord& record, const lessons::Lesson& at) {
    const std::string where = lesson + when + ", projector, with the help open";
    const ImGuiWindow* help = ImGui::FindWindowByName("Help (F1 shows and hides it)");
    ASSERT_TRUE(help != nullptr && help->Active) << where;
    check_layout(record, at, where);
    for (const draw::FrameRecord::Lane& lane : record.lanes) {
      if (!not_yet(lesson, true, false)) values += check_beside_own_arrow(lane.forces, where + ", world");
    }
    draw::FrameRecord world_texts = record;
    std::erase_if(world_texts.texts, [](const draw::ShownText& text) {
      return !text.panel.ends_with("###legend") && !text.panel.ends_with("###world");
    });
    for (const draw::ShownText& text : world_texts.texts) scale_bars += text.text.ends_with(" cm") || text.text.ends_with(" m");
    check_texts(world_texts, where);
  }, true);
  EXPECT_GE(values, 100);
  // Every frame has its bar: 15 lessons at three moments.
  EXPECT_EQ(scale_bars, static_cast<int>(lessons::catalog().size()) * 3);
}

// stacked_blocks in the window at 1920 × 1080 in projector mode, light and dark, at each of
// `times` (the run's end for one past it): each frame's record, with where (" at 2.12 s, dark").
// `check` is given the lesson as the frame shows it.
void stacked_blocks_on_a_projector(const std::vector<double>& times,
                                   const std::function<void(const std::string& where, const draw::FrameRecord& record,
                                                            const lessons::Lesson& at)>& check) {
  const ImVec2 display(1920.0f, 1080.0f);
  draw::HeadlessContext gl;
  draw::ImGuiHost host(nullptr);
  for (const draw::ThemeName theme : {draw::ThemeName::light, draw::ThemeName::dark}) {
    ClassroomOptions options = class_window(lessons::resolve_lesson("stacked_blocks"), {"1920x1080", 1920, 1080, true});
    options.window.theme = theme;
    Classroom window(options);
    draw_window_frame(gl, host, window, display);
    for (const double wanted : times) {
      const double t = std::min(wanted, window.playback().lesson().duration());
      const draw::FrameRecord record = recorded_at(gl, host, window, display, t);
      check("stacked_blocks" + said_at(t) + (theme == draw::ThemeName::dark ? ", dark" : ""), record, window.playback().lesson());
    }
  }
}

// stacked_blocks at its end (4.23 s) in the window at 1920 × 1080 in projector mode, both themes:
// each friction's value within a line of its own arrow and nearer it than any other, and each
// contact's word drawn. Issue 31: the friction on the bottom block, 3.43 N, stood 127 px from its
// arrow, for "← slipping" had taken the only place beside it (37 px between the word and the top
// block's weight label, where a value needs 39 px); a picture whose values find no place beside
// their arrows is placed again with the values first and the words after.
TEST(ForceLabels, StackedBlocksFrictionsStandBesideTheirArrowsAtTheEndOnAProjector) {
  int frictions = 0;
  stacked_blocks_on_a_projector({std::numeric_limits<double>::infinity()}, [&](const std::string& where,
                                                                              const draw::FrameRecord& record, const lessons::Lesson&) {
    int words = 0;
    for (const draw::FrameRecord::Lane& lane : record.lanes) {
      for (const std::string& text : lane.texts) words += text.find("slipping") != std::string::npos ? 1 : 0;
      std::vector<draw::LabelPlacer::ForceLabel> with_frictions_held;
      for (std::size_t i = 0; i < lane.forces.size(); ++i) {
        draw::LabelPlacer::ForceLabel force = lane.forces[i];
        // The other values are arrows here, the rule held for the frictions' values alone.
        if (force.kind != ForceKind::friction) force.text.clear();
        frictions += force.kind == ForceKind::friction ? 1 : 0;
        with_frictions_held.push_back(force);
      }
      check_beside_own_arrow(with_frictions_held, where);
    }
    // Both contacts slip at the end: the floor's and the blocks'.
    EXPECT_EQ(words, 2) << where;
  });
  EXPECT_EQ(frictions, 2 * 3);
}

// stacked_blocks at 0.2 s and 2.12 s in the window at 1920 × 1080 in projector mode, both
// themes: every value within a line of its own arrow and nearer it than any other (a value with a
// leader, nearer its own arrow than any other), and both contacts' words drawn. Issue 31: the top
// block's 9.81 N weight stood 53 px (0.2 s) and 38 px (2.12 s) from its arrow with a leader,
// nearer the normal forces, for no place by its middle or tip was free; at 2.12 s the pressing
// force on the lower block, 9.81 N, stood 74 px off, 21 px from the lower block's weight, for
// "sticking" held the one gap by its tip.
TEST(ForceLabels, StackedBlocksWeightsAndPressingForceStandBesideTheirArrowsOnAProjector) {
  int values = 0;
  stacked_blocks_on_a_projector({0.2, 2.12}, [&](const std::string& where, const draw::FrameRecord& record, const lessons::Lesson&) {
    int words = 0;
    for (const draw::FrameRecord::Lane& lane : record.lanes) {
      for (const std::string& text : lane.texts) {
        words += text.find("sticking") != std::string::npos || text.find("slipping") != std::string::npos ? 1 : 0;
      }
      values += check_beside_own_arrow(lane.forces, where);
    }
    EXPECT_EQ(words, 2) << where << ": a contact's word is not drawn";
  });
  // Seven forces at 0.2 s (the frictions between the blocks are nought), nine at 2.12 s.
  EXPECT_EQ(values, 2 * (7 + 9));
}

// A teacher's trial (issue 31, projector mode at 1920 × 1080, and the README's picture):
// stacked_blocks as its top block slips (its top_slips moment, 4.2 s) crowded its labels, three
// "9.81 N" close together round the top block, one across the top block's edge and another
// across the bottom block's, and drew "← slipping" in the middle of the bottom block, 150 px from
// the contact it names. In the window on a projector and in the README's picture (1280 × 720):
// each contact's word is drawn, its box within one line of its text of its dot's rim (the dot's
// box as the lane avoids it), or joined to its dot by a leader no longer than three lines (a
// trial found "sticking" 131 px from its dot from 2 s on, the room by it taken by values beside
// their arrows); every label stands a quarter of a line of its text or more from every other
// (such a word, off nothing but its neighbours, may stand closer, and across its own surface); and each value is beside its own arrow by check_beside_own_arrow's rule, with
// check_layout's rules. On the projector, where the blocks are large enough for their values to
// find room off their edges, every label lies wholly on or wholly off each block, across neither's
// outline (its box as drawn against the block's box, the blocks lying square). (The README's
// picture, its world under a third of the projector's in text heights, has its friction between
// the blocks' value across their edges still: on the top block it has no room, on the bottom one
// it reads as the bottom block's, and a leader to the sky is longer than three lines.)
TEST(WorldLabels, StackedBlocksLabelsStandClearOfEachOtherAndOfTheBlocksEdgesAndTheWordsByTheirDots) {
  const auto check = [](const draw::FrameRecord& record, const lessons::Lesson& lesson, const std::string& where, bool edges) {
    check_layout(record, lesson, where);
    ASSERT_EQ(record.lanes.size(), 1u) << where;
    const draw::FrameRecord::Lane& lane = record.lanes.front();
    ASSERT_EQ(lane.texts.size(), lane.labels.size()) << where;
    ASSERT_EQ(lane.bodies.size(), 2u) << where << ": the two blocks";
    check_beside_own_arrow(lane.forces, where);
    // The contacts' dots: the marks the lane avoids that are square and no bigger than a line.
    std::vector<ImVec4> dots;
    for (const ImVec4& mark : lane.avoided) {
      if (std::abs((mark.z - mark.x) - (mark.w - mark.y)) < 0.01f) dots.push_back(mark);
    }
    ASSERT_EQ(dots.size(), 2u) << where << ": the floor's contact and the blocks'";
    const auto is_word = [&](std::size_t i) {
      return lane.texts[i].find("slipping") != std::string::npos || lane.texts[i].find("sticking") != std::string::npos;
    };
    // The dot a word is joined to by a leader, if it is: a line from the dot's rim (1.5 px past
    // it, over the dot's outline) to the word's box, padding included, three lines long at most.
    const auto led_from = [&](std::size_t i) -> std::optional<ImVec4> {
      const ImVec4 padded = lane.labels[i];
      const float line = drawn(padded).w - drawn(padded).y;
      for (const draw::DrawnSegment& segment : lane.arrows) {
        const bool on_box = segment.to.x >= padded.x - 0.5f && segment.to.x <= padded.z + 0.5f &&
                            segment.to.y >= padded.y - 0.5f && segment.to.y <= padded.w + 0.5f;
        if (!on_box || draw::length(draw::sub(segment.to, segment.from)) > draw::LabelPlacer::longest_leader(ImVec2(0.0f, line))) continue;
        for (const ImVec4& dot : dots) {
          const ImVec2 centre(0.5f * (dot.x + dot.z), 0.5f * (dot.y + dot.w));
          if (std::abs(draw::length(draw::sub(segment.from, centre)) - (0.5f * (dot.z - dot.x) + 1.5f)) < 0.5f) return dot;
        }
      }
      return std::nullopt;
    };
    int words = 0;
    for (std::size_t i = 0; i < lane.labels.size(); ++i) {
      const ImVec4 box = drawn(lane.labels[i]);
      const float line = box.w - box.y;
      const std::string& text = lane.texts[i];
      const std::optional<ImVec4> led = is_word(i) ? led_from(i) : std::nullopt;
      if (is_word(i)) {
        ++words;
        float nearest = std::numeric_limits<float>::max();
        for (const ImVec4& dot : dots) {
          const ImVec2 centre(0.5f * (dot.x + dot.z), 0.5f * (dot.y + dot.w));
          const float dx = std::max({box.x - centre.x, 0.0f, centre.x - box.z}), dy = std::max({box.y - centre.y, 0.0f, centre.y - box.w});
          nearest = std::min(nearest, std::hypot(dx, dy) - 0.5f * (dot.z - dot.x));
        }
        EXPECT_TRUE(nearest <= line || led) << where << ": \"" << text << "\" at " << text_of(box) << " is " << nearest
                                            << " px from the nearest contact's dot, more than a line (" << line
                                            << " px), and no leader joins it to a dot";
      }
      for (std::size_t j = i + 1; j < lane.labels.size(); ++j) {
        const ImVec4 other = drawn(lane.labels[j]);
        const float apart = std::max({other.x - box.z, box.x - other.z, other.y - box.w, box.y - other.w});
        // A word joined to its dot by a leader stands in what room the values beside their
        // arrows leave, closer to one if need be, never over one.
        const bool led_word = led || (is_word(j) && led_from(j));
        EXPECT_GE(apart, led_word ? 0.0f : 0.25f * line)
            << where << ": \"" << text << "\" at " << text_of(box) << " and \"" << lane.texts[j] << "\" at " << text_of(other)
            << " are " << apart << " px apart, under " << (led_word ? "nothing" : "a quarter of a line");
      }
      for (const ImVec4& body : lane.bodies) {
        const bool inside = box.x >= body.x && box.z <= body.z && box.y >= body.y && box.w <= body.w;
        // Such a word may lie across the surface it names: the line through its dot.
        const float surface = led ? 0.5f * (led->y + led->w) : 0.0f;
        const bool across_its_surface = led && box.y < surface && box.w > surface &&
                                        (std::abs(body.y - surface) < 0.5f * line || std::abs(body.w - surface) < 0.5f * line);
        EXPECT_TRUE(!edges || !draw::overlaps(box, body) || inside || across_its_surface)
            << where << ": \"" << text << "\" at " << text_of(box) << " lies across the edge of the block at " << text_of(body);
      }
    }
    EXPECT_EQ(words, 2) << where << ": a contact's word is not drawn";
  };
  const lessons::Moment* slips = nullptr;
  for (const lessons::CatalogEntry& entry : lessons::catalog()) {
    for (const lessons::Moment& moment : entry.moments) {
      if (entry.name == "stacked_blocks" && moment.name == "top_slips") slips = &moment;
    }
  }
  ASSERT_NE(slips, nullptr);
  // In the window on a projector, as the trial had it, and through the run before it (a trial
  // found "sticking" 150 px from its dot at 3.5 s).
  stacked_blocks_on_a_projector({1.0, 2.0, 2.5, 3.0, 3.5, slips->at},
                                [&](const std::string& where, const draw::FrameRecord& record, const lessons::Lesson& at) {
                                  check(record, at, where + ", projector", true);
                                });
  // The README's picture (frictionlab render stacked_blocks --moment top_slips).
  draw::HeadlessRenderer renderer(1280, 720);
  draw::LessonAt at("stacked_blocks", slips->set, slips->at);
  draw::FrameRecord record;
  renderer.render(*at.lesson, at.framing, &record);
  check(record, *at.lesson, "stacked_blocks at its top_slips moment, the README's picture at 1280 × 720", false);
}

// incline in the window at 1920 × 1080 in projector mode with every tool on, both themes, at
// 25°, 35°, 45° and 60°, at rest at t = 0, while it slides and at the end: the weight's parts
// (Tools > Weight along and across a slope) drawn as m·g·sin θ and m·g·cos θ, each arrow from the
// block's centre of mass along or into the slope at the lane's newtons-to-pixels (the lesson's
// own weight arrow's, where that is drawn to scale), and each value within a line of its own
// arrow and nearer it than any other, by check_beside_own_arrow's rule, with the lesson's own
// values held to it beside them (but at the moments crowded_not_yet names). Issue 31: a
// teacher's projector trial read each component's value far from its arrow (placed wherever it
// was free, up to fifteen lines away: m·g·sin θ 181 px off at 25°, 109 px at 35° at rest).
TEST(ToolLabels, TheWeightsComponentsStandBesideTheirArrowsOnAProjector) {
  const ImVec2 display(1920.0f, 1080.0f);
  draw::HeadlessContext gl;
  draw::ImGuiHost host(nullptr);
  int components = 0, scales = 0;
  // Not yet: where the block nears the foot of a steep slope, the lesson's weight value (and at
  // 60° at 0.6 s the friction's, 1.96 N) finds no place beside its arrow once the parts' values
  // and the ruler's have theirs: 78 to 170 px off (left open; the list only shrinks).
  const std::set<std::string> crowded_not_yet = {"45 at 1.00 s", "60 at 0.60 s", "60 at 1.00 s"};
  std::map<std::string, int> still_crowded;
  for (const draw::ThemeName theme : {draw::ThemeName::light, draw::ThemeName::dark}) {
    for (const char* angle : {"25", "35", "45", "60"}) {
      ClassroomOptions options = class_window(lessons::resolve_lesson("incline"), {"1920x1080", 1920, 1080, true});
      options.window.theme = theme;
      options.window.tools = ToolSettings{true, true, true, true};
      options.overrides = {{"angle", angle}};
      Classroom window(options);
      draw_window_frame(gl, host, window, display);
      for (const double t : {0.0, 0.3, 0.6, 1.0}) {
        const draw::FrameRecord record = recorded_at(gl, host, window, display, t);
        const std::string where =
            std::string("incline at ") + angle + "°" + said_at(t) + (theme == draw::ThemeName::dark ? ", dark" : "");
        check_layout(record, window.playback().lesson(), where);
        const Scene& scene = window.playback().lesson().scene();
        const b2Body* block = scene.body("block");
        const std::optional<SlopeWeight> weight = slope_weight(scene, block);
        ASSERT_TRUE(weight.has_value()) << where;
        ASSERT_EQ(record.lanes.size(), 1u) << where;
        const draw::FrameRecord::Lane& lane = record.lanes.front();
        const ImVec2 centre = lane.camera.to_screen(block->GetWorldCenter());
        const double mg = static_cast<double>(block->GetMass() * scene.world().GetGravity().Length());
        const double theta = std::stod(angle) * b2_pi / 180.0;
        // Pixels a newton, as the lesson's weight arrow is drawn (none before the first step).
        std::optional<float> weight_scale;
        for (const draw::LabelPlacer::ForceLabel& force : lane.forces) {
          if (force.kind == ForceKind::weight && force.body == block && !force.text.empty() && force.text.rfind("m\u00b7g", 0) != 0 &&
              !force.broken) {
            weight_scale = length(sub(force.arrow.to, force.arrow.from)) / static_cast<float>(mg);
          }
        }
        int found = 0;
        for (const draw::LabelPlacer::ForceLabel& force : lane.forces) {
          const bool along = force.text.rfind("m\u00b7g\u00b7sin \u03b8 = ", 0) == 0;
          const bool across = force.text.rfind("m\u00b7g\u00b7cos \u03b8 = ", 0) == 0;
          if (!along && !across) continue;
          ++found;
          // The closed forms, as the label prints them.
          EXPECT_EQ(force.text, (along ? "m\u00b7g\u00b7sin \u03b8 = " : "m\u00b7g\u00b7cos \u03b8 = ") +
                                    draw::format_quantity(mg * (along ? std::sin(theta) : std::cos(theta)), "N"))
              << where;
          // From the centre of mass (a pixel: screen rounding), the way the part acts.
          EXPECT_LT(length(sub(force.arrow.from, centre)), 1.0f) << where << ": " << force.text;
          const b2Vec2 way = along ? weight->downhill : weight->into;
          const ImVec2 drawn_way = sub(force.arrow.to, force.arrow.from);
          const float span = length(drawn_way);
          ASSERT_GT(span, 0.0f) << where;
          EXPECT_NEAR(drawn_way.x / span, way.x, 1e-3f) << where << ": " << force.text;
          EXPECT_NEAR(drawn_way.y / span, -way.y, 1e-3f) << where << ": " << force.text;
          if (weight_scale) {
            const double newtons = along ? weight->along : weight->across;
            EXPECT_NEAR(span, *weight_scale * static_cast<float>(newtons), 1.0f) << where << ": " << force.text;
            ++scales;
          }
        }
        EXPECT_EQ(found, 2) << where << ": the weight's two parts drawn with their values";
        components += found;
        // The parts' values held to the rule, every other arrow counting as one they must be
        // nearer their own than; then the lesson's own values the same way.
        std::vector<draw::LabelPlacer::ForceLabel> parts = lane.forces, lessons_own = lane.forces;
        for (draw::LabelPlacer::ForceLabel& force : parts) {
          if (force.text.rfind("m\u00b7g\u00b7", 0) != 0) force.text.clear();
        }
        for (draw::LabelPlacer::ForceLabel& force : lessons_own) {
          if (force.text.rfind("m\u00b7g\u00b7", 0) == 0) force.text.clear();
        }
        check_beside_own_arrow(parts, where);
        const std::string moment = std::string(angle) + said_at(t);
        if (crowded_not_yet.count(moment) != 0) {
          check_beside_own_arrow(lessons_own, where, &still_crowded[moment]);
        } else {
          check_beside_own_arrow(lessons_own, where);
        }
      }
    }
  }
  EXPECT_EQ(components, 2 * 4 * 4 * 2);
  EXPECT_GE(scales, 2 * 4 * 3 * 2);
  for (const auto& [moment, broken] : still_crowded) {
    EXPECT_GT(broken, 0) << "incline at " << moment << " now has the lesson's values beside their arrows: take it off crowded_not_yet";
  }
}

// The distance marks' line runs only along the surface the block stands on: on incline, from
// the slope's foot to its top at most, at rest before the first step (the block set down on the
// slope, no contact yet), while it slides and at the end, at 25° and 60°, in projector mode.
// Issue 31: before the first step the ruler ran the whole view's width along the slope's line,
// past the top into the sky and past the foot into the ground, a line standing for nothing.
TEST(ToolLabels, TheDistanceMarksRunOnlyAlongTheSlope) {
  const ImVec2 display(1920.0f, 1080.0f);
  draw::HeadlessContext gl;
  draw::ImGuiHost host(nullptr);
  int rulers = 0;
  for (const char* angle : {"25", "60"}) {
    ClassroomOptions options = class_window(lessons::resolve_lesson("incline"), {"1920x1080", 1920, 1080, true});
    options.window.tools = ToolSettings{false, true, false, false};
    options.overrides = {{"angle", angle}};
    Classroom window(options);
    draw_window_frame(gl, host, window, display);
    for (const double t : {0.0, 0.5, 1.0}) {
      const draw::FrameRecord record = recorded_at(gl, host, window, display, t);
      const std::string where = std::string("incline at ") + angle + "°" + said_at(t);
      const lessons::Lesson& lesson = window.playback().lesson();
      const draw::Fonts& fonts = host.prepare(window.ui_scale(display), window.window_settings().theme);
      ASSERT_EQ(record.lanes.size(), 1u) << where;
      const draw::Camera& camera = record.lanes.front().camera;
      const std::optional<DistanceMarks> marks = window.tools().distance_marks(lesson, camera, fonts);
      ASSERT_TRUE(marks.has_value()) << where;
      // The slope's face: the incline's corners along the slope's line, from its foot to its top.
      const b2Body* slope = lesson.scene().body("slope");
      const double theta = std::stod(angle) * b2_pi / 180.0;
      const b2Vec2 up_slope(static_cast<float>(std::cos(theta)), static_cast<float>(std::sin(theta)));
      float foot = 1e30f, top = -1e30f;
      for (const b2Fixture* fixture = slope->GetFixtureList(); fixture != nullptr; fixture = fixture->GetNext()) {
        const auto* polygon = static_cast<const b2PolygonShape*>(fixture->GetShape());
        for (int i = 0; i < polygon->m_count; ++i) {
          const float at = b2Dot(slope->GetWorldPoint(polygon->m_vertices[i]), up_slope);
          foot = std::min(foot, at), top = std::max(top, at);
        }
      }
      // A pixel's play at each end: the line is drawn a few pixels inside the face.
      const float pixel = 1.0f / camera.pixels_per_metre;
      for (const ImVec2 end : {marks->from, marks->to}) {
        const float at = b2Dot(camera.to_world(end), up_slope);
        EXPECT_GE(at, foot - pixel) << where << ": the line's end at " << end.x << ", " << end.y << " is "
                                    << (foot - at) * camera.pixels_per_metre << " px past the slope's foot";
        EXPECT_LE(at, top + pixel) << where << ": the line's end at " << end.x << ", " << end.y << " is "
                                   << (at - top) * camera.pixels_per_metre << " px past the slope's top";
      }
      ++rulers;
    }
  }
  EXPECT_EQ(rulers, 6);
}

// The distance marks are a ruler the slide can be read against: a teacher's projector trial
// (issue 31) read "ticks 5 m apart" under incline's block, one tick in view, for a slide of
// 1.2 m. On a projector at 1920 × 1080, at 35° (the defaults) and at 60°, at the run's end: the
// slide, from the closed form d = ½·g·(sin θ − μk·cos θ)·t² at t = 1 s (1.21 m at 35°, 3.27 m at
// 60°), spans two of the ticks' steps at least (three ticks or more along it), the ticks no
// closer on the screen than least_tick_spacing(); and two numbers or more are drawn at their
// ticks, no "ticks … apart" in their place.
TEST(ToolLabels, TheDistanceMarksReadTheSlideInStepsOfAFractionOfIt) {
  const ImVec2 display(1920.0f, 1080.0f);
  draw::HeadlessContext gl;
  draw::ImGuiHost host(nullptr);
  for (const char* angle : {"35", "60"}) {
    ClassroomOptions options = class_window(lessons::resolve_lesson("incline"), {"1920x1080", 1920, 1080, true});
    options.window.tools = ToolSettings{false, true, false, false};
    options.overrides = {{"angle", angle}};
    Classroom window(options);
    draw_window_frame(gl, host, window, display);
    const lessons::Lesson& lesson = window.playback().lesson();
    const double t = lesson.duration();
    const draw::FrameRecord record = recorded_at(gl, host, window, display, t);
    const std::string where = std::string("incline at ") + angle + "°" + said_at(t);
    const draw::Fonts& fonts = host.prepare(window.ui_scale(display), window.window_settings().theme);
    ASSERT_EQ(record.lanes.size(), 1u) << where;
    const draw::Camera& camera = record.lanes.front().camera;
    const std::optional<DistanceMarks> marks = window.tools().distance_marks(lesson, camera, fonts);
    ASSERT_TRUE(marks.has_value()) << where;
    const double theta = std::stod(angle) * M_PI / 180.0, g = 9.81, mu_k = 0.4;
    const double slide = 0.5 * g * (std::sin(theta) - mu_k * std::cos(theta)) * t * t;
    EXPECT_NEAR(lesson.scene().probe("distance").history.back(), slide, 0.02 * slide) << where << ": the slide is not the closed form's";
    EXPECT_GE(slide / marks->step, 2.0) << where << ": a slide of " << slide << " m over ticks " << marks->step << " m apart";
    EXPECT_GE(marks->step * camera.pixels_per_metre, least_tick_spacing(fonts.scale) - 1e-3)
        << where << ": ticks " << marks->step * camera.pixels_per_metre << " px apart";
    int numbers = 0;
    for (const std::string& text : record.lanes.front().texts) {
      EXPECT_EQ(text.find(" apart"), std::string::npos) << where << ": \"" << text << "\"";
      numbers += text.size() > 2 && text.ends_with(" m") && (std::isdigit(static_cast<unsigned char>(text[0])) || text.rfind("\u2212", 0) == 0);
    }
    EXPECT_GE(numbers, 2) << where << ": the ruler's numbers";
  }
}

// A contact's word ("sticking", "← slipping") by its dot, on a floor and on slopes as steep as
// 60°: its box as drawn within one line of its text (the box's height) of the dot's rim, at a
// screen's and a projector's text size. Issue 31: on incline at 60° in projector mode the word
// sat 120 px below its dot, half its width along the slope away (the wanted place went along the
// surface by half the box's width, which on a steep slope is mostly down). The dot's radius is
// contact_dot_radius times the text scale, its box as the lane avoids it.
TEST(ContactWords, EachStateWordIsWithinALineOfItsDot) {
  int checked = 0;
  for (const Screen& screen : {screens[0], screens[3]}) {
    draw::HeadlessRenderer renderer(screen.width, screen.height, draw::ThemeName::light, screen.scale);
    for (const char* angle : {"25", "35", "45", "60"}) {
      for (const double t : {0.3, 0.6}) {
        draw::LessonAt at("incline", {{"angle", angle}}, t);
        draw::FrameRecord record;
        renderer.render(*at.lesson, at.framing, &record);
        const std::string where = std::string("incline at ") + angle + "° at " + std::to_string(t) + " s, " + screen.name;
        for (const draw::FrameRecord::Lane& lane : record.lanes) {
          for (std::size_t i = 0; i < lane.texts.size(); ++i) {
            const std::string& text = lane.texts[i];
            if (text.find("sticking") == std::string::npos && text.find("slipping") == std::string::npos) continue;
            const ImVec4 box = drawn(lane.labels[i]);
            float nearest = 1e9f, radius = 0.0f;
            for (const ContactMark& mark : contact_marks(at.lesson->scene())) {
              const ImVec2 centre = lane.camera.to_screen(mark.point);
              const float dx = std::max({box.x - centre.x, 0.0f, centre.x - box.z});
              const float dy = std::max({box.y - centre.y, 0.0f, centre.y - box.w});
              for (const ImVec4& dot : lane.avoided) {
                if (std::abs(0.5f * (dot.x + dot.z) - centre.x) < 0.01f && std::abs(0.5f * (dot.y + dot.w) - centre.y) < 0.01f &&
                    std::hypot(dx, dy) < nearest) {
                  nearest = std::hypot(dx, dy);
                  radius = 0.5f * (dot.z - dot.x);
                }
              }
            }
            ASSERT_LT(nearest, 1e9f) << where << ": no dot for \"" << text << "\"";
            EXPECT_LE(nearest - radius, box.w - box.y)
                << where << ": \"" << text << "\" at " << text_of(box) << " is " << nearest - radius << " px from its dot's rim";
            ++checked;
          }
        }
      }
    }
  }
  EXPECT_GE(checked, 16);
}

// A friction acts where its contact's dot is drawn: stacked_blocks' friction between the blocks
// (3 N, a few pixels long) was drawn under the dot, unseen, in the trial. Each friction arrow
// starts outside every contact dot of its lane (the dot's box, as the lane avoids it, gives its
// radius), at the start, as the lessons run and at their ends, at normal size and projector size.
TEST(ForceArrows, FrictionStartsOutsideTheContactDots) {
  int frictions = 0;
  for (const Screen& screen : {screens[0], screens[3]}) {
    draw::HeadlessRenderer renderer(screen.width, screen.height, draw::ThemeName::light, screen.scale);
    for (const char* lesson : {"stacked_blocks", "push", "tipping_box", "contact_area", "incline"}) {
      for (const double t : {0.5, 1.5, 3.0}) {
        draw::LessonAt at(lesson, {}, t);
        draw::FrameRecord record;
        renderer.render(*at.lesson, at.framing, &record);
        const std::string where = std::string(lesson) + " at " + std::to_string(t) + " s, " + screen.name;
        for (const draw::FrameRecord::Lane& lane : record.lanes) {
          std::vector<std::pair<ImVec2, float>> dots;  // centre, radius
          for (const ContactMark& mark : contact_marks(at.lesson->scene())) {
            const ImVec2 centre = lane.camera.to_screen(mark.point);
            for (const ImVec4& box : lane.avoided) {
              const float half = 0.5f * (box.z - box.x);
              if (std::abs(0.5f * (box.x + box.z) - centre.x) < 0.01f && std::abs(0.5f * (box.y + box.w) - centre.y) < 0.01f &&
                  std::abs(0.5f * (box.w - box.y) - half) < 0.01f) {
                dots.emplace_back(centre, half);
              }
            }
          }
          for (const draw::LabelPlacer::ForceLabel& force : lane.forces) {
            if (force.kind != ForceKind::friction) continue;
            ++frictions;
            for (const auto& [centre, radius] : dots) {
              EXPECT_GE(length(sub(force.arrow.from, centre)), radius)
                  << where << ": the friction " << force.text << " starts under the contact dot at (" << centre.x << ", "
                  << centre.y << ")";
            }
          }
        }
      }
    }
  }
  EXPECT_GE(frictions, 20);
}

// Every built-in lesson at its defaults in the window in projector mode at 1920 × 1080, light,
// at its opening, half way and at its end: each lane's drawn forces, with where they were drawn
// (" at 1.73 s" after the lesson's name).
void each_projector_lane(const std::function<void(const std::string& where, const draw::FrameRecord::Lane& lane)>& check) {
  each_lesson_frame(true, draw::ThemeName::light,
                    [&](const std::string& lesson, const std::string& when, const draw::FrameRecord& record, const lessons::Lesson&) {
                      for (const draw::FrameRecord::Lane& lane : record.lanes) check(lesson + when, lane);
                    });
}

// One lesson in the window in projector mode at 1920 × 1080, light, with `set` (as --set), run to
// each of `times`: the frame's record at each, with where (" at 2.20 s").
void projector_frames_at(const std::string& lesson, const std::map<std::string, std::string>& set, std::vector<double> times,
                         const std::function<void(const std::string& where, const draw::FrameRecord& record,
                                                  const lessons::Lesson& at)>& check) {
  const ImVec2 display(1920.0f, 1080.0f);
  draw::HeadlessContext gl;
  draw::ImGuiHost host(nullptr);
  ClassroomOptions options = class_window(lessons::resolve_lesson(lesson), {"1920x1080", 1920, 1080, true});
  options.overrides = set;
  Classroom window(options);
  draw_window_frame(gl, host, window, display);
  for (const double t : times) {
    const draw::FrameRecord record = recorded_at(gl, host, window, display, t);
    std::string where = lesson + said_at(t);
    for (const auto& [name, value] : set) where += ", " + name + " = " + value;
    check(where, record, window.playback().lesson());
  }
}

// The same, the first lane's record.
void projector_lane_at(const std::string& lesson, const std::map<std::string, std::string>& set, std::vector<double> times,
                       const std::function<void(const std::string& where, const draw::FrameRecord::Lane& lane,
                                                const lessons::Lesson& at)>& check) {
  projector_frames_at(lesson, set, std::move(times),
                      [&](const std::string& where, const draw::FrameRecord& record, const lessons::Lesson& at) {
                        ASSERT_FALSE(record.lanes.empty()) << where;
                        check(where, record.lanes.front(), at);
                      });
}

// Checks one lane: each friction's arrow starts at its contact's dot's rim (within the 1.5 px
// past its outline that start_frictions_past_their_dots leaves, and a hundredth of a pixel of
// floats), and no other arrow drawn after it (over it) but a normal force from that dot lies over its first pixels: the
// distance from the friction's tail to another arrow's centre line is at least that arrow's half
// width there (its shaft's half thickness, or its head's half width, draw_arrow's 0.45 of a head
// four thicknesses long, where the head is) and its halo. Returns how many frictions it checked.
int check_friction_starts_at_its_contact(const std::string& where, const draw::FrameRecord::Lane& lane, const lessons::Lesson& at) {
  int checked = 0;
  for (const draw::LabelPlacer::ForceLabel& friction : lane.forces) {
    if (friction.kind != ForceKind::friction) continue;
    const float thickness = 2.0f * friction.arrow.half_width;
    const float rim = draw::contact_dot_radius * thickness / draw::world_arrow_thickness(1.0f) + 1.5f + 0.01f;
    float nearest = 1e9f;
    ImVec2 dot(0.0f, 0.0f);
    for (const ContactMark& mark : contact_marks(at.scene())) {
      const ImVec2 centre = lane.camera.to_screen(mark.point);
      const float distance = length(sub(friction.arrow.from, centre));
      if (distance < nearest) nearest = distance, dot = centre;
    }
    EXPECT_LE(nearest, rim) << where << ": the friction " << friction.text << " starts at (" << friction.arrow.from.x << ", "
                            << friction.arrow.from.y << "), " << nearest << " px from the nearest contact's dot, at (" << dot.x
                            << ", " << dot.y << ")";
    ++checked;
    for (const draw::LabelPlacer::ForceLabel& other : lane.forces) {
      if (&other == &friction) continue;
      // One drawn before the friction lies under it: the friction's first pixels are its own (a
      // weight from its centre of mass passing under push's friction's start, as a textbook draws it).
      if (other.drawn < friction.drawn) continue;
      // A normal force from the same dot starts there too, as a textbook draws a contact's two forces.
      if (other.kind == ForceKind::normal && length(sub(other.arrow.from, dot)) <= rim + draw::side_by_side_gap(thickness)) continue;
      const ImVec2 along = sub(other.arrow.to, other.arrow.from);
      const float span = length(along);
      const float f = std::clamp(((friction.arrow.from.x - other.arrow.from.x) * along.x +
                                  (friction.arrow.from.y - other.arrow.from.y) * along.y) / (span * span), 0.0f, 1.0f);
      const float distance = length(sub(friction.arrow.from, add(other.arrow.from, mul(along, f))));
      const float head = std::min(4.0f * thickness, 0.6f * span);
      const float half_width = (1.0f - f) * span <= head ? 0.45f * head * (1.0f - f) * span / head : 0.5f * thickness;
      EXPECT_GE(distance, half_width + draw::arrow_halo_width(thickness) - 0.01f)
          << where << ": the " << draw::force_kind_name(other.kind) << " " << other.text << "'s arrow lies over the start of the friction "
          << friction.text << " at (" << friction.arrow.from.x << ", " << friction.arrow.from.y << ")";
    }
  }
  return checked;
}

// A contact's friction starts at its contact, where the class sees its dot, and no other arrow
// is drawn over where it starts (a teacher's trial on a projector, issue 31; a weight drawn under
// it, from its centre of mass, leaves the friction's first pixels its own). tipping_box at 2.2 s
// stood on its corner with its 30.8 N friction drawn from the middle of its bottom, 45 px from
// the corner's dot: uncross_arrows had slid it along its line past the weight's shaft. Pushed
// 0.2 m up, at 1 s its 19.9 N friction ran under the weight's head; push at 2.5 s and spring_pull at
// 2 s had the weight's shaft over the friction's first pixels. Those moments, and every built-in
// lesson at its defaults at its opening, half way and at its end, in the window in projector
// mode at 1920 × 1080, light.
TEST(ForceArrows, AFrictionStartsAtItsContactWithNoOtherArrowOverItsStart) {
  int checked = 0;
  const auto check = [&](const std::string& where, const draw::FrameRecord::Lane& lane, const lessons::Lesson& at) {
    checked += check_friction_starts_at_its_contact(where, lane, at);
  };
  projector_lane_at("tipping_box", {}, {2.2}, check);
  projector_lane_at("tipping_box", {{"push_height", "0.2"}}, {1.0, 2.0, 2.5}, check);
  projector_lane_at("push", {}, {2.5}, check);
  projector_lane_at("spring_pull", {}, {2.0}, check);
  each_lesson_frame(true, draw::ThemeName::light, [&](const std::string& lesson, const std::string& when,
                                                      const draw::FrameRecord& record, const lessons::Lesson& at) {
    for (const draw::FrameRecord::Lane& lane : record.lanes) checked += check_friction_starts_at_its_contact(lesson + when, lane, at);
  });
  EXPECT_GE(checked, 40);
}

// The window on a projector draws no free-body inset, and at t = 0 its world showed the
// weight alone, unbalanced, on a block at rest on its floor (a teacher's trial, issue 31). At
// t = 0 the world says once, above the lesson's body, when the other forces come (in a lane,
// where a free place holds the words, and never in two); after a step, with those forces
// drawn, it does not.
TEST(WorldLabels, AtTheStartTheWorldSaysTheOtherForcesComeWithTheRun) {
  const std::string words = "the other forces appear once the run starts";
  for (const char* lesson : {"push", "incline", "where_methods_fail"}) {
    projector_frames_at(lesson, {}, {0.0, 0.5}, [&](const std::string& where, const draw::FrameRecord& record, const lessons::Lesson& at) {
      int said = 0;
      for (const draw::FrameRecord::Lane& lane : record.lanes) said += static_cast<int>(std::count(lane.texts.begin(), lane.texts.end(), words));
      // where_methods_fail's thin lanes may leave no free place for the words: never twice there.
      if (std::string(lesson) == "where_methods_fail" && at.scene().frame() == 0) {
        EXPECT_LE(said, 1) << where;
      } else {
        EXPECT_EQ(said, at.scene().frame() == 0 ? 1 : 0) << where;
      }
    });
  }
}

// Before the run, where each of the lesson's forces at its body's outline will act: its name
// ("push") beside its point, within a line and a half of its text of it, in tipping_box (the
// push's height is a slider, and its question turns on it) and stacked_blocks (the pull at the
// bottom block's corner); after the first step the arrow and its value say it, and the name is
// gone. Issue 31: a push that grows from nought had no arrow at t = 0, and nothing showed where
// it would act.
TEST(WorldLabels, AtTheStartTheWorldShowsWhereEachForceWillAct) {
  for (const char* lesson : {"tipping_box", "stacked_blocks"}) {
    projector_frames_at(lesson, {}, {0.0, 0.5}, [&](const std::string& where, const draw::FrameRecord& record, const lessons::Lesson& at) {
      ASSERT_FALSE(at.scene().applied_forces().empty()) << where;
      const AppliedForce& push = at.scene().applied_forces().front();
      const std::string name = lessons::class_words(push.name);
      int named = 0, rings = 0;
      for (const draw::FrameRecord::Lane& lane : record.lanes) {
        const ImVec2 point = lane.camera.to_screen(push.body->GetWorldPoint(push.local_point));
        // The ring: a square mark the lane keeps labels off, centred on the point.
        for (const ImVec4& mark : lane.avoided) {
          const bool square = std::abs((mark.z - mark.x) - (mark.w - mark.y)) < 0.01f && mark.z > mark.x;
          if (square && std::abs(0.5f * (mark.x + mark.z) - point.x) < 0.5f && std::abs(0.5f * (mark.y + mark.w) - point.y) < 0.5f) ++rings;
        }
        for (std::size_t i = 0; i < lane.texts.size(); ++i) {
          if (lane.texts[i] != name) continue;
          ++named;
          const ImVec4 box = drawn(lane.labels[i]);
          const float dx = std::max({box.x - point.x, 0.0f, point.x - box.z}), dy = std::max({box.y - point.y, 0.0f, point.y - box.w});
          EXPECT_LE(std::hypot(dx, dy), 1.5f * (box.w - box.y)) << where << ": \"" << name << "\" at " << text_of(box) << " is far from its point";
        }
      }
      EXPECT_EQ(named, at.scene().frame() == 0 ? 1 : 0) << where;
      EXPECT_EQ(rings, at.scene().frame() == 0 ? 1 : 0) << where << ": the ring at the force's point";
    });
  }
}

// stacked_blocks while the pair slides on the floor (2 s to 3.5 s; the top block slips from
// 3.9 s) in the window at 1920 × 1080 in projector mode: of the two frictions
// between the blocks, equal and opposite, the top block's lies inside the top block, above the
// surface between them, and the bottom block's inside the bottom block, below it, each shaft
// wholly a thickness off the surface's line, within two thicknesses of it (on its own side, not
// wandered off), and its ends within its block's width; and each value names its block ("2.20 N
// on top"). Issue 31: drawn from one dot on the surface, the two 2.2 N arrows lay over each other
// and nothing said which block each pushed; the bottom block's value, beside the top block, was
// read as the top block's friction pushing it back.
TEST(ForceArrows, StackedBlocksFrictionPairBetweenTheBlocksIsDrawnEachInsideItsOwnBlock) {
  int pairs = 0;
  projector_lane_at("stacked_blocks", {}, {2.0, 2.5, 3.0, 3.5}, [&](const std::string& where, const draw::FrameRecord::Lane& lane,
                                                                      const lessons::Lesson& lesson) {
    const b2Body* top = lesson.scene().body("top");
    const b2Body* bottom = lesson.scene().body("bottom");
    ASSERT_TRUE(top != nullptr && bottom != nullptr) << where;
    // The surface between the blocks, on the screen: the top block's lowest point.
    const b2AABB top_box = lessons::body_box(top);
    const float surface = lane.camera.to_screen(top_box.lowerBound).y;
    const float left = lane.camera.to_screen(lessons::body_box(bottom).lowerBound).x;
    const float right = lane.camera.to_screen(lessons::body_box(bottom).upperBound).x;
    const draw::LabelPlacer::ForceLabel* on_top = nullptr;
    const draw::LabelPlacer::ForceLabel* on_bottom = nullptr;
    for (const draw::LabelPlacer::ForceLabel& force : lane.forces) {
      if (force.kind != ForceKind::friction) continue;
      if (force.body == top) on_top = &force;
      // Of the bottom block's two frictions, the floor's lies at its foot, far below the surface.
      const float floor = lane.camera.to_screen(lessons::body_box(bottom).lowerBound).y;
      if (force.body == bottom && std::abs(force.arrow.from.y - surface) < std::abs(force.arrow.from.y - floor)) on_bottom = &force;
    }
    ASSERT_TRUE(on_top != nullptr && on_bottom != nullptr) << where << ": both frictions between the blocks drawn";
    ++pairs;
    // Each value names the block it acts on; the floor's friction, which has no partner drawn, does not.
    EXPECT_TRUE(on_top->text.ends_with(" N on top")) << where << ": \"" << on_top->text << "\"";
    EXPECT_TRUE(on_bottom->text.ends_with(" N on bottom")) << where << ": \"" << on_bottom->text << "\"";
    for (const draw::LabelPlacer::ForceLabel& force : lane.forces) {
      if (force.kind == ForceKind::friction && &force != on_top && &force != on_bottom) {
        EXPECT_TRUE(force.text.ends_with(" N")) << where << ": the floor's friction reads \"" << force.text << "\"";
      }
    }
    for (const auto* force : {on_top, on_bottom}) {
      const float thickness = 2.0f * force->arrow.half_width;
      const float side = force == on_top ? -1.0f : 1.0f;  // screen y grows downward
      for (const ImVec2 end : {force->arrow.from, force->arrow.to}) {
        const float off = side * (end.y - surface);
        EXPECT_GE(off, thickness) << where << ": the friction " << force->text << " on the "
                                  << (force == on_top ? "top" : "bottom") << " block lies " << off
                                  << " px into its own block from the surface between them";
        EXPECT_LE(off, 2.0f * thickness) << where << ": the friction " << force->text << " lies " << off << " px off the surface";
        EXPECT_TRUE(end.x > left && end.x < right) << where << ": the friction " << force->text << " ends at x = " << end.x;
      }
    }
  });
  EXPECT_EQ(pairs, 4);
}

// The legend's number is where the world's arrows turn to dashes, and it holds all through the
// run (a teacher's trial on a projector, issue 31). Push at 0.5 to 1 s drew its 1.99 N push and
// friction solid, 27.9 px (the drawing counted a length within half a pixel of the legible 28 px
// as to scale), under a legend saying "under 2.02 N: longer, dashed"; and the legend's words
// changed as the run played ("all arrows to scale" by 3 s). Push, spring_pull and tipping_box in
// the window in projector mode at 1920 × 1080 from 0.2 s to their ends: the legend says
// "dashed: too small" "to draw to scale" "(under X N)" at every moment (a teacher found "under
// X N: longer, dashed" cryptic), the same X, and each arrow is drawn broken exactly where its
// printed value is under X (a value within a unit of its last printed digit of X is not judged:
// both are rounded to three figures).
TEST(ForceArrows, TheLegendsNumberIsWhereArrowsTurnToDashesAllThroughTheRun) {
  int judged = 0, broken = 0;
  for (const char* lesson : {"push", "spring_pull", "tipping_box"}) {
    std::vector<double> times = {0.2, 0.5, 0.6, 0.75, 0.9, 1.0, 1.5, 2.0, 2.5};
    const double end = draw::LessonAt(lesson, {}, 0.0).lesson->duration();
    for (double t = 3.0; t <= end + 1e-9; t += 1.0) times.push_back(t);
    std::string said;
    projector_frames_at(lesson, {}, times, [&](const std::string& where, const draw::FrameRecord& record, const lessons::Lesson&) {
      std::string under;
      bool dashed = false, to_scale = false;
      for (const draw::ShownText& text : record.texts) {
        if (text.text.rfind("(under ", 0) == 0) under = text.text;
        dashed = dashed || text.text == "dashed: too small";
        to_scale = to_scale || text.text == "to draw to scale";
        EXPECT_EQ(text.text.find("all arrows"), std::string::npos) << where << ": the legend says \"" << text.text << "\"";
      }
      EXPECT_TRUE(dashed && to_scale) << where << ": the legend does not say that a dashed arrow is too small to draw to scale";
      ASSERT_FALSE(under.empty()) << where << ": the legend does not say under which force arrows are drawn longer";
      if (said.empty()) said = under;
      EXPECT_EQ(under, said) << where << ": the legend's words changed during the run";
      const double below = std::strtod(under.c_str() + 7, nullptr);
      const double step = draw::printed_number(below).step;
      for (const draw::FrameRecord::Lane& lane : record.lanes) {
        for (const draw::LabelPlacer::ForceLabel& force : lane.forces) {
          if (force.text.empty() || force.text.find("in all") != std::string::npos) continue;
          const double value = std::strtod(force.text.c_str(), nullptr);
          if (std::abs(value - below) <= step + draw::printed_number(value).step) continue;
          EXPECT_EQ(force.broken, value < below)
              << where << ": the " << draw::force_kind_name(force.kind) << " " << force.text << " is drawn "
              << (force.broken ? "dashed" : "solid") << ", " << length(sub(force.arrow.to, force.arrow.from)) << " px, under \""
              << under << "\"";
          ++judged;
          broken += force.broken ? 1 : 0;
        }
      }
    });
  }
  EXPECT_GE(judged, 80);
  EXPECT_GE(broken, 4);  // some are drawn dashed: the test is not empty
}

// Every force arrow of every built-in lesson at its defaults, in the window in projector mode at
// 1920 × 1080, at its opening, half way and at its end, can be read from a classroom's back row:
// at least four of the arrow's thicknesses long (legible_arrow_pixels; the recorded arrow's half
// width is half of one), a head of 2.4 and a shaft of 1.6. Issue 31: with one scale set by the
// heaviest weight, tipping_box's 19.9 N push was a 15 px stub. Eight thicknesses (56 px) kept
// every arrow long but lengthened spring_pull's 3.43 N friction to its 4.64 N spring's length.
TEST(ForceArrows, EveryArrowOnAProjectorIsFourThicknessesLongAtLeast) {
  int checked = 0;
  each_projector_lane([&](const std::string& where, const draw::FrameRecord::Lane& lane) {
    for (const draw::LabelPlacer::ForceLabel& force : lane.forces) {
      const float thickness = 2.0f * force.arrow.half_width;
      const float drawn = length(sub(force.arrow.to, force.arrow.from));
      // The floats of a tail moved to a dot's rim: a hundredth of a pixel.
      EXPECT_GE(drawn, 4.0f * thickness - 0.01f)
          << where << ": the " << draw::force_kind_name(force.kind) << " " << force.text << " is drawn " << drawn
          << " px long, shorter than four thicknesses (" << 4.0f * thickness << " px)";
      ++checked;
    }
  });
  EXPECT_GE(checked, 200);
}

// A smaller force never has the longer arrow, lengthened or not: push's 2.94 N friction and
// 4.99 N push, both drawn simply as long as a back row can read, came out 56 and 54 px, the
// friction the longer, against the lesson's own question (a teacher's trial, issue 31). Forces
// are read from their printed values (three figures); two within 10 % of each other are not
// compared, nor a foot's share of a force summed over feet. The smaller's arrow is no longer than
// the larger's, to the floats' rounding of a tail moved to a dot's rim (a hundredth of a pixel):
// two forces both under the legible length are both drawn that long, broken (drawn_arrow_pixels),
// and tie; lengthening them "in order" kept every ratio false (issue 31).
TEST(ForceArrows, ASmallerForceNeverHasTheLongerArrow) {
  int compared = 0;
  each_projector_lane([&](const std::string& where, const draw::FrameRecord::Lane& lane) {
    for (const draw::LabelPlacer::ForceLabel& smaller : lane.forces) {
      for (const draw::LabelPlacer::ForceLabel& larger : lane.forces) {
        // A value for one arrow: not a foot's unlabelled share, nor a sum over feet ("9.81 N in all").
        const auto alone = [](const std::string& text) { return !text.empty() && text.find("in all") == std::string::npos; };
        if (!alone(smaller.text) || !alone(larger.text)) continue;
        const double small_value = std::strtod(smaller.text.c_str(), nullptr);
        const double large_value = std::strtod(larger.text.c_str(), nullptr);
        if (!(small_value < 0.9 * large_value)) continue;
        const float small_drawn = length(sub(smaller.arrow.to, smaller.arrow.from));
        const float large_drawn = length(sub(larger.arrow.to, larger.arrow.from));
        EXPECT_LE(small_drawn, large_drawn + 0.01f)
            << where << ": the " << draw::force_kind_name(smaller.kind) << " " << smaller.text << " is drawn " << small_drawn
            << " px, longer than the " << draw::force_kind_name(larger.kind) << " " << larger.text << " at " << large_drawn
            << " px";
        ++compared;
      }
    }
  });
  EXPECT_GE(compared, 200);
}

// No arrow's shaft crosses another's: push's friction, from a contact right of the block's
// middle, crossed the shaft of the weight, which reaches past the floor, and its push crossed the
// normal force's (issue 31, a teacher's trial on a projector). Every built-in lesson at its
// defaults in the window in projector mode at 1920 × 1080, light, at its opening, half way and
// at its end: two arrows' centre lines of one lane cross only within a thickness of a tail (forces
// that start together at one contact, as friction and normal force do), or where a weight passes
// under a contact force's start, drawn beneath it (ForceLabel::drawn): the weight starts at its
// body's centre of mass and a contact's forces at its dot, as a textbook draws them (sliding the
// weight up its line off the friction drew it from 50 px above push's block, read as a push from
// above: a teacher's trial, issue 31).
TEST(ForceArrows, NoArrowOnAProjectorCrossesAnothersShaft) {
  const auto cross = [](ImVec2 a, ImVec2 b) { return a.x * b.y - a.y * b.x; };
  int pairs = 0;
  each_projector_lane([&](const std::string& where, const draw::FrameRecord::Lane& lane) {
    for (std::size_t i = 0; i < lane.forces.size(); ++i) {
      for (std::size_t j = i + 1; j < lane.forces.size(); ++j) {
        const draw::DrawnSegment& p = lane.forces[i].arrow;
        const draw::DrawnSegment& q = lane.forces[j].arrow;
        ++pairs;
        const ImVec2 d = sub(p.to, p.from), e = sub(q.to, q.from), w = sub(q.from, p.from);
        const float denominator = cross(d, e);
        if (std::abs(denominator) < 1e-6f * length(d) * length(e)) continue;
        const float on_p = cross(w, e) / denominator, on_q = cross(w, d) / denominator;
        if (on_p <= 0.0f || on_p >= 1.0f || on_q <= 0.0f || on_q >= 1.0f) continue;
        const float thickness = 2.0f * std::max(p.half_width, q.half_width);
        const float from_tails = std::min(on_p * length(d), on_q * length(e));
        // A weight from its centre of mass passing under the start of a contact's force drawn
        // over it is a textbook's figure, not a tangle: the weight's line within the contact's
        // dot's width of the dot, so the crossing lies within the dot's diameter and the weight's
        // half shaft of the contact force's tail, which is at the dot's rim (its 1.5 px outline
        // past it).
        const auto under_a_contacts_start = [&](const draw::LabelPlacer::ForceLabel& weight, float on_weight,
                                                const draw::LabelPlacer::ForceLabel& contact, float on_contact) {
          if (weight.kind != ForceKind::weight || (contact.kind != ForceKind::friction && contact.kind != ForceKind::normal)) {
            return false;
          }
          const float radius = draw::contact_dot_radius * thickness / draw::world_arrow_thickness(1.0f);
          return contact.drawn > weight.drawn && on_weight > 0.0f &&
                 on_contact <= 2.0f * radius + 1.5f + 0.5f * thickness;
        };
        if (under_a_contacts_start(lane.forces[i], on_p * length(d), lane.forces[j], on_q * length(e)) ||
            under_a_contacts_start(lane.forces[j], on_q * length(e), lane.forces[i], on_p * length(d))) {
          continue;
        }
        EXPECT_LE(from_tails, thickness)
            << where << ": the " << draw::force_kind_name(lane.forces[i].kind) << " " << lane.forces[i].text << " and the "
            << draw::force_kind_name(lane.forces[j].kind) << " " << lane.forces[j].text << " cross " << on_p * length(d)
            << " and " << on_q * length(e) << " px from their tails";
      }
    }
  });
  EXPECT_GE(pairs, 300);
}

// Checks one lane: each weight starts at its body's centre of mass, as a textbook draws it: its
// tail at the centre of mass's point on the screen, along its line and across it, to a hundredth
// of a pixel of floats (a normal force along its line moves aside instead, place_arrows).
// Returns how many weights it checked.
int check_weight_starts_at_its_centre(const std::string& where, const draw::FrameRecord::Lane& lane) {
  int checked = 0;
  for (const draw::LabelPlacer::ForceLabel& weight : lane.forces) {
    if (weight.kind != ForceKind::weight || weight.body == nullptr) continue;
    const ImVec2 centre = lane.camera.to_screen(weight.body->GetWorldCenter());
    const ImVec2 line = sub(weight.arrow.to, weight.arrow.from);
    const ImVec2 unit = mul(line, 1.0f / length(line));
    const ImVec2 from_centre = sub(weight.arrow.from, centre);
    const float along = from_centre.x * unit.x + from_centre.y * unit.y;
    const float across = std::abs(from_centre.x * unit.y - from_centre.y * unit.x);
    EXPECT_LE(std::abs(along), 0.01f) << where << ": the weight " << weight.text << " starts " << -along
                                      << " px above its body's centre of mass along its line";
    EXPECT_LE(across, 0.01f)
        << where << ": the weight " << weight.text << " starts " << across << " px across its line from its body's centre of mass";
    ++checked;
  }
  return checked;
}

// A weight starts at its body's centre of mass, always (a teacher's trial on a projector, issue
// 31): where it met a contact's arrow it slid back up its line until it cleared it, and push at
// 2.5 s and spring_pull at 2 s drew it from about 50 px above the block, read by a class as a
// push from above; between 3.4 and 3.6 s push's weight jumped from above the block to its centre.
// Those moments, and every built-in lesson at its defaults at its opening, half way and at its
// end, in the window in projector mode at 1920 × 1080, light.
TEST(ForceArrows, AWeightStartsWithinItsBody) {
  int checked = 0;
  const auto check = [&](const std::string& where, const draw::FrameRecord::Lane& lane, const lessons::Lesson&) {
    checked += check_weight_starts_at_its_centre(where, lane);
  };
  projector_lane_at("push", {}, {2.5, 3.4, 3.5, 3.6}, check);
  projector_lane_at("spring_pull", {}, {2.0}, check);
  projector_lane_at("tipping_box", {{"push_height", "0.2"}}, {1.0, 2.0, 2.5}, check);
  each_projector_lane([&](const std::string& where, const draw::FrameRecord::Lane& lane) {
    checked += check_weight_starts_at_its_centre(where, lane);
  });
  EXPECT_GE(checked, 50);
}

// Checks one lane: no arrow lies over an arrow of another body along one line: two within 10°
// of one line (either way along it) whose centre lines stand under side_by_side_gap apart
// (less a hundredth of a pixel of floats) overlap along it by no more than where they meet:
// two arrows from one point in opposite directions (a contact's pair of normal forces, each
// into its own body) only touch. Returns how many pairs along one line it checked.
int check_no_arrow_over_another_bodys(const std::string& where, const draw::FrameRecord::Lane& lane) {
  int checked = 0;
  for (std::size_t i = 0; i < lane.forces.size(); ++i) {
    for (std::size_t j = i + 1; j < lane.forces.size(); ++j) {
      const draw::LabelPlacer::ForceLabel& p = lane.forces[i];
      const draw::LabelPlacer::ForceLabel& q = lane.forces[j];
      if (p.body == q.body) continue;
      const ImVec2 d = sub(p.arrow.to, p.arrow.from);
      const float span = length(d);
      const ImVec2 e = sub(q.arrow.to, q.arrow.from);
      if (!(span > 0.0f) || !(length(e) > 0.0f)) continue;
      const ImVec2 u = mul(d, 1.0f / span);
      if (std::abs(u.x * e.y - u.y * e.x) / length(e) > 0.17f) continue;
      const ImVec2 w0 = sub(q.arrow.from, p.arrow.from), w1 = sub(q.arrow.to, p.arrow.from);
      const float across = std::abs(w0.x * -u.y + w0.y * u.x);
      const float gap = draw::side_by_side_gap(2.0f * p.arrow.half_width);
      if (across >= gap - 0.01f) continue;
      ++checked;
      const float q0 = w0.x * u.x + w0.y * u.y, q1 = w1.x * u.x + w1.y * u.y;
      const float overlap = std::min(span, std::max(q0, q1)) - std::max(0.0f, std::min(q0, q1));
      EXPECT_LE(overlap, 0.01f) << where << ": the " << draw::force_kind_name(p.kind) << " " << p.text << " and the "
                                << draw::force_kind_name(q.kind) << " " << q.text << ", on two bodies, lie along one line "
                                << across << " px apart, over each other for " << overlap << " px";
    }
  }
  return checked;
}

// Arrows of different bodies along one line stand side by side, as one body's weight and
// normal force do (a teacher's trial on a projector, issue 31): stacked_blocks' top block's
// weight ran on past the surface under the normal force the top block presses the bottom one
// with, drawn over it, and a class saw a stub of it and could not tell whose arrow was whose.
// That lesson through its run, and every built-in lesson at its defaults at its opening, half
// way and at its end, in the window in projector mode at 1920 × 1080, light.
TEST(ForceArrows, NoArrowLiesOverAnotherBodysAlongOneLine) {
  int pairs = 0;
  projector_lane_at("stacked_blocks", {}, {1.0, 1.5, 2.12, 3.0, 4.0, 4.2},
                    [&](const std::string& where, const draw::FrameRecord::Lane& lane, const lessons::Lesson&) {
                      pairs += check_no_arrow_over_another_bodys(where, lane);
                    });
  each_projector_lane([&](const std::string& where, const draw::FrameRecord::Lane& lane) {
    pairs += check_no_arrow_over_another_bodys(where, lane);
  });
  // stacked_blocks' arrows of two bodies within a gap along its middle line at each moment (a
  // contact's pair of normal forces from one dot, and what stands by them).
  EXPECT_GE(pairs, 12);
}

// A force's value lies across no ground's surface line where a place beside its arrow off it
// is free (a teacher's trial on a projector, issue 31): incline's weight, its tip on the floor
// where the view ends, had its 9.81 N across the floor's line, read as standing on it, with the
// slope's face beside the shaft free. Its box as placed (padding included) against the
// slab's top, as far as the lane shows it. incline at its end and through its slide, push
// before and after its breakaway, in the window in projector mode at 1920 × 1080, light.
TEST(ForceLabels, AValueLiesOffTheGroundsLineWhereItsArrowLeavesRoom) {
  int checked = 0;
  const auto check = [&](const std::string& where, const draw::FrameRecord::Lane& lane, const lessons::Lesson& at) {
    for (const b2Body* body = at.scene().world().GetBodyList(); body != nullptr; body = body->GetNext()) {
      for (const b2Fixture* fixture = body->GetFixtureList(); fixture != nullptr; fixture = fixture->GetNext()) {
        if (!lessons::is_ground(fixture) || fixture->GetType() == b2Shape::e_edge) continue;
        const b2AABB& box = fixture->GetAABB(0);
        const float top = lane.camera.to_screen(b2Vec2(0.0f, box.upperBound.y - fixture->GetShape()->m_radius)).y;
        const float left = lane.camera.to_screen(box.lowerBound).x, right = lane.camera.to_screen(box.upperBound).x;
        for (const draw::LabelPlacer::ForceLabel& force : lane.forces) {
          if (!force.box) continue;
          ++checked;
          const ImVec4& value = *force.box;
          EXPECT_FALSE(value.y < top && value.w > top && value.x < right && value.z > left)
              << where << ": " << force.text << " at " << text_of(value) << " lies across the ground's line at y = " << top;
        }
      }
    }
  };
  projector_lane_at("incline", {}, {0.5, 1.0}, check);
  projector_lane_at("push", {}, {1.0, 2.5, 3.5}, check);
  EXPECT_GE(checked, 12);
}

// How many of 21 × 21 points inside a box-shaped body, seen through `camera`, show `fill` (to 8
// in each channel), and of how many: a margin of its outline's width (1.5 px times the text
// scale) and a pixel of smoothing in from its edges, and none within `dot_radius` of `dot`.
std::pair<int, int> fill_seen(const draw::Image& picture, const draw::Camera& camera, const b2Body* body, ImU32 fill,
                              float text_scale, std::optional<ImVec2> dot = std::nullopt, float dot_radius = 0.0f) {
  const auto& shape = *static_cast<const b2PolygonShape*>(body->GetFixtureList()->GetShape());
  b2Vec2 low = shape.m_vertices[0], high = low;
  for (int k = 1; k < shape.m_count; ++k) low = b2Min(low, shape.m_vertices[k]), high = b2Max(high, shape.m_vertices[k]);
  const float margin = (1.5f * text_scale + 1.0f) / camera.pixels_per_metre;
  const int fill_rgb[3] = {static_cast<int>(fill >> IM_COL32_R_SHIFT & 0xFF), static_cast<int>(fill >> IM_COL32_G_SHIFT & 0xFF),
                           static_cast<int>(fill >> IM_COL32_B_SHIFT & 0xFF)};
  int sampled = 0, seen = 0;
  constexpr int steps = 20;
  for (int i = 0; i <= steps; ++i) {
    for (int j = 0; j <= steps; ++j) {
      const b2Vec2 local(low.x + margin + (high.x - low.x - 2.0f * margin) * static_cast<float>(i) / steps,
                         low.y + margin + (high.y - low.y - 2.0f * margin) * static_cast<float>(j) / steps);
      const ImVec2 at = camera.to_screen(body->GetWorldPoint(local));
      if (dot && std::hypot(at.x - dot->x, at.y - dot->y) <= dot_radius) continue;
      const std::uint8_t* pixel = picture.pixel(static_cast<int>(at.x), static_cast<int>(at.y));
      ++sampled;
      seen += std::max({std::abs(pixel[0] - fill_rgb[0]), std::abs(pixel[1] - fill_rgb[1]), std::abs(pixel[2] - fill_rgb[2])}) <= 8;
    }
  }
  return {seen, sampled};
}

// incline in the window at 1920 × 1080 in projector mode at each of `angles`, both themes, drawn
// to `t`: its record and its picture, for `check`.
void incline_on_a_projector(
    const std::vector<const char*>& angles, double t,
    const std::function<void(const std::string& where, draw::ThemeName theme, Classroom& window, const draw::FrameRecord& record,
                             const draw::Image& picture, const draw::ImGuiHost& host)>& check) {
  const ImVec2 display(1920.0f, 1080.0f);
  draw::HeadlessContext gl;
  draw::ImGuiHost host(nullptr);
  for (const draw::ThemeName name : {draw::ThemeName::light, draw::ThemeName::dark}) {
    for (const char* angle : angles) {
      ClassroomOptions options = class_window(lessons::resolve_lesson("incline"), {"1920x1080", 1920, 1080, true});
      options.window.theme = name;
      options.overrides["angle"] = angle;
      Classroom window(options);
      draw_window_frame(gl, host, window, display);
      const draw::FrameRecord record = recorded_at(gl, host, window, display, t);
      gl.make_current();
      gl.bind_framebuffer(static_cast<int>(display.x), static_cast<int>(display.y));
      ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
      const draw::Image picture = gl.read_pixels();
      check(std::string("incline at ") + angle + "°, " + (name == draw::ThemeName::dark ? "dark" : "light"), name, window, record,
            picture, host);
    }
  }
}

// Issue 31: incline's block on a projector at its defaults (0.4 by 0.2 m, 23 by 12 px in the
// window's world) lay whole under its contact's 24 px dot, the normal force and weight that start
// on it and the friction's plate: the class saw arrows and no block (2 % of its inside in its
// material's colour at 1 s, light). A body thinner than its dot is drawn over them. Read from the
// window's pixels in projector mode at 1920 × 1080, both themes, as it sits and as it slides: the
// block's inside, a margin of its outline's width and a pixel of smoothing in from its edges,
// shows its material's fill at 90 % of the points sampled or more (the rest: its corners' smoothing).
// Its contact's dot is drawn again over the arrows, before the block, so its half in the slope
// says the contact's state (the dark theme's was hidden whole under the arrows' outlines).
TEST(WorldView, InclinesSmallBlockIsSeenOverItsDotAndArrowsOnAProjector) {
  incline_on_a_projector({"25", "35"}, 1.0, [](const std::string& where, draw::ThemeName name, Classroom& window,
                                               const draw::FrameRecord& record, const draw::Image& picture, const draw::ImGuiHost& host) {
    ASSERT_EQ(record.lanes.size(), 1u) << where;
    const draw::Camera& camera = record.lanes.front().camera;
    const lessons::Lesson& lesson = window.playback().lesson();
    const b2Body* block = lesson.scene().body("block");
    ASSERT_NE(block, nullptr);
    const b2Fixture* fixture = block->GetFixtureList();
    ASSERT_EQ(fixture->GetType(), b2Shape::e_polygon) << where;
    const ImU32 fill = draw::fixture_colour(lesson.scene(), fixture, draw::theme(name));
    const auto [seen, sampled] = fill_seen(picture, camera, block, fill, host.fonts().scale);
    EXPECT_GE(seen, 0.9 * sampled) << where << ": " << seen << " of " << sampled << " points inside the block show its fill";
    // And its contact's dot, over the weight's shaft and the friction's plate that hid it in the
    // dark theme: the half under the surface shows its state's colour half a radius into the slope.
    const std::vector<ContactMark> marks = contact_marks(lesson.scene());
    ASSERT_EQ(marks.size(), 1u) << where;
    const b2Vec2 into = -upper_side(marks[0]) * b2Cross(1.0f, marks[0].tangent);
    const float half_radius = 0.5f * draw::contact_dot_radius * host.fonts().scale;
    const ImVec2 dot = add(camera.to_screen(marks[0].point), ImVec2(into.x * half_radius, -into.y * half_radius));
    const draw::Theme& colours = draw::theme(name);
    const ImU32 state = marks[0].state == ContactState::slipping ? colours.slipping : colours.sticking;
    const std::uint8_t* pixel = picture.pixel(static_cast<int>(std::lround(dot.x)), static_cast<int>(std::lround(dot.y)));
    EXPECT_LE(std::max({std::abs(pixel[0] - static_cast<int>(state >> IM_COL32_R_SHIFT & 0xFF)),
                        std::abs(pixel[1] - static_cast<int>(state >> IM_COL32_G_SHIFT & 0xFF)),
                        std::abs(pixel[2] - static_cast<int>(state >> IM_COL32_B_SHIFT & 0xFF))}), 8)
        << where << ": the contact's dot does not show at (" << dot.x << ", " << dot.y << ")";
  });
}

// Issue 31: incline's window holds the whole slope, foot and angle mark, and its 0.4 m block is
// 23 px long on a projector, too small to see from the back row. Where the free-body inset
// cannot be read (a projector), a close-up of the block stands over a corner of the world that
// the slope leaves clear: at 2°, 35° and 60°, both themes, at 0.5 s, the block in it is at least
// min_body_pixels long (at the text scale), as every framed view keeps it, shows its fill at 90 %
// of the points sampled inside it off its contact's dot, lies whole inside the close-up, and the
// close-up covers none of the slope; no label of the world's lies on it. In the 1280 × 720 window the free-body inset shows the block, and
// no close-up is drawn.
TEST(WorldView, InclinesBlockHasAReadableCloseUpOnAProjector) {
  incline_on_a_projector({"2", "35", "60"}, 0.5, [](const std::string& where, draw::ThemeName name, Classroom& window,
                                                    const draw::FrameRecord& record, const draw::Image& picture,
                                                    const draw::ImGuiHost& host) {
    const lessons::Lesson& lesson = window.playback().lesson();
    const b2Body* block = lesson.scene().body("block");
    ASSERT_NE(block, nullptr);
    ASSERT_EQ(record.lanes.size(), 1u) << where;
    const float scale = host.fonts().scale;
    const float in_the_world = draw::own_length(block) * record.lanes.front().camera.pixels_per_metre;
    if (in_the_world >= draw::min_body_pixels * scale) {
      // A gentle slope's window is as wide as it is long: the block is readable there.
      EXPECT_TRUE(record.close_ups.empty()) << where << ": a close-up of a block " << in_the_world << " px long";
      return;
    }
    ASSERT_EQ(record.close_ups.size(), 1u) << where << ": the block is " << in_the_world << " px long and has no close-up";
    const draw::FrameRecord::Lane& close_up = record.close_ups.front();
    const ImVec4 place = close_up.shown;
    EXPECT_GE(draw::own_length(block) * close_up.camera.pixels_per_metre, draw::min_body_pixels * scale) << where;
    const std::vector<ContactMark> marks = contact_marks(lesson.scene());
    ASSERT_EQ(marks.size(), 1u) << where;
    // The dot's outline and a pixel of smoothing past its radius.
    const float dot_radius = draw::contact_dot_radius * scale + 1.5f + 1.0f;
    const auto [seen, sampled] =
        fill_seen(picture, close_up.camera, block, draw::fixture_colour(lesson.scene(), block->GetFixtureList(), draw::theme(name)),
                  scale, close_up.camera.to_screen(marks[0].point), dot_radius);
    EXPECT_GE(seen, 0.9 * sampled) << where << ": " << seen << " of " << sampled << " points inside the close-up's block show its fill";
    const b2AABB box = lessons::body_box(block);
    for (const b2Vec2 corner : {box.lowerBound, box.upperBound}) {
      const ImVec2 at = close_up.camera.to_screen(corner);
      EXPECT_TRUE(at.x > place.x && at.x < place.z && at.y > place.y && at.y < place.w) << where << ": the block leaves its close-up";
    }
    const b2Body* slope = lesson.scene().body("slope");
    ASSERT_NE(slope, nullptr);
    const draw::Camera& world = record.lanes.front().camera;
    for (int i = 0; i <= 12; ++i) {
      for (int j = 0; j <= 8; ++j) {
        const ImVec2 at(place.x + (place.z - place.x) * static_cast<float>(i) / 12.0f, place.y + (place.w - place.y) * static_cast<float>(j) / 8.0f);
        EXPECT_FALSE(slope->GetFixtureList()->TestPoint(world.to_world(at))) << where << ": the close-up covers the slope at (" << at.x << ", " << at.y << ")";
      }
    }
    for (const ImVec4& label : record.lanes.front().labels) {
      EXPECT_FALSE(label.x < place.z && label.z > place.x && label.y < place.w && label.w > place.y)
          << where << ": a world's label at (" << label.x << ", " << label.y << ") lies on the close-up";
    }
  });
  draw::HeadlessContext gl;
  draw::ImGuiHost host(nullptr);
  // The window at a screen's size: the free-body inset is there, and no close-up.
  const ImVec2 screen(1280.0f, 720.0f);
  ClassroomOptions options = class_window(lessons::resolve_lesson("incline"), {"1280x720", 1280, 720, false});
  Classroom window(options);
  draw_window_frame(gl, host, window, screen);
  const draw::FrameRecord record = recorded_at(gl, host, window, screen, 0.5);
  EXPECT_TRUE(record.close_ups.empty());
  EXPECT_GT(record.inset.z, record.inset.x);
}

// The view does not zoom during a run (a teacher's projector trial, issue 31): incline's window
// grew from its block's foot of the moment to hold the normal force above it, and its 2 m scale
// bar was 93 px at 0.6 s and 133 px at 1.5 s as the block slid down. Every built-in lesson at
// its defaults in the window at 1920 × 1080, in projector mode and not, at its opening, half way
// and at its end, and incline on a projector at 0.2, 0.6, 1 and 1.5 s: each lane's scale (pixels
// a metre) is the one of the first frame, to a millionth of it.
TEST(WorldView, DoesNotZoomDuringTheRun) {
  int compared = 0;
  std::map<std::string, float> first;
  const auto check = [&](const std::string& lesson, const std::string& where, const draw::FrameRecord& record) {
    for (const draw::FrameRecord::Lane& lane : record.lanes) {
      const auto [at, inserted] = first.emplace(lesson, lane.camera.pixels_per_metre);
      if (inserted) continue;
      EXPECT_NEAR(lane.camera.pixels_per_metre, at->second, 1e-6f * at->second)
          << where << ": the view shows " << lane.camera.pixels_per_metre << " px a metre, " << at->second << " at first";
      ++compared;
    }
  };
  projector_frames_at("incline", {}, {0.2, 0.6, 1.0, 1.5}, [&](const std::string& where, const draw::FrameRecord& record,
                                                                const lessons::Lesson&) { check("incline", where, record); });
  for (const bool projector : {true, false}) {
    first.clear();
    each_lesson_frame(projector, draw::ThemeName::light,
                      [&](const std::string& lesson, const std::string& when, const draw::FrameRecord& record,
                          const lessons::Lesson&) { check(lesson, lesson + when + (projector ? ", projector" : ""), record); });
  }
  EXPECT_GE(compared, 40);
}

// Every arrow's tip is in the picture: pulley's 9.81 N normal force ran out of the view's top
// once the arrows' scale came from the lesson's run (its largest force 0.4 of the view's height)
// while the camera kept room above the bodies as a share of the view, not of the arrows' drawn
// lengths. Every built-in lesson at its defaults in the window at 1920 × 1080, in projector mode
// and not, at its opening, half way and at its end: each arrow's tip inside what of its lane
// shows (the lane's clip), to the floats' rounding (a hundredth of a pixel). The lessons in lanes
// too (contact_area, friction_models, terrain, thrown_box, where_methods_fail), each lane's
// arrows in that lane: terrain's four lanes on a projector were 84.5 px high, where a normal force
// and a weight of the legible 61 px each need about 150, and their tips left their lanes; the
// lanes now stand in columns side by side where a strip would be thinner than that
// (framing_cameras' lane_grid).
TEST(ForceArrows, EveryArrowsTipIsInsideTheWorldView) {
  int checked = 0, lanes_checked = 0;
  for (const bool projector : {true, false}) {
    each_lesson_frame(projector, draw::ThemeName::light,
                      [&](const std::string& lesson, const std::string& when, const draw::FrameRecord& record,
                          const lessons::Lesson&) {
                        for (const draw::FrameRecord::Lane& lane : record.lanes) {
                          for (const draw::LabelPlacer::ForceLabel& force : lane.forces) {
                            const ImVec2 tip = force.arrow.to;
                            const float slack = 0.01f;
                            const bool inside = tip.x >= lane.shown.x - slack && tip.x <= lane.shown.z + slack &&
                                                tip.y >= lane.shown.y - slack && tip.y <= lane.shown.w + slack;
                            lanes_checked += record.lanes.size() > 1 ? 1 : 0;
                            EXPECT_TRUE(inside)
                                << lesson << when << (projector ? ", projector" : "") << ": the "
                                << draw::force_kind_name(force.kind) << " " << force.text << "'s tip (" << tip.x << ", "
                                << tip.y << ") is outside the view (" << lane.shown.x << ", " << lane.shown.y << ") to ("
                                << lane.shown.z << ", " << lane.shown.w << ")";
                            ++checked;
                          }
                        }
                      });
  }
  EXPECT_GE(checked, 250);
  EXPECT_GE(lanes_checked, 100);
}

// Every force's arrow stands out from whatever it is drawn over, in both themes: against every
// material's fill (the known looks and the palette's six), the sky and the background, either
// the arrow's own colour differs from it 3:1 or more (WCAG 2.1's non-text contrast), or its
// outline (Theme::arrow_halo, drawn round every arrow) differs from the arrow 3:1 or more, so the
// arrow's edge is seen whatever lies beyond. Issue 31: the dark theme's normal force on
// aluminium was 1.09:1, its weight 1.58:1, with nothing between them.
TEST(ForceArrows, StandOutFromEveryBodyTheSkyAndTheBackgroundInBothThemes) {
  const char* const materials[] = {"wood",     "aluminium", "metal", "plastic", "rubber", "ice",
                                   "concrete", "stone",     "asphalt", "grass"};
  int pairs = 0, outlined = 0;
  for (const draw::ThemeName name : {draw::ThemeName::light, draw::ThemeName::dark}) {
    const draw::Theme& colours = draw::theme(name);
    std::vector<std::pair<std::string, ImU32>> under = {{"sky", colours.sky}, {"background", colours.background}};
    for (const char* material : materials) under.emplace_back(material, draw::material_colour(colours, material, 0));
    for (int slot = 0; slot < 6; ++slot) {
      under.emplace_back("palette " + std::to_string(slot), draw::material_colour(colours, "unnamed", slot));
    }
    for (int kind = 0; kind < draw::force_kind_count; ++kind) {
      const ImU32 arrow = colours.force[kind];
      for (const auto& [what, fill] : under) {
        ++pairs;
        if (draw::contrast_ratio(arrow, fill) >= 3.0) continue;
        ++outlined;
        EXPECT_GE(colours.arrow_halo == 0 ? 1.0 : draw::contrast_ratio(arrow, colours.arrow_halo), 3.0)
            << draw::theme_name(name) << ": the " << draw::force_kind_name(static_cast<ForceKind>(kind)) << " arrow on "
            << what << " is " << draw::contrast_ratio(arrow, fill) << ":1, and its outline does not set it apart";
      }
    }
  }
  EXPECT_EQ(pairs, 2 * draw::force_kind_count * 18);
  EXPECT_GE(outlined, 10);  // the outline is what sets many apart: the test is not empty
}

// And it is drawn: in spring_pull's dark-theme picture (an aluminium block) in projector mode,
// across the normal force's shaft where it lies over the block, the pixels just past each side
// of the shaft are the outline's colour, not the block's.
TEST(ForceArrows, TheOutlineIsDrawnRoundTheShaft) {
  const Screen& screen = screens[3];
  for (const draw::ThemeName name : {draw::ThemeName::dark, draw::ThemeName::light}) {
    draw::HeadlessRenderer renderer(screen.width, screen.height, name, screen.scale);
    const draw::Theme& colours = draw::theme(name);
    draw::LessonAt at("spring_pull", {}, 1.0);
    draw::FrameRecord record;
    const draw::Image image = renderer.render(*at.lesson, at.framing, &record);
    int checked = 0;
    for (const draw::FrameRecord::Lane& lane : record.lanes) {
      for (const draw::LabelPlacer::ForceLabel& force : lane.forces) {
        if (force.kind != ForceKind::normal) continue;
        const draw::DrawnSegment& shaft = force.arrow;
        const ImVec2 unit = mul(sub(shaft.to, shaft.from), 1.0f / length(sub(shaft.to, shaft.from)));
        const ImVec2 across(-unit.y, unit.x);
        // A point a quarter along, over the block; half the shaft and half the outline out.
        const ImVec2 middle = add(shaft.from, mul(sub(shaft.to, shaft.from), 0.25f));
        const float out = shaft.half_width + 0.5f * draw::arrow_halo_width(2.0f * shaft.half_width);
        for (const float side : {1.0f, -1.0f}) {
          const ImVec2 p = add(middle, mul(across, side * out));
          const std::uint8_t* pixel = image.pixel(static_cast<int>(std::lround(p.x)), static_cast<int>(std::lround(p.y)));
          const ImU32 seen = IM_COL32(pixel[0], pixel[1], pixel[2], 255);
          EXPECT_GE(draw::contrast_ratio(seen, colours.force[static_cast<int>(ForceKind::normal)]), 3.0)
              << draw::theme_name(name) << ": beside the normal force's shaft at (" << p.x << ", " << p.y << ") the pixel ("
              << int(pixel[0]) << ", " << int(pixel[1]) << ", " << int(pixel[2]) << ") does not set the arrow apart";
          ++checked;
        }
      }
    }
    EXPECT_EQ(checked, 2) << draw::theme_name(name);
  }
}

// Every arrow stands out from a surround as wide as its shaft, whatever it lies over: driven_wheel's
// dark grey weight on its dark rubber wheel showed only its thin white outline at 1 s on a
// projector, read as an empty arrow (a teacher's trial, issue 31). Across each force's shaft at
// its middle, every pixel from the shaft's edge to a thickness beyond it, on both sides, differs
// from the arrow's colour 3:1 or more (WCAG 2.1's non-text contrast): the arrow's outline, its
// plate where it lies over a fill like its colour, or the fill itself where that stands apart.
// Lessons whose arrows lie over bodies, floors and slopes, in both themes, at projector size.
TEST(ForceArrows, EachStandsOutFromASurroundAsWideAsItsShaft) {
  const Screen& screen = screens[3];
  int checked = 0;
  for (const draw::ThemeName name : {draw::ThemeName::light, draw::ThemeName::dark}) {
    draw::HeadlessRenderer renderer(screen.width, screen.height, name, screen.scale);
    const draw::Theme& colours = draw::theme(name);
    for (const auto& [lesson, t] : {std::pair{"driven_wheel", 1.0}, std::pair{"spring_pull", 1.0}, std::pair{"push", 2.5},
                                    std::pair{"tipping_box", 2.2}, std::pair{"incline", 1.0}}) {
      draw::LessonAt at(lesson, {}, t);
      draw::FrameRecord record;
      const draw::Image image = renderer.render(*at.lesson, at.framing, &record);
      for (const draw::FrameRecord::Lane& lane : record.lanes) {
        for (const draw::LabelPlacer::ForceLabel& force : lane.forces) {
          // A leader to its value leaves the shaft in the arrow's own colour.
          if (force.leader) continue;
          const draw::DrawnSegment& shaft = force.arrow;
          const ImU32 colour = colours.force[static_cast<int>(force.kind)];
          const float span = length(sub(shaft.to, shaft.from));
          const ImVec2 unit = mul(sub(shaft.to, shaft.from), 1.0f / span), across(-unit.y, unit.x);
          // The middle of the shaft's part before the head (draw_arrow's: four thicknesses, at most 0.6 of the arrow).
          const float thickness = 2.0f * shaft.half_width;
          const float head = std::min(4.0f * thickness, 0.6f * span);
          const ImVec2 middle = add(shaft.from, mul(unit, 0.5f * (span - head)));
          // A broken shaft's dash or gap there: the surround is judged beside it all the same.
          double worst = 1e9;
          ImVec2 where(0.0f, 0.0f);
          for (const float side : {1.0f, -1.0f}) {
            for (float out = shaft.half_width + 1.0f; out <= shaft.half_width + thickness; out += 1.0f) {
              const ImVec2 p = add(middle, mul(across, side * out));
              const std::uint8_t* pixel = image.pixel(static_cast<int>(std::lround(p.x)), static_cast<int>(std::lround(p.y)));
              const double ratio = draw::contrast_ratio(IM_COL32(pixel[0], pixel[1], pixel[2], 255), colour);
              if (ratio < worst) worst = ratio, where = p;
            }
          }
          EXPECT_GE(worst, 3.0) << lesson << " at " << t << " s, " << draw::theme_name(name) << ": beside the "
                                << draw::force_kind_name(force.kind) << " " << force.text << "'s shaft at (" << where.x << ", "
                                << where.y << ") the picture is " << worst << ":1 against the arrow";
          ++checked;
        }
      }
    }
  }
  EXPECT_GE(checked, 30);
}

// The plate an arrow lies on where its fill is like its colour (draw_arrow's `plate`) is the
// arrow's own outline, a thickness wide, not a bar: in the dark theme its near-black strip, as
// wide as the head from the tail to the tip, read on a projector as black rectangles beside
// terrain's and driven_wheel's weights (a teacher's trial, issue 31). In the dark theme at
// projector size, every pixel of the plate's colour lies within a thickness and a pixel (and a
// pixel of rounding) of some arrow's shaft or head, where the surround
// ForceArrows.EachStandsOutFromASurroundAsWideAsItsShaft asks for is, but for one in fifty;
// before, 846 pixels lay further out in terrain (7522 within) and 1290 in driven_wheel (5868
// within). The arrows on plates here: terrain's weights and normal forces on their boxes,
// driven_wheel's weight on its rubber wheel.
TEST(ForceArrows, APlateIsTheArrowsOutlineNotABar) {
  const Screen& screen = screens[3];
  const draw::ThemeName name = draw::ThemeName::dark;
  draw::HeadlessRenderer renderer(screen.width, screen.height, name, screen.scale);
  const ImU32 plate = draw::theme(name).arrow_halo;
  const auto near_plate_colour = [&](const std::uint8_t* pixel) {
    const int channel[3] = {static_cast<int>(plate & 0xff), static_cast<int>((plate >> 8) & 0xff),
                            static_cast<int>((plate >> 16) & 0xff)};
    return std::abs(pixel[0] - channel[0]) <= 2 && std::abs(pixel[1] - channel[1]) <= 2 && std::abs(pixel[2] - channel[2]) <= 2;
  };
  int plated = 0;
  for (const auto& [lesson, t] : {std::pair{"terrain", 2.0}, std::pair{"driven_wheel", 1.0}}) {
    draw::LessonAt at(lesson, {}, t);
    draw::FrameRecord record;
    const draw::Image image = renderer.render(*at.lesson, at.framing, &record);
    int inside = 0, outside = 0;
    for (const draw::FrameRecord::Lane& lane : record.lanes) {
      // How far a point is outside an arrow's shape (its shaft as a segment `half_width` wide,
      // its head draw_arrow's triangle), px; 0 inside.
      const auto outside_arrow = [](ImVec2 p, const draw::DrawnSegment& arrow) {
        const float span = length(sub(arrow.to, arrow.from));
        const ImVec2 unit = mul(sub(arrow.to, arrow.from), 1.0f / span), across(-unit.y, unit.x);
        const float thickness = 2.0f * arrow.half_width;
        const float head = std::min(4.0f * thickness, 0.6f * span);
        const ImVec2 d = sub(p, arrow.from);
        const float along = d.x * unit.x + d.y * unit.y, side = d.x * across.x + d.y * across.y;
        const float shaft = std::hypot(std::max({0.0f, -along, along - span}), std::max(0.0f, std::abs(side) - arrow.half_width));
        // The head: the triangle from the tip back `head` to a base 0.45 head wide each side.
        const ImVec2 base = sub(arrow.to, mul(unit, head));
        const ImVec2 corners[3] = {arrow.to, add(base, mul(across, 0.45f * head)), sub(base, mul(across, 0.45f * head))};
        const auto cross = [](ImVec2 a, ImVec2 b, ImVec2 q) { return (b.x - a.x) * (q.y - a.y) - (b.y - a.y) * (q.x - a.x); };
        const float c0 = cross(corners[0], corners[1], p), c1 = cross(corners[1], corners[2], p), c2 = cross(corners[2], corners[0], p);
        float in_head = 0.0f;
        if (!((c0 >= 0.0f && c1 >= 0.0f && c2 >= 0.0f) || (c0 <= 0.0f && c1 <= 0.0f && c2 <= 0.0f))) {
          in_head = 1e9f;
          for (int k = 0; k < 3; ++k) {
            in_head = std::min(in_head, draw::gap(draw::DrawnSegment{corners[k], corners[(k + 1) % 3], 0.0f},
                                                  draw::DrawnSegment{p, p, 0.0f}));
          }
        }
        return std::min(shaft, in_head);
      };
      for (int y = static_cast<int>(lane.shown.y); y < static_cast<int>(lane.shown.w); ++y) {
        for (int x = static_cast<int>(lane.shown.x); x < static_cast<int>(lane.shown.z); ++x) {
          if (!near_plate_colour(image.pixel(x, y))) continue;
          const ImVec2 p(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f);
          float nearest = 1e9f, allowed = 0.0f;
          for (const draw::LabelPlacer::ForceLabel& force : lane.forces) {
            const float off = outside_arrow(p, force.arrow);
            if (off < nearest) nearest = off, allowed = 2.0f * force.arrow.half_width + 2.0f;
          }
          // Only pixels by an arrow: the sky or a body of about the plate's colour far off is not a plate.
          if (nearest > 4.0f * allowed) continue;
          (nearest <= allowed ? inside : outside) += 1;
        }
      }
    }
    EXPECT_GT(inside, 200) << lesson << ": no arrow on a plate (its fill no longer like its colour?)";
    EXPECT_LE(outside, inside / 50) << lesson << " at " << t << " s: " << outside << " pixels of the plate's colour lie more than a thickness outside the arrows, "
                                    << inside << " within";
    ++plated;
  }
  EXPECT_EQ(plated, 2);
}

// The speed readout of a body at the world view's left edge, with projector text: centred over
// the body it would start left of the view; the placer moves it in, and used to stop at the
// lane's edge, where the world's panel clips 10 px (half its padding) and the readout lost its
// first letter. Every label is inside the part of the lane that shows.
TEST(WorldLabels, StayInsideWhatTheWorldViewShowsAtItsEdge) {
  draw::HeadlessContext gl;
  draw::ImGuiHost host(nullptr);
  const float scale = 1.35f * 1.5f;
  const draw::Fonts& fonts = host.prepare(scale, draw::ThemeName::light);
  const ImVec2 display(1920.0f, 944.0f);
  for (const char* name : {"push", "incline"}) {
    draw::LessonAt at(name, {}, 0.5);
    lessons::Lesson& lesson = *at.lesson;
    MeasuringTools tools;
    tools.on.speed = true;
    tools.follow(lesson, false);
    draw::FrameRecord record;
    draw::FrameStyle style;
    style.fonts = &fonts;
    style.record = &record;
    // The view panned so that the main body's centre is at its left edge.
    const draw::Camera before = draw::world_camera(lesson, at.framing, display, scale);
    const b2Body* body = measured_body(lesson);
    ASSERT_NE(body, nullptr) << name;
    const float offset = before.to_screen(body->GetWorldCenter()).x - before.origin.x;
    style.view_adjust.pan = b2Vec2(offset / before.pixels_per_metre, 0.0f);
    style.world_tools = [&](draw::WorldToolsPass pass, ImDrawList* draw, const draw::Camera& camera, std::size_t /*lane*/,
                            float newtons_to_pixels, draw::LabelPlacer& labels) {
      tools.in_world(pass, draw, lesson, camera, 0, newtons_to_pixels, theme(draw::ThemeName::light), fonts, labels);
    };
    ImGuiIO& io = ImGui::GetIO();
    io.DisplaySize = display;
    io.DeltaTime = 1.0f / 60.0f;
    host.begin_frame();
    build_frame(lesson, at.framing, style, display);
    ImGui::Render();
    ASSERT_EQ(record.lanes.size(), 1u) << name;
    const draw::FrameRecord::Lane& lane = record.lanes.front();
    const float body_x = lane.camera.to_screen(body->GetWorldCenter()).x;
    ASSERT_NEAR(body_x, lane.camera.origin.x, 2.0f) << name << ": the body is not at the view's left edge";
    EXPECT_GT(lane.shown.x, lane.camera.origin.x) << name << ": the world's panel clips nothing off its lane";
    check_layout(record, lesson, std::string(name) + " panned to the left edge, speed readout on");
  }
}

// The measuring tools' labels in the lessons a teacher tried them on, at 1280 × 720 and in
// projector mode: the speed readout is never on the body it measures (it was drawn on
// spring_pull's block); no label lies on a spring's coils (spring_pull's force label was drawn
// on them); every distance mark's number is drawn at its tick unless an arrow, a contact mark, a
// spring, a body or the view's edge is there, never given up to a label that could move (force
// labels and the speed readout hid them); and behind the start the numbers are negative (they
// had no minus sign; forward is rightwards, or downhill on a slope). With every other layout
// rule of check_layout.
TEST(WorldLabels, TheMeasuringToolsReadingsKeepOffTheBodiesTheSpringsAndEachOther) {
  draw::HeadlessContext gl;
  draw::ImGuiHost host(nullptr);
  struct Size {
    const char* name;
    ImVec2 display;
    float scale;
  };
  // The window's world frame in projector mode: under its menu bar, above its transport bar.
  const Size sizes[] = {{"1280x720", ImVec2(1280.0f, 720.0f), draw::frame_scale(1280, 720)},
                        {"projector_1920x1080", ImVec2(1920.0f, 944.0f), 1.35f * draw::frame_scale(1920, 1080)}};
  struct Moment {
    const char* lesson;
    std::map<std::string, std::string> set;
    double at;
  };
  const Moment moments[] = {{"spring_pull", {}, 0.0},  {"spring_pull", {}, 0.5}, {"spring_pull", {}, 1.2},
                            {"spring_pull", {}, 2.5},  {"push", {}, 0.0},        {"push", {}, 1.0},
                            {"push", {}, 2.0},         {"incline", {}, 0.0},     {"incline", {}, 0.3},
                            {"incline", {}, 0.8},      {"incline", {{"angle", "25"}}, 0.5},
                            // Two blocks, eight arrows and a ruler in a short projector view: the
                            // stopwatch and the speed, placed last, found no room and covered the
                            // forces' values and the block. (At t = 0 in projector text the speed
                            // has no place off the blocks at all and goes on the bottom one.)
                            {"stacked_blocks", {}, 2.0}, {"stacked_blocks", {}, 4.2}};
  int numbers_shown = 0, negative_numbers = 0, springs_checked = 0;
  for (const Size& size : sizes) {
    for (const draw::ThemeName theme_name : {draw::ThemeName::light, draw::ThemeName::dark}) {
      const draw::Fonts& fonts = host.prepare(size.scale, theme_name);
      for (const Moment& moment : moments) {
        draw::LessonAt at(moment.lesson, moment.set, 0.0);
        lessons::Lesson& lesson = *at.lesson;
        MeasuringTools tools;
        tools.on = ToolSettings{true, true, true, true};
        tools.follow(lesson, false);  // the start is taken at t = 0, as the window does
        at.step_to(moment.at);
        tools.follow(lesson, false);
        draw::FrameRecord record;
        draw::FrameStyle style;
        style.theme = theme_name;
        style.fonts = &fonts;
        style.record = &record;
        std::vector<std::optional<DistanceMarks>> marks;
        style.world_tools = [&](draw::WorldToolsPass pass, ImDrawList* draw, const draw::Camera& camera, std::size_t /*lane*/,
                                float newtons_to_pixels, draw::LabelPlacer& labels) {
          // As the marks find the placer when they are drawn.
          if (pass == draw::WorldToolsPass::fixed_labels) marks.push_back(tools.distance_marks(lesson, camera, fonts, &labels));
          tools.in_world(pass, draw, lesson, camera, 0, newtons_to_pixels, theme(theme_name), fonts, labels);
        };
        ImGuiIO& io = ImGui::GetIO();
        io.DisplaySize = size.display;
        io.DeltaTime = 1.0f / 60.0f;
        host.begin_frame();
        build_frame(lesson, at.framing, style, size.display);
        ImGui::Render();
        char when[32];
        std::snprintf(when, sizeof when, " at %.1f s", moment.at);
        std::string where = std::string(moment.lesson) + (moment.set.empty() ? "" : " at 25°") + when + ", " + size.name;
        if (theme_name == draw::ThemeName::dark) where += ", dark";
        check_layout(record, lesson, where);
        ASSERT_EQ(record.lanes.size(), 1u) << where;
        ASSERT_EQ(marks.size(), 1u) << where;
        const draw::FrameRecord::Lane& lane = record.lanes.front();
        ASSERT_EQ(lane.texts.size(), lane.labels.size()) << where;
        const draw::Camera& camera = lane.camera;
        const Scene& scene = lesson.scene();

        // The speed readout, once, off the body it measures (its polygons as drawn).
        const b2Body* body = measured_body(lesson);
        ASSERT_NE(body, nullptr) << where;
        const int readouts = readings_off(lane, body, where);
        EXPECT_EQ(readouts, 1) << where;

        // No label on a spring's coils: its line, and the coils' 7 px (times the text scale) either
        // side of it.
        for (const Spring& spring : scene.springs()) {
          const ImVec2 from = camera.to_screen(spring.body->GetWorldPoint(spring.local_point));
          const ImVec2 to = camera.to_screen(spring.other ? spring.other->GetWorldPoint(spring.other_local_point)
                                                          : scene.hand_position(spring));
          const draw::DrawnSegment coils{from, to, 7.0f * size.scale};
          ++springs_checked;
          for (std::size_t i = 0; i < lane.labels.size(); ++i) {
            EXPECT_FALSE(overlaps(drawn(lane.labels[i]), coils))
                << where << ": the label \"" << lane.texts[i] << "\" at " << text_of(drawn(lane.labels[i]))
                << " lies on the spring's coils";
          }
        }

        // Each tick's number at its tick, or a fixed drawing in its place: never a label.
        ASSERT_TRUE(marks.front().has_value()) << where << ": no distance marks";
        const ImVec2 start = camera.to_screen(*tools.distance_origin());
        const std::optional<Surface> surface = surface_under(scene, body);
        ASSERT_TRUE(surface.has_value()) << where;
        const bool downhill_left = surface->along.y > 0.01f;
        // Where too few numbers find room, only every few ticks are numbered: how many, from the
        // nearest two numbers shown. The ticks between are not numbered by rule, not for a label.
        std::vector<double> shown_metres;
        for (const DistanceMark& mark : marks.front()->ticks) {
          if (std::find(lane.texts.begin(), lane.texts.end(), mark.text) != lane.texts.end()) shown_metres.push_back(mark.metres);
        }
        double nearest = marks.front()->step;
        for (std::size_t i = 1; i < shown_metres.size(); ++i) {
          nearest = i == 1 ? std::abs(shown_metres[1] - shown_metres[0]) : std::min(nearest, std::abs(shown_metres[i] - shown_metres[i - 1]));
        }
        // And never closer than the ruler's least spacing of its numbers (DistanceMarks::least_every).
        const auto every = std::max(static_cast<std::size_t>(std::lround(nearest / marks.front()->step)), marks.front()->least_every);
        for (const DistanceMark& mark : marks.front()->ticks) {
          if (!counted(mark, std::max<std::size_t>(every, 1), marks.front()->step)) continue;
          const auto shown = std::find_if(lane.texts.begin(), lane.texts.end(), [&](const std::string& text) {
            return text == mark.text;
          });
          if (shown != lane.texts.end()) {
            const ImVec4& box = lane.labels[static_cast<std::size_t>(shown - lane.texts.begin())];
            // Beyond its tick, or across the line from it.
            const auto there = [&](const ImVec4& place) {
              return std::abs(box.x - place.x) < 0.01f && std::abs(box.y - place.y) < 0.01f;
            };
            EXPECT_TRUE(there(mark.number_box) || there(mark.across_box)) << where << ": " << mark.text << " is not at its tick";
            ++numbers_shown;
            // Its sign says which side of the start it is on: forward is rightwards on a floor,
            // downhill on a slope. (The start's own tick, a few pixels into a slope, says 0 m.)
            if (mark.text == "0 m") continue;
            const bool behind = downhill_left ? mark.foot.x > start.x + 1.0f : mark.foot.x < start.x - 1.0f;
            EXPECT_EQ(mark.text.rfind("\u2212", 0) == 0, behind) << where << ": " << mark.text << " at x = " << mark.foot.x
                                                                   << ", the start at x = " << start.x;
            if (behind) ++negative_numbers;
            continue;
          }
          const ImVec4& view = lane.shown;
          const auto any = [&](const auto& list, const ImVec4& box) {
            return std::any_of(list.begin(), list.end(), [&](const auto& other) { return draw::overlaps(box, other); });
          };
          // The speed's readout is placed before the numbers (a thin lane has room for it or them),
          // and so are the weight's parts' values, beside their arrows (MeasuringTools::place_fixed_labels).
          const auto under_speed = [&](const ImVec4& box) {
            for (std::size_t i = 0; i < lane.labels.size(); ++i) {
              const bool before = lane.texts[i].find("v = ") != std::string::npos || lane.texts[i].rfind("m\u00b7g\u00b7", 0) == 0;
              if (before && draw::overlaps(box, lane.labels[i])) return true;
            }
            return false;
          };
          const auto blocked = [&](const ImVec4& box) {
            const bool cut = box.x < view.x || box.y < view.y || box.z > view.z || box.w > view.w;
            return cut || under_speed(box) || any(lane.arrows, box) || any(lane.avoided, box) || any(lane.bodies, box);
          };
          const ImVec4& box = mark.number_box;
          EXPECT_TRUE(blocked(mark.number_box) && blocked(mark.across_box))
              << where << ": the number " << mark.text << " at " << text_of(box)
              << " was left out where only labels were";
        }
      }
    }
  }
  EXPECT_GE(springs_checked, 16);
  EXPECT_GE(numbers_shown, 100);
  EXPECT_GE(negative_numbers, 4);  // push's view shows the floor behind the block, incline's the slope above it
}

}  // namespace
}  // namespace frictionlab::classroom
