// Materials and the symmetric table of friction parameters for each pair of them.
#pragma once

#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace frictionlab {

// Bad input from a user, a script or the command line: the message names the thing and the
// allowed range. Callers turn it into exit code 2 or an on-screen error; it never aborts.
struct InvalidInput : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

// Friction belongs to a pair of surfaces, not to one material.
struct FrictionPair {
  double mu_s = 0.0;  // static coefficient: holds until |friction| reaches mu_s * N
  double mu_k = 0.0;  // kinetic coefficient: sliding friction is mu_k * N
  double c = 0.0;     // viscous coefficient, N·s/m: F = -c·v
  double b = 0.0;     // quadratic coefficient, N·s²/m²: F = -b·v²·sign(v)
};

// The pair's four coefficients, described once: the physics checks a pair against this table,
// the script runtime makes pair{}'s fields, sliders and timed values from it, and the theory,
// the mystery and the window find a coefficient here by the name scripts, --set and setup
// files spell it with.
struct PairCoefficient {
  const char* name;  // "mu_s": a script's field, a slider's parameter (after the pair's prefix)
  const char* unit;  // "" for the dimensionless coefficients
  double FrictionPair::*value;  // which of the pair's values it is
  // A lesson's slider, and a value a script gives, run from 0 to this: the range every lesson's
  // theory rows are held to (the random settings of `check --random`), past any classroom surface.
  double lesson_largest;
  // The physics refuses more than this from anyone (a C++ caller, a benchmark): above a μ of 10
  // no real pair of surfaces exists and the solver's impulses stop meaning anything; drag past
  // 1e6 outruns any step.
  double largest;
  const char* meaning;  // "static friction coefficient", as a slider's tooltip says it
  // The meaning in one word, after the coefficient's letter on its slider ("μs static"): the
  // Parameters panel's names column is a third of the panel, too narrow for `meaning`.
  const char* word;
  // A drag coefficient, off at 0 (a pair's folded line leaves it out then); dry friction's are not.
  bool drag;
};
inline constexpr PairCoefficient pair_coefficients[] = {
    {"mu_s", "", &FrictionPair::mu_s, 2.0, 10.0, "static friction coefficient", "static", false},
    {"mu_k", "", &FrictionPair::mu_k, 2.0, 10.0, "kinetic friction coefficient", "kinetic", false},
    {"c", "N·s/m", &FrictionPair::c, 1000.0, 1e6, "viscous drag coefficient", "viscous", true},
    {"b", "N·s²/m²", &FrictionPair::b, 1000.0, 1e6, "quadratic drag coefficient", "quadratic", true},
};
// The dry pair, μs and μk, which the window takes together (a pair's presets, a mystery, the
// stability map's boundary): by the table's rows, so their names are spelt here alone.
inline constexpr const PairCoefficient& static_coefficient = pair_coefficients[0];
inline constexpr const PairCoefficient& kinetic_coefficient = pair_coefficients[1];
// The coefficient of that name; nullptr when it is none of the four.
const PairCoefficient* pair_coefficient(std::string_view name);
// "mu_s, mu_k, c, b", for messages that list them.
std::string pair_coefficient_names();

// How the dry (Coulomb) part of friction is treated; selectable per run so they can be compared,
// and per pair so that one world can hold them side by side (physics/treatment.h).
enum class FrictionTreatment {
  stick_slip,   // each contact sticks (mu_s) or slips (mu_k), switched by what the solver did
  threshold,    // mu_s below a sliding speed epsilon, mu_k above: the usual game approach
  regularized,  // the tribology article's F = mu_s·N·v/epsilon below epsilon, an explicit force
  box2d,        // Box2D's single coefficient (mu_k of the pair) for sticking and sliding alike
};
std::string_view treatment_name(FrictionTreatment treatment);
// Throws InvalidInput listing the allowed names.
FrictionTreatment parse_treatment(std::string_view name);
// Whether the treatment has a threshold speed epsilon (threshold and regularized).
bool uses_epsilon(FrictionTreatment treatment);

// A pair's own treatment. A pair without one follows the run's (StepSettings::treatment, the
// command line's --friction, the window's Simulation menu); a pair that names one keeps it
// whatever the run's is, so a lesson can set a regularized block beside a stick-slip one.
struct PairTreatment {
  bool own = false;
  FrictionTreatment treatment = FrictionTreatment::stick_slip;
  double epsilon = 0.0;  // m/s, threshold and regularized; 0: the run's threshold speed
};

