#include "physics/scenarios.h"

#include <algorithm>
#include <cmath>

#include "physics/closed_forms.h"

namespace frictionlab {
namespace {

constexpr float ground_thickness = 1.0f;

// Flat ground whose top surface is the line y = 0.
void add_flat_ground(Scene& scene) {
  scene.add_box("ground", b2_staticBody, "ground", {0.0f, -0.5f * ground_thickness}, 400.0f, ground_thickness);
}

b2Body* add_block_on_flat_ground(Scene& scene, const Block& block, const std::string& name) {
  const float half_height = 0.5f * static_cast<float>(block.height);
  return scene.add_box(name, b2_dynamicBody, "block", {0.0f, half_height + resting_gap},
                       static_cast<float>(block.width), static_cast<float>(block.height));
}

// Runs the scene frame by frame until `until` says stop or the time is up.
template <typename Stop>
void run(Scene& scene, double duration, Stop until) {
  while (scene.time() < duration - 0.5 * scene.frame_step()) {
    scene.step();
    if (until()) return;
  }
}

}  // namespace

PairTable block_on_ground(const Block& block) {
  PairTable table;
  table.add_material({"block", block.mass / (block.width * block.height), "sized to give the block its mass"});
  table.add_material({"ground", 2000.0, "static, so its density does not matter"});
  table.set_pair("block", "ground", block.pair);
  return table;
}

std::unique_ptr<Scene> make_spring_pull(const SpringPull& setup, const StepSettings& settings) {
  auto scene = std::make_unique<Scene>(block_on_ground(setup.block), settings);
  add_flat_ground(*scene);
  b2Body* block = add_block_on_flat_ground(*scene, setup.block, "block");
  const b2Vec2 start = block->GetPosition();
  const double rest_length = setup.rest_length;
  const double pull_speed = setup.pull_speed;
  Spring spring;
  spring.name = "spring";
  spring.body = block;
  spring.hand = [start, rest_length, pull_speed](double t) {
    return b2Vec2{start.x + static_cast<float>(rest_length + pull_speed * t), start.y};
  };
  spring.stiffness = setup.stiffness;
  spring.rest_length = setup.rest_length;
  scene->add_spring(spring);
  Scene* s = scene.get();
  scene->add_probe("spring_force", [s] { return s->spring_force(s->springs().front()).x; });
  scene->add_probe("friction_force", [s, block] {
    const ContactRecord* contact = s->friction().find(block, s->body("ground"));
    return contact == nullptr ? 0.0 : static_cast<double>(contact->friction_on(block).x);
  });
  return scene;
}

OneDofBlock spring_pull_model(const SpringPull& setup) {
  OneDofBlock model;
  model.mass = setup.block.mass;
  model.normal_force = setup.block.mass * standard_gravity;
  model.pair = setup.block.pair;
  model.spring_k = setup.stiffness;
  model.anchor_start = setup.rest_length;
  model.pull_speed = setup.pull_speed;
  model.rest_length = setup.rest_length;
  return model;
}

std::unique_ptr<Scene> make_incline(const Incline& setup, const StepSettings& settings) {
  auto scene = std::make_unique<Scene>(block_on_ground(setup.block), settings);
  const float angle = static_cast<float>(setup.angle);
  const b2Vec2 normal{-std::sin(angle), std::cos(angle)};
  const b2Vec2 downhill{-std::cos(angle), -std::sin(angle)};
  // The slope's surface passes through the origin, rising to the right.
  scene->add_box("ground", b2_staticBody, "ground", -0.5f * ground_thickness * normal, 60.0f, ground_thickness, angle);
  const float lift = 0.5f * static_cast<float>(setup.block.height) + resting_gap;
  b2Body* block = scene->add_box("block", b2_dynamicBody, "block", lift * normal, static_cast<float>(setup.block.width),
                                 static_cast<float>(setup.block.height), angle);
  const b2Vec2 start = block->GetPosition();
  scene->add_probe("distance", [block, start, downhill] { return b2Dot(block->GetPosition() - start, downhill); });
  scene->add_probe("speed", [block, downhill] { return b2Dot(block->GetLinearVelocity(), downhill); });
  return scene;
}

std::unique_ptr<Scene> make_slide(const Slide& setup, const StepSettings& settings) {
  auto scene = std::make_unique<Scene>(block_on_ground(setup.block), settings);
  add_flat_ground(*scene);
  b2Body* block = add_block_on_flat_ground(*scene, setup.block, "block");
  block->SetLinearVelocity({static_cast<float>(setup.launch_speed), 0.0f});
  const float start = block->GetPosition().x;
  scene->add_probe("distance", [block, start] { return block->GetPosition().x - start; });
  return scene;
}

std::unique_ptr<Scene> make_pushed_box(const PushedBox& setup, const StepSettings& settings) {
  auto scene = std::make_unique<Scene>(block_on_ground(setup.block), settings);
  add_flat_ground(*scene);
  b2Body* box = add_block_on_flat_ground(*scene, setup.block, "box");
  const double rate = setup.push_rate;
  AppliedForce push;
  push.name = "push";
  push.body = box;
  // On the left side, push_height above the plane the box stands on. Box2D keeps the box's
  // face resting_gap above the ground's and its contact points midway between the two, so
  // that plane, the one the moments are taken about, is half the gap below the face.
  push.local_point = {-0.5f * static_cast<float>(setup.block.width),
                      static_cast<float>(setup.push_height - 0.5 * setup.block.height - 0.5 * resting_gap)};
  push.force = [rate](double t) { return b2Vec2{static_cast<float>(rate * t), 0.0f}; };
  scene->add_applied_force(push);
  // Sliding is measured at the front bottom corner, the pivot of a box that tips: its centre
  // moves forward as it tips, the pivot does not.
  const b2Vec2 corner{0.5f * static_cast<float>(setup.block.width), -0.5f * static_cast<float>(setup.block.height)};
  const float start = box->GetWorldPoint(corner).x;
  Scene* s = scene.get();
  scene->add_probe("push", [s, rate] { return rate * s->time(); });
  scene->add_probe("tilt", [box] { return -box->GetAngle(); });  // pushed right, it tips clockwise
  scene->add_probe("slide", [box, start, corner] { return box->GetWorldPoint(corner).x - start; });
  return scene;
}

StickSlipObservation observe_spring_pull(const SpringPull& setup, const StepSettings& settings, double duration) {
  const Trajectory exact = solve_exact(spring_pull_model(setup), duration);
  auto scene = make_spring_pull(setup, settings);
  b2Body* block = scene->body("block");
  const b2Body* ground = scene->body("ground");
  const float start = block->GetPosition().x;
  const std::vector<double>& spring_force = scene->probe("spring_force").history;
  StickSlipObservation seen;
  ContactState last = ContactState::sticking;
  run(*scene, duration, [&] {
    seen.max_error = std::max(seen.max_error, std::abs((block->GetPosition().x - start) - exact.position(scene->time())));
    const ContactRecord* contact = scene->friction().find(block, ground);
    const ContactState now = contact ? contact->friction.state : last;
    // The state changed during the step just taken; the spring force of that step is the
    // one that was acting when it did.
    const double force = spring_force.size() >= 2 ? spring_force[spring_force.size() - 2] : 0.0;
    if (last == ContactState::sticking && now == ContactState::slipping) {
      seen.breakaway_times.push_back(scene->time() - scene->frame_step());
      seen.breakaway_forces.push_back(force);
    } else if (last == ContactState::slipping && now == ContactState::sticking) {
      seen.restick_forces.push_back(force);
    }
    last = now;
    return false;
  });
  return seen;
}

double spring_pull_max_error(const SpringPull& setup, const StepSettings& settings, double duration) {
  return observe_spring_pull(setup, settings, duration).max_error;
}

std::vector<Measurement> spring_pull_measurements(const SpringPull& setup, const StepSettings& settings,
                                                  double duration) {
  const Block& b = setup.block;
  const theory::StickSlip expected =
      theory::spring_stick_slip(b.mass, setup.stiffness, setup.pull_speed, b.pair.mu_s, b.pair.mu_k, standard_gravity);
  const StickSlipObservation seen = observe_spring_pull(setup, settings, duration);
  auto mean = [](const std::vector<double>& values) {
    double sum = 0.0;
    for (double v : values) sum += v;
    return values.empty() ? NAN : sum / static_cast<double>(values.size());
  };
  const size_t n = seen.breakaway_times.size();
  const double period =
      n >= 2 ? (seen.breakaway_times[n - 1] - seen.breakaway_times[0]) / static_cast<double>(n - 1) : NAN;
  const double weight = b.mass * standard_gravity;
  return {
      {"stick-slip breakaway force", "N", expected.breakaway_force, mean(seen.breakaway_forces), 0.01 * weight * b.pair.mu_s},
      {"stick-slip re-stick force", "N", expected.restick_force, mean(seen.restick_forces), 0.02 * weight * b.pair.mu_s},
      {"stick-slip period", "s", expected.period, period, 0.01 * expected.period},
      {"stick-slip max position error", "m", 0.0, seen.max_error, 0.005},
  };
}

Measurement measure_incline_creep(const Incline& setup, const StepSettings& settings, double duration) {
  auto scene = make_incline(setup, settings);
  run(*scene, duration, [] { return false; });
  return {"creep below the sticking angle", "m", 0.0, scene->probe("distance").history.back(), 1e-4};
}

Measurement measure_incline_acceleration(const Incline& setup, const StepSettings& settings) {
  auto scene = make_incline(setup, settings);
  // Velocities, not positions: the first step still holds with mu_s, which shifts the
  // position by O(h) but leaves the later acceleration alone.
  const double early = 0.5, late = 2.0;
  double early_speed = 0.0;
  run(*scene, late, [&] {
    if (std::abs(scene->time() - early) < 0.5 * scene->frame_step()) early_speed = scene->probe("speed").history.back();
    return false;
  });
  const double measured = (scene->probe("speed").history.back() - early_speed) / (late - early);
  const double predicted = theory::incline_sliding_acceleration(setup.angle, setup.block.pair.mu_k, standard_gravity);
  return {"sliding acceleration", "m/s²", predicted, measured, 0.01 * std::abs(predicted)};
}

namespace {
// The static limit a pulled block must beat: mu_s, or mu_k where that is larger.
double breakaway_limit(const FrictionPair& pair) { return std::max(pair.mu_s, pair.mu_k); }

struct PulledBlock {
  double breakaway_force = NAN;
  double mean_sliding_friction = NAN;
};

// Pulls the block at its centre with a force growing at 0.5 N/s: slow enough that one step
// adds well under 0.1 % of the breakaway force at 240 Hz.
PulledBlock pull_block(const Block& block, const StepSettings& settings) {
  const double rate = 0.5;
  auto scene = std::make_unique<Scene>(block_on_ground(block), settings);
  add_flat_ground(*scene);
  b2Body* body = add_block_on_flat_ground(*scene, block, "block");
  scene->add_applied_force({"pull", body, {0.0f, 0.0f}, [rate](double t) {
                              return b2Vec2{static_cast<float>(rate * t), 0.0f};
                            }});
  const b2Body* ground = scene->body("ground");
  PulledBlock result;
  // The sliding friction is read from the motion, not from the solver's clamp (which holds
  // it at mu_k·N by construction): over one second of sliding, friction = mean pull - m·Δv/Δt.
  double pull_sum = 0.0;
  double start_speed = 0.0;
  int sliding_frames = 0;
  const double limit = 4.0 * breakaway_limit(block.pair) * block.mass * standard_gravity / rate;
  run(*scene, limit, [&] {
    const ContactRecord* contact = scene->friction().find(body, ground);
    if (contact == nullptr) return false;
    const double pull = rate * (scene->time() - scene->frame_step());  // what acted in this frame
    if (std::isnan(result.breakaway_force)) {
      if (contact->friction.state == ContactState::slipping) {
        result.breakaway_force = pull;
        start_speed = body->GetLinearVelocity().x;
      }
      return false;
    }
    pull_sum += pull;
    ++sliding_frames;
    if (sliding_frames < static_cast<int>(settings.hz)) return false;
    const double duration = sliding_frames * scene->frame_step();
    const double speed_gain = body->GetLinearVelocity().x - start_speed;
    result.mean_sliding_friction = pull_sum / sliding_frames - block.mass * speed_gain / duration;
    return true;
  });
  return result;
}
}  // namespace

Measurement measure_breakaway_force(const Block& block, const StepSettings& settings) {
  const double predicted = breakaway_limit(block.pair) * block.mass * standard_gravity;
  return {"breakaway force", "N", predicted, pull_block(block, settings).breakaway_force, 0.01 * predicted};
}

Measurement measure_sliding_friction(const Block& block, const StepSettings& settings) {
  const double predicted = block.pair.mu_k * block.mass * standard_gravity;
  return {"sliding friction", "N", predicted, pull_block(block, settings).mean_sliding_friction, 0.01 * predicted};
}

Measurement measure_slide_distance(const Slide& setup, const StepSettings& settings) {
  auto scene = make_slide(setup, settings);
  b2Body* block = scene->body("block");
  const theory::SlideToRest expected =
      theory::slide_to_rest(setup.launch_speed, setup.block.mass, setup.block.pair, standard_gravity);
  const double duration = std::isfinite(expected.time) ? 2.0 * expected.time + 1.0 : 30.0;
  int resting_frames = 0;
  run(*scene, duration, [&] {
    resting_frames = block->GetLinearVelocity().Length() < 1e-6f ? resting_frames + 1 : 0;
    return resting_frames > 10;
  });
  return {"slide-to-rest distance", "m", expected.distance, scene->probe("distance").history.back(),
          0.01 * expected.distance};
}

PushResult run_pushed_box(const PushedBox& setup, const StepSettings& settings, double duration) {
  auto scene = make_pushed_box(setup, settings);
  const b2Body* box = scene->body("box");
  const b2Body* ground = scene->body("ground");
  PushResult result;
  double back_before = NAN;  // the back edge's load at the step before, N
  run(*scene, duration, [&] {
    // The push applied during the step just taken (it is set at the step's start).
    const double push = setup.push_rate * (scene->time() - scene->frame_step());
    const ContactRecord* contact = scene->friction().find(box, ground);
    if (contact != nullptr && contact->friction.state == ContactState::slipping) {
      result.tipped = false;
      result.force = push;
      return true;
    }
    // Tipping starts when the back edge stops carrying any of the weight: where its load,
    // falling in a straight line with the push, reaches zero between two steps.
    const double back = contact == nullptr || contact->solver.point_count < 2
                            ? 0.0
                            : std::min(contact->solver.point_normal_force[0], contact->solver.point_normal_force[1]);
    const double total =
        contact == nullptr ? 0.0 : contact->solver.point_normal_force[0] + contact->solver.point_normal_force[1];
    if (back > 1e-9 * total) {
      back_before = back;
      return false;
    }
    result.tipped = true;
    const double step_push = setup.push_rate * scene->frame_step();
    const double fraction = std::isfinite(back_before) ? back_before / (back_before - back) : 1.0;
    result.force = push - step_push + fraction * step_push;
    return true;
  });
  return result;
}

Pyramid make_pyramid(int rows, bool use_listener, const StepSettings& settings) {
  Pyramid pyramid;
  const float size = 1.0f;
  const float gap = resting_gap;
  b2PolygonShape box;
  box.SetAsBox(0.5f * size, 0.5f * size);
  const float ground_width = 1.2f * size * static_cast<float>(rows) + 20.0f;
  b2PolygonShape ground_box;
  ground_box.SetAsBox(0.5f * ground_width, 0.5f);

  auto place = [&](auto&& add_ground, auto&& add_box) {
    add_ground();
    for (int row = 0; row < rows; ++row) {
      const int count = rows - row;
      const float left = -0.5f * size * static_cast<float>(count - 1) * 1.05f;
      for (int i = 0; i < count; ++i) {
        add_box(b2Vec2{left + static_cast<float>(i) * 1.05f * size,
                       0.5f * size + gap + static_cast<float>(row) * (size + gap)});
        ++pyramid.boxes;
      }
    }
  };

  if (use_listener) {
    PairTable table;
    table.add_material({"box", 1.0, ""});
    table.add_material({"ground", 1.0, ""});
    table.set_pair("box", "box", {0.6, 0.4, 0.0, 0.0});
    table.set_pair("box", "ground", {0.6, 0.4, 0.0, 0.0});
    pyramid.scene = std::make_unique<Scene>(std::move(table), settings);
    Scene& scene = *pyramid.scene;
    int index = 0;
    place([&] { scene.add_box("ground", b2_staticBody, "ground", {0.0f, -0.5f}, ground_width, 1.0f); },
          [&](b2Vec2 p) { scene.add_box("box" + std::to_string(index++), b2_dynamicBody, "box", p, size, size); });
  } else {
    pyramid.plain = std::make_unique<b2World>(b2Vec2{0.0f, -9.81f});
    b2World& world = *pyramid.plain;
    world.SetAllowSleeping(false);
    world.SetContinuousPhysics(false);
    place(
        [&] {
          b2BodyDef definition;
          definition.position = {0.0f, -0.5f};
          world.CreateBody(&definition)->CreateFixture(&ground_box, 0.0f)->SetFriction(0.6f);
        },
        [&](b2Vec2 p) {
          b2BodyDef definition;
          definition.type = b2_dynamicBody;
          definition.position = p;
          world.CreateBody(&definition)->CreateFixture(&box, 1.0f)->SetFriction(0.6f);
        });
  }
  return pyramid;
}

}  // namespace frictionlab
