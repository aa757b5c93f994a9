#include "classroom/measuring_tools.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "draw/overlays.h"
#include "draw/panels.h"
#include "draw/text_record.h"
#include "draw/words.h"
#include "lessons/runtime/class_words.h"

namespace frictionlab::classroom {

const b2Body* measured_body(const lessons::Lesson& lesson) {
  const lessons::View& view = lesson.view();
  if (view.kind == lessons::View::Kind::follow && !view.bodies.empty()) {
    for (const auto& [name, body] : lesson.scene().bodies()) {
      if (name == view.bodies.front() && body->GetType() == b2_dynamicBody) return body;
    }
  }
  return main_body(lesson.scene());
}

std::optional<SlopeWeight> slope_weight(const Scene& scene, const b2Body* body) {
  const std::optional<Surface> surface = surface_under(scene, body);
  if (!surface) return std::nullopt;
  const b2Vec2 gravity = scene.world().GetGravity();
  const double g = static_cast<double>(gravity.Length());
  if (g <= 0.0) return std::nullopt;
  b2Vec2 down = gravity;
  down.Normalize();
  // θ is the angle between the surface's normal and straight up.
  const double cos_angle = std::clamp(static_cast<double>(-b2Dot(surface->normal, down)), -1.0, 1.0);
  const double angle = std::acos(cos_angle);
  if (angle < 0.5 * b2_pi / 180.0) return std::nullopt;
  SlopeWeight weight;
  weight.angle = angle;
  const double mg = static_cast<double>(body->GetMass()) * g;
  weight.along = mg * std::sin(angle);
  weight.across = mg * std::cos(angle);
  weight.into = -surface->normal;
  weight.downhill = b2Dot(surface->along, down) > 0.0f ? surface->along : -surface->along;
  return weight;
}

void MeasuringTools::follow(const lessons::Lesson& lesson, bool playing, bool run_ended) {
  const Scene& scene = lesson.scene();
  // Back in time (R, a step back, the time bar, a rebuild): the stopwatch as it was then.
  if (scene.frame() < last_frame_) stopwatch.rewind(scene.time());
  last_frame_ = scene.frame();
  playing_ = playing;
  run_ended_ = run_ended;
  arm_stopwatch(scene.time(), playing);
  // Only at t = 0: taken later, the marks would count from wherever the body had got to (a
  // window opened with --at showed push's block at "0 m" after sliding 2 m).
  if (scene.frame() != 0) return;
  // The body's centre of mass then: the marks count from its foot on the surface it stands on
  // later (the ruler's line through it). Not the surface under it at t = 0, which a body
  // launched or thrown at t = 0 (terrain's boxes, thrown_box) has not got yet: their lanes had
  // no marks at all.
  if (const b2Body* body = measured_body(lesson)) origin_ = body->GetWorldCenter();
}

void MeasuringTools::arm_stopwatch(double now, bool playing) {
  // The trial's teacher showed the stopwatch, pressed Play and saw it stay at 0.
  if (on.stopwatch && !playing && !stopwatch.used()) stopwatch.start_stop(now);
}

void MeasuringTools::draw_menu(ToolSettings& shown, double now, bool playing, ControlPlaces& controls) {
  const bool open = ImGui::BeginMenu("Tools");
  remember_item(controls, "Tools menu");
  if (!open) return;
  // Shown before the run, it is armed at once: the teacher's next key may well be Space.
  if (ImGui::MenuItem("Stopwatch (lesson time)", nullptr, &shown.stopwatch)) {
    on = shown;
    arm_stopwatch(now, playing);
  }
  remember_item(controls, "tool stopwatch");
  // Armed before the run, it has not started: the trial's menu offered to stop it, and a lap of 0 s.
  const bool armed = stopwatch.armed(now);
  if (ImGui::MenuItem(stopwatch.start_stop_words(now), "W")) {
    shown.stopwatch = true;
    stopwatch.start_stop(now);
  }
  remember_item(controls, "stopwatch start");
  if (ImGui::MenuItem("Lap", "L", false, stopwatch.running() && !armed)) stopwatch.lap(now);
  remember_item(controls, "stopwatch lap");
  if (ImGui::MenuItem("Reset the stopwatch")) stopwatch.reset();
  remember_item(controls, "stopwatch reset");
  ImGui::Separator();
  ImGui::MenuItem("Distance marks along the surface", nullptr, &shown.distance_marks);
  remember_item(controls, "tool distance marks");
  ImGui::MenuItem("Speed of the main body", nullptr, &shown.speed);
  remember_item(controls, "tool speed");
  ImGui::MenuItem("Weight along and across a slope", nullptr, &shown.weight_components);
  remember_item(controls, "tool weight components");
  ImGui::EndMenu();
}

namespace {

// Whether the body is drawn in this lane: with lanes named by their bodies, the lane of its
// name (where its forces are drawn; a slope's lanes overlap, and where_methods_fail's block was
// in three strips at once, its speed drawn twice), else the lane whose strip holds its centre.
bool in_lane(const lessons::Lesson& lesson, const draw::Camera& camera, std::size_t lane, const b2Body* body) {
  const lessons::View& view = lesson.view();
  if (view.kind == lessons::View::Kind::lanes) {
    for (std::size_t k = 0; k < view.bodies.size(); ++k) {
      for (const auto& [name, each] : lesson.scene().bodies()) {
        if (each == body && name == view.bodies[k]) return k == lane;
      }
    }
  }
  const ImVec2 centre = camera.to_screen(body->GetWorldCenter());
  return centre.y >= camera.origin.y && centre.y <= camera.origin.y + camera.size.y;
}

struct ComponentArrows {
  ImVec2 centre, along_tip, across_tip;
};

ComponentArrows component_arrows(const SlopeWeight& weight, const b2Body* body, const draw::Camera& camera,
                                 float newtons_to_pixels) {
  const ImVec2 centre = camera.to_screen(body->GetWorldCenter());
  const auto tip = [&](b2Vec2 direction, double newtons) {
    const ImVec2 screen(direction.x, -direction.y);
    return draw::add(centre, draw::mul(screen, static_cast<float>(newtons) * newtons_to_pixels));
  };
  return {centre, tip(weight.downhill, weight.along), tip(weight.into, weight.across)};
}

// The places hugging an arrow's tip where a value's box of `size` may stand, `gap` px clear of
// it: level with the tip on either side, over and under it, and at its four corners, those
// furthest along the arrow first. A long value on a short arrow ("m·g·sin θ = 5.63 N" on 60 px)
// wanted beyond the tip along the arrow's line lay across the slope's face, and the placer's
// rings round that place, half the text's width apart, missed the room beside the tip.
std::vector<ImVec2> hugging_the_tip(ImVec2 tail, ImVec2 tip, ImVec2 size, float gap) {
  const float dx = 0.5f * size.x + gap, dy = 0.5f * size.y + gap;
  std::vector<ImVec2> places;
  for (const ImVec2 offset : {ImVec2(-dx, 0.0f), ImVec2(dx, 0.0f), ImVec2(0.0f, -dy), ImVec2(0.0f, dy), ImVec2(-dx, -dy),
                              ImVec2(dx, -dy), ImVec2(-dx, dy), ImVec2(dx, dy)}) {
    places.push_back(draw::add(tip, offset));
  }
  const ImVec2 along = draw::sub(tip, tail);
  std::stable_sort(places.begin(), places.end(), [&](ImVec2 a, ImVec2 b) {
    const auto ahead = [&](ImVec2 p) { return (p.x - tip.x) * along.x + (p.y - tip.y) * along.y; };
    return ahead(a) > ahead(b);
  });
  return places;
}

}  // namespace

std::string speed_text(const Scene& scene, const b2Body* body) {
  // With one moving body, whose speed it is goes without saying.
  int moving = 0;
  std::string name;
  for (const auto& [body_name, each] : scene.bodies()) {
    if (each->GetType() != b2_dynamicBody) continue;
    ++moving;
    if (each == body) name = body_name;
  }
  if (moving <= 1 || name.empty()) return speed_reading(body);
  return lessons::class_words(name) + ": " + speed_reading(body);
}

std::string speed_reading(const b2Body* body) {
  const double speed = static_cast<double>(body->GetLinearVelocity().Length());
  // A body at rest moves by float round-off only, a few nm/s (ForceGauge.ABodyTheHandHoldsStillSticks
  // holds it under 1 µm/s): 0.
  if (speed < 1e-6) return "v = 0 m/s";
  // Below 0.1 m/s in mm/s, to three figures: to the millimetre a second, a block the gauge let
  // slip on to its re-stick at 0.46 mm/s read "v = 0.000 m/s" beside "slipping →" (issue 31).
  if (speed < 0.1) return "v = " + draw::format_quantity(1000.0 * speed, "mm/s");
  // To the millimetre a second, as a class's stopwatch-and-ruler speed is read.
  char text[48];
  std::snprintf(text, sizeof text, "v = %.3f m/s", speed);
  return text;
}

void MeasuringTools::avoid(const lessons::Lesson& lesson, const draw::Camera& camera, std::size_t lane, float newtons_to_pixels,
                           float scale, draw::LabelPlacer& labels) const {
  const Scene& scene = lesson.scene();
  const b2Body* body = measured_body(lesson);
  if (body == nullptr || !in_lane(lesson, camera, lane, body)) return;
  // The distance marks tell the placer what they draw when they draw it (draw_distance_marks),
  // before any label: their step and side depend on where their numbers find room.
  if (on.weight_components) {
    if (const std::optional<SlopeWeight> weight = slope_weight(scene, body)) {
      const ComponentArrows arrows = component_arrows(*weight, body, camera, newtons_to_pixels);
      // Known as arrows: each value placed is then nearer its own arrow than any of these.
      labels.arrow(draw::DrawnSegment{arrows.centre, arrows.along_tip, 4.0f * scale});
      labels.arrow(draw::DrawnSegment{arrows.centre, arrows.across_tip, 4.0f * scale});
    }
  }
}

void MeasuringTools::in_world(draw::WorldToolsPass pass, ImDrawList* draw, const lessons::Lesson& lesson, const draw::Camera& camera,
                              std::size_t lane, float newtons_to_pixels, const draw::Theme& theme, const draw::Fonts& fonts,
                              draw::LabelPlacer& labels) const {
  switch (pass) {
    case draw::WorldToolsPass::avoid: avoid(lesson, camera, lane, newtons_to_pixels, fonts.scale, labels); break;
    case draw::WorldToolsPass::fixed_labels:
      place_fixed_labels(draw, lesson, camera, lane, newtons_to_pixels, theme, fonts, labels);
      break;
    case draw::WorldToolsPass::draw: break;  // nothing of theirs is left to the end
  }
}

void MeasuringTools::place_fixed_labels(ImDrawList* draw, const lessons::Lesson& lesson, const draw::Camera& camera,
                                        std::size_t lane, float newtons_to_pixels, const draw::Theme& theme,
                                        const draw::Fonts& fonts, draw::LabelPlacer& labels) const {
  // The distance marks' line and ticks, on the side where their numbers find room; the speed,
  // in its place or the nearest free one (smaller where its font has no room), keeping off
  // the numbers if it can; then the numbers, on every tick or every few where they are free
  // (a number names its place: there or nowhere), or the ticks' spacing where fewer than two
  // are: all before the lesson's labels, which then keep off them (placed last, the readings
  // had no room left and covered a lane's name, the forces' values or the body they read).
  std::optional<DistanceMarks> marks = distance_marks(lesson, camera, fonts, &labels, lane);
  bool speed_placed = false;
  if (marks) draw_distance_lines(draw, *marks, theme, fonts.scale, labels);
  // The weight's parts next, their values beside their arrows before any other label takes the
  // room there (placed last, "ticks 5 m apart" had taken it and m·g·sin θ went 168 px off).
  draw_weight_components(draw, lesson, camera, lane, newtons_to_pixels, theme, fonts, labels);
  if (marks) {
    // The speed off every number, else off every 2nd, 5th or 10th; else where it finds room.
    for (const std::size_t every : {1u, 2u, 5u, 10u}) {
      DistanceMarks kept = *marks;
      number_marks(kept, labels, every);
      draw::LabelPlacer with_numbers = labels;
      for (const DistanceMark& mark : kept.ticks) {
        if (mark.numbered && with_numbers.free(mark.number_box, true)) with_numbers.take(mark.number_box, mark.text);
      }
      speed_placed = draw_readings(draw, lesson, camera, lane, theme, fonts, labels, &with_numbers);
      if (speed_placed) break;
    }
  }
  if (!speed_placed) draw_readings(draw, lesson, camera, lane, theme, fonts, labels);
  if (marks) {
    number_marks(*marks, labels);
    draw_distance_numbers(draw, *marks, theme, fonts, labels);
  }
}

std::optional<DistanceMarks> MeasuringTools::distance_marks(const lessons::Lesson& lesson, const draw::Camera& camera,
                                                            const draw::Fonts& fonts, const draw::LabelPlacer* labels,
                                                            std::size_t lane) const {
  const b2Body* body = measured_body(lesson);
  if (!on.distance_marks || !origin_ || body == nullptr || !in_lane(lesson, camera, lane, body)) return std::nullopt;
  const std::optional<Surface> surface = surface_under(lesson.scene(), body);
  if (!surface) return std::nullopt;
  return distance_marks_along(*surface, *origin_, length_along(body, surface->along), camera, fonts, labels);
}

bool MeasuringTools::draw_readings(ImDrawList* draw, const lessons::Lesson& lesson, const draw::Camera& camera,
                                   std::size_t lane, const draw::Theme& theme, const draw::Fonts& fonts, draw::LabelPlacer& labels,
                                   const draw::LabelPlacer* preferred) const {
  const float s = fonts.scale;
  const b2Body* body = measured_body(lesson);
  if (!on.speed || body == nullptr || !in_lane(lesson, camera, lane, body)) return true;
  // Centred over the body's top, or the nearest place that covers nothing; left out rather
  // than drawn over a lane's name, a force's value or another body's readout. Where the body's
  // font finds no room (a projector's thin lanes), the small font; and in a lane named by the
  // body itself, whose name is then beside it already, without the name.
  const lessons::View& view = lesson.view();
  const bool lane_names_it = view.kind == lessons::View::Kind::lanes && view.titles.empty();
  const std::string named = speed_text(lesson.scene(), body);
  struct Try {
    ImFont* font;
    std::string text;
  };
  std::vector<Try> tries = {{fonts.body, named}, {fonts.small, named}};
  if (lane_names_it) tries.push_back({fonts.small, speed_reading(body)});
  const b2AABB box = lessons::body_box(body);
  const ImVec2 top = camera.to_screen(b2Vec2(body->GetWorldCenter().x, box.upperBound.y));
  const draw::LabelPlacer& against = preferred != nullptr ? *preferred : labels;
  for (const Try& attempt : tries) {
    const ImVec2 size = attempt.font->CalcTextSizeA(attempt.font->FontSize, 1e6f, 0.0f, attempt.text.c_str());
    const ImVec2 wanted(top.x, top.y - 10.0f * s - 0.5f * size.y);
    const ImVec2 label(size.x + 6.0f, size.y + 2.0f);
    draw::LabelPlacer trial = against;
    const std::optional<ImVec2> at = trial.place_if_free(wanted, label, attempt.text, true);
    // Never on a body: it hid the block it read.
    const auto on_body = [&](ImVec2 centre) {
      const ImVec4 taken = draw::LabelPlacer::box_around(centre, label);
      return std::any_of(against.bodies().begin(), against.bodies().end(),
                         [&](const ImVec4& body_box) { return draw::overlaps(taken, body_box); });
    };
    if (at && !on_body(*at)) {
      labels.take(draw::LabelPlacer::box_around(*at, label), attempt.text);
      draw::draw_label(draw, attempt.font, *at, theme.text, theme.panel, attempt.text.c_str());
      return true;
    }
  }
  return false;
}

void MeasuringTools::draw_weight_components(ImDrawList* draw, const lessons::Lesson& lesson, const draw::Camera& camera,
                                            std::size_t lane, float newtons_to_pixels, const draw::Theme& theme,
                                            const draw::Fonts& fonts, draw::LabelPlacer& labels) const {
  const float s = fonts.scale;
  const Scene& scene = lesson.scene();
  const b2Body* body = measured_body(lesson);
  if (body == nullptr || !in_lane(lesson, camera, lane, body)) return;
  if (on.weight_components) {
    if (const std::optional<SlopeWeight> weight = slope_weight(scene, body)) {
      const ComponentArrows arrows = component_arrows(*weight, body, camera, newtons_to_pixels);
      // The weight's own colour, paler: parts of it, not forces beside it.
      const ImU32 colour = (theme.force[static_cast<int>(ForceKind::weight)] & 0x00FFFFFFu) | (170u << IM_COL32_A_SHIFT);
      // Each value beside its own arrow, as the lesson's forces' values are (place_force_label):
      // by its tip, else along its shaft, else joined to it by a leader, and told to the placer
      // as a force's value, nearer its own arrow than any other. Placed where it was free, up to
      // fifteen lines off, a projector showed m·g·sin θ 181 px from its arrow (issue 31).
      const auto beside = [&](ImVec2 tip, b2Vec2 way, double newtons, const std::string& text) {
        const ForceOnBody part{ForceKind::weight, body, body->GetWorldCenter(), static_cast<float>(newtons) * way, nullptr};
        const draw::DrawnSegment own{arrows.centre, tip, 1.0f * s};
        const ImVec2 size = fonts.small->CalcTextSizeA(fonts.small->FontSize, 1e6f, 0.0f, text.c_str());
        // Of the free places beside it, the one furthest from the other arrows' tips, by which the
        // lesson's values are placed later: by the nearest, the incline's m·g·cos θ took the place
        // beside the weight's tip and sent 9.81 N 200 px off.
        std::optional<ImVec2> wanted;
        float clearest = -1.0f;
        for (const ImVec2 place : hugging_the_tip(arrows.centre, tip, size, 6.0f * s)) {
          const ImVec4 box = draw::LabelPlacer::box_around(place, size);
          if (!labels.free(box, true) || !labels.beside(place, size, own)) continue;
          float clearance = 1e9f;
          for (const draw::DrawnSegment& other : labels.arrows()) {
            if (draw::length(draw::sub(other.to, tip)) < 0.5f) continue;  // its own
            clearance = std::min(clearance, draw::gap(box, draw::DrawnSegment{other.to, other.to, 0.0f}));
          }
          if (clearance > clearest) wanted = place, clearest = clearance;
        }
        const draw::PlacedForce placed = draw::place_force_label(draw::ScreenArrow{part, arrows.centre, tip}, fonts.small, 2.0f * s,
                                                                 labels, text, labels.force_labels().size(), wanted);
        draw::draw_arrow(draw, arrows.centre, tip, colour, 2.0f * s);
        const ImU32 ink = theme.force[static_cast<int>(ForceKind::weight)];
        if (placed.leader) draw->AddLine(placed.leader->from, placed.leader->to, ink, 2.0f * placed.leader->half_width);
        if (placed.at) draw::draw_label(draw, fonts.small, *placed.at, ink, theme.panel, text.c_str());
      };
      beside(arrows.along_tip, weight->downhill, weight->along, "m\u00b7g\u00b7sin \u03b8 = " + draw::format_quantity(weight->along, "N"));
      beside(arrows.across_tip, weight->into, weight->across,
             "m\u00b7g\u00b7cos \u03b8 = " + draw::format_quantity(weight->across, "N"));
    }
  }
}

float MeasuringTools::stopwatch_strip_height(bool shown, float scale) {
  if (!shown) return 0.0f;
  // One line of the body's text, as large as the panels' (a class reads it from the back), with
  // a little room above and below.
  return ImGui::GetTextLineHeight() + 8.0f * scale;
}

void MeasuringTools::draw_stopwatch_strip(ImVec2 corner, ImVec2 size, double now, const draw::Fonts& fonts) const {
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(ImGui::GetStyle().WindowPadding.x, 4.0f * fonts.scale));
  if (draw::begin_panel("stopwatch", "", corner, size)) {
    // Right-aligned, over the lesson's clock that it reads; the oldest laps give way first on a
    // narrow screen, then the small font.
    const float room = ImGui::GetContentRegionAvail().x;
    std::string line;
    for (std::size_t laps = 4; laps-- > 0;) {
      line = stopwatch_line(now, laps);
      if (ImGui::CalcTextSize(line.c_str()).x <= room) break;
    }
    const bool small = ImGui::CalcTextSize(line.c_str()).x > room;
    if (small) ImGui::PushFont(fonts.small);
    ImGui::SetCursorPosX(ImGui::GetWindowContentRegionMax().x - ImGui::CalcTextSize(line.c_str()).x);
    draw::shown_text(line.c_str());
    if (small) ImGui::PopFont();
  }
  draw::end_panel();
  ImGui::PopStyleVar();
}

}  // namespace frictionlab::classroom
