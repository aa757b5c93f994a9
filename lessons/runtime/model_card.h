// What a lesson models, in the words of its model card: how many degrees of freedom, which
// friction terms are switched on, and how it is stepped. "Model no more than a scene needs":
// the card lets a teacher see that a lesson with c = 0 pays nothing for a viscous term.
#pragma once

#include <string>
#include <vector>

#include "lessons/runtime/lesson.h"

namespace frictionlab::lessons {

struct ModelCard {
  int moving_bodies = 0;       // dynamic bodies
  int constraints = 0;         // degrees of freedom the joints take away
  int degrees_of_freedom = 0;  // 3 per body (2 with fixed rotation) less the constraints
  bool dry = false;            // some pair has mu_s or mu_k above zero
  bool viscous = false;        // some pair has c above zero
  bool quadratic = false;      // some pair has b above zero
  std::string treatment;       // the run's: "stick-slip", ...
  // Each pair that can touch in the scene, with the treatment its contacts use (its own, or
  // the run's) and, for threshold and regularized, its epsilon in m/s.
  struct PairLine {
    std::string material_a, material_b;
    std::string treatment;
    bool own = false;     // named by the pair itself, not inherited from the run
    double epsilon = 0.0;  // m/s; 0 when the treatment has none
  };
  std::vector<PairLine> pairs;
  double hz = 0.0;
  int substeps = 1;
  int velocity_iterations = 8;
};
ModelCard model_card(const Lesson& lesson);

}  // namespace frictionlab::lessons
