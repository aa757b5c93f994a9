#include "classroom_state/gauge_record.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace frictionlab::classroom_state {

void GaugeRecord::after_step(const Scene& scene) {
  const b2Body* body = scene.grabbed();
  if (body == nullptr || scene.forces_applied().empty()) return;
  // The hand is always the scene's last applied force.
  const b2Vec2 hand = scene.forces_applied().back();
  bool lesson_pulls = false;
  const auto name_pull = [&](const std::string& name, b2Vec2 force) {
    if (force.LengthSquared() == 0.0f) return;
    lesson_pulls = true;
    if (lesson_pulls_.find(name) != std::string::npos) return;
    lesson_pulls_ += (lesson_pulls_.empty() ? "" : " and ") + name;
  };
  for (std::size_t i = 0; i + 1 < scene.applied_forces().size(); ++i) {
    if (scene.applied_forces()[i].body == body) name_pull(scene.applied_forces()[i].name, scene.forces_applied()[i]);
  }
  for (std::size_t i = 0; i < scene.springs().size(); ++i) {
    const Spring& spring = scene.springs()[i];
    if (spring.body == body || spring.other == body) name_pull(spring.name, scene.spring_forces_applied()[i]);
  }
  // Every pull on the body as the step applied it, the hand's among them: what friction answers
  // while the body sticks.
  b2Vec2 total{0.0f, 0.0f};
  for (const ForceOnBody& force : forces_on(scene, body)) {
    if (force.kind == ForceKind::tension) name_pull("rope", force.force);
    if (force.kind == ForceKind::applied || force.kind == ForceKind::spring || force.kind == ForceKind::tension) {
      total += force.force;
    }
  }
  // Along the surface it stands on; off any, along the hand's pull.
  b2Vec2 along = hand;
  if (const std::optional<Surface> surface = surface_under(scene, body)) along = surface->along;
  const float size = along.Normalize();
  const double pull = size > 0.0f ? static_cast<double>(b2Dot(total, along)) : static_cast<double>(total.Length());
  const b2Vec2 velocity = body->GetLinearVelocity();
  const double momentum = static_cast<double>(body->GetMass()) *
                          (size > 0.0f ? static_cast<double>(b2Dot(velocity, along)) : static_cast<double>(velocity.Length()));
  samples_.push_back({scene.frame(), scene.time(), static_cast<double>(hand.Length()), pull, lesson_pulls,
                      !scene.slipping().empty() && scene.slipping().back() != 0, momentum});
}

std::vector<HandStretch> GaugeRecord::stretches(double frame_step) const {
  std::vector<HandStretch> found;
  for (std::size_t i = 0; i < samples_.size(); ++i) {
    const bool continues = i > 0 && samples_[i].frame == samples_[i - 1].frame + 1;
    if (!continues) found.push_back({samples_[i].t - frame_step, samples_[i].t});
    found.back().to = samples_[i].t;
  }
  return found;
}

std::size_t GaugeRecord::latest_stretch_start() const {
  // Back from the last sample while the frames run on without a gap.
  std::size_t first = samples_.empty() ? 0 : samples_.size() - 1;
  while (first > 0 && samples_[first].frame == samples_[first - 1].frame + 1) --first;
  return first;
}

std::optional<GaugeFigures> GaugeRecord::figures(double frame_step) const {
  if (samples_.empty()) return std::nullopt;
  const std::size_t first = latest_stretch_start();
  GaugeFigures figures;
  bool lesson_pulled = false;
  for (std::size_t i = first; i < samples_.size(); ++i) lesson_pulled = lesson_pulled || samples_[i].lesson_pulls;
  // The gauge alone when the hand pulled alone: the pull along the surface then differs from it
  // only by a slant the hand gave it.
  const auto pull = [&](const GaugeSample& sample) { return lesson_pulled ? std::abs(sample.pull) : sample.force; };
  if (lesson_pulled) figures.lesson_pulls = lesson_pulls_;
  // The first step that held (a body taken while sliding may come to rest and break away
  // later), and the step it broke away in: the first after that one to end slipping.
  std::size_t held = first;
  while (held < samples_.size() && samples_[held].slipping) ++held;
  std::size_t end = samples_.size();
  for (std::size_t i = held; i < samples_.size(); ++i) {
    if (samples_[i].slipping) {
      end = i + 1;
      figures.broke_away = true;
      break;
    }
  }
  if (held < samples_.size()) {
    for (std::size_t i = held; i < end; ++i) {
      if (!figures.peak || pull(samples_[i]) > *figures.peak) {
        figures.peak = pull(samples_[i]);
        figures.peak_time = samples_[i].t;
      }
    }
  }
  // Sliding from the start of the stretch: the plateau counts from there.
  const double slid_from = figures.peak ? figures.peak_time : samples_[first].t;
  double sum = 0.0;
  long count = 0;
  for (std::size_t i = first + 1; i < samples_.size(); ++i) {
    const GaugeSample& sample = samples_[i];
    if (sample.t < slid_from + settle_time - 0.5 * frame_step || !sample.slipping) continue;
    const double net_force = (sample.momentum - samples_[i - 1].momentum) / frame_step;
    if (std::abs(net_force) > steady_share * pull(sample)) continue;
    if (count == 0) figures.plateau_from = sample.t;
    figures.plateau_to = sample.t;
    sum += pull(sample);
    ++count;
  }
  // A tenth of a second of steady sliding at least, or there is no plateau to speak of yet: its
  // steps counted, not the time from the first to the last (two steady steps of a swing a tenth
  // of a second apart are no plateau).
  if (count > 0 && static_cast<double>(count) * frame_step >= 0.1 - 0.5 * frame_step) {
    figures.plateau = sum / static_cast<double>(count);
  }
  return figures;
}

std::string stretches_text(const std::vector<HandStretch>& stretches) {
  std::string text;
  for (const HandStretch& stretch : stretches) {
    char line[64];
    std::snprintf(line, sizeof line, "%.2f\u2013%.2f s", std::max(0.0, stretch.from), stretch.to);
    text += (text.empty() ? "hand-pulled " : ", ") + std::string(line);
  }
  return text;
}

}  // namespace frictionlab::classroom_state
