// The help panel (classroom/help_panel.h).
#include "classroom/help_panel.h"

#include <imgui.h>

#include <algorithm>
#include <filesystem>

#include "classroom/settings.h"
#include "classroom_state/window_keys.h"

namespace frictionlab::classroom {

float help_strip_height(bool shown) {
  if (!shown) return 0.0f;
  const ImGuiStyle& style = ImGui::GetStyle();
  const float title_bar = ImGui::GetFontSize() + 2.0f * style.FramePadding.y;
  // A row of the keys' table: a line and the cells' padding above and below it.
  const float row = ImGui::GetTextLineHeight() + 2.0f * style.CellPadding.y;
  return title_bar + 3.0f * row + 2.0f * style.WindowPadding.y;
}

void help_panel(bool& shown, bool browser, bool script_paths, const std::string& output_folder, ImVec2 corner,
                ImVec2 size) {
  if (!shown) return;
  // Docked: it keeps its strip, which the lesson's frame was laid out above. Its keys and words
  // scroll in it.
  ImGui::SetNextWindowPos(corner);
  ImGui::SetNextWindowSize(size);
  // Opaque, and square-cornered: a rounded window's title bar and body are each filled with an
  // anti-aliased fringe, and where the two fringes meet, one row of pixels is only partly
  // covered. Over the tabs it stands on, their words showed through that row as a band of
  // glyphs under the title (a projector trial). Square rectangles are filled edge to edge.
  ImGui::SetNextWindowBgAlpha(1.0f);
  ImGui::PushStyleVar(ImGuiStyleVar_WindowRounding, 0.0f);
  const bool open = ImGui::Begin("Help (F1 shows and hides it)", &shown,
                                 ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                                     ImGuiWindowFlags_NoSavedSettings);
  ImGui::PopStyleVar();
  if (open) {
    // The keys in pairs of columns across the strip's width (a key, then what it does), as many
    // pairs as leave each key's words about 28 letters' width, in the list's order a row at a
    // time: its three lines show the first keys, playing, stepping and resetting.
    const int pairs = std::clamp(static_cast<int>(ImGui::GetContentRegionAvail().x / (28.0f * ImGui::GetFontSize())), 1, 3);
    // The keys' columns as wide as their widest key, the words wrapped in what is left: at
    // projector size a column is narrower than its longest line (the trial saw "…and pla").
    if (ImGui::BeginTable("keys", 2 * pairs)) {
      for (int pair = 0; pair < pairs; ++pair) {
        ImGui::TableSetupColumn("key", ImGuiTableColumnFlags_WidthFixed);
        ImGui::TableSetupColumn("what it does", ImGuiTableColumnFlags_WidthStretch);
      }
      for (const classroom_state::WindowKey& row : classroom_state::window_keys()) {
        const std::string_view what = browser && !row.on_the_page.empty() ? row.on_the_page : row.does;
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(row.key.data(), row.key.data() + row.key.size());
        ImGui::TableNextColumn();
        ImGui::PushTextWrapPos(0.0f);
        ImGui::TextUnformatted(what.data(), what.data() + what.size());
        ImGui::PopTextWrapPos();
      }
      ImGui::EndTable();
    }
    ImGui::Separator();
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextUnformatted(
        "Mouse: drag a body to pull it with your hand through a force gauge (a spring scale): its reading in "
        "newtons is drawn beside it and plotted under the world. Pull slowly along a level floor: the peak is "
        "static friction (\u03bcs\u00b7m\u00b7g), the plateau while it slides kinetic friction (\u03bck\u00b7m\u00b7g); the "
        "theory table marks the run hand-pulled. Let go while it moves to give it a push. The wheel zooms, a "
        "drag on empty space pans, a double click there gives the lesson's view back. Drag a slider, or "
        "type an exact value in the box beside it and press Enter (Ctrl+click a slider that has no box); the "
        "round arrow resets it to the script's value. When the column is short a friction pair's sliders go two "
        "a row or fold into their heading: the arrow before the pair's name opens or folds them. "
        "Drag the time bar to go back through the run: it is replayed exactly, and playing on from there repeats it "
        "until you change something. The Mystery menu draws a pair's \u03bcs and \u03bck from a seed and hides them "
        "until revealed: the class measures them and types its answers in the Mystery tab.");
    ImGui::TextUnformatted(
        "Tools menu: a stopwatch on the lesson's clock (shown before the run, it starts with Play and stops when the "
        "run pauses or ends; W starts and stops it, L takes a lap; slow motion does not fool it, and R or the time "
        "bar takes it back with the run), distance marks along the floor or the slope from where the main body stood at t = 0, "
        "the main body's speed, and its weight split along and across a slope (m\u00b7g\u00b7sin \u03b8, "
        "m\u00b7g\u00b7cos \u03b8). They are this session's only: the next one opens with them off.");
    if (script_paths) {
      ImGui::TextUnformatted(("Files are saved in " + std::filesystem::absolute(output_folder).lexically_normal().string() +
                              ". Settings are kept in " + settings_folder() + ".")
                                 .c_str());
    } else {
      // The web page: its files are the browser's, not folders anyone opens.
      ImGui::TextUnformatted("Screenshots and exports arrive as downloads. Your lessons and these settings are kept in this "
                             "browser.");
    }
    ImGui::PopTextWrapPos();
  }
  ImGui::End();
}

}  // namespace frictionlab::classroom
