// Colours and fonts. Two themes, light for a bright classroom and dark for a dim one, and a
// TrueType font at sizes that read from the back of a room: every size scales with the
// frame's height, 720 pixels being 1.
#pragma once

#include <imgui.h>

#include <string>
#include <string_view>

#include "physics/scene_forces.h"

namespace frictionlab::draw {

enum class ThemeName { light, dark };
// Throws InvalidInput listing the themes.
ThemeName parse_theme(std::string_view name);
std::string_view theme_name(ThemeName theme);

// Each kind of force (physics/scene_forces.h) has its own colour, the same in every picture.
using frictionlab::force_kind_count;
using frictionlab::force_kind_name;

struct Theme {
  ThemeName name;
  ImU32 background, panel, text, faint_text, grid, axis;
  ImU32 sky, ground_edge, outline, driven_outline, spring, rope, hand;
  ImU32 force[force_kind_count];
  // A second force of one kind on one plot (stacked_blocks' two frictions): its kind's colour
  // taken half way to a crimson, still nearer friction's vermilion than any other kind's colour,
  // told apart by the legend. (Darkened toward the text instead, it came nearer the rope's brown
  // than friction's own colour.)
  ImU32 second_force[force_kind_count];
  // The outline round every force's arrow in the world and the free-body inset: 3:1 or more
  // against every force's colour (WCAG 2.1's non-text contrast), so an arrow stands out from
  // a body of its own lightness (issue 31: the dark theme's normal force on aluminium, 1.09:1;
  // the light theme's weight on rubber, 1.1:1). White in the light theme, near black in the dark.
  ImU32 arrow_halo;
  ImU32 sticking, slipping, slip_band, now_marker;
  // A frame with no contact touching (every body in the air): neither sticking nor slipping.
  ImU32 no_contact;
  ImU32 series[4];
  // Laws drawn beside the measurements (plots' theory curves): a plot's curves take them in turn.
  ImU32 theory[2];
  ImU32 good, bad;
  ImVec4 imgui_text, imgui_window, imgui_title, imgui_border, imgui_header;
};
const Theme& theme(ThemeName name);

// WCAG 2.1's contrast ratio of two opaque colours, 1 to 21.
double contrast_ratio(ImU32 a, ImU32 b);
// `ink` as text on `background`: itself where it reads 4.5:1 or more (WCAG 2.1 AA), else mixed
// toward black (on a light background) or white (on a dark one) just far enough. A force's
// value is written in its arrow's colour; vermilion friction on white read 4.3:1.
ImU32 readable_ink(ImU32 ink, ImU32 background);

// A material's fill as a plot's line (probe{ like = ... }): its hue, made strong where it has
// one, dark enough (light enough, on a dark theme) to stand 3:1 from `background`, WCAG 2.1's
// contrast for what is not text.
ImU32 line_like(ImU32 fill, ImU32 background);

// A material's fill colour: known materials by look (wood brown, ice pale blue), others from
// a palette by the order they were declared in.
ImU32 material_colour(const Theme& theme, const std::string& material, int index);

// Sizes in a frame are given for 1280×720 and scaled by this: by the height, or by the width
// when the frame is narrower than 16:9 (a 1024×768 projector).
float frame_scale(int width, int height);

// The small text's size at scale 1, pt (the legend's, the free-body inset's, a lane's name):
// what the layout measures the inset's arrows against before any font is loaded.
constexpr float small_text_points = 14.0f;
// The body text's (a panel's words; a projector's key plot's numbers: number_font in chart_parts.h).
constexpr float body_text_points = 17.0f;
// How far apart a plot's y ticks stand at least, pt at scale 1 (Chart::y_tick_spacing): a line
// and a half of its numbers' text, the body text's on a page of its own (a steady chart: a
// projector's lesson plots and force gauge), the small text's beside others.
constexpr float plot_tick_spacing_points(bool steady) { return 1.5f * (steady ? body_text_points : small_text_points); }

struct Fonts {
  ImFont* body = nullptr;
  ImFont* title = nullptr;
  ImFont* small = nullptr;
  float scale = 1.0f;  // frame height / 720
};
// Adds DejaVu Sans at the three sizes to the current context's atlas, with the Greek letters,
// degree sign, arrows and maths signs the lessons use. Throws std::runtime_error naming the
// file and the package when the font is missing. The atlas keeps pointing into
// `glyph_ranges`, which must live as long as it does.
Fonts load_fonts(float scale, ImVector<ImWchar>& glyph_ranges);
// The font file used; compiled in from where the build found Debian's fonts-dejavu-core.
std::string font_path();

// ImGui's own colours and spacing for the theme.
void apply_imgui_style(ThemeName name, float scale);

}  // namespace frictionlab::draw
