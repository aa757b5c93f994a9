// The theory.* functions written out by hand: those that run a model over time (spring_stick_slip's
// run, regularized_run, regularized_creep, wedge), take nested tables (stacked_blocks,
// intermittent_slide), read the run itself (velocity_hack) or work through a long
// calculation (thrown_box). The rest are described in script_theory.cpp's table, which lists
// these too.

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <span>
#include <string>

#include "lessons/runtime/theory_binding.h"
#include "physics/closed_forms.h"
#include "physics/friction_laws.h"
#include "physics/reduced_model.h"
#include "physics/scenarios.h"
#include "physics/wedge_model.h"

namespace frictionlab::lessons {
namespace {

// A pair's fields are read by the names and in the units of the pair's table
// (physics/materials.h), which scripts, sliders and the physics share.

// The dry pair as given, with the table's drag coefficients (c, b), each off when left out.
FrictionPair with_drag(Fields& fields, double mu_s, double mu_k) {
  FrictionPair pair{mu_s, mu_k, 0.0, 0.0};
  for (const PairCoefficient& coefficient : pair_coefficients) {
    if (coefficient.drag) pair.*coefficient.value = fields.number(coefficient.name, coefficient.unit, 0.0);
  }
  return pair;
}

// mu_s may be left out where only sliding matters (it then equals mu_k).
FrictionPair pair_from(Fields& fields) {
  const double mu_k = fields.number(kinetic_coefficient.name, kinetic_coefficient.unit);
  return with_drag(fields, fields.number(static_coefficient.name, static_coefficient.unit, mu_k), mu_k);
}

// The table's names, the only fields a nested pair has.
constexpr auto coefficient_names = [] {
  std::array<const char*, std::size(pair_coefficients)> names{};
  for (std::size_t i = 0; i < names.size(); ++i) names[i] = pair_coefficients[i].name;
  return names;
}();

FrictionPair nested_pair(lua_State* state, Fields& outer, const char* key) {
  outer.push(key);
  Fields fields(state, -1, outer.what() + ": " + key, std::span<const char* const>(coefficient_names));
  const FrictionPair pair = pair_from(fields);
  lua_pop(state, 1);
  return pair;
}

// spring_stick_slip's run, read as a lesson reads its record (see spring_stick_slip).
struct SpringRunReading {
  int breakaways = 0, resticks = 0;
  double breakaway_sum = 0.0, restick_sum = 0.0, first = 0.0, last = 0.0, first_force = 0.0;
  // How long the block stays stuck after a stop before it breaks away again: a stepped world
  // cannot show a stick much shorter than its step (a lesson says so rather than compare).
  double shortest_stick = std::numeric_limits<double>::infinity();
  // And the longest it moves without stopping (a reversal does not stop it): every step of
  // a slip rounds the world's single-precision position, so a lesson's tolerance counts them.
  double longest_slip = 0.0;
  // The fastest the block slides, and how near a slide comes to a stop without stopping: the
  // slowest it goes at a dip inside a slide (not at its ends, where it starts from or comes
  // to rest). A world whose speed is off by more than that may stop there and stick.
  double fastest_slide = 0.0, nearest_stop = std::numeric_limits<double>::infinity();
};

// RK4's step: 200 a swing of the spring, and short against the drag's own time m/(c + 2b·v)
// (RK4 is stable only while h·(c + 2b·v)/m < 2.78), v at most the hand's speed and the
// lurch's, max(mu_s, mu_k)·g/ω.
double spring_run_step(const OneDofBlock& block, double g, double duration) {
  const double mass = block.mass, k = block.spring_k, c = block.pair.c, b = block.pair.b;
  const double mu = std::max(block.pair.mu_s, block.pair.mu_k);
  const double swing = 2.0 * std::numbers::pi * std::sqrt(mass / k);
  // (The lurch is slower still where the drag at that speed would outpull the spring's
  // largest pull, max(mu_s, mu_k)·m·g plus what it takes to stop.)
  const double largest = 2.0 * mu * mass * g;
  double fastest = mu * g * swing / (2.0 * std::numbers::pi);
  if (b > 0.0) fastest = std::min(fastest, std::sqrt(largest / b));
  if (c > 0.0) fastest = std::min(fastest, largest / c);
  fastest += block.pull_speed;
  return std::min({1e-3, swing / 200.0, duration / 16.0, 0.5 * mass / (c + 2.0 * b * fastest)});
}

SpringRunReading read_spring_run(const OneDofBlock& block, const Trajectory& run, double duration) {
  SpringRunReading reading;
  double stopped_at = std::numeric_limits<double>::quiet_NaN(), moving_since = stopped_at;
  for (const Event& event : run.events()) {
    if (event.kind == EventKind::breakaway && std::isnan(moving_since)) moving_since = event.t;
    if (event.kind == EventKind::stop && !std::isnan(moving_since)) {
      reading.longest_slip = std::max(reading.longest_slip, event.t - moving_since);
      moving_since = std::numeric_limits<double>::quiet_NaN();
    }
    const double force = applied_force(block, event.t, event.x);
    const bool breaks = event.kind == EventKind::breakaway || event.kind == EventKind::reversal;
    if (event.kind == EventKind::stop || event.kind == EventKind::reversal) ++reading.resticks, reading.restick_sum += force;
    if (event.kind == EventKind::breakaway && !std::isnan(stopped_at)) {
      reading.shortest_stick = std::min(reading.shortest_stick, event.t - stopped_at);
    }
    stopped_at = event.kind == EventKind::stop ? event.t : std::numeric_limits<double>::quiet_NaN();
    if (breaks) {
      if (reading.breakaways == 0) reading.first = event.t, reading.first_force = force;
      reading.last = event.t;
      ++reading.breakaways, reading.breakaway_sum += force;
    }
  }
  if (!std::isnan(moving_since)) reading.longest_slip = std::max(reading.longest_slip, duration - moving_since);
  for (const Phase& phase : run.phases()) {
    if (phase.kind == PhaseKind::stick) continue;
    constexpr int samples = 400;
    double before = 0.0, now = std::abs(phase.state(phase.t_start).v);
    for (int i = 1; i <= samples; ++i) {
      const double next = std::abs(phase.state(phase.t_start + (phase.t_end - phase.t_start) * i / samples).v);
      reading.fastest_slide = std::max(reading.fastest_slide, next);
      if (i >= 2 && now <= before && now < next) reading.nearest_stop = std::min(reading.nearest_stop, now);
      before = now, now = next;
    }
  }
  return reading;
}

// The reading as the table `run` on the table at the top of the stack.
void push_spring_run(lua_State* state, const SpringRunReading& reading) {
  lua_createtable(state, 0, 10);
  set_number(state, "breakaways", reading.breakaways);
  set_number(state, "resticks", reading.resticks);
  if (reading.breakaways > 0) set_number(state, "breakaway_force", reading.breakaway_sum / reading.breakaways);
  if (reading.breakaways > 0) set_number(state, "first_breakaway_force", reading.first_force);
  if (reading.resticks > 0) set_number(state, "restick_force", reading.restick_sum / reading.resticks);
  if (reading.breakaways > 1) set_number(state, "period", (reading.last - reading.first) / (reading.breakaways - 1));
  if (std::isfinite(reading.shortest_stick)) set_number(state, "shortest_stick", reading.shortest_stick);
  set_number(state, "longest_slip", reading.longest_slip);
  set_number(state, "fastest_slide", reading.fastest_slide);
  if (std::isfinite(reading.nearest_stop)) set_number(state, "nearest_stop", reading.nearest_stop);
  lua_setfield(state, -2, "run");
}

}  // namespace

namespace theory_written {

int spring_stick_slip(lua_State* state) {
  return guarded(state, [&] {
    Fields fields(state, 1, "theory.spring_stick_slip",
                  {"mass", "k", "pull_speed", "mu_s", "mu_k", "c", "b", "duration", "g"});
    const double mass = fields.number("mass", "kg"), k = fields.number("k", "N/m");
    const double pull_speed = fields.number("pull_speed", "m/s"), mu_s = fields.number("mu_s", "");
    const double mu_k = fields.number("mu_k", ""), g = fields.number("g", "m/s²", standard_gravity);
    const FrictionPair read = with_drag(fields, mu_s, mu_k);
    const double c = read.c, b = read.b;
    const double duration = fields.number_in("duration", "s", 0.0, 0.0, 86400.0);
    lua_createtable(state, 0, 8);
    // The closed form's cycle, where it has one (no drag, mu_k <= mu_s).
    if (c == 0.0 && b == 0.0 && mu_k <= mu_s) {
      const theory::StickSlip cycle = theory::spring_stick_slip(mass, k, pull_speed, mu_s, mu_k, g);
      set_number(state, "breakaway_force", cycle.breakaway_force);
      set_number(state, "restick_force", cycle.restick_force);
      set_number(state, "stick_duration", cycle.stick_duration);
      set_number(state, "slip_duration", cycle.slip_duration);
      set_number(state, "period", cycle.period);
      set_number(state, "first_breakaway_time", cycle.first_breakaway_time);
      set_number(state, "slip_distance", cycle.slip_distance);
    } else {
      lua_pushstring(state, mu_k > mu_s ? "no periodic cycle: μk > μs" : "no closed form with drag c or b");
      lua_setfield(state, -2, "no_closed_form");
    }
    // With a duration: the run itself from rest, by the exact reduced model (closed-form phases
    // joined at events; with b, RK4 phases with their events bisected to 1e-13 s), read as a
    // lesson reads its record: the mean spring force at the breakaways and at the re-sticks
    // (a reversal, where the block stops and at once slides back, is both), and the mean time
    // from one breakaway to the next. Drag (c, b) has no closed form here; this answers it.
    if (duration > 0.0) {
      OneDofBlock block;
      block.mass = mass;
      block.normal_force = mass * g;
      block.pair = {mu_s, mu_k, c, b};
      block.spring_k = k;
      block.pull_speed = pull_speed;
      const double h = spring_run_step(block, g, duration);
      if (b != 0.0 && duration / h > 2e7) throw InvalidInput("theory.spring_stick_slip: duration is over 20 million model steps");
      const Trajectory run = b == 0.0 ? solve_exact(block, duration) : solve_event_rk4(block, duration, h);
      push_spring_run(state, read_spring_run(block, run, duration));
    }
    return 1;
  });
}

int stacked_blocks(lua_State* state) {
  return guarded(state, [&] {
    Fields fields(state, 1, "theory.stacked_blocks", {"top_mass", "bottom_mass", "between", "ground", "push", "g"});
    const double top_mass = fields.number("top_mass", "kg"), bottom_mass = fields.number("bottom_mass", "kg");
    const FrictionPair between = nested_pair(state, fields, "between"), ground = nested_pair(state, fields, "ground");
    const double push = fields.number("push", "N"), g = fields.number("g", "m/s²", standard_gravity);
    // A slider may put mu_k above mu_s; the closed form has no answer there, and says so in words
    // (`no_closed_form`) rather than refusing the value.
    if (between.mu_k > between.mu_s || ground.mu_k > ground.mu_s) {
      lua_createtable(state, 0, 1);
      lua_pushstring(state, "no closed form (μk > μs)");
      lua_setfield(state, -2, "no_closed_form");
      return 1;
    }
    const theory::StackedBlocks stack = theory::stacked_blocks(top_mass, bottom_mass, between, ground, push, g);
    lua_createtable(state, 0, 4);
    const char* regime = stack.regime == theory::StackRegime::at_rest    ? "at_rest"
                         : stack.regime == theory::StackRegime::together ? "together"
                                                                          : "top_slips";
    lua_pushstring(state, regime);
    lua_setfield(state, -2, "regime");
    set_number(state, "top_acceleration", stack.top_acceleration);
    set_number(state, "bottom_acceleration", stack.bottom_acceleration);
    set_number(state, "max_push_together", stack.max_push_together);
    return 1;
  });
}

int intermittent_slide(lua_State* state) {
  return guarded(state, [&] {
    Fields fields(state, 1, "theory.intermittent_slide", {"mass", "pull", "dry", "lubricated", "from", "until", "t", "g"});
    const theory::IntermittentSlide slide = theory::intermittent_slide(
        fields.number("mass", "kg"), fields.number("pull", "N"), nested_pair(state, fields, "dry"),
        nested_pair(state, fields, "lubricated"), fields.number("from", "s"), fields.number("until", "s"),
        fields.number("t", "s"), fields.number("g", "m/s²", standard_gravity));
    lua_createtable(state, 0, 4);
    set_flag(state, "sliding", slide.sliding);
    set_number(state, "acceleration", slide.acceleration);
    set_number(state, "speed", slide.speed);
    set_number(state, "distance", slide.distance);
    return 1;
  });
}

// The tribology article's regularized friction on a slope, run the way a game runs it: a
// block released at rest, a fixed step, and friction -mu_s·N·v/epsilon below the threshold
// speed. Returns speed and distance down the slope at t = 0, step, 2·step, ... so a lesson can
// set it beside its own (Box2D) block and the exact answer.
int regularized_run(lua_State* state) {
  return guarded(state, [&] {
    Fields fields(state, 1, "theory.regularized_run",
                  {"angle", "mu_s", "mu_k", "epsilon", "step", "duration", "integrator", "g"});
    const double angle = fields.number_in("angle", "°", 0.0, 90.0) * degrees;
    const double g = fields.number_in("g", "m/s²", standard_gravity, 0.0, 1000.0, true);
    const double step = fields.number_in("step", "s", 1e-6, 1.0);
    const double duration = fields.number_in("duration", "s", 0.0, 3600.0);
    const std::string name = fields.text("integrator", "semi-implicit");
    const Integrator integrator = name == "explicit"        ? Integrator::explicit_euler
                                  : name == "semi-implicit" ? Integrator::semi_implicit_euler
                                  : name == "rk4"           ? Integrator::rk4
                                                            : throw InvalidInput("theory.regularized_run: integrator '" + name +
                                                                                 "' is none of explicit, semi-implicit, rk4");
    // Two lists of this many numbers stay well inside the script's 64 MB.
    if (duration / step > 500000.0) {
      throw InvalidInput("theory.regularized_run: duration / step is over 500000 samples; take a longer step or a shorter run");
    }
    OneDofBlock block;
    block.mass = 1.0;
    block.normal_force = g * std::cos(angle);
    block.constant_force = g * std::sin(angle);
    // A lesson's range of μ, as its sliders have it.
    block.pair = {fields.number_in(static_coefficient.name, "", 0.0, static_coefficient.lesson_largest, true),
                  fields.number_in(kinetic_coefficient.name, "", 0.0, kinetic_coefficient.lesson_largest), 0.0, 0.0};
    const double epsilon = fields.number_in("epsilon", "m/s", 0.0, 100.0, true);
    const std::vector<Sample> samples = integrate_regularized(block, duration, step, epsilon, integrator);
    lua_createtable(state, 0, 2);
    for (const auto& [key, of] : {std::pair{"speed", &Sample::v}, std::pair{"distance", &Sample::x}}) {
      lua_createtable(state, static_cast<int>(samples.size()), 0);
      for (std::size_t i = 0; i < samples.size(); ++i) {
        lua_pushnumber(state, samples[i].*of);
        lua_rawseti(state, -2, static_cast<lua_Integer>(i + 1));
      }
      lua_setfield(state, -2, key);
    }
    return 1;
  });
}

// The regularized law's creep down a slope it should stick to, as a fixed step takes it: each
// step the drag c, b acts exactly over the step on the speed the block brings (as the listener
// applies it), the law's linear branch −μs·N·v/ε and gravity's pull explicitly, so the step's
// speed v' = damped(v) + h·g·(sin θ − μs·cos θ·v/ε) and the creep is its fixed point. With no
// drag that is ε·tan θ/μs at any step; with step 0, the continuous law's b v² + (μs·m·g·cos θ/ε
// + c)·v = m·g·sin θ. `amplification` is dv'/dv there: the step settles onto the creep while
// its size is below 1 (with no drag: while h < 2ε/(μs·g·cos θ)) and jitters for ever past it.
// Where μs <= tan θ the linear branch cannot balance the slope: `no_creep` says so. With `duration`, the steps
// from rest are taken too: `breaks_away` when the block ends faster than ε, and `settles` then
// false whatever the amplification.
int regularized_creep(lua_State* state) {
  return guarded(state, [&] {
    Fields fields(state, 1, "theory.regularized_creep",
                  {"angle", "mu_s", "mu_k", "epsilon", "step", "c", "b", "mass", "duration", "g"});
    const double angle = fields.number_in("angle", "°", 0.0, 90.0) * degrees;
    const double mu_s = fields.number("mu_s", ""), epsilon = fields.number_in("epsilon", "m/s", 0.0, 100.0, true);
    const double h = fields.number_in("step", "s", 0.0, 0.0, 1.0), mass = fields.number("mass", "kg", 1.0);
    const double g = fields.number_in("g", "m/s²", standard_gravity, 0.0, 1000.0, true);
    const FrictionPair drag = with_drag(fields, 0.0, 0.0);
    if (mu_s <= std::tan(angle)) {  // an answer in words, not a refusal
      lua_createtable(state, 0, 1);
      lua_pushstring(state, "no creep: μs ≤ tan θ, the law's linear branch cannot hold the slope");
      lua_setfield(state, -2, "no_creep");
      return 1;
    }
    const double pull = g * std::sin(angle), k = mu_s * g * std::cos(angle) / epsilon;  // per unit mass
    // What the step lacks of a fixed point at v: rises with v (damped(v) rises slower than v).
    const auto excess = [&](double v) {
      if (h == 0.0) return (drag.c * v + drag.b * v * v) / mass - (pull - k * v);
      return v - damped_velocity(v, mass, h, drag) - h * (pull - k * v);
    };
    double low = 0.0, high = epsilon;  // excess(0) <= 0 < excess(ε), as μs > tan θ
    for (int i = 0; i < 200 && high - low > 1e-15 * epsilon; ++i) {
      const double middle = 0.5 * (low + high);
      (excess(middle) > 0.0 ? high : low) = middle;
    }
    const double creep = 0.5 * (low + high);
    double amplification = 0.0;
    if (h > 0.0) {
      const double dv = 1e-6 * epsilon;
      const double slope = (damped_velocity(creep + dv, mass, h, drag) - damped_velocity(std::max(creep - dv, 0.0), mass, h, drag)) /
                           (creep + dv - std::max(creep - dv, 0.0));
      amplification = slope - h * k;
    }
    // The steps themselves from rest, over `duration`, with the whole law (kinetic friction
    // μk·N past ε): a step that overshoots ε (the first one does where h·g·sin θ > ε) lets a
    // slope steeper than atan μk take the block away, whatever the creep's own stability.
    const double mu_k = fields.number("mu_k", "", mu_s);
    const double duration = fields.number_in("duration", "s", 0.0, 0.0, 3600.0);
    // The last two steps are judged, not the last one: where μk > μs the kinetic branch past ε
    // can throw the block back under ε and the linear branch past it again, a cycle of two
    // steps whose last step alone reads as settled every other step (30°, μs 0.7316, μk 1.127,
    // ε 0.02 m/s at 240 Hz: 0.0204 and 0.00023 m/s in turn, the world's too).
    double v = 0.0, v_before = 0.0;
    if (h > 0.0 && duration / h > 1e7) throw InvalidInput("theory.regularized_creep: duration / step is over 10 million steps");
    for (double t = 0.0; h > 0.0 && t < duration - 0.5 * h; t += h) {
      const double dry = std::abs(v) < epsilon ? -k * v : -mu_k * g * std::cos(angle) * (v > 0.0 ? 1.0 : -1.0);
      v_before = v;
      v = damped_velocity(v, mass, h, drag) + h * (pull + dry);
    }
    lua_createtable(state, 0, 5);
    set_number(state, "speed", creep);
    set_number(state, "amplification", amplification);
    set_flag(state, "breaks_away", std::min(v, v_before) > epsilon);
    set_number(state, "speed_at_end", v);
    set_flag(state, "settles", std::abs(amplification) < 1.0 && std::max(std::abs(v), std::abs(v_before)) <= epsilon);
    return 1;
  });
}

namespace {

// The face the thrown box lands on, beyond its landing corner: the far end of that face (the
// second-lowest corner), how much higher that end is, and where it is from the centre.
struct FarEnd {
  double rise = std::numeric_limits<double>::infinity();
  double x = 0.0, y = 0.0;
};

// The corner at (sx, sy) of the box's own frame (each ±0.5), from the centre at the landing
// pose, and how much higher it is than the landing corner.
FarEnd corner_at(const theory::BoxLanding& landing, double width, double height, double sx, double sy) {
  const double c = std::cos(landing.angle), s = std::sin(landing.angle);
  FarEnd corner;
  corner.x = sx * width * c - sy * height * s, corner.y = sx * width * s + sy * height * c;
  corner.rise = corner.y - landing.corner_y;
  return corner;
}

bool is_landing_corner(const theory::BoxLanding& landing, const FarEnd& corner) {
  return std::abs(corner.x - landing.corner_x) < 1e-12 && std::abs(corner.y - landing.corner_y) < 1e-12;
}

// The lowest corner but the landing one (where no corner matches the landing one, the lowest
// of all four: a flat landing's far end).
FarEnd far_end_of(const theory::BoxLanding& landing, double width, double height) {
  FarEnd far;
  for (const double sx : {-0.5, 0.5}) {
    for (const double sy : {-0.5, 0.5}) {
      const FarEnd here = corner_at(landing, width, height, sx, sy);
      if (!is_landing_corner(landing, here) && here.rise < far.rise) far = here;
    }
  }
  return far;
}

// The ends of the two faces through the landing corner, from the centre at the landing pose
// (the far end is the lower of them).
std::array<FarEnd, 2> neighbours_of(const theory::BoxLanding& landing, double width, double height) {
  for (const double sx : {-0.5, 0.5}) {
    for (const double sy : {-0.5, 0.5}) {
      if (is_landing_corner(landing, corner_at(landing, width, height, sx, sy))) {
        return {corner_at(landing, width, height, -sx, sy), corner_at(landing, width, height, sx, -sy)};
      }
    }
  }
  return {FarEnd{}, FarEnd{}};  // (no corner is the landing one: nothing comes down after it)
}

// How far above reach the lowest corner but the landing one is `late` s after the landing (0 or
// less: within reach), the box's pose followed exactly: its centre on the parabola, its angle
// turned by spin·late. The far end's first-order fall is not enough at coarse steps: at 9 Hz the
// corner is met 54 ms after the landing, the box turned 0.33 rad since, and the far corner,
// first-order 2 cm above reach, was 1 cm into the floor (both corners met in that step: the spin
// stopped in the world, -21.3 rad/s predicted).
double far_end_gap(const theory::BoxLanding& landing, double width, double height, double spin, double g, double late) {
  const double turned = landing.angle + spin * late;
  const double c_late = std::cos(turned), s_late = std::sin(turned);
  const double drop = g * landing.time * late + 0.5 * g * late * late;  // thrown level: falling g·t at the landing
  double gap = std::numeric_limits<double>::infinity();
  for (const double sx : {-0.5, 0.5}) {
    for (const double sy : {-0.5, 0.5}) {
      if (is_landing_corner(landing, corner_at(landing, width, height, sx, sy))) continue;
      gap = std::min(gap, sx * width * s_late + sy * height * c_late - landing.corner_y - drop);
    }
  }
  return gap;
}

// The sub-steps of the impact's frame left after the sub-step that met the corner (0 without
// sub-steps). That sub-step starts at the first sub-step boundary after the landing (the
// late impact below, a bound on where in it the corner was met, is met in the same one); the
// frame ends at the next frame boundary after it ends. Rounded to whole sub-steps: the
// boundaries are multiples of the sub-step, read in floating point.
int substeps_left_in_frame(double landing_time, double step, double substeps) {
  if (step <= 0.0) return 0;
  const double frame = step * substeps;
  const double met_end = std::ceil(landing_time / step - 1e-9) * step + step;
  const double frame_end = std::ceil(met_end / frame - 1e-9) * frame;
  return std::max(static_cast<int>(std::lround((frame_end - met_end) / step)), 0);
}

// The frame's sub-steps, as the run takes them unless the script says otherwise: a whole number
// from 1 to 1000.
double substeps_field(lua_State* state, Fields& fields) {
  const double substeps = fields.number_in("substeps", "", build_of(state).scene->settings().substeps, 1.0, 1000.0);
  if (substeps != std::floor(substeps)) {
    throw InvalidInput(fields.what() + ": substeps must be a whole number, got " + std::to_string(substeps));
  }
  return substeps;
}

// Box2D keeps positions and speeds in single precision: each step rounds the centre's height,
// the angle (the corner moves r times its rounding) and the fall speed by up to 2^-24 of
// themselves, so n steps to the landing can move the corner by about n·2^-24·(height + r·|angle| + g·t²/3)
// (the speeds' roundings, summed over the steps' moves, give the last term). The
// corner's fall crosses that in the time returned: a landing that close before a step boundary
// may be met a step later (1.2 µs before one, met a step late, at 8 m/s and 2.99 rad/s).
double landing_rounding_time(const theory::BoxLanding& landing, double width, double height, double centre_height,
                             double spin, double g, double step) {
  if (step <= 0.0) return 0.0;
  const double fall_speed = g * landing.time - spin * landing.corner_x;  // the corner's, downward
  const double steps = std::ceil(landing.time / step), reach = 0.5 * std::hypot(width, height);
  const double drift = steps * std::ldexp(1.0, -24) *
                       (centre_height + reach * std::abs(landing.angle) + g * landing.time * landing.time / 3.0);
  return fall_speed > 0.0 ? drift / fall_speed : std::numeric_limits<double>::infinity();
}

// The box's first impact on the floor, and which corner took it.
struct FirstImpact {
  theory::CornerImpact impact{};
  std::string corner = "lands flat";  // or "pitches over its front/rear edge", "grips", "slides"
  double hit_x = 0.0, hit_y = 0.0;    // the corner that takes the impact, from the centre
  // How far Box2D's solver, in its turns, leaves the corner's spin from the impact's (rad/s): the
  // world's impact step ends there, and only the frame's later sub-steps settle it further.
  double solver_shortfall = 0.0;
  // How far the spin after moves if the world's single-precision corner is landing_rounding's
  // time ahead of or behind theory's (rad/s).
  double rounding_spread = 0.0;
};

// The box turning on the corner it hit, at (rx, ry) from its centre.
struct CornerTurn {
  // Box2D's solver takes friction and the normal impulse in turns (Gauss–Seidel). On a sliding
  // corner each turn leaves mu_k·|k_tn|/k_nn of the last one's error (k: how an impulse at the
  // corner moves it; k_tn couples sliding to falling). 0 where the corner grips.
  double swing = 0.0;
  // After the impact the box turns about that corner, gravity's moment m·g·r_x against the
  // inertia about the corner: how fast the spin changes there, rad/s².
  double pivot = 0.0;
};

CornerTurn corner_turn(double mass, double inertia, double mu_k, double g, double rx, double ry, bool grips) {
  CornerTurn turn;
  if (!grips) turn.swing = mu_k * std::abs(rx * ry / inertia) / (1.0 / mass + rx * rx / inertia);
  turn.pivot = mass * g * std::abs(rx) / (inertia + mass * (rx * rx + ry * ry));
  return turn;
}

// What a run shows of the thrown box's landing: its first impact (on a corner, carried through
// the frame's remaining sub-steps) and how a stepped world may differ from it.
struct ShownImpact {
  FirstImpact first;
  theory::CornerImpact impact;           // the speeds and spin after it, at the frame's end
  double landing_rounding = 0.0;         // s, landing_rounding_time
  double second_corner = 0.0;            // s, second_corner_after (infinity: none)
  double far_above_reach = 0.0;          // m, the far end when the corner is met (infinity: none)
  CornerTurn turn;                       // the box turning on the corner it hit
  double spin_a_step_late = 0.0, spin_a_step_early = 0.0;  // rad/s, met a step after or before
};

// The thrown box as theory.thrown_box reads it, and the impacts of its corners on the floor in
// a world stepped as the run steps (step 0: an instant's impact, unstepped).
struct ThrownBox {
  double width, height, mass, speed, spin, centre_height, mu_k, mu_s, restitution, g, clearance, step;
  FrictionPair drag;  // the floor's viscous and quadratic drag (c, b), with mu_k
  theory::BoxLanding landing;
  double inertia;
  int remaining;  // substeps_left_in_frame

