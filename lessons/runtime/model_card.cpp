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
  // Scripts make one kind of tie, the rope over a pulley: taut, it ties the two ends' lengths
  // together, one degree of freedom (slack, none: the card counts the rope as the lesson made it).
  card.constraints += static_cast<int>(scene.ropes().size());
  card.degrees_of_freedom -= card.constraints;
  // The terms in use are those of the pairs that can rub in this scene, whether their values
  // came from sliders, from the presets or from the script (pair{ ..., sliders = false }).
  const PairTable& pairs = scene.pairs();
  for (int a = 0; a < pairs.material_count(); ++a) {
    for (int b = a; b < pairs.material_count(); ++b) {
      if (!pairs.has_pair(a, b) || !scene.can_touch(pairs.material(a).name, pairs.material(b).name)) continue;
      const FrictionPair& pair = pairs.pair(a, b);
      card.dry = card.dry || pair.mu_s > 0.0 || pair.mu_k > 0.0;
      card.viscous = card.viscous || pair.c > 0.0;
      card.quadratic = card.quadratic || pair.b > 0.0;
    }
  }
  const StepSettings& settings = scene.settings();
  card.treatment = std::string(treatment_name(settings.treatment));
  const PairTable& table = scene.pairs();
  for (int a = 0; a < table.material_count(); ++a) {
    for (int b = a; b < table.material_count(); ++b) {
      const std::string& name_a = table.material(a).name;
      const std::string& name_b = table.material(b).name;
      if (!table.has_pair(a, b) || !scene.can_touch(name_a, name_b)) continue;
      const FrictionTreatment treatment = scene.friction().treatment_of(a, b);
      card.pairs.push_back({name_a, name_b, std::string(treatment_name(treatment)), table.treatment(a, b).own,
                            uses_epsilon(treatment) ? scene.friction().epsilon_of(a, b) : 0.0});
    }
  }
  card.hz = settings.hz;
  card.substeps = settings.substeps;
  card.velocity_iterations = settings.velocity_iterations;
  return card;
}

}  // namespace frictionlab::lessons
