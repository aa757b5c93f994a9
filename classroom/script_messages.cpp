// A script's mistakes as the class sees them (classroom/script_messages.h).
#define IMGUI_DEFINE_MATH_OPERATORS
#include "classroom/script_messages.h"

#include <imgui_internal.h>

#include <cfloat>
#include <utility>
#include <vector>

#include "classroom/exports.h"
#include "classroom_state/plain_words.h"
#include "draw/text_record.h"
#include "draw/words.h"

namespace frictionlab::classroom {

std::string ScriptWords::operator()(const std::string& text) const {
  if (paths) return text;
  // Each path to a ".lua" file in the text is left as the file's name: "/a/b/my_push.lua:26: x"
  // reads "my_push.lua:26: x", "Reloaded /lessons/push.lua." reads "Reloaded push.lua.".
  std::string words;
  std::size_t from = 0;
  for (std::size_t end = text.find(".lua"); end != std::string::npos; end = text.find(".lua", end + 4)) {
    // The path's start: after the blank, quote or bracket before it.
    std::size_t start = text.find_last_of(" \n\t'\"(", end);
    start = start == std::string::npos || start < from ? from : start + 1;
    const std::size_t last_slash = text.rfind('/', end);
    if (last_slash == std::string::npos || last_slash < start) continue;
    words += text.substr(from, start - from);
    from = last_slash + 1;
  }
  return words + text.substr(from);
}

bool FailedScript::changed(double wall_seconds) {
  if (path.empty()) return false;
  since_check += wall_seconds;
  if (since_check < 0.25) return false;
  since_check = 0.0;
  const classroom_state::FileStamp now = classroom_state::file_stamp(path);
  if (now == stamp) return false;
  stamp = now;
  return true;
}

void messages_panel(ImVec2 corner, float width, const classroom_state::Playback& playback, const FailedScript& failed, bool browser,
                    const ScriptWords& words, const draw::Theme& colours, ControlPlaces& controls) {
  std::vector<std::pair<std::string, bool>> lines;  // text, is it a fault
  // A script's mistake, and under it Lua's message in plain words when it is a common one.
  const auto mistake = [&](const std::string& message, const std::string& then) {
    lines.push_back({words(message) + then, true});
    if (std::string plain = classroom_state::plain_words(message); !plain.empty()) lines.push_back({std::move(plain), false});
  };
  if (!failed.path.empty()) {
    mistake(failed.error, "  (showing " + lesson_name(playback.lesson().path()) + " until " + lesson_name(failed.path) + ".lua builds)");
  }
  if (!playback.script_error().empty()) mistake(playback.script_error(), "  (the last good version keeps running)");
  if (browser && playback.lesson().failed()) {
    // The page's editor is where the student mends it (the desktop's advice is to save the file).
    mistake(playback.lesson().last_error(), ". Mend it in the editor (Edit lesson) and Apply, or press R to start again.");
  } else if (!playback.problem().empty()) {
    mistake(playback.problem(), "");
  }
  if (lines.empty()) return;
  ImGui::SetNextWindowPos(corner, ImGuiCond_Always, ImVec2(0.0f, 1.0f));
  ImGui::SetNextWindowSizeConstraints(ImVec2(width, 0.0f), ImVec2(width, FLT_MAX));
  ImGui::SetNextWindowBgAlpha(0.92f);
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                                 ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
                                 ImGuiWindowFlags_NoMove;
  if (ImGui::Begin("###messages", nullptr, flags)) {
    ImGui::PushTextWrapPos(0.0f);
    // Broken between words here, so that ImGui's wrapping, which also breaks after a full
    // stop, never splits the script's name ("my_incline." and "lua").
    // (A pixel short of the region: ImGui wraps a line whose width reaches the wrap position,
    // not only one past it.)
    const float room = ImGui::GetContentRegionAvail().x - 1.0f;
    for (const auto& [text, fault] : lines) {
      ImGui::PushStyleColor(ImGuiCol_Text, fault ? colours.bad : ImGui::GetColorU32(ImGuiCol_Text));
      draw::shown_text(draw::broken_at_spaces(text, room).c_str());
      ImGui::PopStyleColor();
    }
    ImGui::PopTextWrapPos();
    controls["messages"] = ImRect(ImGui::GetWindowPos(), ImGui::GetWindowPos() + ImGui::GetWindowSize());
  }
  ImGui::End();
}

}  // namespace frictionlab::classroom
