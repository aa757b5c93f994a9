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
  // Noted for the layout test against what of its panel shows (the clip rectangle) less what of
  // the bar and its ticks reaches below the words (a column's bar is under them): the words are
  // whole only where the bar is too. A projector's legend column, shortened, cut the bar under
  // "20 cm" (issue 31, with the help open).
  const float words_foot = label.y + 0.5f * fonts.small->FontSize;
  const float bar_foot = end.y + std::max(1.0f, fonts.scale);  // the ticks' ends, the bar's lower edge
  const ImVec2 shown_min = draw->GetClipRectMin(), shown_max = draw->GetClipRectMax();
  const ImRect room(shown_min, ImVec2(shown_max.x, shown_max.y - std::max(0.0f, bar_foot - words_foot)));
  ImGui::PushFont(fonts.small);
  note_text_in(length.c_str(), ImVec2(std::round(label.x - 0.5f * width), std::round(words_foot - fonts.small->FontSize)), room);
  ImGui::PopFont();
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

namespace {

// What the legend keys, whichever way it is laid out: the kinds of force in the picture with the
// arrow scale (so a teacher can read a length as newtons), then the contact states and the
// materials.
struct LegendContent {
  bool present[force_kind_count] = {};
  bool torque = false;
  float newtons = 0.0f;  // the arrows' scale bar's length, N
  char scale_text[48] = {};
  ArrowScaleWords words;
  std::vector<std::pair<ImU32, std::string>> materials;
};

// The legend's font, scale and strip, and how it writes and measures.
struct LegendPen {
  ImDrawList* draw;
  ImFont* font;
  float s, line;
  const Theme& theme;
  ImRect strip;
  float left, right;

