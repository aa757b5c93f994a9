// The machinery behind theory.*: how a theory function is described (its named arguments with
// unit, default and range, and the answer it gives) so that reading the arguments, refusing
// bad ones and building the answer's table is written once, here, and not again in every
// function. script_theory.cpp holds the one list of every theory function; the few that need
// more than a description can say (a model run over time, nested tables, an answer that is
// sometimes only words) are written out in script_theory_written.cpp.

#pragma once

#include <optional>
#include <variant>
#include <vector>

#include "lessons/runtime/build.h"

namespace frictionlab::lessons {

class TheoryValues;

// One named argument. Arguments are read in the order they are listed (the order a call's
// "it takes ..." message lists them), except that an argument whose default is another's
// reads that one first, as mu_s = mu_k must.
struct TheoryArgument {
  enum class Missing { required, constant, same_as, computed };
  struct Range {
    double low, high;
    bool low_open;
  };
  const char* key = nullptr;
  const char* unit = "";
  Missing missing = Missing::required;
  double fallback = 0.0;                                // Missing::constant
  const char* same_as = nullptr;                        // Missing::same_as: that argument's value
  double (*computed)(TheoryValues&) = nullptr;          // Missing::computed, from other arguments
  std::optional<Range> range = std::nullopt;            // checked on the value as given (degrees)
  bool in_degrees = false;                              // given in degrees, handed over in radians
};

// A required number (unit "" for a plain ratio such as mu_s), or one within [low, high]
// ((low, high] with low_open).
TheoryArgument needed(const char* key, const char* unit);
TheoryArgument needed_in(const char* key, const char* unit, double low, double high, bool low_open = false);
// A number that defaults to `fallback`; ranged, its value, given or not, must lie within [low, high].
TheoryArgument defaulted(const char* key, const char* unit, double fallback);
TheoryArgument defaulted_in(const char* key, const char* unit, double fallback, double low, double high);
// A number that defaults to another argument's value (mu_s = mu_k).
TheoryArgument same_as(const char* key, const char* unit, const char* other);
// A number that defaults to what `of` makes of other arguments (inertia = ½ m r²).
TheoryArgument computed(const char* key, const char* unit, double (*of)(TheoryValues&));
// `angle`: degrees from 0 to 90, handed over in radians.
TheoryArgument slope_angle();
// `g`, 9.81 m/s² unless given.
TheoryArgument gravity();

// The arguments of one call, each read from the script's table the first time it is asked for.
class TheoryValues {
 public:
  TheoryValues(Fields& fields, const std::vector<TheoryArgument>& arguments);
  // The argument's value (in radians for an angle). A key the description does not list is a
  // mistake in the description, not the script's: std::logic_error.
  double operator[](const char* key);

 private:
  double read(const TheoryArgument& argument);

  Fields& fields_;
  const std::vector<TheoryArgument>& arguments_;
  std::vector<std::optional<double>> values_;
};

// An answer: one number, or a table whose entries are set in the order listed (a number, true
// or false, or words).
using TheoryValue = std::variant<double, bool, const char*>;
struct TheoryEntry {
  const char* key;
  TheoryValue value;
};
using TheoryAnswer = std::variant<double, std::vector<TheoryEntry>>;

// One theory function: either described (arguments and answer) or written out by hand.
struct TheoryFunction {
  const char* name = nullptr;  // theory.NAME
  std::vector<TheoryArgument> arguments = {};
  TheoryAnswer (*answer)(TheoryValues&) = nullptr;
  lua_CFunction written = nullptr;
};
TheoryFunction described(const char* name, std::vector<TheoryArgument> arguments, TheoryAnswer (*answer)(TheoryValues&));
TheoryFunction written_out(const char* name, lua_CFunction function);

// Every theory function, in the order they are registered (script_theory.cpp).
const std::vector<TheoryFunction>& theory_functions();

// Calls a described function: the TheoryFunction is the closure's first upvalue.
int call_described(lua_State* state);

// Sets table[key] = value on the table at the stack top.
void set_number(lua_State* state, const char* key, double value);
void set_flag(lua_State* state, const char* key, bool value);

// The functions written out by hand (script_theory_written.cpp).
namespace theory_written {
int spring_stick_slip(lua_State* state);
int stacked_blocks(lua_State* state);
int intermittent_slide(lua_State* state);
int regularized_run(lua_State* state);
int regularized_creep(lua_State* state);
int thrown_box(lua_State* state);
int velocity_hack(lua_State* state);
int wedge(lua_State* state);
}  // namespace theory_written

}  // namespace frictionlab::lessons
