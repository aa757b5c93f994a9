#include "draw/theme.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <stdexcept>

#include "physics/materials.h"

namespace frictionlab::draw {

ThemeName parse_theme(std::string_view name) {
  if (name == "light") return ThemeName::light;
  if (name == "dark") return ThemeName::dark;
  throw InvalidInput("unknown theme '" + std::string(name) + "'; allowed: light, dark");
}

std::string_view theme_name(ThemeName theme) { return theme == ThemeName::light ? "light" : "dark"; }

namespace {

ImVec4 rgb(int r, int g, int b) {
  return ImVec4(static_cast<float>(r) / 255.0f, static_cast<float>(g) / 255.0f, static_cast<float>(b) / 255.0f, 1.0f);
}

// Each kind's colour taken half way to `crimson`: Theme::second_force.
void mix_second_forces(Theme& t, ImU32 crimson) {
  const ImVec4 to = ImGui::ColorConvertU32ToFloat4(crimson);
  constexpr float toward = 0.5f;
  for (int kind = 0; kind < force_kind_count; ++kind) {
    const ImVec4 from = ImGui::ColorConvertU32ToFloat4(t.force[kind]);
    t.second_force[kind] = ImGui::ColorConvertFloat4ToU32(
        ImVec4(from.x + toward * (to.x - from.x), from.y + toward * (to.y - from.y), from.z + toward * (to.z - from.z), from.w));
  }
}

// Force colours are told apart by people with the common colour-vision deficiencies too:
// blue, green, vermilion, purple and dark grey differ in lightness as well as hue.
Theme make_light() {
  Theme t{};
  t.name = ThemeName::light;
  t.background = IM_COL32(250, 250, 247, 255);
  t.panel = IM_COL32(255, 255, 255, 255);
  t.text = IM_COL32(20, 20, 24, 255);
  t.faint_text = IM_COL32(95, 95, 105, 255);
  t.grid = IM_COL32(226, 226, 222, 255);
  t.axis = IM_COL32(70, 70, 78, 255);
  t.sky = IM_COL32(238, 244, 250, 255);
  t.ground_edge = IM_COL32(92, 82, 66, 255);
  t.outline = IM_COL32(30, 30, 34, 255);
  t.driven_outline = IM_COL32(160, 110, 0, 255);
  t.spring = IM_COL32(40, 40, 46, 255);
  t.rope = IM_COL32(120, 80, 30, 255);
  t.hand = IM_COL32(160, 110, 0, 255);
  t.force[0] = IM_COL32(0, 100, 210, 255);    // applied: blue
  t.force[1] = IM_COL32(0, 140, 70, 255);     // spring: green
  t.force[2] = IM_COL32(220, 70, 0, 255);     // friction: vermilion
  t.force[3] = IM_COL32(130, 50, 170, 255);   // normal: purple
  t.force[4] = IM_COL32(60, 60, 60, 255);     // weight: dark grey
  t.force[5] = IM_COL32(140, 90, 30, 255);    // rope: brown
  t.force[6] = IM_COL32(110, 130, 0, 255);    // drag (c, b): olive
  t.arrow_halo = IM_COL32(255, 255, 255, 255);
  mix_second_forces(t, IM_COL32(190, 0, 40, 255));
  // Friction is the kind lessons plot twice (stacked_blocks' two surfaces, friction_models):
  // half way to the crimson, (205, 35, 20), was 15 apart from vermilion in CIELAB (ΔE76) and
  // 1.28:1 in lightness, one colour on a projector (issue 31). A deep crimson, 37 apart and
  // 1.8:1 darker, still nearer vermilion than any other kind's colour or a contact state's
  // (slipping's magenta 39, rope's brown 47; in RGB too), 7.7:1 on the panel.
  t.second_force[2] = IM_COL32(170, 0, 40, 255);
  // Contact states have colours no arrow has, so a mark never reads as a force.
  t.sticking = IM_COL32(0, 150, 160, 255);    // teal
  t.slipping = IM_COL32(215, 0, 120, 255);    // magenta
  t.slip_band = IM_COL32(240, 120, 190, 60);
  // Indigo: off the states' teal and magenta and the theory's grey and mustard (an X–Y plot's
  // other curves), 7.4:1 on white.
  t.no_contact = IM_COL32(80, 60, 200, 255);
  t.now_marker = IM_COL32(20, 20, 24, 255);
  t.series[0] = IM_COL32(0, 100, 210, 255);
  t.series[1] = IM_COL32(220, 70, 0, 255);
  t.series[2] = IM_COL32(0, 140, 70, 255);
  t.series[3] = IM_COL32(130, 50, 170, 255);
  t.theory[0] = IM_COL32(90, 90, 100, 255);    // grey
  // Mustard: no series, force or contact state has it. An ochre, (150, 95, 20), was 43 apart
  // from friction's vermilion in CIELAB (ΔE76), and stacked_blocks' μk·N level, thin, read as
  // the friction on top it lies along, on a projector (a teacher's trial, issue 31); mustard is
  // 57 apart, 5.0:1 on white. Nearer are only colours never plotted: the hand's and a driven
  // body's gold (15), rope's brown and drag's olive (21).
  t.theory[1] = IM_COL32(130, 110, 0, 255);
  // Dark enough to read 4.5:1 on the theory table's grey rows (#efefef): (0, 130, 60) read 4.3.
  t.good = IM_COL32(0, 115, 55, 255);
  t.bad = IM_COL32(200, 20, 20, 255);
  t.imgui_text = rgb(20, 20, 24);
  t.imgui_window = rgb(255, 255, 255);
  t.imgui_title = rgb(222, 228, 238);
  t.imgui_border = rgb(190, 190, 196);
  t.imgui_header = rgb(236, 238, 242);
  return t;
}

Theme make_dark() {
  Theme t{};
  t.name = ThemeName::dark;
  t.background = IM_COL32(24, 26, 30, 255);
  t.panel = IM_COL32(34, 36, 42, 255);
  t.text = IM_COL32(236, 236, 236, 255);
  t.faint_text = IM_COL32(165, 165, 175, 255);
  t.grid = IM_COL32(52, 55, 62, 255);
  t.axis = IM_COL32(190, 190, 196, 255);
  t.sky = IM_COL32(30, 34, 42, 255);
  t.ground_edge = IM_COL32(190, 175, 150, 255);
  t.outline = IM_COL32(230, 230, 230, 255);
  t.driven_outline = IM_COL32(230, 180, 60, 255);
  t.spring = IM_COL32(225, 225, 225, 255);
  t.rope = IM_COL32(225, 180, 120, 255);
  t.hand = IM_COL32(230, 180, 60, 255);
  t.force[0] = IM_COL32(90, 170, 255, 255);
  t.force[1] = IM_COL32(70, 210, 130, 255);
  t.force[2] = IM_COL32(255, 130, 60, 255);
  t.force[3] = IM_COL32(200, 140, 255, 255);
  t.force[4] = IM_COL32(200, 200, 200, 255);
  t.force[5] = IM_COL32(210, 160, 100, 255);
  t.force[6] = IM_COL32(190, 210, 60, 255);
  t.arrow_halo = IM_COL32(16, 16, 20, 255);
  mix_second_forces(t, IM_COL32(255, 80, 110, 255));
  // Friction's shade, as in the light theme: (255, 105, 85) was 22 apart from the orange; a
  // rose red 40 apart, nearer the orange than any other colour of a force or a state (slipping's
  // pink 45), 4.5:1 on the panel.
  t.second_force[2] = IM_COL32(255, 65, 90, 255);
  t.sticking = IM_COL32(40, 200, 210, 255);
  t.slipping = IM_COL32(255, 90, 180, 255);
  t.slip_band = IM_COL32(255, 90, 180, 45);
  t.no_contact = IM_COL32(160, 150, 255, 255);  // periwinkle, 6:1 on the panel
  t.now_marker = IM_COL32(236, 236, 236, 255);
  t.series[0] = IM_COL32(90, 170, 255, 255);
  t.series[1] = IM_COL32(255, 130, 60, 255);
  t.series[2] = IM_COL32(70, 210, 130, 255);
  t.series[3] = IM_COL32(200, 140, 255, 255);
  t.theory[0] = IM_COL32(190, 190, 200, 255);
  t.theory[1] = IM_COL32(250, 210, 0, 255);  // yellow: 56 from the orange (a gold was 36), 10.6:1
  t.good = IM_COL32(90, 220, 130, 255);
  t.bad = IM_COL32(255, 90, 90, 255);
  t.imgui_text = rgb(236, 236, 236);
  t.imgui_window = rgb(34, 36, 42);
  t.imgui_title = rgb(48, 52, 62);
  t.imgui_border = rgb(70, 74, 84);
  t.imgui_header = rgb(44, 48, 56);
  return t;
}

}  // namespace

const Theme& theme(ThemeName name) {
  static const Theme light = make_light();
  static const Theme dark = make_dark();
  return name == ThemeName::light ? light : dark;
}

namespace {

double relative_luminance(ImU32 colour) {
  const auto linear = [](unsigned channel) {
    const double c = static_cast<double>(channel & 0xFFu) / 255.0;
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
  };
  return 0.2126 * linear(colour >> IM_COL32_R_SHIFT) + 0.7152 * linear(colour >> IM_COL32_G_SHIFT) +
         0.0722 * linear(colour >> IM_COL32_B_SHIFT);
}

}  // namespace

double contrast_ratio(ImU32 a, ImU32 b) {
  const double la = relative_luminance(a), lb = relative_luminance(b);
  return (std::max(la, lb) + 0.05) / (std::min(la, lb) + 0.05);
}

ImU32 readable_ink(ImU32 ink, ImU32 background) {
  constexpr double wcag_aa = 4.5;
  if (contrast_ratio(ink, background) >= wcag_aa) return ink;
  const ImU32 toward = relative_luminance(background) > 0.18 ? IM_COL32(0, 0, 0, 255) : IM_COL32(255, 255, 255, 255);
  const ImVec4 from = ImGui::ColorConvertU32ToFloat4(ink), to = ImGui::ColorConvertU32ToFloat4(toward);
  // Twenty steps of 5 %: the first that reads is the one nearest the arrow's own colour.
  for (int step = 1; step <= 20; ++step) {
    const float f = 0.05f * static_cast<float>(step);
    const ImU32 mixed = ImGui::ColorConvertFloat4ToU32(ImVec4(from.x + f * (to.x - from.x), from.y + f * (to.y - from.y),
                                                              from.z + f * (to.z - from.z), from.w));
    if (contrast_ratio(mixed, background) >= wcag_aa) return mixed;
  }
  return toward;
}

ImU32 line_like(ImU32 fill, ImU32 background) {
  constexpr double wcag_non_text = 3.0;
  const ImVec4 colour = ImGui::ColorConvertU32ToFloat4(fill);
  float hue = 0.0f, saturation = 0.0f, value = 0.0f;
  ImGui::ColorConvertRGBtoHSV(colour.x, colour.y, colour.z, hue, saturation, value);
  // A pale fill's hue made strong (ice's pale blue a blue): darkened as it was, three pale
  // fills all came out grey. A grey (asphalt) stays grey.
  if (saturation >= 0.15f) saturation = std::max(saturation, 0.7f);
  const bool darken = relative_luminance(background) > 0.18;
  for (int step = 0; step < 40; ++step) {
    float red = 0.0f, green = 0.0f, blue = 0.0f;
    ImGui::ColorConvertHSVtoRGB(hue, saturation, value, red, green, blue);
    const ImU32 line = ImGui::ColorConvertFloat4ToU32(ImVec4(red, green, blue, 1.0f));
    if (contrast_ratio(line, background) >= wcag_non_text) return line;
    if (darken) {
      value *= 0.93f;
    } else if (value < 1.0f) {
      value = std::min(1.0f, value + 0.05f);
    } else {
      saturation *= 0.9f;  // as bright as it goes: paler
    }
  }
  return readable_ink(fill, background);
}

ImU32 material_colour(const Theme& theme, const std::string& material, int index) {
  const bool dark = theme.name == ThemeName::dark;
  struct Look {
    const char* name;
    ImU32 light, dark;
  };
  static const Look looks[] = {
      {"wood", IM_COL32(196, 150, 98, 255), IM_COL32(150, 110, 70, 255)},
      {"aluminium", IM_COL32(190, 198, 208, 255), IM_COL32(150, 160, 172, 255)},
      {"metal", IM_COL32(150, 158, 170, 255), IM_COL32(120, 128, 140, 255)},
      {"plastic", IM_COL32(120, 190, 230, 255), IM_COL32(70, 140, 190, 255)},
      {"rubber", IM_COL32(70, 70, 76, 255), IM_COL32(110, 110, 118, 255)},
      {"ice", IM_COL32(205, 235, 250, 255), IM_COL32(140, 185, 210, 255)},
      {"concrete", IM_COL32(170, 170, 165, 255), IM_COL32(120, 120, 116, 255)},
      {"stone", IM_COL32(160, 150, 140, 255), IM_COL32(115, 108, 100, 255)},
      {"asphalt", IM_COL32(90, 92, 96, 255), IM_COL32(80, 82, 86, 255)},
      {"grass", IM_COL32(120, 180, 90, 255), IM_COL32(70, 130, 60, 255)},
  };
  for (const Look& look : looks) {
    if (material == look.name) return dark ? look.dark : look.light;
  }
  // Tan, then slate: a lesson's first two materials (a crate and its floor, say) look like them.
  static const ImU32 light_palette[] = {IM_COL32(230, 180, 90, 255), IM_COL32(160, 168, 182, 255),
                                        IM_COL32(220, 140, 160, 255), IM_COL32(160, 150, 220, 255),
                                        IM_COL32(120, 200, 200, 255), IM_COL32(210, 200, 120, 255)};
  static const ImU32 dark_palette[] = {IM_COL32(180, 130, 50, 255), IM_COL32(105, 112, 128, 255),
                                       IM_COL32(170, 90, 110, 255), IM_COL32(110, 100, 170, 255),
                                       IM_COL32(70, 150, 150, 255), IM_COL32(160, 150, 70, 255)};
  const int slot = (index < 0 ? 0 : index) % 6;
  return dark ? dark_palette[slot] : light_palette[slot];
}

float frame_scale(int width, int height) {
  return std::min(static_cast<float>(height) / 720.0f, static_cast<float>(width) / 1280.0f);
}

std::string font_path() { return FRICTIONLAB_FONT_DIR "/DejaVuSans.ttf"; }

Fonts load_fonts(float scale, ImVector<ImWchar>& ranges) {
  const std::string path = font_path();
  if (!std::filesystem::exists(path)) {
    throw std::runtime_error(path + " is missing; install Debian's fonts-dejavu-core (scripts/setup.sh does)");
  }
  ImGuiIO& io = ImGui::GetIO();
  ImFontGlyphRangesBuilder builder;
  builder.AddRanges(io.Fonts->GetGlyphRangesDefault());  // Latin-1: °, ², ·, ±, µ
  static const ImWchar extra[] = {
      0x0370, 0x03FF,  // Greek: μ, θ, Δ, ε
      0x2010, 0x2027,  // dashes, bullet, ellipsis
      0x2070, 0x209F,  // superscripts and subscripts
      0x2190, 0x21FF,  // arrows
      0x2212, 0x2212,  // minus
      0x2248, 0x2248,  // almost equal
      0x2260, 0x2265,  // not equal, less or equal, greater or equal
      0x2713, 0x2717,  // check and cross marks
      0,
  };
  builder.AddRanges(extra);
  ranges.clear();
  builder.BuildRanges(&ranges);
  ImFontConfig config;
  config.OversampleH = 2;
  config.OversampleV = 1;
  Fonts fonts;
  fonts.scale = scale;
  fonts.body = io.Fonts->AddFontFromFileTTF(path.c_str(), body_text_points * scale, &config, ranges.Data);
  fonts.title = io.Fonts->AddFontFromFileTTF(path.c_str(), 26.0f * scale, &config, ranges.Data);
  fonts.small = io.Fonts->AddFontFromFileTTF(path.c_str(), small_text_points * scale, &config, ranges.Data);
  if (fonts.body == nullptr || fonts.title == nullptr || fonts.small == nullptr) {
    throw std::runtime_error(path + " could not be read as a TrueType font");
  }
  if (!io.Fonts->Build()) throw std::runtime_error("the font atlas could not be built from " + path);
  return fonts;
}

void apply_imgui_style(ThemeName name, float scale) {
  const Theme& t = theme(name);
  ImGuiStyle style;
  if (name == ThemeName::light) {
    ImGui::StyleColorsLight(&style);
  } else {
    ImGui::StyleColorsDark(&style);
  }
  style.WindowRounding = 4.0f;
  style.WindowBorderSize = 1.0f;
  style.WindowPadding = ImVec2(10, 6);
  style.ItemSpacing = ImVec2(8, 3);
  style.CellPadding = ImVec2(6, 1);
  style.Colors[ImGuiCol_Text] = t.imgui_text;
  style.Colors[ImGuiCol_WindowBg] = t.imgui_window;
  style.Colors[ImGuiCol_TitleBg] = t.imgui_title;
  style.Colors[ImGuiCol_TitleBgActive] = t.imgui_title;
  style.Colors[ImGuiCol_TitleBgCollapsed] = t.imgui_title;
  style.Colors[ImGuiCol_Border] = t.imgui_border;
  style.Colors[ImGuiCol_TableHeaderBg] = t.imgui_header;
  // Menus and other popups opaque: ImGui's own are slightly see-through (94 %, 98 %), and on a
  // projector the title and panels behind an open menu showed through its items.
  style.Colors[ImGuiCol_PopupBg].w = 1.0f;
  style.Colors[ImGuiCol_MenuBarBg].w = 1.0f;
  // Every text 4.5:1 from what lies under it (WCAG 2.1 AA), on a projector too. ImGui's own
  // greyed text read 2.85:1 on white and 3.9:1 on the dark panels ("measured: …", the status
  // line): the theme's faint text reads 4.6:1 or more on every panel, menu bar and frame.
  style.Colors[ImGuiCol_TextDisabled] = ImGui::ColorConvertU32ToFloat4(t.faint_text);
  // A greyed control (the first plot page's ←) fades to 70 %, not ImGui's 60 %: still plainly
  // off, and its label still 4.5:1 from its button.
  style.DisabledAlpha = 0.7f;
  if (name == ThemeName::light) {
    // Sliders and boxes stand out from the white panels (ImGui's light frames are white too).
    style.Colors[ImGuiCol_FrameBg] = ImVec4(0.89f, 0.90f, 0.93f, 1.0f);
    style.Colors[ImGuiCol_FrameBgHovered] = ImVec4(0.82f, 0.86f, 0.93f, 1.0f);
    style.Colors[ImGuiCol_FrameBgActive] = ImVec4(0.76f, 0.82f, 0.93f, 1.0f);
  } else {
    // A slider's value is written over its knob: ImGui's knob blue under the light text read
    // 3.2:1; this deeper blue reads 4.8:1.
    style.Colors[ImGuiCol_SliderGrab] = ImVec4(0.18f, 0.40f, 0.72f, 1.0f);
    style.Colors[ImGuiCol_SliderGrabActive] = ImVec4(0.15f, 0.35f, 0.66f, 1.0f);
    // The same under the pointer: a hovered tab, button or row in ImGui's bright blue read
    // 3.45:1 behind its light label (the tab just clicked stays hovered).
    const ImVec4 hovered(0.18f, 0.40f, 0.72f, 1.0f), pressed(0.15f, 0.35f, 0.66f, 1.0f);
    style.Colors[ImGuiCol_TabHovered] = hovered;
    style.Colors[ImGuiCol_ButtonHovered] = hovered;
    style.Colors[ImGuiCol_HeaderHovered] = hovered;
    style.Colors[ImGuiCol_ButtonActive] = pressed;
    style.Colors[ImGuiCol_HeaderActive] = pressed;
  }
  style.ScaleAllSizes(scale);
  ImGui::GetStyle() = style;
}

}  // namespace frictionlab::draw