  // Landing flat, the face's drag goes through the centre (as Box2D's face contacts take it).
  double flat_drag(double vx) const { return step > 0.0 ? damped_velocity(vx, mass, step, drag) : vx; }

  // An impact on one corner (rx, ry from the centre, world axes), `late` s after the landing,
  // its lever arm turned with the box. The contact point is where the two skins meet, half the
  // clearance below the core's corner (Box2D puts it in the middle of the gap): a skin's lever
  // arm, which changes the spin after by up to 0.5 rad/s (at spin −1 rad/s: 4.77, not 5.27).
  // Met `late` s after the landing, the corner has sunk into the gap by its fall since, and the
  // middle of what is left of the gap, where the point is, has risen by half that. A script's
  // gap (two 2.5 mm skins) is less than a step's fall at landing (16 mm at 3.8 m/s and 240 Hz),
  // so the corner may sink past it into the floor before a step finds it: the point is then
  // in the middle of the overlap, as far below the floor as the corner is below the gap's end.
  // `face`: the step met the whole face (a flat landing), whose two-point contact takes the
  // step's drag through the centre on the whole mass, not at the corner (b = 1000 N·s²/m² on
  // 14.5 kg at 5.8 m/s: 2.2 m/s left, which mu_k 1.114 stops within the impact; the corner's
  // drag, through its lever arm, left the box pitching over its front edge at -8.0 rad/s
  // where the world's stopped turning).
  // `turns`: 0 for the impact itself, or the turns of Box2D's solver, for what those leave.
  theory::CornerImpact impact_on(double rx, double ry, double late, bool face = false, int turns = 0) const;

