#include "lessons/runtime/model_card.h"

namespace frictionlab::lessons {

ModelCard model_card(const Lesson& lesson) {
  ModelCard card;
  const Scene& scene = lesson.scene();
  for (const auto& [name, body] : scene.bodies()) {
    if (body->GetType() != b2_dynamicBody) continue;
    ++card.moving_bodies;
    card.degrees_of_freedom += body->IsFixedRotation() ? 2 : 3;
  }
  for (const b2Joint* joint = scene.world().GetJointList(); joint != nullptr; joint = joint->GetNext()) {
    switch (joint->GetType()) {
      case e_pulleyJoint:
      case e_distanceJoint: card.constraints += 1; break;
      case e_revoluteJoint:
      case e_prismaticJoint:
      case e_wheelJoint: card.constraints += 2; break;
      case e_weldJoint: card.constraints += 3; break;
      default: break;  // mouse, motor, friction and rope joints hold nothing exactly
    }
  }
  card.degrees_of_freedom -= card.constraints;
  for (const Parameter& parameter : lesson.parameters()) {
    if (parameter.coefficient.empty() || parameter.value <= 0.0) continue;
    if (parameter.coefficient == "mu_s" || parameter.coefficient == "mu_k") card.dry = true;
    if (parameter.coefficient == "c") card.viscous = true;
    if (parameter.coefficient == "b") card.quadratic = true;
  }
  const StepSettings& settings = scene.settings();
  card.treatment = std::string(treatment_name(settings.treatment));
  card.hz = settings.hz;
  card.substeps = settings.substeps;
  card.velocity_iterations = settings.velocity_iterations;
  return card;
}

}  // namespace frictionlab::lessons
