// The Parameters panel: each parameter the class may change as a slider with a box for a typed
// value and a reset, a friction pair's rows under a heading with its material presets. When the
// column is short it gives way in steps (pairs two a row, then folded into their headings, then
// the whole panel folded, when the class's answers need its room, from the lesson's opening on).
//
// It keeps its own state (which pairs the teacher opened or folded, the slider held, the values
// asked for and why one was refused) and draws itself, as each of Dear ImGui's demo windows
// does: the classroom holds one, hands the frame its heights and draw(), and sets the values it
// asked for once the frame is drawn (a rebuild replaces what the panel was reading).
#pragma once

#include <imgui.h>

#include <map>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "classroom/control_places.h"
#include "classroom_state/mystery.h"
#include "draw/panels.h"
#include "draw/theme.h"
#include "lessons/runtime/lesson.h"

namespace frictionlab::classroom {

// Whether a control is shown under the teacher's lock (none: every control).
inline bool unlocked(const std::set<std::string>& lock, const std::string& control_name) {
  return lock.empty() || lock.count(control_name) > 0;
}

// A control's name as its row says it: "μs static" for a pair's coefficient, the parameter's
// own name in words otherwise ("push height" for push_height).
std::string control_label(const lessons::Parameter& parameter);

// What a refused value's message says, with the control named as its row names it: the lesson's
// "push_height = 5 m is outside…" read to a class whose slider says "push height".
std::string refusal_in_class_words(const lessons::Parameter& parameter, const std::string& error);

// The lesson as the panel shows it this frame.
struct ParametersOnShow {
  const lessons::Lesson& lesson;
  const std::set<std::string>& lock;       // the controls the teacher chose; empty: all of them
  const std::optional<classroom_state::Mystery>& mystery;   // its pair has no slider, box, reset or presets
  draw::HiddenValues hidden;                     // what the class must not see now
  // The class's predictions are asked: their answers may take the panel's room. The same from
  // the lesson's opening to the run's end and after R, so that the panel never folds because a
  // run ended (the trial's tabs jumped up under the teacher's pointer as it did).
  bool answers_asked = false;
};

struct ParametersPanel {
  std::map<std::string, bool> pair_open;  // friction pairs the teacher opened (true) or folded (false)
  bool opened = false;  // the teacher opened the panel folded for the class's answers, for this lesson
  std::optional<std::pair<std::string, double>> sliding;  // a slider that rebuilds on release
  // Values asked for during this frame: a slider's, a preset's, a reset's, a choice's as numbers
  // (never written out and read back), a typed one as its text.
  std::vector<std::pair<std::string, lessons::GivenValue>> asked;
  // A refused value's message, by the parameter's name: said under its row, over the rows below,
  // until the teacher's next click or a value taken.
  std::map<std::string, std::string> errors;

  // Another lesson: nothing opened, folded, held or refused in the one before.
  void forget();
  // The panel's height at each step of giving way (FrameStyle::parameters_heights), in the current font.
  std::vector<float> heights(const ParametersOnShow& on_show) const;
  // The last step that leaves sliders in sight (every pair folded into its heading), before the
  // whole panel folds away (FrameStyle::parameters_step_for_the_theory).
  std::size_t last_step_with_sliders(const ParametersOnShow& on_show) const {
    return foldable_pairs(on_show, true).size() + foldable_pairs(on_show, false).size();
  }
  // The panel at `step` of giving way; `scale` is the fonts' scale.
  void draw(ImVec2 corner, ImVec2 size, std::size_t step, const ParametersOnShow& on_show, float scale,
            const draw::Theme& colours, ControlPlaces& controls);

 private:
  // The panel's rows: each parameter shown, and whether a friction pair's heading (with its
  // presets) comes before it. The panel draws them; its height is counted from them.
  // Friction pairs give way to a short column in steps: step k (up to the number of pairs the
  // teacher has not folded) puts the last k pairs' coefficients two a row; each step beyond
  // folds one more pair the teacher has not opened, the last first, into its heading with its
  // values.
  struct Row {
    const lessons::Parameter* parameter;
    const lessons::Parameter* partner;  // the second coefficient on a row of two
    bool pair_heading, folded, two_a_row;
  };
  // The pairs shown that the teacher has not folded (opened_too) or neither opened nor folded.
  std::vector<std::string> foldable_pairs(const ParametersOnShow& on_show, bool opened_too) const;
  std::vector<Row> rows_at(const ParametersOnShow& on_show, std::size_t step) const;
  // While the class's predictions are asked, the whole panel may fold into a heading, the last
  // step of giving way (taken when the answers fit beside no other), which a click opens again
  // for the rest of the lesson.
  bool may_fold_away(const ParametersOnShow& on_show) const;
  std::size_t folded_away_step(const ParametersOnShow& on_show) const;  // the step that folds it, when it may
  void draw_folded_away(ImVec2 corner, ImVec2 size, const ParametersOnShow& on_show, ControlPlaces& controls);
  // One control: its label from `label_x` (0: the row's start), its slider, a box for a typed
  // value (none when value_x is reset_x) and its reset.
  void parameter_row(const lessons::Parameter& parameter, const std::string& label, float label_x, float slider_x,
                     float value_x, float reset_x, const ParametersOnShow& on_show, ControlPlaces& controls);
  // parameter_row's parts, each at the place and width set before it: a choice's list, a
  // number's slider (a structural one asks once let go), the box for a typed value, the reset.
  void choice_list(const lessons::Parameter& parameter, ControlPlaces& controls);
  void value_slider(const lessons::Parameter& parameter, ControlPlaces& controls);
  void typed_value(const lessons::Parameter& parameter, ControlPlaces& controls);
  void reset_button(const lessons::Parameter& parameter, ControlPlaces& controls);
  void preset_row(const lessons::Parameter& mu_s, const ParametersOnShow& on_show, ControlPlaces& controls);
  // The refused values' messages in a panel of their own from `corner` (its top left) down, over
  // whatever is there: no panel gives way for them.
  void say_refusals(ImVec2 corner, float width, const draw::Theme& colours) const;
};

}  // namespace frictionlab::classroom
