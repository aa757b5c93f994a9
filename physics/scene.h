// A lesson's world: Box2D plus the friction listener, springs (with a moving hand), applied
// forces, bodies driven by functions of time, probes and the energy ledger.
// Stepping and drawing are separate: a scene knows nothing about pictures.
#pragma once

#include <box2d/box2d.h>

#include <array>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "physics/friction_listener.h"
#include "physics/materials.h"

namespace frictionlab {

struct StepSettings {
  double hz = 240.0;             // frames per simulated second, [1, 100000]
  int substeps = 1;              // world steps per frame, [1, 1000]
  int velocity_iterations = 8;   // [1, 1000]
  int position_iterations = 3;   // [0, 1000]
  FrictionTreatment treatment = FrictionTreatment::stick_slip;
  double threshold_speed = 0.01; // epsilon of the threshold and regularized treatments, m/s
  bool operator==(const StepSettings&) const = default;
};
// Throws InvalidInput naming the setting and its allowed range.
void validate(const StepSettings& settings);

using VectorOfTime = std::function<b2Vec2(double t)>;
// A driven body's path, in doubles: its velocity over a step is the difference of two points
// over the step, which float positions would leave with noise of an ulp over h (1.8e-4 m/s at
// 3000 Hz half a metre out, enough to set a resting block slipping).
using PointOfTime = std::function<std::array<double, 2>(double t)>;
using ScalarOfTime = std::function<double(double t)>;

// A driven coordinate's path given as numbers rather than as a script function, worked out in
// doubles without running any script: offset + speed·t + ½·acceleration·t² + swing·sin(omega·t
// + phase). A shaken table, a belt at a steady speed, a truck speeding up, a swinging plank.
struct Motion {
  double offset = 0.0, speed = 0.0, acceleration = 0.0;
  double swing = 0.0, omega = 0.0, phase = 0.0;  // amplitude, rad/s, rad
  double at(double t) const;
};

// A spring from a point on a body to either a point on another body or a hand that moves
// along `hand` (world coordinates, a function of time).
struct Spring {
  std::string name;
  b2Body* body = nullptr;
  b2Vec2 local_point{0.0f, 0.0f};
  b2Body* other = nullptr;          // null: the far end is the hand
  b2Vec2 other_local_point{0.0f, 0.0f};
  VectorOfTime hand;                // where the hand holds the far end at time t
  double stiffness = 0.0;           // k, N/m, > 0
  double rest_length = 0.0;         // m, >= 0
};

// A force on a body at a point fixed in the body, given in world axes as a function of time,
// and perhaps a torque about the body's centre of mass (N·m, counter-clockwise positive): a
// motor turning a wheel. Either may be left out (a force of zero, no torque).
struct AppliedForce {
  std::string name;
  b2Body* body = nullptr;
  b2Vec2 local_point{0.0f, 0.0f};
  VectorOfTime force;
  ScalarOfTime torque{};
};

// Energies in joules. The residual is what the books fail to explain: zero for an exact
// integrator, and small compared with `dissipated()` for a good one.
struct EnergyLedger {
  double kinetic = 0.0;
  double potential = 0.0;        // gravity, relative to the start
  double spring = 0.0;
  double work_applied = 0.0;     // applied forces and hands pulling springs
  double work_drivers = 0.0;     // kinematic bodies pushing through contacts
  double work_friction = 0.0;    // dry friction, <= 0
  double work_damping = 0.0;     // viscous and quadratic terms, <= 0
  double work_impacts = 0.0;     // collisions, <= 0
  double work_script = 0.0;      // kinetic energy given (> 0) or taken (< 0) by a script setting velocities
  double initial = 0.0;          // kinetic + spring at t = 0 (potential is counted from the start)
  double potential_reference = 0.0;  // gravity potential at t = 0, the zero of `potential`
  double dissipated() const { return -(work_friction + work_damping + work_impacts); }
  double residual() const {
    return kinetic + potential + spring - initial - work_applied - work_drivers - work_friction - work_damping -
           work_impacts - work_script;
  }
};

// A rope over a pulley tying two bodies: its two stretches, from each end to where it leaves the
// pulley, add up to at most `length`. A rope pulls and never pushes; Box2D's pulley joint holds
// the sum fixed both ways, as a rod would (the hanging weight that landed on the floor stopped
// the sliding block dead, and a hand pushing the block towards the pulley pressed the weight
// into the floor). So the scene lets the joint go in the step its impulse turns to a push,
// giving the ends back what that push did to their velocities (the rope goes slack), and ties
// it again when the ends move apart past the rope's length (taut again, with a rope's jerk).
struct Rope {
  std::string name;
  b2Body* body_a = nullptr;
  b2Body* body_b = nullptr;
  b2Vec2 local_a{0.0f, 0.0f}, local_b{0.0f, 0.0f};    // the ends, in the bodies' frames
  b2Vec2 pulley_a{0.0f, 0.0f}, pulley_b{0.0f, 0.0f};  // where each stretch leaves the pulley
  float length = 0.0f;                                 // both stretches when taut, m
  b2PulleyJoint* joint = nullptr;                      // null while slack
  float parting_before = 0.0f;  // m/s, how fast the ends drew apart as the last step began