  // Under sub-steps the world records the spin at the end of the frame, not of the sub-step
  // that met the corner: the frame's remaining sub-steps act on the box first, each applying
  // the corner's drag (c·v + b·v², on the sliding speed it brings in) and then the contact's
  // impulse that stops the corner's fall again, with friction up to mu_k (mu_s if the corner
  // gripped) times that impulse. At c = 949 N·s/m on a 20 kg box they take the spin from
  // 3.9 to 1.6 rad/s in three 1/960 s sub-steps. Stepped here as the world steps them: drag,
  // gravity, contact, the lever arm turned with the box. For a box met on a corner only.
  theory::CornerImpact through_frame(theory::CornerImpact hit, double rx, double ry, double late) const;

  // Landing flat, met `first_met` s after the landing (`far`: the face's other end), the face's
  // two ends share the impact: each end's fall is stopped (or, with restitution e, turned back
  // at e times its speed), and two ends that stop together stop the box's fall and its spin
  // together (fall and spin each turned back at e times), the ends' loads shifting to hold
  // friction's moment and the spin's. That holds while both loads are pushes: where one end
  // alone, taking the impact, leaves the other rising (friction's moment about the front end,
  // or a spin too fast for the fall to stop), that end takes it alone and the other lifts. A
  // spinning box does not keep its spin through such a landing: at spin 7.638 rad/s and mu_k
  // 0.4, the world's box stops turning.
  FirstImpact on_its_face(const FarEnd& far, double first_met) const;
  // Landing on its lowest corner, met `first_met` s after the landing; with what Box2D's solver
  // in `solver_turns` turns, and a landing `landing_rounding` s sooner or later, would change.
  FirstImpact on_its_corner(double first_met, double landing_rounding, int solver_turns) const;
  // The first impact as a world stepped as the run steps meets it, whose solver takes
  // `solver_turns` turns.
  ShownImpact shown_impact(int solver_turns) const;
};

FirstImpact ThrownBox::on_its_face(const FarEnd& far, double first_met) const {
  FirstImpact first;
  const double far_x = far.x, far_y = far.y;
  const bool landing_leads = (landing.corner_x - far_x) * speed >= 0.0;
  const double front_x = landing_leads ? landing.corner_x : far_x, front_y = landing_leads ? landing.corner_y : far_y;
  const double rear_x = landing_leads ? far_x : landing.corner_x;
  const double rear_y = landing_leads ? far_y : landing.corner_y;
  const theory::CornerImpact front = impact_on(front_x, front_y, first_met, true), rear = impact_on(rear_x, rear_y, first_met, true);
  first.hit_x = landing.corner_x, first.hit_y = landing.corner_y;
  if (front.vy + front.omega * rear_x > 0.0) {
    first.impact = front;
    first.corner = "pitches over its front edge";
    first.hit_x = front_x, first.hit_y = front_y;
  } else if (rear.vy + rear.omega * front_x > 0.0) {
    first.impact = rear;
    first.corner = "pitches over its rear edge";
    first.hit_x = rear_x, first.hit_y = rear_y;
  } else {
    first.impact = theory::corner_impact(mass, inertia, 0.0, 0.0, flat_drag(speed), -g * landing.time, spin, mu_k, restitution);
    first.impact.omega = -restitution * spin;
  }
  return first;
}

FirstImpact ThrownBox::on_its_corner(double first_met, double landing_rounding, int solver_turns) const {
  FirstImpact first;
  first.hit_x = landing.corner_x, first.hit_y = landing.corner_y;
  first.impact = impact_on(landing.corner_x, landing.corner_y, first_met);
  first.solver_shortfall =
      std::abs(impact_on(landing.corner_x, landing.corner_y, first_met, false, solver_turns).omega - first.impact.omega);
  // The world's corner may be where theory's is a rounding's time sooner or later (a grazing
  // corner that does not fall into the floor has no such time: nothing to weigh).
  for (const double off : {-landing_rounding, landing_rounding}) {
    if (!std::isfinite(off)) break;
    first.rounding_spread = std::max(first.rounding_spread,
                                     std::abs(impact_on(landing.corner_x, landing.corner_y, first_met + off).omega - first.impact.omega));
  }
  first.corner = first.impact.grips ? "grips" : "slides";
  return first;
}

theory::CornerImpact ThrownBox::impact_on(double rx, double ry, double late, bool face, int turns) const {
  const double turn = spin * late, c = std::cos(turn), s = std::sin(turn);
  // The corner's fall since the landing: the centre's, and the turning's, taken whole (its
  // curvature, omega²·|ry|·late²/2, is 0.4 mm at -17 rad/s a step late, and 0.2 mm of the
  // point's height decides whether drag stops a corner there).
  const double sunk = std::max(g * landing.time * late + 0.5 * g * late * late + ry - (s * rx + c * ry), 0.0);
  const double px = c * rx - s * ry, py = s * rx + c * ry - 0.5 * (clearance - sunk);
  // The step's drag on the point's sliding speed vx − ω·py, through the mass an impulse
  // along the floor at that point feels.
  double vx = face ? flat_drag(speed) : speed, omega = spin;
  if (!face && step > 0.0 && (drag.c > 0.0 || drag.b > 0.0)) {
    const double felt = 1.0 / (1.0 / mass + py * py / inertia), sliding = vx - omega * py;
    const double impulse = felt * (damped_velocity(sliding, felt, step, drag) - sliding);
    vx += impulse / mass;
    omega -= py * impulse / inertia;
  }
  // A stepped world's corner born barely sliding (drag may have stopped it) starts stuck
  // and is held in that step's impact up to static friction, a little over: at c = 300
  // N·s/m on a 0.52 kg box the corner came in at 0.6 mm/s and left spinning at -6.16 rad/s,
  // where sliding under mu_k = 0 leaves it at -13.6.
  double mu = mu_k;
  if (step > 0.0 && std::abs(vx - omega * py) <= stick_slip_birth_sliding_speed) {
    mu = std::max(mu_s, mu_k) * (1.0 + stick_slip_hold_band);
  }
  // The world's flight starts with half a step's gravity (its positions the exact parabola's at
  // step boundaries, its speeds half a step behind), and the step adds a whole step's before
  // its impact is solved: the box falls half a step's gravity faster than at the meeting.
  const double vy = -g * (landing.time + late + 0.5 * step);
  // Drag strong enough to turn the corner up off the floor leaves the normal impulse
  // nothing to stop: the step's drag is then the whole of the impact.
  if (vy + omega * px >= 0.0) return theory::CornerImpact{false, 0.0, 0.0, vx, vy, omega};
  if (turns > 0) return theory::solver_corner_impact(mass, inertia, px, py, vx, vy, omega, mu, restitution, turns);
  const theory::CornerImpact hit = theory::corner_impact(mass, inertia, px, py, vx, vy, omega, mu, restitution);
  // A corner that arrives sliding one way and leaves sliding the other (the normal impulse
  // turning the box back) stopped within the impact. The stick-slip treatment finds that at
  // the step's end and owes the box the impulse that makes the step end as Coulomb's law
  // would, static friction holding the corner: paid at the next sub-step's start, so seen
  // at the frame's end only when a sub-step of the frame is left (at c = 446 N·s/m, mu_k 0,
  // mu_s 0.8: spin 4.6 rad/s after the impact's sub-step, -0.9 after the next).
  const double arriving = vx - omega * py;
  if (remaining > 0 && mu == mu_k && !hit.grips && arriving * (hit.vx - hit.omega * py) < 0.0) {
    return theory::corner_impact(mass, inertia, px, py, vx, vy, omega,
                                 std::max(mu_s, mu_k) * (1.0 + stick_slip_hold_band), restitution);
  }
  return hit;
}

theory::CornerImpact ThrownBox::through_frame(theory::CornerImpact hit, double rx, double ry, double late) const {
  if (step <= 0.0) return hit;
  // Static friction as the stick-slip treatment lets a stuck contact hold it, a little over.
  const double held = std::max(mu_s, mu_k) * (1.0 + stick_slip_hold_band);
  bool stuck = hit.grips;
  double turned = spin * late;
  for (int k = 0; k < remaining; ++k) {
    turned += hit.omega * step;
    const double c = std::cos(turned), s = std::sin(turned);
    const double px = c * rx - s * ry, py = s * rx + c * ry - 0.5 * clearance;
    // Drag acts on a sliding corner only: the stick-slip treatment leaves a stuck contact's
    // leftover motion undragged (physics/friction_listener.cpp). Dragged here too, a corner the
    // impact gripped (b = 1000 N·s²/m², spin -20 rad/s at 6.4 m/s, 60 Hz and 8 sub-steps) was
    // turned from -16.3 to -15.1 rad/s over the frame's seven later sub-steps, where the
    // world's kept -16.27.
    if (!stuck && (drag.c > 0.0 || drag.b > 0.0)) {
      const double felt = 1.0 / (1.0 / mass + py * py / inertia), sliding = hit.vx - hit.omega * py;
      const double impulse = felt * (damped_velocity(sliding, felt, step, drag) - sliding);
      hit.vx += impulse / mass;
      hit.omega -= py * impulse / inertia;
    }
    hit.vy -= g * step;
    // A corner moving up has left the floor: nothing stops it within the frame.
    if (hit.vy + hit.omega * px >= 0.0) continue;
    // A sliding corner whose sliding the contact's own impulse turns back (through the
    // turning the normal impulse gives the box) stopped within the sub-step: the world
    // sticks it again there and static friction holds it (at c = 446 N·s/m, mu_k 0, the
    // spin went from 4.6 to -0.9 rad/s in that sub-step, where sliding on would leave it
    // at 3.7). A stuck corner that static friction cannot hold breaks away and slides.
    const double sliding = hit.vx - hit.omega * py;
    theory::CornerImpact next =
        theory::corner_impact(mass, inertia, px, py, hit.vx, hit.vy, hit.omega, stuck ? held : mu_k, 0.0);
    if (!stuck && sliding * (next.vx - next.omega * py) < 0.0) {
      next = theory::corner_impact(mass, inertia, px, py, hit.vx, hit.vy, hit.omega, held, 0.0);
      stuck = next.grips;
    } else if (stuck && !next.grips) {
      next = theory::corner_impact(mass, inertia, px, py, hit.vx, hit.vy, hit.omega, mu_k, 0.0);
      stuck = false;
    }
    hit = next;
  }
  hit.grips = stuck;
  return hit;
}

// How soon after the impact a second corner comes down (falling at the impact's end speed, and
// under gravity), s: within a step or two a stepped world meets both corners in one step, and
// no single-corner impact describes what it shows.
// Either face through the corner may come down: the far end's, or, where the impact turns
// the box the other way, the other face's end, higher at the landing but brought down by the
// spin (12 Hz with 2 sub-steps: the box 46° over, the far end lifted by -15.9 rad/s, the
// other end met a sub-step after the impact, and the world's spin was -3.49 at the frame's
// end).
double second_corner_after(const theory::BoxLanding& landing, double width, double height,
                           const theory::CornerImpact& impact, double g) {
  double soonest = std::numeric_limits<double>::infinity();
  for (const FarEnd& end : neighbours_of(landing, width, height)) {
    const double end_speed = -(impact.vy + impact.omega * end.x);  // downward, m/s
    const double end_root = end_speed + std::sqrt(end_speed * end_speed + 2.0 * g * std::max(end.rise, 0.0));
    if (end_root > 0.0) soonest = std::min(soonest, 2.0 * std::max(end.rise, 0.0) / end_root);
  }
  return soonest;
}

ShownImpact ThrownBox::shown_impact(int solver_turns) const {
  constexpr double infinity = std::numeric_limits<double>::infinity();
  const FarEnd far = far_end_of(landing, width, height);
  const double rise = far.rise;
  // Before any impact, a stepped world finds contacts at a step's start, so it first
  // meets the corner at the first step boundary after the landing, the corner sunk into the gap
  // by its fall since, and it finds the far end in the same step if that end has fallen as far
  // as its rise (then both ends take that step's impact together, and no single-corner impact
  // describes it: a box landing 0.88° off flat at 4.1 m/s, 6 mm rise against a 10 mm fall,
  // stopped turning in the world where one corner's impact with the step's drag leaves it at
  // -3.6 rad/s). How far above reach the far end still is then, m (0 or less: met at once).
  double reach_gap = rise;
  // The world's flight starts with half a step's gravity, so its positions at step boundaries are
  // the exact parabola's: it meets the corner this long after the exact landing (0 unstepped).
  const double first_met = step > 0.0 ? std::ceil(landing.time / step) * step - landing.time : 0.0;
  const double landing_rounding = landing_rounding_time(landing, width, height, centre_height, spin, g, step);
  if (step > 0.0) reach_gap = far_end_gap(landing, width, height, spin, g, first_met);
  // A stepped world lands the box flat only where it meets the whole face in one step: a face
  // under 1 mm off flat whose far end is still above reach then meets one corner first, and
  // that corner's impact is what the first step shows (a 20 kg box at spin 19.5 rad/s, 0.15°
  // off flat at 960 sub-steps a second: -9.78 rad/s, the face a sub-step later).
  const bool lands_flat = landing.flat && (step <= 0.0 || reach_gap <= 0.0);
  const FirstImpact first = lands_flat ? on_its_face(far, first_met) : on_its_corner(first_met, landing_rounding, solver_turns);
  theory::CornerImpact impact = first.impact;
  const std::string& corner = first.corner;
  const double hit_x = first.hit_x, hit_y = first.hit_y;
  const bool on_a_corner = corner != "lands flat";
  if (on_a_corner && !lands_flat) impact = through_frame(impact, landing.corner_x, landing.corner_y, first_met);
  const double second_corner =
      on_a_corner && !lands_flat ? second_corner_after(landing, width, height, impact, g) : infinity;
  // (How far above reach the far end is when the corner is met: computed above.)
  const double far_above_reach = on_a_corner && !lands_flat ? reach_gap : infinity;
  const CornerTurn turn = on_a_corner ? corner_turn(mass, inertia, mu_k, g, hit_x, hit_y - 0.5 * clearance, impact.grips)
                                      : CornerTurn{};
  // A world whose rounding puts the landing just past a step boundary meets the corner a step
  // after theory's meeting, turned and falling further, and one that puts it just before a
  // boundary, a step sooner: the spin those impacts leave (spin_after itself when step = 0 or it
  // lands flat).
  const auto met_at = [&](double late_by) {
    return !on_a_corner || lands_flat ? impact.omega
                                      : through_frame(impact_on(landing.corner_x, landing.corner_y, late_by),
                                                      landing.corner_x, landing.corner_y, late_by).omega;
  };
  const double late = met_at(first_met + step), early = met_at(first_met - step);
  return {first, impact, landing_rounding, second_corner, far_above_reach, turn, late, early};
}

// The rotation-locked twin, thrown level: it lands flat, with no lever arm, so only its sliding
// and its fall are stopped; then it slides to rest under mu_k, c and b (never, with no dry
// friction: drag alone only slows it, ever more slowly).
struct LockedBox {
  double landing_time = 0.0, speed_after_landing = 0.0, distance = 0.0, stop_time = 0.0;
};

LockedBox locked_box(const ThrownBox& box) {
  const theory::BoxLanding flat = theory::box_landing(box.width, box.height, box.centre_height, 0.0, 0.0, box.g, box.clearance);
  const theory::CornerImpact lands = theory::corner_impact(box.mass, box.inertia, 0.0, 0.0, box.flat_drag(box.speed),
                                                           -box.g * flat.time, 0.0, box.mu_k, box.restitution);
  const theory::SlideToRest slide = theory::slide_to_rest(lands.vx, box.mass, box.drag, box.g);
  return {flat.time, lands.vx, box.speed * flat.time + slide.distance, flat.time + slide.time};
}

// The thrown box as a script gives it (theory.thrown_box's fields).
ThrownBox thrown_box_from(lua_State* state, Fields& fields) {
  const double width = fields.number("width", "m"), height = fields.number("height", "m");
  const double mass = fields.number("mass", "kg"), speed = fields.number("throw_speed", "m/s");
  const double spin = fields.number("spin", "rad/s", 0.0), angle = fields.number("angle", "°", 0.0) * degrees;
  const double centre_height = fields.number("centre_height", "m"), mu_k = fields.number("mu_k", "");
  const double mu_s = fields.number("mu_s", "", mu_k);
  const double restitution = fields.number("restitution", "", 0.0), g = fields.number("g", "m/s²", standard_gravity);
  // Box2D's polygons touch when they are two skins apart: a script's, true_skin each.
  const double clearance = fields.number("clearance", "m", 2.0 * true_skin);
  const double step = fields.number_in("step", "s", 0.0, 0.0, 1.0);
  // The sub-steps in a frame (the world records the box at the frame's end), as the run takes
  // them unless the script says otherwise.
  const double substeps = substeps_field(state, fields);
  // Viscous and quadratic drag on the floor: no impulse of their own in an instant's impact,
  // but a stepped world (step > 0) applies them once, for the whole step, on the sliding
  // speed the box brings into the step it lands in, before that step's impact is solved
  // (a contact born in a step has its drag at once). The same once here.
  const FrictionPair drag = with_drag(fields, mu_k, mu_k);
  const theory::BoxLanding landing = theory::box_landing(width, height, centre_height, angle, spin, g, clearance);
  const double inertia = mass * (width * width + height * height) / 12.0;
  return ThrownBox{width, height, mass, speed, spin, centre_height, mu_k, mu_s, restitution, g, clearance, step,
                   drag, landing, inertia, substeps_left_in_frame(landing.time, step, substeps)};
}

}  // namespace

// The thrown box and its rotation-locked twin: the landing of the lowest corner, the impact on
// it, and how far the locked box (thrown level, landing flat) goes before it stops.
int thrown_box(lua_State* state) {
  return guarded(state, [&] {
    Fields fields(state, 1, "theory.thrown_box", {"width", "height", "mass", "throw_speed", "spin", "angle",
                                                  "centre_height", "mu_k", "mu_s", "c", "b", "restitution", "g",
                                                  "clearance", "step", "substeps"});
    const ThrownBox box = thrown_box_from(state, fields);
    const ShownImpact shown = box.shown_impact(build_of(state).scene->settings().velocity_iterations);
    const LockedBox locked = locked_box(box);
    lua_createtable(state, 0, 19);
    set_number(state, "landing_time", box.landing.time);
    set_number(state, "landing_rounding", shown.landing_rounding);
    set_number(state, "landing_angle", box.landing.angle / degrees);
    lua_pushstring(state, shown.first.corner.c_str());
    lua_setfield(state, -2, "corner");
    set_number(state, "spin_after", shown.impact.omega);
    set_number(state, "spin_after_a_step_late", shown.spin_a_step_late);
    set_number(state, "spin_after_a_step_early", shown.spin_a_step_early);
    set_number(state, "solver_shortfall", shown.first.solver_shortfall);
    set_number(state, "rounding_spread", shown.first.rounding_spread);
    set_number(state, "pivot_acceleration", shown.turn.pivot);
    set_number(state, "second_corner_after", shown.second_corner);
    set_number(state, "far_end_above_reach", shown.far_above_reach);
    set_number(state, "solver_swing", shown.turn.swing);
    set_number(state, "vx_after", shown.impact.vx);
    set_number(state, "vy_after", shown.impact.vy);
    set_number(state, "locked_landing_time", locked.landing_time);
    set_number(state, "locked_speed_after_landing", locked.speed_after_landing);
    set_number(state, "locked_distance", locked.distance);
    set_number(state, "locked_stop_time", locked.stop_time);
    return 1;
  });
}

int velocity_hack(lua_State* state) {
  return guarded(state, [&] {
    Fields fields(state, 1, "theory.velocity_hack", {"v0", "keep", "step", "angle", "g", "substeps"});
    const double substeps = substeps_field(state, fields);
    const theory::VelocityHack hack = theory::velocity_hack(
        fields.number("v0", "m/s"), fields.number("keep", ""), fields.number("step", "s"),
        fields.number_in("angle", "°", 0.0, 0.0, 90.0) * degrees, fields.number("g", "m/s²", standard_gravity),
        static_cast<int>(substeps));
    lua_createtable(state, 0, 2);
    set_number(state, "distance_up", hack.distance_up);
    set_number(state, "drift_speed", hack.drift_speed);
    return 1;
  });
}

// The article's block on a swinging, accelerating wedge, reduced to its slide along the surface
// (physics/wedge_model.h), solved once over `duration` and sampled every `step`: lists of the
// state at t = 0, step, 2·step, ... (index k + 1 for t = k·step), the events, and the windows in
// which the block slips. law = "coulomb" (friction opposes the sliding; static friction holds)
// or "article" (the article's equation as written: friction opposes the driving force, always
// sliding). rotation = true puts back the turning surface's terms the article leaves out, for a
// block whose centre is centre_height above the surface line and starts `start` m up the slope
// from the pivot; start_speed (m/s, down the slope) starts it moving instead of at rest. With
// world_step (s), also stepped_slide and stepped_speed: the same equations stepped as a Box2D
// world with the listener steps them at that step (step_as_the_world), up to the first flight.
int wedge(lua_State* state) {
  return guarded(state, [&] {
    Fields fields(state, 1, "theory.wedge", {"mass", "theta0", "omega", "a_x", "a_x_omega", "mu_s", "mu_k", "g",
                                             "duration", "step", "law", "rotation", "centre_height", "start",
                                             "start_speed", "world_step"});
    WedgeDrive drive;
    drive.mass = fields.number_in("mass", "kg", 0.0, 1e6, true);
    drive.theta0 = fields.number_in("theta0", "°", -85.0, 85.0) * degrees;
    drive.omega = fields.number_in("omega", "rad/s", 0.0, 0.0, 1000.0);
    drive.a_x = fields.number_in("a_x", "m/s²", 0.0, -1e4, 1e4);
    drive.a_x_omega = fields.number_in("a_x_omega", "rad/s", 0.0, 0.0, 1000.0);
    // The physics' own limit (check_wedge's), not a lesson's: a student's drive may exceed 2.
    drive.mu_k = fields.number_in(kinetic_coefficient.name, "", 0.0, kinetic_coefficient.largest);
    drive.mu_s = fields.number_in(static_coefficient.name, "", drive.mu_k, 0.0, static_coefficient.largest);
    drive.g = fields.number_in("g", "m/s²", standard_gravity, 0.0, 1000.0, true);
    drive.rotation = fields.flag("rotation").value_or(false);
    drive.centre_height = fields.number_in("centre_height", "m", 0.0, 0.0, 100.0);
    drive.start = fields.number_in("start", "m", 0.0, -1000.0, 1000.0);
    drive.start_speed = fields.number_in("start_speed", "m/s", 0.0, -1000.0, 1000.0);
    const double duration = fields.number_in("duration", "s", 0.0, 3600.0);
    const double step = fields.number_in("step", "s", 1e-6, 1.0);
    const std::string law_name = fields.text("law", "coulomb");
    const WedgeLaw law = law_name == "coulomb"   ? WedgeLaw::coulomb
                         : law_name == "article" ? WedgeLaw::article
                                                 : throw InvalidInput("theory.wedge: law '" + law_name +
                                                                      "' is neither \"coulomb\" nor \"article\"");
    // Twelve lists of this many numbers stay well inside the script's 64 MB.
    if (duration / step > 100000.0) {
      throw InvalidInput("theory.wedge: duration / step is over 100000 samples; take a longer step or a shorter run");
    }
    const WedgeRun run = solve_wedge(drive, law, duration, step);
    // Given the world's step, the same equations stepped as the world steps them (the lists
    // end at the first flight).
    const std::optional<WedgeStepped> stepped =
        fields.has("world_step")
            ? std::optional<WedgeStepped>(step_as_the_world(drive, run, fields.number_in("world_step", "s", 0.0, 1.0, true)))
            : std::nullopt;
    const auto list = [&](const char* key, auto of) {
      lua_createtable(state, static_cast<int>(run.samples.size()), 0);
      for (std::size_t i = 0; i < run.samples.size(); ++i) {
        of(run.samples[i]);
        lua_rawseti(state, -2, static_cast<lua_Integer>(i + 1));
      }
      lua_setfield(state, -2, key);
    };
    const auto number_list = [&](const char* key, double WedgeState::*field) {
      list(key, [&](const WedgeState& sample) { lua_pushnumber(state, sample.*field); });
    };
    lua_createtable(state, 0, 16);
    number_list("slide", &WedgeState::slide);
    number_list("speed", &WedgeState::speed);
    number_list("height", &WedgeState::height);
    number_list("normal", &WedgeState::normal);
    number_list("friction", &WedgeState::friction);
    number_list("work_gravity", &WedgeState::work_gravity);
    number_list("work_pseudo", &WedgeState::work_pseudo);
    number_list("work_friction", &WedgeState::work_friction);
    number_list("work_landings", &WedgeState::work_landings);
    number_list("work_rotation", &WedgeState::work_rotation);
    list("kinetic", [&](const WedgeState& sample) { lua_pushnumber(state, kinetic_energy(drive, sample)); });
    list("contact", [&](const WedgeState& sample) {
      lua_pushstring(state, sample.contact == WedgeContact::stick ? "sticking"
                            : sample.contact == WedgeContact::slip ? "slipping"
                                                                   : "flying");
    });
    lua_createtable(state, static_cast<int>(run.events.size()), 0);
    for (std::size_t i = 0; i < run.events.size(); ++i) {
      const WedgeEvent& event = run.events[i];
      lua_createtable(state, 0, 4);
      set_number(state, "t", event.t);
      lua_pushstring(state, name_of(event.kind));
      lua_setfield(state, -2, "kind");
      set_number(state, "slide", event.slide);
      set_number(state, "speed", event.speed);
      lua_rawseti(state, -2, static_cast<lua_Integer>(i + 1));
    }
    lua_setfield(state, -2, "events");
    lua_createtable(state, static_cast<int>(run.slip_windows.size()), 0);
    for (std::size_t i = 0; i < run.slip_windows.size(); ++i) {
      lua_createtable(state, 2, 0);
      lua_pushnumber(state, run.slip_windows[i].first);
      lua_rawseti(state, -2, 1);
      lua_pushnumber(state, run.slip_windows[i].second);
      lua_rawseti(state, -2, 2);
      lua_rawseti(state, -2, static_cast<lua_Integer>(i + 1));
    }
    lua_setfield(state, -2, "slip_windows");
    if (stepped) {
      for (const auto& [key, values] : {std::pair{"stepped_slide", &stepped->slide}, std::pair{"stepped_speed", &stepped->speed}}) {
        lua_createtable(state, static_cast<int>(values->size()), 0);
        for (std::size_t i = 0; i < values->size(); ++i) {
          lua_pushnumber(state, (*values)[i]);
          lua_rawseti(state, -2, static_cast<lua_Integer>(i + 1));
        }
        lua_setfield(state, -2, key);
      }
    }
    set_number(state, "step", step);
    return 1;
  });
}

}  // namespace theory_written
}  // namespace frictionlab::lessons