  float width_of(const std::string& text) const { return font->CalcTextSizeA(font->FontSize, 1e6f, 0.0f, text.c_str()).x; }
  // The text drawn in the strip, noted for the layout test.
  void text_at(ImVec2 at, const std::string& text) const {
    draw->AddText(font, font->FontSize, at, theme.text, text.c_str());
    ImGui::PushFont(font);
    note_text_in(text.c_str(), at, strip);
    ImGui::PopFont();
  }
  // A key's room in a row: its arrow (or arc) and the gap to its word, the word, a gap after.
  float key_width(const std::string& word) const { return 40.0f * s + width_of(word) + 10.0f * s; }
  // A force's key: a short arrow in its colour and its name after it.
  void force_key(ImVec2 at, int kind) const {
    draw_arrow(draw, ImVec2(at.x, at.y + 0.5f * font->FontSize), ImVec2(at.x + 26.0f * s, at.y + 0.5f * font->FontSize),
               theme.force[kind], 3.0f * s);
    text_at(ImVec2(at.x + 32.0f * s, at.y), std::string(force_kind_name(static_cast<ForceKind>(kind))));
  }
  // A torque's key: a small arc where the straight arrows' keys start, its word where theirs go.
  void torque_key(ImVec2 at) const {
    const float radius = 0.38f * font->FontSize;
    draw_torque_arrow(draw, torque_arc(ImVec2(at.x + 13.0f * s, at.y + 0.5f * font->FontSize), radius, 1.0),
                      theme.force[static_cast<int>(ForceKind::applied)], 2.0f * s);
    text_at(ImVec2(at.x + 32.0f * s, at.y), torque_word);
  }
  // The arrows' scale: a line `newtons` long and its "= N" after it.
  void scale_key(ImVec2 at, const LegendContent& content, float newtons_to_pixels) const {
    draw->AddLine(ImVec2(at.x, at.y + 0.5f * font->FontSize),
                  ImVec2(at.x + content.newtons * newtons_to_pixels, at.y + 0.5f * font->FontSize), theme.text, 3.0f * s);
    text_at(ImVec2(at.x + content.newtons * newtons_to_pixels + 6.0f * s, at.y), content.scale_text);
  }
};

LegendContent legend_content(const Scene& scene, const Theme& theme, float newtons, float newtons_to_pixels, float s) {
  LegendContent content;
  // Friction, normal force and weight are always named: they are the lesson.
  content.present[static_cast<int>(ForceKind::friction)] = content.present[static_cast<int>(ForceKind::normal)] =
      content.present[static_cast<int>(ForceKind::weight)] = true;
  for (const auto& [name, body] : scene.bodies()) {
    for (const ForceOnBody& force : forces_on(scene, body)) content.present[static_cast<int>(force.kind)] = true;
  }
  // A torque is drawn as a curved arrow in the applied forces' colour (driven_wheel's motor):
  // keyed as such, or a class does not know what the curved arrow is (a teacher's trial).
  content.torque = std::any_of(scene.torques_applied().begin(), scene.torques_applied().end(),
                               [](double applied) { return applied != 0.0; });
  content.newtons = newtons;
  std::snprintf(content.scale_text, sizeof content.scale_text, "= %g N", static_cast<double>(newtons));
  // Where the scale stops being linear, said beside it: the world draws a force smaller than this
  // longer than to scale (legible_arrow_pixels), its value giving its size.
  content.words = arrow_scale_words(newtons_to_pixels, s);
  for (const auto& [name, body] : scene.bodies()) {
    for (const b2Fixture* fixture = body->GetFixtureList(); fixture != nullptr; fixture = fixture->GetNext()) {
      const std::string material = lessons::class_words(material_name(scene, fixture));
      bool listed = false;
      for (const auto& [colour, named] : content.materials) listed = listed || named == material;
      if (!listed) content.materials.emplace_back(fixture_colour(scene, fixture, theme), material);
    }
  }
  return content;
}

// A column (projector mode, beside the plots): an entry a line, the arrows with their scale, the
// contact states, the materials, and the scale bar under them. The lines close up (to 2 pt
// between) when there are more than its height holds at 6 pt.
void draw_legend_column(const LegendPen& pen, const LegendContent& content, const Camera& camera, ImVec2 corner,
                        ImVec2 size, const Fonts& fonts, float newtons_to_pixels) {
  const float s = pen.s;
  const std::size_t forces = static_cast<std::size_t>(std::count(std::begin(content.present), std::end(content.present), true));
  const std::size_t lines = forces + (content.torque ? 1 : 0) + 4 + 2 + content.materials.size() + 2;  // the arrows' scale takes four, the metres' bar two
  const float room = size.y - 8.0f * s;
  const float step = std::max(pen.font->FontSize + 2.0f * s, std::min(pen.line, room / static_cast<float>(lines)));
  ImVec2 at(pen.left, corner.y + 6.0f * s);
  for (int kind = 0; kind < force_kind_count; ++kind) {
    if (!content.present[kind]) continue;
    pen.force_key(at, kind);
    at.y += step;
  }
  if (content.torque) {
    pen.torque_key(at);
    at.y += step;
  }
  pen.scale_key(at, content, newtons_to_pixels);
  at.y += step;
  for (const std::string& words_line : content.words) {
    pen.text_at(at, words_line);
    at.y += step;
  }
  const float inside = pen.right - 6.0f * s;
  // The chips are named by a word each: the column stays narrow.
  const auto chip = [&](ImU32 colour, const std::string& text, bool round) {
    chip_mark(pen.draw, ImVec2(at.x + 7.0f * s, at.y + 0.5f * pen.font->FontSize), colour, round, pen.theme, s);
    pen.text_at(ImVec2(at.x + 20.0f * s, at.y), text);
    at.y += step;
  };
  chip(pen.theme.sticking, "sticking", true);
  chip(pen.theme.slipping, "slipping", true);
  for (const auto& [colour, material] : content.materials) chip(colour, material, false);
  // The bar from the column's left, its length written above it: rounded down, so that it
  // fits the column whole (a bar rounded up ran past the column's edge, cut shorter than the
  // length written above it).
  const float metre_bar = nice_length_within(std::min(110.0f * s, inside - pen.left - 16.0f * s) / camera.pixels_per_metre);
  const float bar_pixels = metre_bar * camera.pixels_per_metre;
  draw_scale_bar(pen.draw, camera.pixels_per_metre, ImVec2(pen.left + bar_pixels + 16.0f * s, at.y + step + 12.0f * s),
                 pen.theme, fonts, false, metre_bar);
}

// A strip under the world: the arrows' row with their scale and its words, the chips' row, and
// the scale bar at the right of the arrows' row, or of the chips' row (its length written before
// it) when the arrows leave it no room. With large text in a narrow world the contact states are
// then named by a word each, and then the chips close up, as far as the row needs.
void draw_legend_strip(const LegendPen& pen, const LegendContent& content, const Camera& camera, ImVec2 corner,
                       ImVec2 size, const Fonts& fonts, float newtons_to_pixels) {
  const float s = pen.s, left = pen.left, right = pen.right;
  const ImVec2 bottom_left(corner.x, corner.y + size.y - 2.0f * s);
  // The strip joins the words, and leaves the number out where the row would not hold it beside
  // every kind of force's key (whether it acts yet or not, so that the words stay the same all
  // through the run): "dashed: too small to draw to scale (under 1.83 N)" ran past a 1024 px
  // screen's world.
  float every_key = left + pen.key_width(torque_word);
  for (int kind = 0; kind < force_kind_count; ++kind) {
    every_key += pen.key_width(std::string(force_kind_name(static_cast<ForceKind>(kind))));
  }
  const float scale_room = content.newtons * newtons_to_pixels + 6.0f * s + pen.width_of(content.scale_text) + 8.0f * s;
  const std::string without_number = content.words[0] + " " + content.words[1];
  const std::string with_number = without_number + " " + content.words[2];
  const std::string joined = every_key + scale_room + pen.width_of(with_number) <= right ? with_number : without_number;
  float arrows_end = left;
  for (int kind = 0; kind < force_kind_count; ++kind) {
    if (content.present[kind]) arrows_end += pen.key_width(std::string(force_kind_name(static_cast<ForceKind>(kind))));
  }
  if (content.torque) arrows_end += pen.key_width(torque_word);
  arrows_end += scale_room + pen.width_of(joined);
  // A chip's swatch, its name after it and a gap before the next: closer together when tight.
  const auto chips_width = [&](const char* sticking, const char* slipping, float advance) {
    float width = left + 2.0f * advance + pen.width_of(sticking) + pen.width_of(slipping);
    for (const auto& [colour, material] : content.materials) width += advance + pen.width_of(material);
    return width;
  };
  const float bar = nice_length(110.0f * s / camera.pixels_per_metre);
  const float bar_room = bar * camera.pixels_per_metre + 32.0f * s;
  const bool bar_below = arrows_end + bar_room > right;
  const float chips_room = bar_below ? right - bar_room - pen.width_of(metres(bar)) - 8.0f * s : right;
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
  const float arrows_y = bottom_left.y - 2.0f * pen.line, chips_y = bottom_left.y - pen.line;
  draw_scale_bar(pen.draw, camera.pixels_per_metre,
                 ImVec2(right, (bar_below ? chips_y : arrows_y) + 0.5f * pen.font->FontSize + 14.0f * s), pen.theme, fonts,
                 bar_below);

  ImVec2 at(left, arrows_y);
  for (int kind = 0; kind < force_kind_count; ++kind) {
    if (!content.present[kind]) continue;
    pen.force_key(at, kind);
    at.x += pen.key_width(std::string(force_kind_name(static_cast<ForceKind>(kind))));
  }
  if (content.torque) {
    pen.torque_key(at);
    at.x += pen.key_width(torque_word);
  }
  pen.scale_key(at, content, newtons_to_pixels);
  pen.text_at(ImVec2(at.x + content.newtons * newtons_to_pixels + 6.0f * s + pen.width_of(content.scale_text) + 8.0f * s, at.y),
              joined);

  at = ImVec2(left, chips_y);
  const auto chip = [&](ImU32 colour, const std::string& text, bool round) {
    chip_mark(pen.draw, ImVec2(at.x + 7.0f * s, at.y + 0.5f * pen.font->FontSize), colour, round, pen.theme, s);
    pen.text_at(ImVec2(at.x + name_offset, at.y), text);
    at.x += advance + pen.width_of(text);
  };
  chip(pen.theme.sticking, sticking, true);
  chip(pen.theme.slipping, slipping, true);
  for (const auto& [colour, material] : content.materials) chip(colour, material, false);
}

}  // namespace