  b2Vec2 end_a() const { return body_a->GetWorldPoint(local_a); }
  b2Vec2 end_b() const { return body_b->GetWorldPoint(local_b); }
  float stretches() const { return (end_a() - pulley_a).Length() + (end_b() - pulley_b).Length(); }
  bool taut() const { return joint != nullptr; }
};

struct Probe {
  std::string name;
  std::function<double()> measure;
  std::vector<double> history;   // one value per frame, beside Scene::times()
};

class Scene {
 public:
  explicit Scene(PairTable pairs, StepSettings settings = {}, b2Vec2 gravity = {0.0f, -9.81f});
  Scene(const Scene&) = delete;
  Scene& operator=(const Scene&) = delete;

  b2World& world() { return *world_; }
  const b2World& world() const { return *world_; }
  // Live edits of friction values take effect at the next step.
  PairTable& pairs() { return pairs_; }
  const PairTable& pairs() const { return pairs_; }
  const FrictionListener& friction() const { return listener_; }
  const StepSettings& settings() const { return settings_; }
  double frame_step() const { return 1.0 / settings_.hz; }
  // The contact solver's passes a step, for a scene whose contacts settle in fewer than the
  // default (a lesson says so: lesson{ velocity_iterations = 4 }). Throws InvalidInput naming
  // the range [1, 1000].
  void set_velocity_iterations(int count);

  // Bodies. Every fixture names its material; a material with no pair value for a material
  // already in the scene that it could touch (one of the two on a dynamic body) is rejected
  // here, not mid-step. Give a body its type before its fixtures.
  b2Body* add_body(const std::string& name, const b2BodyDef& definition);
  b2Fixture* add_fixture(b2Body* body, const b2Shape& shape, const std::string& material);
  // A box of the given size (m), centre and angle (rad): a convenience over the two above. Its
  // skin is Box2D's own unless given (a script's box: true_skin).
  b2Body* add_box(const std::string& name, b2BodyType type, const std::string& material, b2Vec2 center,
                  float width, float height, float angle = 0.0f, float skin = b2_polygonRadius);
  b2Body* body(const std::string& name) const;  // throws InvalidInput listing the known names
  std::string name_of(const b2Body* body) const;  // "(unnamed)" for a body the scene did not make
  // Whether bodies of these two materials are in the scene where they can rub: both in use,
  // one of them on a dynamic body (Box2D makes no contact between two fixed ones), and a
  // material with itself only on two bodies.
  bool can_touch(const std::string& material_a, const std::string& material_b) const;
  const std::vector<std::pair<std::string, b2Body*>>& bodies() const { return bodies_; }

