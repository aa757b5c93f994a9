// What the layout tests share (tests/scenarios/test_layout.cpp, test_world_labels.cpp,
// test_contrast.cpp, test_projector.cpp): the screens a classroom uses, and the checks on what a
// frame recorded. The frame records every rectangle it placed and every text it drew; the
// checks read that record rather than pixels.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "classroom/classroom.h"
#include "classroom/measuring_tools.h"
#include "draw/frame.h"
#include "draw/headless.h"
#include "draw/headless_render.h"
#include "draw/imgui_host.h"
#include "draw/theme.h"
#include "draw/words.h"
#include "lessons/runtime/catalog.h"
#include "lessons/runtime/class_words.h"
#include "tests/classroom_hands.h"
#include "tests/lesson_scripts.h"
#include "tests/rendering.h"
#include "tests/text_contrast.h"

namespace frictionlab::classroom::layout_checks {


struct Screen {
  const char* name;
  int width, height;
  float scale;  // 0: the size's own; the window's projector mode makes text 1.35 times larger
  // Pictures are drawn at a size's own text scale (the window's projector mode is tested with
  // its sliders and tabs below); at projector scale only the world's layout is checked here.
  bool text;
};
inline const Screen screens[] = {{"1280x720", 1280, 720, 0.0f, true},
                          {"1024x768", 1024, 768, 0.0f, true},
                          {"1920x1080", 1920, 1080, 0.0f, true},
                          {"projector_1920x1080", 1920, 1080, 1.35f * 1.5f, false},
                          // The window's frame in projector mode on a 1920 × 1080 screen, under its
                          // menu bar and above its transport bar.
                          {"window_projector_1920x1080", 1920, 944, 1.35f * 1.5f, false}};

// A label's box as drawn, without the placer's 2 px of padding, so labels that only touch pass.
inline ImVec4 drawn(const ImVec4& box) { return ImVec4(box.x + 2.0f, box.y + 2.0f, box.z - 2.0f, box.w - 2.0f); }

inline std::string text_of(const ImVec4& box) {
  char text[80];
  std::snprintf(text, sizeof text, "(%.0f, %.0f)–(%.0f, %.0f)", static_cast<double>(box.x), static_cast<double>(box.y),
                static_cast<double>(box.z), static_cast<double>(box.w));
  return text;
}

inline void check_layout(const draw::FrameRecord& record, const lessons::Lesson& lesson, const std::string& where) {
  ASSERT_FALSE(record.lanes.empty()) << where;
  for (const draw::FrameRecord::Lane& lane : record.lanes) {
    const draw::Camera& camera = lane.camera;
    for (std::size_t i = 0; i < lane.labels.size(); ++i) {
      const ImVec4 label = drawn(lane.labels[i]);
      for (std::size_t j = i + 1; j < lane.labels.size(); ++j) {
        const auto said = [&](std::size_t k) { return k < lane.texts.size() ? " \"" + lane.texts[k] + "\"" : std::string(); };
        EXPECT_FALSE(draw::overlaps(label, drawn(lane.labels[j])))
            << where << ": labels" << said(i) << " at " << text_of(label) << " and" << said(j) << " at "
            << text_of(drawn(lane.labels[j])) << " overlap";
      }
      for (const draw::DrawnSegment& arrow : lane.arrows) {
        // The shaft as drawn (its head is wider, and the placer keeps clear of that too).
        const draw::DrawnSegment shaft{arrow.from, arrow.to, 0.25f * arrow.half_width};
        EXPECT_FALSE(overlaps(label, shaft)) << where << ": the label at " << text_of(label) << " lies on an arrow";
      }
      EXPECT_FALSE(draw::overlaps(label, record.inset)) << where << ": the label at " << text_of(label)
                                                  << " is under the free-body diagram";
      // Contact marks and lane titles (and the inset) were there before any label.
      for (const ImVec4& mark : lane.avoided) {
        EXPECT_FALSE(draw::overlaps(label, mark)) << where << ": the label at " << text_of(label) << " covers a mark at "
                                            << text_of(mark);
      }
      // Inside what of the lane shows (its panel clips its edges), which is inside the lane.
      const ImVec4& shown = lane.shown;
      EXPECT_TRUE(label.x >= shown.x && label.z <= shown.z && label.y >= shown.y && label.w <= shown.w)
          << where << ": the label at " << text_of(label) << " is cut by the edge of its view, " << text_of(shown);
      EXPECT_TRUE(shown.x >= camera.origin.x && shown.z <= camera.origin.x + camera.size.x &&
                  shown.y >= camera.origin.y && shown.w <= camera.origin.y + camera.size.y)
          << where << ": the view's visible part " << text_of(shown) << " runs out of its lane";
    }
  }
  // No panel covers a moving body: none is under the free-body diagram in the lane it is in.
  for (const auto& [name, body] : lesson.scene().bodies()) {
    if (body->GetType() != b2_dynamicBody) continue;
    for (const draw::FrameRecord::Lane& lane : record.lanes) {
      const ImVec2 centre = lane.camera.to_screen(body->GetWorldCenter());
      const bool in_lane = centre.y >= lane.camera.origin.y && centre.y <= lane.camera.origin.y + lane.camera.size.y &&
                           centre.x >= lane.camera.origin.x && centre.x <= lane.camera.origin.x + lane.camera.size.x;
      if (!in_lane) continue;
      for (const b2Fixture* fixture = body->GetFixtureList(); fixture != nullptr; fixture = fixture->GetNext()) {
        const b2AABB& box = fixture->GetAABB(0);
        const ImVec2 a = lane.camera.to_screen(box.lowerBound), b = lane.camera.to_screen(box.upperBound);
        const ImVec4 on_screen(std::min(a.x, b.x), std::min(a.y, b.y), std::max(a.x, b.x), std::max(a.y, b.y));
        EXPECT_FALSE(draw::overlaps(on_screen, record.inset)) << where << ": " << name << " is under the free-body diagram";
      }
    }
  }
}

// A label's box and a convex polygon share a point unless some edge of either parts them.
inline bool overlaps_polygon(const ImVec4& box, const std::vector<ImVec2>& polygon) {
  const ImVec2 corners[4] = {{box.x, box.y}, {box.z, box.y}, {box.z, box.w}, {box.x, box.w}};
  std::vector<ImVec2> axes = {{1.0f, 0.0f}, {0.0f, 1.0f}};
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const ImVec2 edge = draw::sub(polygon[(i + 1) % polygon.size()], polygon[i]);
    axes.push_back(ImVec2(-edge.y, edge.x));
  }
  for (const ImVec2& axis : axes) {
    const auto span = [&](const ImVec2* points, std::size_t count) {
      float low = 1e30f, high = -1e30f;
      for (std::size_t k = 0; k < count; ++k) {
        const float at = points[k].x * axis.x + points[k].y * axis.y;
        low = std::min(low, at), high = std::max(high, at);
      }
      return std::pair(low, high);
    };
    const auto [box_low, box_high] = span(corners, 4);
    const auto [shape_low, shape_high] = span(polygon.data(), polygon.size());
    if (box_high <= shape_low || shape_high <= box_low) return false;
  }
  return true;
}

