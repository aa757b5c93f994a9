// theory.*: the closed forms of physics/closed_forms.h, so a lesson's expectations use the
// same answers the tests check. Arguments are named (theory.tip_height{ width = 0.5,
// mu_s = 0.5 }); angles are in degrees, as everywhere in scripts; g defaults to 9.81 m/s².
//
// The table below is every theory function, in one place. Most are described: their arguments
// (with unit, default and range, read and refused by theory_binding.cpp) and the answer made of
// them. A function that needs more than that says is written out in script_theory_written.cpp
// and named here with written_out. To add one: describe it here (or write it out there and name
// it here), and give it a row in lessons/reference/theory.md's table of theory.* functions, which
// test_script_theory checks against this one.

#include "lessons/runtime/theory_binding.h"
#include "physics/closed_forms.h"

namespace frictionlab::lessons {
namespace {

// A pair's arguments by the names and units of the pair's table (physics/materials.h).
// μs and μk where a call cannot do without them.
const TheoryArgument static_mu = needed(static_coefficient.name, static_coefficient.unit);
const TheoryArgument kinetic_mu = needed(kinetic_coefficient.name, kinetic_coefficient.unit);
// The drag coefficients, c and b: off unless given.
const std::vector<TheoryArgument> drag_pair = [] {
  std::vector<TheoryArgument> arguments;
  for (const PairCoefficient& coefficient : pair_coefficients) {
    if (coefficient.drag) arguments.push_back(defaulted(coefficient.name, coefficient.unit, 0.0));
  }
  return arguments;
}();
// mu_s may be left out where only sliding matters (it then equals mu_k).
// (Listed mu_s first, as the calls' messages list them; reading it reads mu_k first.)
const std::vector<TheoryArgument> sliding_pair = [] {
  std::vector<TheoryArgument> arguments = {
      same_as(static_coefficient.name, static_coefficient.unit, kinetic_coefficient.name), kinetic_mu};
  arguments.insert(arguments.end(), drag_pair.begin(), drag_pair.end());
  return arguments;
}();

// A disk's or wheel's moment of inertia, unless given: a uniform disk's, ½ m r².
double uniform_disk(TheoryValues& values) { return 0.5 * values["mass"] * values["radius"] * values["radius"]; }

std::vector<TheoryArgument> joined(std::vector<TheoryArgument> first, const std::vector<TheoryArgument>& then,
                                   std::vector<TheoryArgument> last) {
  first.insert(first.end(), then.begin(), then.end());
  first.insert(first.end(), last.begin(), last.end());
  return first;
}

// The four coefficients, each read by its own name (physics/materials.h).
FrictionPair pair_of(TheoryValues& values) {
  FrictionPair pair;
  for (const PairCoefficient& coefficient : pair_coefficients) pair.*coefficient.value = values[coefficient.name];
  return pair;
}

// The order is the one the functions were always registered in (the order of `pairs(theory)`).
std::vector<TheoryFunction> make_table() {
  using Entries = std::vector<TheoryEntry>;
  return {
      described("sticking_angle", {static_mu},
                [](TheoryValues& v) -> TheoryAnswer { return theory::sticking_angle(v["mu_s"]) / degrees; }),
      described("incline_acceleration", {slope_angle(), kinetic_mu, gravity()},
                [](TheoryValues& v) -> TheoryAnswer {
                  return theory::incline_sliding_acceleration(v["angle"], v["mu_k"], v["g"]);
                }),
      described("incline_motion",
                joined({slope_angle(), kinetic_mu}, drag_pair,
                       {needed("mass", "kg"), needed("t", "s"), gravity(), defaulted_in("step", "s", 0.0, 0.0, 1.0)}),
                [](TheoryValues& v) -> TheoryAnswer {
                  const double angle = v["angle"], mu_k = v["mu_k"], c = v["c"], b = v["b"], mass = v["mass"];
                  const double g = v["g"], t = v["t"], step = v["step"];
                  if (step > 0.0) {
                    const theory::InclineSlide slide = theory::incline_slide_stepped(angle, mu_k, c, b, mass, g, t, step);
                    return Entries{{"speed", slide.speed}, {"distance", slide.distance}};
                  }
                  return Entries{{"speed", theory::incline_speed(angle, mu_k, c, b, mass, g, t)},
                                 {"distance", theory::incline_distance(angle, mu_k, c, b, mass, g, t)}};
                }),
      described("tip_height", {needed("width", "m"), static_mu},
                [](TheoryValues& v) -> TheoryAnswer { return theory::tip_height(v["width"], v["mu_s"]); }),
      described("push_outcome",
                {needed("mass", "kg"), needed("width", "m"), needed("push_height", "m"), static_mu, gravity()},
                [](TheoryValues& v) -> TheoryAnswer {
                  const theory::PushOutcome outcome =
                      theory::push_outcome(v["mass"] * v["g"], v["width"], v["push_height"], v["mu_s"]);
                  return Entries{{"outcome", outcome.tips ? "tips" : "slides"}, {"force", outcome.force}};
                }),
      written_out("spring_stick_slip", theory_written::spring_stick_slip),
      described("slide_to_rest", joined({needed("v0", "m/s"), needed("mass", "kg")}, sliding_pair, {gravity()}),
                [](TheoryValues& v) -> TheoryAnswer {
                  const theory::SlideToRest rest = theory::slide_to_rest(v["v0"], v["mass"], pair_of(v), v["g"]);
                  return Entries{{"time", rest.time}, {"distance", rest.distance}};
                }),
      described("disk_on_incline",
                {slope_angle(), needed("mass", "kg"), needed("radius", "m"), computed("inertia", "kg·m²", uniform_disk),
                 static_mu, kinetic_mu, gravity()},
                [](TheoryValues& v) -> TheoryAnswer {
                  const theory::DiskOnIncline disk = theory::disk_on_incline(
                      v["angle"], v["mass"], v["radius"], v["inertia"], v["mu_s"], v["mu_k"], v["g"]);
                  return Entries{{"rolls", disk.rolls},
                                 {"acceleration", disk.acceleration},
                                 {"angular_acceleration", disk.angular_acceleration},
                                 {"friction_force", disk.friction_force}};
                }),
      described("disk_starts_rolling",
                {needed("v0", "m/s"), needed("mass", "kg"), needed("radius", "m"),
                 computed("inertia", "kg·m²", uniform_disk), kinetic_mu, gravity()},
                [](TheoryValues& v) -> TheoryAnswer {
                  const theory::RollStart start =
                      theory::disk_starts_rolling(v["v0"], v["mass"], v["radius"], v["inertia"], v["mu_k"], v["g"]);
                  return Entries{{"time", start.time}, {"speed", start.speed}, {"distance", start.distance}};
                }),
      written_out("stacked_blocks", theory_written::stacked_blocks),
      described("connected_masses",
                {needed("block_mass", "kg"), needed("hanging_mass", "kg"), static_mu, kinetic_mu,
                 gravity()},
                [](TheoryValues& v) -> TheoryAnswer {
                  const theory::ConnectedMasses pulled =
                      theory::connected_masses(v["block_mass"], v["hanging_mass"], v["mu_s"], v["mu_k"], v["g"]);
                  return Entries{{"slides", pulled.slides},
                                 {"acceleration", pulled.acceleration},
                                 {"tension", pulled.tension},
                                 {"friction", pulled.friction},
                                 {"heaviest_held", pulled.heaviest_held}};
                }),
      described("driven_wheel",
                {needed("mass", "kg"), needed("radius", "m"), computed("inertia", "kg·m²", uniform_disk),
                 needed("torque", "N·m"), static_mu, kinetic_mu, gravity()},
                [](TheoryValues& v) -> TheoryAnswer {
                  const theory::DrivenWheel wheel = theory::driven_wheel(v["mass"], v["radius"], v["inertia"], v["torque"],
                                                                         v["mu_s"], v["mu_k"], v["g"]);
                  return Entries{{"rolls", wheel.rolls},
                                 {"acceleration", wheel.acceleration},
                                 {"angular_acceleration", wheel.angular_acceleration},
                                 {"friction", wheel.friction},
                                 {"traction_limit", wheel.traction_limit}};
                }),
      written_out("intermittent_slide", theory_written::intermittent_slide),
      described("growing_push",
                joined({needed("mass", "kg"), needed("rate", "N/s")}, sliding_pair,
                       {defaulted_in("t", "s", 0.0, 0.0, 86400.0), gravity()}),
                [](TheoryValues& v) -> TheoryAnswer {
                  const theory::GrowingPush push = theory::growing_push(v["mass"], v["rate"], pair_of(v), v["g"], v["t"]);
                  return Entries{{"breakaway_push", push.breakaway_push},
                                 {"breakaway_time", push.breakaway_time},
                                 {"push", push.push},
                                 {"friction", push.friction},
                                 {"acceleration", push.acceleration},
                                 {"speed", push.speed},
                                 {"distance", push.distance}};
                }),
      written_out("thrown_box", theory_written::thrown_box),
      described("slope_launch",
                {needed("v0", "m/s"), slope_angle(), static_mu, kinetic_mu, gravity()},
                [](TheoryValues& v) -> TheoryAnswer {
                  const theory::SlopeLaunch launch = theory::slope_launch(v["v0"], v["angle"], v["mu_s"], v["mu_k"], v["g"]);
                  return Entries{{"distance", launch.distance},
                                 {"time", launch.time},
                                 {"then", launch.stays ? "stays" : "slides back"}};
                }),
      written_out("velocity_hack", theory_written::velocity_hack),
      written_out("wedge", theory_written::wedge),
      written_out("regularized_run", theory_written::regularized_run),
      written_out("regularized_creep", theory_written::regularized_creep),
  };
}

}  // namespace

const std::vector<TheoryFunction>& theory_functions() {
  static const std::vector<TheoryFunction> table = make_table();
  return table;
}

void register_theory_api(lua_State* state) {
  const std::vector<TheoryFunction>& table = theory_functions();
  lua_createtable(state, 0, static_cast<int>(table.size()));
  for (const TheoryFunction& function : table) {
    if (function.written != nullptr) {
      lua_pushcfunction(state, function.written);
    } else {
      // The description travels with the call as its upvalue; the table lives as long as the program.
      lua_pushlightuserdata(state, const_cast<TheoryFunction*>(&function));
      lua_pushcclosure(state, call_described, 1);
    }
    lua_setfield(state, -2, function.name);
  }
  lua_setglobal(state, "theory");
}

}  // namespace frictionlab::lessons