  // Add the bodies' fixtures first: the spring is refused when it is too stiff for the step
  // given the mass it moves.
  void add_spring(const Spring& spring);
  // A rope over a pulley, taut as the bodies lie now (each end at least 5 cm from the pulley,
  // the script checks); returns its index in ropes().
  std::size_t add_rope(const std::string& name, b2Body* a, b2Vec2 end_a, b2Body* b, b2Vec2 end_b, b2Vec2 pulley_a,
                       b2Vec2 pulley_b);
  void add_applied_force(const AppliedForce& force);
  // A kinematic body follows position(t) and angle(t) exactly at every step.
  void drive(b2Body* body, PointOfTime position, ScalarOfTime angle);
  void add_probe(const std::string& name, std::function<double()> measure);
  // Runs after each frame, just before the probes sample: a script runtime measures all its
  // probes there in one go, and they then only hand over the values.
  void set_before_probes(std::function<void()> work) { before_probes_ = std::move(work); }
  // Called after every world step (each sub-step of a frame) with the time it reached: a
  // method that flips the velocity every sub-step shows nothing at frames of an even count.
  void set_after_substep(std::function<void(double t)> watch) { after_substep_ = std::move(watch); }
  // Called at the start of every (sub-)step with its start time, before anything is applied:
  // what a lesson changes as time goes on, such as a pair's coefficients given as functions of
  // time. The trial half step at t = 0 calls it too.
  void set_before_substep(std::function<void(double t)> prepare) { before_substep_ = std::move(prepare); }

  // One frame: 1/hz of simulated time in `substeps` world steps.
  void step();
  // Wakes every body the scene put to rest (see the private rest_resting_bodies()): a pair's
  // friction values changed under it, and a body held only by static friction may now slide.
  void wake();
  double time() const { return time_; }
  long frame() const { return frame_; }
  const std::vector<double>& times() const { return times_; }
  const std::vector<Probe>& probes() const { return probes_; }
  // One entry a frame, beside times(): 1 if some touching contact was slipping at the end of
  // that frame, else 0. Plots shade the slip regime with it.
  const std::vector<unsigned char>& slipping() const { return slipping_; }
  // One entry a frame, beside times(): 1 if some contact was touching at the end of that frame,
  // else 0 (every body in the air: a block thrown or lifted). Neither sticking nor slipping,
  // the plots colour such a frame as a regime of its own.
  const std::vector<unsigned char>& touching() const { return touching_record_; }
  const Probe& probe(const std::string& name) const;

  // Forces now, for probes and arrows: a spring's pull on its body, an applied force.
  b2Vec2 spring_force(const Spring& spring) const;
  const std::vector<Spring>& springs() const { return springs_; }
  const std::vector<Rope>& ropes() const { return ropes_; }
  // N: the pull the last world step's solver gave the rope (0 while it is slack).
  double rope_tension(std::size_t index) const;
  const std::vector<AppliedForce>& applied_forces() const { return applied_; }
  b2Vec2 hand_position(const Spring& spring) const;
  // The forces the last step applied, one per spring (on its body) and per applied force, in
  // the order added: what the contacts' recorded friction answered. Zero before the first step.
  const std::vector<b2Vec2>& spring_forces_applied() const { return spring_forces_applied_; }
  const std::vector<b2Vec2>& forces_applied() const { return forces_applied_; }
  // Each applied force's torque as the last step applied it (0 without one), N·m.
  const std::vector<double>& torques_applied() const { return torques_applied_; }

  const EnergyLedger& ledger() const { return ledger_; }

  // Whether a contact Box2D counts as touching still touches where its bodies are now. Box2D
  // finds that a contact ended only when it next collides the pair, at the start of the next
  // step; contact views ask here to say so in the step the bodies part. Worked out once per
  // contact and world step, when first asked.
  bool touching_now(b2Contact* contact) const;

  // A script setting a dynamic body's velocity between frames, as a game does. The kinetic
  // energy it gives or takes is booked as work_script, so the ledger still closes. Throws
  // InvalidInput for a body that is not dynamic or a velocity that is not finite within ±1e4 m/s
  // (the limits a body's starting velocity has), naming the body.
  void set_velocity(b2Body* body, b2Vec2 velocity);