// The tools' readings of a body ("v = ..." and the gauge's "gauge ..."), each off every polygon
// of that body as drawn. Returns how many were found.
inline int readings_off(const draw::FrameRecord::Lane& lane, const b2Body* body, const std::string& where) {
  int found = 0;
  for (std::size_t i = 0; i < lane.labels.size(); ++i) {
    if (lane.texts[i].find("v = ") == std::string::npos && lane.texts[i].rfind("gauge ", 0) != 0) continue;
    ++found;
    const ImVec4 label = drawn(lane.labels[i]);
    for (const b2Fixture* fixture = body->GetFixtureList(); fixture != nullptr; fixture = fixture->GetNext()) {
      if (fixture->GetType() != b2Shape::e_polygon) continue;
      const auto* shape = static_cast<const b2PolygonShape*>(fixture->GetShape());
      std::vector<ImVec2> polygon;
      for (int k = 0; k < shape->m_count; ++k) polygon.push_back(lane.camera.to_screen(body->GetWorldPoint(shape->m_vertices[k])));
      EXPECT_FALSE(overlaps_polygon(label, polygon))
          << where << ": \"" << lane.texts[i] << "\" at " << text_of(label) << " is drawn on the body it reads";
    }
  }
  return found;
}

// Every text whole where it was drawn. Only the tabs under the sliders may scroll (when even
// folded friction pairs leave the theory table too little room), and the class's predictions
// in the theory table's place: text there may be a scroll away above or below, never cut
// across. The sliders never scroll.
inline void check_texts(const draw::FrameRecord& record, const std::string& where) {
  EXPECT_FALSE(record.texts.empty()) << where << ": no text was recorded";
  for (const draw::ShownText& text : record.texts) {
    const std::string panel = text.panel.substr(text.panel.find("###") == std::string::npos ? 0 : text.panel.find("###") + 3);
    // So may the class's predictions, where they are longer than the theory table they stand in for.
    const bool scrolled = text.scrolls && (panel == "books" || panel == "theory");
    EXPECT_TRUE(scrolled ? text.whole_across() : text.whole())
        << where << ": \"" << text.text << "\" in " << panel << " needs " << text_of(text.needed) << " but only "
        << text_of(text.visible) << " shows";
  }
}

