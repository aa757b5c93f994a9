// A script's mistakes as the class sees them: the messages panel over the world's ground (a
// script that failed to build, a reload that failed, a run that stopped, each with Lua's message
// in plain words when it is a common one), the script named on the command line that failed and
// is watched until it builds, and the script's paths as the page names them.
#pragma once

#include <imgui.h>

#include <string>

#include "classroom/control_places.h"
#include "classroom_state/playback.h"
#include "draw/theme.h"

namespace frictionlab::classroom {

// A text as the class sees it: with `paths` off (the page), every script's path in it
// ("path:line: ...", "Reloaded path.") is its file's name alone.
struct ScriptWords {
  bool paths = true;
  std::string operator()(const std::string& text) const;
};

// A script named on the command line that does not build yet: shown beside the lesson running
// in its place, and looked at a few times a second until it builds.
struct FailedScript {
  std::string path;  // "" when none
  std::string error;
  classroom_state::FileStamp stamp;   // the file as it was when it last failed
  double since_check = 0.0;

  // The wall time since the last look: true when it is time to try the script again (its file
  // changed since it failed).
  bool changed(double wall_seconds);
};

// The messages panel in the world's lower left corner: nothing when all is well.
void messages_panel(ImVec2 corner, float width, const classroom_state::Playback& playback, const FailedScript& failed, bool browser,
                    const ScriptWords& words, const draw::Theme& colours, ControlPlaces& controls);

}  // namespace frictionlab::classroom
