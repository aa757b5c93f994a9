#include "draw/legend.h"

#include <algorithm>
#include <cstdio>
#include <iterator>
#include <string>
#include <vector>

#include "draw/drawing.h"
#include "draw/text_record.h"
#include "draw/words.h"
#include "lessons/runtime/class_words.h"

namespace frictionlab::draw {

namespace {

// The lengthened arrows' shafts are broken (draw_arrow): the words say so, and why, in a
// teacher's words, so that the class can tell them from the picture alone. "under 2.02 N:
// longer, dashed" was cryptic to a teacher (a projector trial, issue 31); the force it turns at
// follows, in brackets, for who wants the number.
constexpr const char* dashed_words = "dashed: too small";
constexpr const char* to_scale_words = "to draw to scale";
// The key to a torque's curved arrow.
constexpr const char* torque_word = "torque";

}  // namespace

namespace {

std::string metres(float value) {
  char text[32];
  if (value >= 1.0f) {
    std::snprintf(text, sizeof text, "%g m", static_cast<double>(value));
  } else {
    std::snprintf(text, sizeof text, "%g cm", static_cast<double>(value * 100.0f));
  }
  return text;
}

// In the legend's strip, right: a bar of a round length in metres, its end at `bottom_right`,
// its length written above it, or before it (`beside`) when the row above is taken.
void draw_scale_bar(ImDrawList* draw, float pixels_per_metre, ImVec2 bottom_right, const Theme& theme, const Fonts& fonts,
                    bool beside, float length_in_metres = 0.0f) {
  const float bar = length_in_metres > 0.0f ? length_in_metres : nice_length(110.0f * fonts.scale / pixels_per_metre);
  const float pixels = bar * pixels_per_metre;
  const ImVec2 end(bottom_right.x - 16.0f * fonts.scale, bottom_right.y - 12.0f * fonts.scale);
  const ImVec2 start(end.x - pixels, end.y);
  const float tick = 6.0f * fonts.scale;
  draw->AddLine(start, end, theme.text, 2.0f * fonts.scale);
  draw->AddLine(ImVec2(start.x, end.y - tick), ImVec2(start.x, end.y + 1), theme.text, 2.0f * fonts.scale);
  draw->AddLine(ImVec2(end.x, end.y - tick), ImVec2(end.x, end.y + 1), theme.text, 2.0f * fonts.scale);
  const std::string length = metres(bar);
  const float width = fonts.small->CalcTextSizeA(fonts.small->FontSize, 1e6f, 0.0f, length.c_str()).x;
  const ImVec2 label = beside ? ImVec2(start.x - 8.0f * fonts.scale - 0.5f * width, end.y - 0.5f * tick)
                              : ImVec2(0.5f * (start.x + end.x), end.y - 14.0f * fonts.scale);
  draw_label(draw, fonts.small, label, theme.text, 0, length.c_str());
}

// A chip's mark at `centre`: a dot for a contact state, a swatch for a material, the same in
// the strip and the column.
void chip_mark(ImDrawList* draw, ImVec2 centre, ImU32 colour, bool round, const Theme& theme, float s) {
  if (round) {
    draw->AddCircleFilled(centre, contact_dot_radius * s, colour, 16);
  } else {
    draw->AddRectFilled(ImVec2(centre.x - 7 * s, centre.y - 6 * s), ImVec2(centre.x + 7 * s, centre.y + 6 * s), colour);
    draw->AddRect(ImVec2(centre.x - 7 * s, centre.y - 6 * s), ImVec2(centre.x + 7 * s, centre.y + 6 * s), theme.outline);
  }
}

}  // namespace

void draw_legend(ImDrawList* draw, const Scene& scene, const Camera& camera, ImVec2 corner, ImVec2 size,
                 const Theme& theme, const Fonts& fonts, float newtons_to_pixels) {
  ImFont* font = fonts.small;
  const float s = fonts.scale, line = font->FontSize + 6.0f * s;
  const auto width_of = [&](const std::string& text) { return font->CalcTextSizeA(font->FontSize, 1e6f, 0.0f, text.c_str()).x; };
  draw->AddRectFilled(corner, add(corner, size), theme.panel);
  draw->AddLine(corner, ImVec2(corner.x + size.x, corner.y), theme.grid);
  const ImVec2 bottom_left(corner.x, corner.y + size.y - 2.0f * s);
  const float left = bottom_left.x + 10.0f * s, right = corner.x + size.x;
  // The strip's edge and the text drawn in it, noted for the layout test.
  const ImRect strip(corner, add(corner, size));
  const auto text_at = [&](ImVec2 at, const std::string& text) {
    draw->AddText(font, font->FontSize, at, theme.text, text.c_str());
    ImGui::PushFont(font);
    note_text_in(text.c_str(), at, strip);
    ImGui::PopFont();
  };

  // What goes on each row: the kinds of force in the picture with the arrow scale (so a
  // teacher can read a length as newtons), then the contact states and the materials.
  // Friction, normal force and weight are always named: they are the lesson.
  bool present[force_kind_count] = {};
  present[static_cast<int>(ForceKind::friction)] = present[static_cast<int>(ForceKind::normal)] =
      present[static_cast<int>(ForceKind::weight)] = true;
  for (const auto& [name, body] : scene.bodies()) {
    for (const ForceOnBody& force : forces_on(scene, body)) present[static_cast<int>(force.kind)] = true;
  }
  // A torque is drawn as a curved arrow in the applied forces' colour (driven_wheel's motor):
  // keyed as such, or a class does not know what the curved arrow is (a teacher's trial).
  const bool torque = std::any_of(scene.torques_applied().begin(), scene.torques_applied().end(),
                                  [](double applied) { return applied != 0.0; });
  const ImU32 torque_colour = theme.force[static_cast<int>(ForceKind::applied)];
  // Its key: a small arc where the straight arrows' keys start, its word where theirs go.
  const auto torque_key = [&](ImVec2 at) {
    const float radius = 0.38f * font->FontSize;
    draw_torque_arrow(draw, torque_arc(ImVec2(at.x + 13.0f * s, at.y + 0.5f * font->FontSize), radius, 1.0), torque_colour,
                      2.0f * s);
    text_at(ImVec2(at.x + 32.0f * s, at.y), torque_word);
  };
  // A key's room in a row: its arrow (or arc) and the gap to its word, the word, a gap after.
  const auto key_width = [&](const std::string& word) { return 40.0f * s + width_of(word) + 10.0f * s; };
  // A column (projector mode, beside the plots) is taller than wide; a strip, wider than tall.
  const bool column = size.y > size.x;
  // The arrows' scale: a line about 40 pt long, of a nice number of newtons; in a column,
  // rounded down, so that it never outgrows the width legend_column_width() keeps for it.
  const float newtons = column ? nice_length_within(40.0f * s / newtons_to_pixels) : nice_length(40.0f * s / newtons_to_pixels);
  char scale_text[48];
  std::snprintf(scale_text, sizeof scale_text, "= %g N", static_cast<double>(newtons));
  // Where the scale stops being linear, said beside it: the world draws a force smaller than this
  // longer than to scale (legible_arrow_pixels), its value giving its size.
  const ArrowScaleWords words = arrow_scale_words(newtons_to_pixels, s);
  // A strip joins the lines, and leaves the number out where the row would not hold it beside
  // every kind of force's key (whether it acts yet or not, so that the words stay the same all
  // through the run): "dashed: too small to draw to scale (under 1.83 N)" ran past a 1024 px
  // screen's world.
  float every_key = left + key_width(torque_word);
  for (int kind = 0; kind < force_kind_count; ++kind) {
    every_key += key_width(std::string(force_kind_name(static_cast<ForceKind>(kind))));
  }
  const float scale_room = newtons * newtons_to_pixels + 6.0f * s + width_of(scale_text) + 8.0f * s;
  const std::string without_number = words[0] + " " + words[1];
  const std::string with_number = without_number + " " + words[2];
  const std::string joined = every_key + scale_room + width_of(with_number) <= right ? with_number : without_number;
  float arrows_end = left;
  for (int kind = 0; kind < force_kind_count; ++kind) {
    if (present[kind]) arrows_end += key_width(std::string(force_kind_name(static_cast<ForceKind>(kind))));
  }
  if (torque) arrows_end += key_width(torque_word);
  arrows_end += scale_room + width_of(joined);
  std::vector<std::pair<ImU32, std::string>> materials;
  for (const auto& [name, body] : scene.bodies()) {
    for (const b2Fixture* fixture = body->GetFixtureList(); fixture != nullptr; fixture = fixture->GetNext()) {
      const std::string material = lessons::class_words(material_name(scene, fixture));
      bool listed = false;
      for (const auto& [colour, named] : materials) listed = listed || named == material;
      if (!listed) materials.emplace_back(fixture_colour(scene, fixture, theme), material);
    }
  }
  // A chip's swatch, its name after it and a gap before the next: closer together when tight.
  const auto chips_width = [&](const char* sticking, const char* slipping, float advance) {
    float width = left + 2.0f * advance + width_of(sticking) + width_of(slipping);
    for (const auto& [colour, material] : materials) width += advance + width_of(material);
    return width;
  };
  // The scale bar goes at the right of the arrows' row, or of the materials' row (its length
  // written before it) when the arrows leave it no room. With large text in a narrow world the
  // contact states are then named by a word each, and then the chips close up, as far as the
  // row needs.
  if (column) {
    // A column (projector mode, beside the plots): an entry a line, the arrows with their
    // scale, the contact states, the materials, and the scale bar under them. The lines close
    // up (to 2 pt between) when there are more than its height holds at 6 pt.
    const std::size_t forces = static_cast<std::size_t>(std::count(std::begin(present), std::end(present), true));
    const std::size_t lines = forces + (torque ? 1 : 0) + 4 + 2 + materials.size() + 2;  // the arrows' scale takes four, the metres' bar two
    const float room = size.y - 8.0f * s;
    const float step = std::max(font->FontSize + 2.0f * s, std::min(line, room / static_cast<float>(lines)));
    ImVec2 at(left, corner.y + 6.0f * s);
    for (int kind = 0; kind < force_kind_count; ++kind) {
      if (!present[kind]) continue;
      draw_arrow(draw, ImVec2(at.x, at.y + 0.5f * font->FontSize), ImVec2(at.x + 26.0f * s, at.y + 0.5f * font->FontSize),
                 theme.force[kind], 3.0f * s);
      text_at(ImVec2(at.x + 32.0f * s, at.y), std::string(force_kind_name(static_cast<ForceKind>(kind))));
      at.y += step;
    }
    if (torque) {
      torque_key(at);
      at.y += step;
    }
    draw->AddLine(ImVec2(at.x, at.y + 0.5f * font->FontSize), ImVec2(at.x + newtons * newtons_to_pixels, at.y + 0.5f * font->FontSize),
                  theme.text, 3.0f * s);
    text_at(ImVec2(at.x + newtons * newtons_to_pixels + 6.0f * s, at.y), scale_text);
    at.y += step;
    for (const std::string& words_line : words) {
      text_at(at, words_line);
      at.y += step;
    }
    const float inside = right - 6.0f * s;
    const bool short_states = true;  // the chips are named by a word each: the column stays narrow
    const auto chip = [&](ImU32 colour, const std::string& text, bool round) {
      chip_mark(draw, ImVec2(at.x + 7.0f * s, at.y + 0.5f * font->FontSize), colour, round, theme, s);
      text_at(ImVec2(at.x + 20.0f * s, at.y), text);
      at.y += step;
    };
    chip(theme.sticking, short_states ? "sticking" : "sticking contact", true);
    chip(theme.slipping, short_states ? "slipping" : "slipping contact", true);
    for (const auto& [colour, material] : materials) chip(colour, material, false);
    // The bar from the column's left, its length written above it: rounded down, so that it
    // fits the column whole (a bar rounded up ran past the column's edge, cut shorter than the
    // length written above it).
    const float metre_bar = nice_length_within(std::min(110.0f * s, inside - left - 16.0f * s) / camera.pixels_per_metre);
    const float bar_pixels = metre_bar * camera.pixels_per_metre;
    draw_scale_bar(draw, camera.pixels_per_metre, ImVec2(left + bar_pixels + 16.0f * s, at.y + step + 12.0f * s), theme, fonts,
                   false, metre_bar);
    return;
  }
  const float bar = nice_length(110.0f * s / camera.pixels_per_metre);
  const float bar_room = bar * camera.pixels_per_metre + 32.0f * s;
  const bool bar_below = arrows_end + bar_room > right;
  const float chips_room = bar_below ? right - bar_room - width_of(metres(bar)) - 8.0f * s : right;
  bool short_states = false, tight = false;
  for (const auto& [shorter, closer] : {std::pair{false, false}, std::pair{true, false}, std::pair{true, true}}) {
    short_states = shorter;
    tight = closer;
    if (chips_width(shorter ? "sticking" : "sticking contact", shorter ? "slipping" : "slipping contact",
                    (closer ? 26.0f : 32.0f) * s) <= chips_room) {
      break;
    }
  }
  const char* sticking = short_states ? "sticking" : "sticking contact";
  const char* slipping = short_states ? "slipping" : "slipping contact";
  const float advance = (tight ? 26.0f : 32.0f) * s, name_offset = (tight ? 18.0f : 20.0f) * s;
  const float arrows_y = bottom_left.y - 2.0f * line, chips_y = bottom_left.y - line;
  draw_scale_bar(draw, camera.pixels_per_metre,
                 ImVec2(right, (bar_below ? chips_y : arrows_y) + 0.5f * font->FontSize + 14.0f * s), theme, fonts,
                 bar_below);

  ImVec2 at(left, arrows_y);
  for (int kind = 0; kind < force_kind_count; ++kind) {
    if (!present[kind]) continue;
    const ImU32 colour = theme.force[kind];
    draw_arrow(draw, ImVec2(at.x, at.y + 0.5f * font->FontSize), ImVec2(at.x + 26.0f * s, at.y + 0.5f * font->FontSize),
               colour, 3.0f * s);
    const std::string name(force_kind_name(static_cast<ForceKind>(kind)));
    text_at(ImVec2(at.x + 32.0f * s, at.y), name);
    at.x += key_width(name);
  }
  if (torque) {
    torque_key(at);
    at.x += key_width(torque_word);
  }
  draw->AddLine(ImVec2(at.x, at.y + 0.5f * font->FontSize), ImVec2(at.x + newtons * newtons_to_pixels, at.y + 0.5f * font->FontSize),
                theme.text, 3.0f * s);
  text_at(ImVec2(at.x + newtons * newtons_to_pixels + 6.0f * s, at.y), scale_text);
  text_at(ImVec2(at.x + newtons * newtons_to_pixels + 6.0f * s + width_of(scale_text) + 8.0f * s, at.y),
          joined);

  at = ImVec2(left, chips_y);
  const auto chip = [&](ImU32 colour, const std::string& text, bool round) {
    chip_mark(draw, ImVec2(at.x + 7.0f * s, at.y + 0.5f * font->FontSize), colour, round, theme, s);
    text_at(ImVec2(at.x + name_offset, at.y), text);
    at.x += advance + width_of(text);
  };
  chip(theme.sticking, sticking, true);
  chip(theme.slipping, slipping, true);
  for (const auto& [colour, material] : materials) chip(colour, material, false);
}

ArrowScaleWords arrow_scale_words(float newtons_to_pixels, float scale) {
  return {dashed_words, to_scale_words, "(under " + format_quantity(not_to_scale_below(newtons_to_pixels, scale), "N") + ")"};
}

float legend_column_width(const Scene& scene, const Fonts& fonts) {
  ImFont* font = fonts.small;
  const float s = fonts.scale;
  const auto width_of = [&](const std::string& text) { return font->CalcTextSizeA(font->FontSize, 1e6f, 0.0f, text.c_str()).x; };
  // Every kind of force, whether it acts yet or not, so that the column keeps its width as the
  // run goes on; the arrows' scale at its longest (40 pt: rounded down in a column) with a
  // four-digit value; the states' words and the materials' names after their marks.
  float widest = std::max(46.0f * s + width_of("= 1000 N"), width_of("(under 1000 N)"));
  widest = std::max({widest, width_of(dashed_words), width_of(to_scale_words)});
  for (int kind = 0; kind < force_kind_count; ++kind) {
    widest = std::max(widest, 32.0f * s + width_of(std::string(force_kind_name(static_cast<ForceKind>(kind)))));
  }
  widest = std::max(widest, 32.0f * s + width_of(torque_word));
  for (const char* state : {"sticking", "slipping"}) widest = std::max(widest, 20.0f * s + width_of(state));
  for (const auto& [name, body] : scene.bodies()) {
    for (const b2Fixture* fixture = body->GetFixtureList(); fixture != nullptr; fixture = fixture->GetNext()) {
      widest = std::max(widest, 20.0f * s + width_of(lessons::class_words(material_name(scene, fixture))));
    }
  }
  return 10.0f * s + widest + 12.0f * s;  // the margins: 10 pt before, 6 pt and the panel's edge after
}

}  // namespace frictionlab::draw