inline std::string screen_name(const ::testing::TestParamInfo<Screen>& screen) { return screen.param.name; }

// The window as a teacher sees it: its sliders, tabs, menu and transport bars, at a screen's
// own text size or in projector mode.
struct WindowScreen {
  const char* name;
  int width, height;
  bool projector;
};
inline const WindowScreen window_screens[] = {
    {"1280x720", 1280, 720, false}, {"1024x768", 1024, 768, false}, {"projector_1920x1080", 1920, 1080, true}};

// The window on `lesson` (a script's path) as a class sees it on `screen`: help panel closed.
inline ClassroomOptions class_window(const std::string& lesson, const WindowScreen& screen) {
  ClassroomOptions options;
  options.lesson = lesson;
  options.window.help = false;
  options.window.projector = screen.projector;
  return options;
}

inline std::string window_screen_name(const ::testing::TestParamInfo<WindowScreen>& screen) { return screen.param.name; }

// The first text drawn in the column's lower panel (the theory panel, or the tab it shares)
// from `from` on that reads `wanted` (or starts with it, `prefix`): its place in the record.
inline std::optional<std::size_t> lower_panel_text(const draw::FrameRecord& record, std::size_t from, const std::string& wanted,
                                            bool prefix = false) {
  for (std::size_t i = from; i < record.texts.size(); ++i) {
    const draw::ShownText& text = record.texts[i];
    const std::size_t id = text.panel.find("###");
    const std::string panel = id == std::string::npos ? text.panel : text.panel.substr(id + 3);
    if (panel != "theory" && panel != "books") continue;
    if (prefix ? text.text.rfind(wanted, 0) == 0 : text.text == wanted) return i;
  }
  return std::nullopt;
}

// The texts one of the class's predictions shows, in the order drawn, each with whether it is a
// prefix: before the reveal its question, the answer and "measured: …"; revealed, its row's
// name and the class's answer in its column of the theory table ("-12.5 N", "—" unanswered), or,
// where the frame found the table too tall for the column and the record shows the class's lines
// above it, the class's line (the answer with its unit and how close it came). Empty (and a
// failure) when the lesson has no row of the prediction's name.
inline std::vector<std::pair<std::string, bool>> answer_texts(Classroom& window, const lessons::Prediction& prediction,
                                                       bool revealed, const std::string& where,
                                                       const draw::FrameRecord& record) {
  const std::string answer = window.predictions().answers[prediction.expectation];
  if (!revealed) return {{prediction.question, false}, {answer, false}, {"measured: ", true}};
  const std::vector<lessons::ExpectationResult>& rows = window.playback().readings().expectations;
  const auto row = std::find_if(rows.begin(), rows.end(),
                                [&](const lessons::ExpectationResult& r) { return r.name == prediction.expectation; });
  if (row == rows.end()) {
    ADD_FAILURE() << where << ": no row " << prediction.expectation;
    return {};
  }
  if (lower_panel_text(record, 0, "class: ", true)) {
    return {{prediction.expectation, false}, {answer_and_closeness(prediction, answer, closeness(prediction, answer, *row)), false}};
  }
  return {{prediction.expectation, false},
          {class_answers(window.playback().lesson(), rows, window.predictions()).at(prediction.expectation).answer, false}};
}

}  // namespace frictionlab::classroom::layout_checks
