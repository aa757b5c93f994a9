// The Simulation menu: the friction treatment, the step rate and the sub-steps per step, each
// greyed where the teacher's lock keeps it, and a reset to t = 0. It draws itself and says what
// was chosen; the classroom applies it to the running lesson.
#pragma once

#include <optional>

#include "classroom/control_places.h"
#include "classroom/lesson_lock.h"
#include "physics/scene.h"

namespace frictionlab::classroom {

struct SimulationChoice {
  std::optional<StepSettings> settings;  // other step settings chosen
  bool reset = false;                    // Reset to t = 0 chosen
};

// The menu in the menu bar being drawn, for a lesson stepping with `settings`.
SimulationChoice simulation_menu(const StepSettings& settings, const LessonLock& lock, ControlPlaces& controls);

}  // namespace frictionlab::classroom
