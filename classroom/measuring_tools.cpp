#include "classroom/measuring_tools.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "draw/overlays.h"
#include "draw/panels.h"
#include "draw/text_record.h"
#include "draw/words.h"
#include "lessons/runtime/class_words.h"

namespace frictionlab::ui {

namespace {

constexpr double never = std::numeric_limits<double>::infinity();
// Lesson times are whole frames of the fixed step; a rounding's worth apart is the same time.
constexpr double same_time = 1e-9;

}  // namespace

bool Stopwatch::Span::on() const { return to == never; }

void Stopwatch::start_stop(double now) {
  used_ = true;
  if (running()) {
    spans_.back().to = now;
    // Switched on and off at one moment (W twice while paused): it never counted anything.
    if (spans_.back().to <= spans_.back().from + same_time) spans_.pop_back();
  } else {
    spans_.push_back({now, never});
  }
}

void Stopwatch::lap(double now) {
  if (!running() || armed(now)) return;  // armed, it has nothing to lap yet
  used_ = true;
  laps_.push_back({now, reading(now)});
}

void Stopwatch::reset() { *this = Stopwatch{}; }

void Stopwatch::rewind(double now) {
  // Spans begun after `now` had not begun then; one that held `now` was on then, and is on again.
  while (!spans_.empty() && spans_.back().from > now + same_time) spans_.pop_back();
  if (!spans_.empty() && spans_.back().to > now + same_time) spans_.back().to = never;
  while (!laps_.empty() && laps_.back().at > now + same_time) laps_.pop_back();
}

double Stopwatch::reading(double now) const {
  double counted = 0.0;
  for (const Span& span : spans_) counted += std::max(0.0, std::min(span.to, now) - span.from);
  return counted;
}

std::vector<double> Stopwatch::laps() const {
  std::vector<double> readings;
  for (const Lap& taken : laps_) readings.push_back(taken.reading);
  return readings;
}

std::string Stopwatch::text(double now, bool playing, bool run_ended) const {
  const double shown = reading(now);
  // At the run's end the stopwatch stopped with the run; "paused" told the trial's class that
  // someone had paused it.
  const char* state = !running()              ? " (stopped)"
                      : playing               ? ""
                      : armed(now)            ? " (starts with Play)"
                      : run_ended             ? " (stopped at the run's end)"
                                              : " (paused)";
  char line[64];
  std::snprintf(line, sizeof line, "stopwatch %.2f s%s", shown, state);
  std::string text = line;
  // The last three laps, numbered as the class counts them.
  const std::size_t first = laps_.size() > 3 ? laps_.size() - 3 : 0;
  for (std::size_t i = first; i < laps_.size(); ++i) {
    std::snprintf(line, sizeof line, "\nlap %zu: %.2f s", i + 1, laps_[i].reading);
    text += line;
  }
  return text;
}

std::string Stopwatch::line(double now, bool playing, bool run_ended, std::size_t laps) const {
  std::string shown = text(now, playing, run_ended);
  // text() puts the last three laps on lines of their own; `laps` of them stay, each after a
  // wide space.
  std::size_t lines = static_cast<std::size_t>(std::count(shown.begin(), shown.end(), '\n'));
  for (; lines > laps; --lines) {
    const std::size_t first = shown.find('\n'), second = shown.find('\n', first + 1);
    shown.erase(first, second == std::string::npos ? std::string::npos : second - first);
  }
  for (std::size_t at = shown.find('\n'); at != std::string::npos; at = shown.find('\n', at)) shown.replace(at, 1, "   ");
  return shown;
}

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

// The distance marks' step: a nice length about 120 pixels long.
float mark_step(const Camera& camera, float scale) { return nice_length(120.0f * scale / camera.pixels_per_metre); }

// Whether the body is drawn in this lane: with lanes named by their bodies, the lane of its
// name (where its forces are drawn; a slope's lanes overlap, and where_methods_fail's block was
// in three strips at once, its speed drawn twice), else the lane whose strip holds its centre.
bool in_lane(const lessons::Lesson& lesson, const Camera& camera, std::size_t lane, const b2Body* body) {
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

struct Ruler {
  ImVec2 from, to;                   // the line, just inside the surface
  std::vector<std::pair<ImVec2, double>> ticks;  // each tick's foot on the line and its distance, m
  ImVec2 inward;                     // screen direction of the ticks: into the surface, or out of it
  double step = 1.0;                 // m between ticks
  float to_surface = 0.0f;           // px from the line back to the surface, against `inward`
};

// `step`: the ticks' spacing, m. `outside`: the line on the surface itself and its ticks out of
// it, for a surface whose inside the view leaves no room under (a lane's thin strip of ground).
std::optional<Ruler> ruler(const Surface& surface, b2Vec2 origin, const Camera& camera, float scale, float step,
                           bool outside = false) {
  // The view's corners projected on the surface's line give the span of it in sight.
  const b2Vec2 corners[4] = {camera.to_world(camera.origin), camera.to_world(add(camera.origin, ImVec2(camera.size.x, 0.0f))),
                             camera.to_world(add(camera.origin, camera.size)),
                             camera.to_world(add(camera.origin, ImVec2(0.0f, camera.size.y)))};
  // The line runs through where the body stood at t = 0, along the surface it stands on now.
  const b2Vec2 base = origin + b2Dot(surface.point - origin, surface.normal) * surface.normal;
  float low = 1e30f, high = -1e30f;
  for (const b2Vec2& corner : corners) {
    low = std::min(low, b2Dot(corner - base, surface.along));
    high = std::max(high, b2Dot(corner - base, surface.along));
  }
  // No further than the surface goes (the foot and the top of a slope).
  const float shift = b2Dot(surface.point - base, surface.along);
  low = std::max(low, surface.low + shift);
  high = std::min(high, surface.high + shift);
  if (!(high > low) || (high - low) / step > 400.0f) return std::nullopt;
  Ruler ruler;
  ruler.step = static_cast<double>(step);
  ruler.to_surface = outside ? 0.0f : 6.0f * scale;
  const ImVec2 inward_world = camera.to_screen(base - surface.normal);
  ImVec2 inward = sub(inward_world, camera.to_screen(base));
  if (length(inward) < 1e-6f) return std::nullopt;
  ruler.inward = mul(inward, outside ? -1.0f / length(inward) : 1.0f / length(inward));
  const ImVec2 offset = mul(ruler.inward, outside ? 0.0f : 6.0f * scale);
  ruler.from = add(camera.to_screen(base + low * surface.along), offset);
  ruler.to = add(camera.to_screen(base + high * surface.along), offset);
  // Counted in whole ticks: far from the start a float count would stop growing.
  const double first = std::ceil(static_cast<double>(low) / step), last = std::floor(static_cast<double>(high) / step);
  // Counted forward the way a body let go moves: rightwards along a level floor, downhill on a
  // slope (as the lessons' distances are); behind the start the marks read negative.
  const double forward = surface.along.y > std::sin(0.5f * b2_pi / 180.0f) ? -1.0 : 1.0;
  for (double k = first; k <= last && k - first < 400.0; k += 1.0) {
    const double metres = k * static_cast<double>(step);
    ruler.ticks.push_back({add(camera.to_screen(base + static_cast<float>(metres) * surface.along), offset), forward * metres});
  }
  return ruler;
}

struct ComponentArrows {
  ImVec2 centre, along_tip, across_tip;
};

ComponentArrows component_arrows(const SlopeWeight& weight, const b2Body* body, const Camera& camera,
                                 float newtons_to_pixels) {
  const ImVec2 centre = camera.to_screen(body->GetWorldCenter());
  const auto tip = [&](b2Vec2 direction, double newtons) {
    const ImVec2 screen(direction.x, -direction.y);
    return add(centre, mul(screen, static_cast<float>(newtons) * newtons_to_pixels));
  };
  return {centre, tip(weight.downhill, weight.along), tip(weight.into, weight.across)};
}

// A tool's reading, its text placed by `anchor` (`in_sizes` of the text's own width and height
// from it to the text's centre), or in the nearest free place: off every moving body, unless
// the bodies leave no room near; none when nothing near is free.
void draw_reading(ImDrawList* draw, LabelPlacer& labels, ImFont* font, ImVec2 anchor, ImVec2 in_sizes,
                  const std::string& text, ImU32 colour, ImU32 background) {
  const ImVec2 size = font->CalcTextSizeA(font->FontSize, 1e6f, 0.0f, text.c_str());
  const ImVec2 wanted(anchor.x + in_sizes.x * size.x, anchor.y + in_sizes.y * size.y);
  // Left out where nothing near is free: drawn over the lesson's labels (where_methods_fail's
  // thin projector lanes) neither could be read.
  if (const std::optional<ImVec2> at = labels.place_if_free(wanted, ImVec2(size.x + 6.0f, size.y + 2.0f), text, true)) {
    draw_label(draw, font, *at, colour, background, text.c_str());
  }
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
  // To the millimetre a second, as a class's stopwatch-and-ruler speed is read: a resting
  // block's 1e-9 m/s of rounding is 0.000.
  char text[48];
  std::snprintf(text, sizeof text, "v = %.3f m/s", static_cast<double>(body->GetLinearVelocity().Length()));
  return text;
}

void MeasuringTools::avoid(const lessons::Lesson& lesson, const Camera& camera, std::size_t lane, float newtons_to_pixels,
                           float scale, LabelPlacer& labels) const {
  const Scene& scene = lesson.scene();
  const b2Body* body = measured_body(lesson);
  if (body == nullptr || !in_lane(lesson, camera, lane, body)) return;
  // The distance marks tell the placer what they draw when they draw it (draw_distance_marks),
  // before any label: their step and side depend on where their numbers find room.
  if (on.weight_components) {
    if (const std::optional<SlopeWeight> weight = slope_weight(scene, body)) {
      const ComponentArrows arrows = component_arrows(*weight, body, camera, newtons_to_pixels);
      labels.avoid(DrawnSegment{arrows.centre, arrows.along_tip, 4.0f * scale});
      labels.avoid(DrawnSegment{arrows.centre, arrows.across_tip, 4.0f * scale});
    }
  }
}

namespace {

// The marks' line and ticks, told to the placer as they are drawn.
void draw_distance_lines(ImDrawList* draw, const DistanceMarks& marks, const Theme& theme, float s, LabelPlacer& labels) {
  draw->AddLine(marks.from, marks.to, theme.text, 1.5f * s);
  labels.avoid(DrawnSegment{marks.from, marks.to, 1.5f * s});
  for (const DistanceMark& mark : marks.ticks) {
    const bool zero = std::abs(mark.metres) < 1e-9;
    const ImVec2 end = add(mark.foot, mul(marks.inward, (zero ? 12.0f : 8.0f) * s));
    draw->AddLine(mark.foot, end, theme.text, (zero ? 2.5f : 1.5f) * s);
    labels.avoid(DrawnSegment{mark.foot, end, 1.0f * s});
  }
}

// Each number just beyond its tick or not at all: moved away it would name another place.
void draw_distance_numbers(ImDrawList* draw, const DistanceMarks& marks, const Theme& theme, const Fonts& fonts,
                           LabelPlacer& labels) {
  std::vector<const DistanceMark*> shown;
  for (const DistanceMark& mark : marks.ticks) {
    if (mark.numbered && labels.free(mark.number_box, true)) shown.push_back(&mark);
  }
  for (const DistanceMark* mark : shown) {
    labels.take(mark->number_box, mark->text);
    const ImVec2 centre(0.5f * (mark->number_box.x + mark->number_box.z), 0.5f * (mark->number_box.y + mark->number_box.w));
    draw_label(draw, fonts.small, centre, theme.text, theme.panel, mark->text.c_str());
  }
  // Fewer than two numbers cannot give the scale: the ticks' spacing then says it, in the
  // nearest free place to the middle of the line, on the numbers' side (it names no place).
  if (shown.size() >= 2 || marks.ticks.size() < 2) return;
  char spacing[48];
  std::snprintf(spacing, sizeof spacing, "ticks %g m apart", marks.step);
  const ImVec2 size = fonts.small->CalcTextSizeA(fonts.small->FontSize, 1e6f, 0.0f, spacing);
  const ImVec2 middle = mul(add(marks.from, marks.to), 0.5f);
  const ImVec2 wanted = add(middle, mul(marks.inward, 15.0f * fonts.scale + 0.5f * size.y + 2.0f));
  if (const std::optional<ImVec2> at = labels.place_if_free(wanted, ImVec2(size.x + 6.0f, size.y + 2.0f), spacing, true)) {
    draw_label(draw, fonts.small, *at, theme.text, theme.panel, spacing);
  }
}

}  // namespace

void MeasuringTools::in_world(WorldToolsPass pass, ImDrawList* draw, const lessons::Lesson& lesson, const Camera& camera,
                              std::size_t lane, float newtons_to_pixels, const Theme& theme, const Fonts& fonts,
                              LabelPlacer& labels) const {
  switch (pass) {
    case WorldToolsPass::avoid: avoid(lesson, camera, lane, newtons_to_pixels, fonts.scale, labels); break;
    case WorldToolsPass::fixed_labels: {
      // The distance marks' line and ticks, on the side where their numbers find room; the speed,
      // in its place or the nearest free one (smaller where its font has no room), keeping off
      // the numbers if it can; then the numbers, on every tick or every few where they are free
      // (a number names its place: there or nowhere), or the ticks' spacing where fewer than two
      // are: all before the lesson's labels, which then keep off them (placed last, the readings
      // had no room left and covered a lane's name, the forces' values or the body they read).
      std::optional<DistanceMarks> marks = distance_marks(lesson, camera, fonts, &labels, lane);
      bool speed_placed = false;
      if (marks) {
        draw_distance_lines(draw, *marks, theme, fonts.scale, labels);
        // The speed off every number, else off every 2nd, 5th or 10th; else where it finds room.
        for (const std::size_t every : {1u, 2u, 5u, 10u}) {
          DistanceMarks kept = *marks;
          number_marks(kept, labels, every);
          LabelPlacer with_numbers = labels;
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
      break;
    }
    case WorldToolsPass::draw: this->draw(draw, lesson, camera, lane, newtons_to_pixels, theme, fonts, labels); break;
  }
}

namespace {

// The marks of one ruler, each number's box at its tick (beyond its end).
DistanceMarks numbered(const Ruler& line, const Fonts& fonts) {
  const float s = fonts.scale;
  DistanceMarks marks{line.from, line.to, line.inward, line.step, {}};
  for (const auto& [foot, metres] : line.ticks) {
    char number[32];
    std::snprintf(number, sizeof number, "%g m", std::abs(metres) < 1e-9 ? 0.0 : metres);
    std::string text = number;
    if (text[0] == '-') text.replace(0, 1, "\u2212");  // a minus sign, not a hyphen
    const ImVec2 size = fonts.small->CalcTextSizeA(fonts.small->FontSize, 1e6f, 0.0f, text.c_str());
    // Clear of the start's tick too, which is longer (12 px) than the others: "0 m" was never shown.
    const ImVec2 centre = add(foot, mul(line.inward, 15.0f * s + 0.5f * size.y + 2.0f));
    // Across the line from its tick, just clear of the surface.
    const ImVec2 across = sub(foot, mul(line.inward, line.to_surface + 4.0f * s + 0.5f * size.y + 2.0f));
    // As the placer pads a label of the size the other readings give it.
    const float half_x = 0.5f * (size.x + 6.0f) + 2.0f, half_y = 0.5f * (size.y + 2.0f) + 2.0f;
    const auto box = [&](ImVec2 c) { return ImVec4(c.x - half_x, c.y - half_y, c.x + half_x, c.y + half_y); };
    marks.ticks.push_back({foot, metres, text, box(centre), box(across), true});
  }
  return marks;
}

// A number that would stick out past the view's edge slides inside it while its tick stays
// under it: it still names its place. Refused for one pixel out, a number of contact_area's
// projector lane sent the marks to the floor's other side, onto the speed readout's only place.
void keep_numbers_in(DistanceMarks& marks, const ImVec4& bounds) {
  const auto slide = [&](ImVec4& box) {
    const float out = box.x < bounds.x ? bounds.x - box.x : box.z > bounds.z ? bounds.z - box.z : 0.0f;
    if (std::abs(out) >= 0.5f * (box.z - box.x)) return;  // its tick would no longer be under it
    box.x += out, box.z += out;
  };
  for (DistanceMark& mark : marks.ticks) slide(mark.number_box), slide(mark.across_box);
}

}  // namespace

// Whether a tick is one of every `every`-th, counted from the start (0 m is always one).
bool counted(const DistanceMark& mark, std::size_t every, double step) {
  const double k = std::round(std::abs(mark.metres) / step);
  return std::fmod(k, static_cast<double>(every)) == 0.0;
}

std::optional<DistanceMarks> MeasuringTools::distance_marks(const lessons::Lesson& lesson, const Camera& camera,
                                                            const Fonts& fonts, const LabelPlacer* labels,
                                                            std::size_t lane) const {
  const b2Body* body = measured_body(lesson);
  if (!on.distance_marks || !origin_ || body == nullptr || !in_lane(lesson, camera, lane, body)) return std::nullopt;
  const std::optional<Surface> surface = surface_under(lesson.scene(), body);
  if (!surface) return std::nullopt;
  const float s = fonts.scale, step = mark_step(camera, s);
  const std::optional<Ruler> under = ruler(*surface, *origin_, camera, s, step);
  if (!under) return std::nullopt;
  DistanceMarks marks = numbered(*under, fonts);
  if (labels == nullptr) return marks;
  keep_numbers_in(marks, labels->bounds());
  // Under the surface when two of the numbers find room there, or as many as over it; else over
  // it: a lane's strip of ground is too thin to hold them (the trial's projector lanes showed none).
  const auto free_numbers = [&](const DistanceMarks& side) {
    return std::count_if(side.ticks.begin(), side.ticks.end(), [&](const DistanceMark& mark) { return labels->free(mark.number_box, true); });
  };
  const auto under_count = free_numbers(marks);
  if (under_count >= 2) return marks;
  const std::optional<Ruler> over = ruler(*surface, *origin_, camera, s, step, true);
  if (!over) return marks;
  DistanceMarks over_marks = numbered(*over, fonts);
  keep_numbers_in(over_marks, labels->bounds());
  return free_numbers(over_marks) > under_count ? over_marks : marks;
}

void number_marks(DistanceMarks& marks, const LabelPlacer& labels, std::size_t fewest_every) {
  // Every tick, else every 2nd, 5th or 10th: the first that gives at least two numbers room, so
  // that the scale can be read (fewer numbers rather than none), else the one giving the most.
  std::size_t best_every = std::max<std::size_t>(fewest_every, 1), best_count = 0;
  for (const std::size_t every : {1u, 2u, 5u, 10u}) {
    if (every < fewest_every) continue;
    std::size_t count = 0;
    std::vector<ImVec4> chosen;
    for (const DistanceMark& mark : marks.ticks) {
      if (!counted(mark, every, marks.step)) continue;
      for (const ImVec4& box : {mark.number_box, mark.across_box}) {
        const bool apart = std::none_of(chosen.begin(), chosen.end(), [&](const ImVec4& other) { return overlaps(box, other); });
        if (!apart || !labels.free(box, true)) continue;
        chosen.push_back(box), ++count;
        break;
      }
    }
    if (count > best_count) best_every = every, best_count = count;
    if (count >= 2) break;
  }
  for (DistanceMark& mark : marks.ticks) {
    mark.numbered = counted(mark, best_every, marks.step);
    // Its number across the line where its own side has no room.
    if (!labels.free(mark.number_box, true) && labels.free(mark.across_box, true)) std::swap(mark.number_box, mark.across_box);
  }
}

bool MeasuringTools::draw_readings(ImDrawList* draw, const lessons::Lesson& lesson, const Camera& camera,
                                   std::size_t lane, const Theme& theme, const Fonts& fonts, LabelPlacer& labels,
                                   const LabelPlacer* preferred) const {
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
  const LabelPlacer& against = preferred != nullptr ? *preferred : labels;
  for (const Try& attempt : tries) {
    const ImVec2 size = attempt.font->CalcTextSizeA(attempt.font->FontSize, 1e6f, 0.0f, attempt.text.c_str());
    const ImVec2 wanted(top.x, top.y - 10.0f * s - 0.5f * size.y);
    const ImVec2 label(size.x + 6.0f, size.y + 2.0f);
    LabelPlacer trial = against;
    const std::optional<ImVec2> at = trial.place_if_free(wanted, label, attempt.text, true);
    // Never on a body: it hid the block it read.
    const auto on_body = [&](ImVec2 centre) {
      const ImVec4 taken = LabelPlacer::box_around(centre, label);
      return std::any_of(against.bodies().begin(), against.bodies().end(),
                         [&](const ImVec4& body_box) { return overlaps(taken, body_box); });
    };
    if (at && !on_body(*at)) {
      labels.take(LabelPlacer::box_around(*at, label), attempt.text);
      draw_label(draw, attempt.font, *at, theme.text, theme.panel, attempt.text.c_str());
      return true;
    }
  }
  return false;
}

void MeasuringTools::draw(ImDrawList* draw, const lessons::Lesson& lesson, const Camera& camera, std::size_t lane,
                          float newtons_to_pixels,
                          const Theme& theme, const Fonts& fonts, LabelPlacer& labels) const {
  const float s = fonts.scale;
  const Scene& scene = lesson.scene();
  const b2Body* body = measured_body(lesson);
  if (body == nullptr || !in_lane(lesson, camera, lane, body)) return;
  if (on.weight_components) {
    if (const std::optional<SlopeWeight> weight = slope_weight(scene, body)) {
      const ComponentArrows arrows = component_arrows(*weight, body, camera, newtons_to_pixels);
      // The weight's own colour, paler: parts of it, not forces beside it.
      const ImU32 colour = (theme.force[static_cast<int>(ForceKind::weight)] & 0x00FFFFFFu) | (170u << IM_COL32_A_SHIFT);
      draw_arrow(draw, arrows.centre, arrows.along_tip, colour, 2.0f * s);
      draw_arrow(draw, arrows.centre, arrows.across_tip, colour, 2.0f * s);
      // Beyond each tip, along its arrow: 8 px past it, and half the text's size.
      const auto beyond = [&](ImVec2 tip, const std::string& text) {
        ImVec2 direction = sub(tip, arrows.centre);
        const float span = std::max(1e-3f, length(direction));
        direction = mul(direction, 1.0f / span);
        draw_reading(draw, labels, fonts.small, add(tip, mul(direction, 8.0f * s)), mul(direction, 0.5f), text,
                     theme.force[static_cast<int>(ForceKind::weight)], theme.panel);
      };
      beyond(arrows.along_tip, "m\u00b7g\u00b7sin \u03b8 = " + format_quantity(weight->along, "N"));
      beyond(arrows.across_tip, "m\u00b7g\u00b7cos \u03b8 = " + format_quantity(weight->across, "N"));
    }
  }
}

float MeasuringTools::stopwatch_strip_height(bool shown, float scale) {
  if (!shown) return 0.0f;
  // One line of the body's text, as large as the panels' (a class reads it from the back), with
  // a little room above and below.
  return ImGui::GetTextLineHeight() + 8.0f * scale;
}

void MeasuringTools::draw_stopwatch_strip(ImVec2 corner, ImVec2 size, double now, const Fonts& fonts) const {
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(ImGui::GetStyle().WindowPadding.x, 4.0f * fonts.scale));
  if (begin_panel("stopwatch", "", corner, size)) {
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
    shown_text(line.c_str());
    if (small) ImGui::PopFont();
  }
  end_panel();
  ImGui::PopStyleVar();
}

}  // namespace frictionlab::ui