void draw_legend(ImDrawList* draw, const Scene& scene, const Camera& camera, ImVec2 corner, ImVec2 size,
                 const Theme& theme, const Fonts& fonts, float newtons_to_pixels) {
  ImFont* font = fonts.small;
  const float s = fonts.scale;
  draw->AddRectFilled(corner, add(corner, size), theme.panel);
  draw->AddLine(corner, ImVec2(corner.x + size.x, corner.y), theme.grid);
  const LegendPen pen{draw, font, s, font->FontSize + 6.0f * s, theme, ImRect(corner, add(corner, size)),
                      corner.x + 10.0f * s, corner.x + size.x};
  // A column (projector mode, beside the plots) is taller than wide; a strip, wider than tall.
  const bool column = size.y > size.x;
  // The arrows' scale: a line about 40 pt long, of a nice number of newtons; in a column,
  // rounded down, so that it never outgrows the width legend_column_width() keeps for it.
  const float newtons = column ? nice_length_within(40.0f * s / newtons_to_pixels) : nice_length(40.0f * s / newtons_to_pixels);
  const LegendContent content = legend_content(scene, theme, newtons, newtons_to_pixels, s);
  if (column) {
    draw_legend_column(pen, content, camera, corner, size, fonts, newtons_to_pixels);
  } else {
    draw_legend_strip(pen, content, camera, corner, size, fonts, newtons_to_pixels);
  }
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