  // A hand on a dynamic body, as the mouse gives it, pulling through a force gauge: a spring
  // scale from the grabbed point to the hand's end of it, which follows `target` (the mouse)
  // within grab_hand_lag s, so the jumps of a mouse read once a display frame become a steady
  // pull. The scale is stiff but finite (it swings at grab_gauge_hz with the body's mass on it,
  // or slower when the step is long, so the explicit pull stays stable: omega·h <= 0.5) and
  // damped against the body's velocity at grab_damping_ratio of critical; its pull is capped at 20·m·g. It is applied like
  // any applied force (drawn, its work counted in the ledger), so the gauge reads the force
  // actually applied. Releasing leaves the body its velocity: that is how a push is given.
  static constexpr double grab_gauge_hz = 1.5;
  // Just under critical: a body the hand brings to rest overshoots a little (4.6 % of its
  // speed), so its sliding stops and static friction takes hold, as under a real hand. Critically
  // damped, a sliding body crept towards the hand ever slower and never stopped: its contact
  // stayed slipping at 0.2 mm/s for as long as the hand held still (push's growing push).
  static constexpr double grab_damping_ratio = 0.7;
  static constexpr double grab_hand_lag = 0.08;  // s
  void grab(b2Body* body, b2Vec2 local_point, b2Vec2 target);
  void move_grab(b2Vec2 target);
  void release();
  b2Body* grabbed() const { return grab_ ? grab_->body : nullptr; }
  b2Vec2 grab_target() const { return grab_ ? grab_->target : b2Vec2{0.0f, 0.0f}; }
  // Where the hand holds the gauge's far end now (the grabbed point at the moment of grabbing).
  b2Vec2 grab_hand() const { return grab_ ? grab_->hand : b2Vec2{0.0f, 0.0f}; }
  // The gauge's stiffness for the body held, N/m (0 with no hand).
  double grab_stiffness() const;

 private:
  void tie(Rope& rope);
  // After each world step: a rope that pushed goes slack, a slack one pulled past its length is
  // tied; the work a taut rope did (a jerk's loss) goes into the ledger's impacts.
  void slacken_or_tie_ropes();
  struct Grab {
    b2Body* body;
    b2Vec2 target;
    b2Vec2 hand;  // the gauge's far end, following target
  };
  // The gauge's angular frequency with the body's mass on it, rad/s.
  double grab_omega() const;
  b2Vec2 grab_force(const AppliedForce& hand) const;
  struct Driver {
    b2Body* body;
    PointOfTime position;
    ScalarOfTime angle;
  };
  // One world step of length h from time t to t_end (t + h, given exactly in double). With
  // `move` false the bodies are put back where they were afterwards, and only their velocities advance.
  void advance(double t, float h, double t_end, bool move);
  // Before the first step: turns the velocities given at t = 0 into the half-step-earlier
  // velocities Box2D's integrator needs.
  void start(float h);
  // The material's id, once it has friction values with every material already in the scene.
  int check_material(const std::string& material, b2BodyType type) const;
  void check_new_name(const std::string& name) const;
  void check_placement(const std::string& name, b2Vec2 position, float angle) const;
  // "Model no more than a scene needs": a body that has come to rest on fixed bodies, every
  // contact stuck (stick-slip) and nothing but gravity acting on it, stays where it is: static
  // friction holds it and nothing changes. After rest_steps such frames in a row it is put to
  // sleep, and Box2D stops solving it (its contacts keep their last record, which is what they
  // would read: the load and the friction holding it) until something touches it, a script sets
  // its velocity, or wake() is called. Box2D's own sleeping (0.5 s below 1 cm/s) stays off:
  // it would also stop a body creeping under a regularized law or a drag's long tail.
  void rest_resting_bodies();
  bool at_rest(const b2Body* body, std::size_t index) const;
  void mechanical_energy(double* kinetic, double* potential, double* elastic) const;
  void update_ledger_state();