struct Material {
  std::string name;
  double density = 1.0;  // kg/m² (2D bodies have area, not volume)
  std::string note;      // where the numbers come from, shown to teachers
};

// Problems with a pair's values, each naming the pair and the allowed range. Empty when valid.
// mu_k > mu_s is allowed (some surfaces do it) but listed in `warnings`.
struct PairCheck {
  std::vector<std::string> errors;
  std::vector<std::string> warnings;
};
PairCheck check_pair(std::string_view material_a, std::string_view material_b, const FrictionPair& pair);

class PairTable {
 public:
  // Returns the material's id; throws InvalidInput for an empty or repeated name or a
  // density outside [0.001, 1e6] kg/m².
  int add_material(const Material& material);
  // Throws InvalidInput naming the unknown material and listing the known ones.
  int material_id(std::string_view name) const;
  // -1 when there is no such material.
  int find_material(std::string_view name) const;
  const Material& material(int id) const { return materials_.at(id); }
  int material_count() const { return static_cast<int>(materials_.size()); }
  // The materials' names in the order they were added, ", " between (for messages).
  std::string material_names() const;

  // Sets the pair in both orders. Throws InvalidInput (see check_pair) and leaves the table
  // unchanged when the values are invalid; returns the warnings otherwise.
  std::vector<std::string> set_pair(std::string_view a, std::string_view b, const FrictionPair& pair);
  bool has_pair(int a, int b) const;
  // Throws InvalidInput naming both materials when the pair was never set.
  const FrictionPair& pair(int a, int b) const;
  const FrictionPair& pair(std::string_view a, std::string_view b) const;

  // Makes the pair a-b take the values of the pair leader_a-leader_b (which must be set), now
  // and whenever those are set again: several pairs with one set of sliders, each free to
  // have its own treatment. Setting a-b's own values later ends the sharing.
  void share_pair(std::string_view a, std::string_view b, std::string_view leader_a, std::string_view leader_b);
  bool is_shared(int a, int b) const;

  // Gives the pair (already set) its own treatment. epsilon (m/s, in (0, 100]) is for the
  // threshold and regularized treatments only; without it they use the run's threshold speed.
  // Throws InvalidInput naming the pair and the allowed values; the table is then unchanged.
  void set_treatment(std::string_view a, std::string_view b, FrictionTreatment treatment,
                     std::optional<double> epsilon = std::nullopt);
  const PairTreatment& treatment(int a, int b) const { return treatments_[pair_index(a, b)]; }

  // A pair's place in the table, fixed once every material is added: the contact listener
  // finds it when a contact begins and then reads the values in place at every step, so live
  // edits still reach running contacts. Both ids must be valid.
  int pair_index(int a, int b) const { return a * material_count() + b; }
  const FrictionPair& pair_at(int index) const { return pairs_[static_cast<size_t>(index)]; }
  const PairTreatment& treatment_at(int index) const { return treatments_[static_cast<size_t>(index)]; }
  // Changes whenever a pair's values or treatment change (or materials are added), and is
  // never the same for two different tables' contents: what is worked out from the whole table
  // (whether any pair has drag) is worked out again only when it changes.
  unsigned long revision() const { return revision_; }

 private:
  unsigned long revision_ = 0;
  void revise();
  std::vector<Material> materials_;
  // Dense, symmetric, indexed by id: the contact listener reads it every step for every
  // contact, so a lookup must cost two multiplies, not a hash.
  std::vector<FrictionPair> pairs_;
  std::vector<char> pair_set_;
  std::vector<PairTreatment> treatments_;
  struct Share {
    int a, b, leader_a, leader_b;
  };
  std::vector<Share> shares_;
  void store(int a, int b, const FrictionPair& pair);
  void grow(int new_count);
};

// The seed articles' materials and pairs: the tribology article's table of static
// coefficients (each mu_s inside its published range, mu_k a little below it), the spring
// article's aluminium and plastic blocks on a wooden bench, and terrain under a rubber tyre.
PairTable preset_table();

}  // namespace frictionlab