  PairTable pairs_;
  StepSettings settings_;
  b2Vec2 gravity_;
  FrictionListener listener_;
  std::unique_ptr<b2World> world_;
  std::vector<std::pair<std::string, b2Body*>> bodies_;
  struct Rest {
    b2Vec2 position{0.0f, 0.0f};  // where the body was at the end of the last frame
    float angle = 0.0f;
    int frames = 0;               // frames in a row it has been at rest
  };
  std::vector<Rest> rest_;        // beside bodies_
  std::vector<Spring> springs_;
  std::vector<Rope> ropes_;
  std::vector<AppliedForce> applied_;
  // Within a step: each applied force and torque with the velocity it started on, whose work
  // is booked once the step is over.
  struct Pending {
    b2Body* body;
    b2Vec2 local_point;
    b2Vec2 force;
    b2Vec2 start_velocity;
  };
  struct Turning {
    b2Body* body;
    double torque;
    double start_spin;
  };
  std::vector<Pending> pending_;
  std::vector<Turning> turning_;
  std::vector<b2Vec2> spring_forces_applied_;
  std::vector<b2Vec2> forces_applied_;
  std::vector<double> torques_applied_;
  std::vector<Driver> drivers_;
  std::vector<Probe> probes_;
  std::function<void()> before_probes_;
  std::function<void(double)> after_substep_;
  std::function<void(double)> before_substep_;
  std::vector<double> times_;
  std::vector<unsigned char> slipping_;
  std::vector<unsigned char> touching_record_;
  struct MaterialUse {
    int id;
    bool on_dynamic;  // some dynamic body is made of it
    int bodies = 0;   // how many bodies have a shape of it
    const b2Body* last_body = nullptr;  // the body its last shape was added to (a body's shapes come together)
  };
  std::vector<MaterialUse> materials_in_use_;
  std::unique_ptr<Grab> grab_;
  double time_ = 0.0;
  long frame_ = 0;
  bool ledger_started_ = false;
  EnergyLedger ledger_;
  long world_steps_ = 0;  // every world step, trial or not: what touching_now() remembers is for one
  mutable long touching_checked_at_ = -1;
  // What touching_now() found: whether the two fixtures' shapes touch at these transforms.
  // Box2D's answer depends on nothing else, so a pair that has not moved since the world step
  // before, bit for bit (a body at rest, put to sleep), is answered without colliding again.
  struct Touching {
    const b2Contact* contact;
    const b2Fixture* fixture_a;
    const b2Fixture* fixture_b;
    int child_a, child_b;  // which edge of a chain
    b2Transform transform_a, transform_b;
    bool touching;
  };
  mutable std::vector<Touching> touching_;         // this world step's answers
  mutable std::vector<Touching> touching_before_;  // those of the last world step that asked
};

// The gap Box2D keeps between the cores of two resting polygons: their skins (b2_polygonRadius
// each) overlap by b2_linearSlop. A body placed this far above a surface starts at rest on it.
// (For shapes Box2D is given directly; a script's shapes are built true to size, below.)
constexpr float resting_gap = 2.0f * b2_polygonRadius - b2_linearSlop;

// A script's shapes are built to the script's sizes. Box2D lets two touching shapes' skins
// (b2Shape::m_radius) overlap by b2_linearSlop and puts the contact point in the middle of the
// overlap. So a script's polygons (and a ground's edges) are given exactly the shape the script
// wrote, with a skin of half the slop, `true_skin`, instead of Box2D's 1 cm; a circle collides
// with a radius `true_skin` past the script's. Resting bodies then touch face to face, corner on
// face and rim on face where the script's sizes say, with the contact point on those surfaces.
constexpr float true_skin = 0.5f * b2_linearSlop;
// The script's radius of a circle built with true_skin.
inline float surface_radius(const b2CircleShape& circle) { return circle.m_radius - true_skin; }
// Gives a dynamic body the mass, centre and rotational inertia of its script's shapes (Box2D's
// own, but a circle's over its script's radius, not over the radius it collides with).
void set_mass_from_surfaces(b2Body* body);

}  // namespace frictionlab
