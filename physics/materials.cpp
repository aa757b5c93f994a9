#include "physics/materials.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <sstream>

namespace frictionlab {
namespace {

std::string pair_name(std::string_view a, std::string_view b) {
  std::string name(a);
  name += "–";
  name += b;
  return name;
}

void check_coefficient(std::vector<std::string>& errors, const std::string& pair, const PairCoefficient& coefficient,
                       double value) {
  if (std::isnan(value) || value < 0.0 || value > coefficient.largest) {
    std::ostringstream message;
    message << "pair " << pair << ": " << coefficient.name << " = " << value
            << (*coefficient.unit == '\0' ? "" : " ") << coefficient.unit << " is outside the allowed range [0, "
            << coefficient.largest << "]";
    errors.push_back(message.str());
  }
}

}  // namespace

std::string_view treatment_name(FrictionTreatment treatment) {
  switch (treatment) {
    case FrictionTreatment::stick_slip: return "stick-slip";
    case FrictionTreatment::threshold: return "threshold";
    case FrictionTreatment::regularized: return "regularized";
    case FrictionTreatment::box2d: return "box2d";
  }
  return "?";
}

FrictionTreatment parse_treatment(std::string_view name) {
  for (FrictionTreatment t : {FrictionTreatment::stick_slip, FrictionTreatment::threshold,
                              FrictionTreatment::regularized, FrictionTreatment::box2d}) {
    if (name == treatment_name(t)) return t;
  }
  throw InvalidInput("unknown friction treatment '" + std::string(name) +
                     "'; allowed: stick-slip, threshold, regularized, box2d");
}

bool uses_epsilon(FrictionTreatment treatment) {
  return treatment == FrictionTreatment::threshold || treatment == FrictionTreatment::regularized;
}

const PairCoefficient* pair_coefficient(std::string_view name) {
  for (const PairCoefficient& coefficient : pair_coefficients) {
    if (coefficient.name == name) return &coefficient;
  }
  return nullptr;
}

std::string PairTable::material_names() const {
  std::string names;
  for (const Material& material : materials_) {
    if (!names.empty()) names += ", ";
    names += material.name;
  }
  return names;
}

std::string pair_coefficient_names() {
  std::string names;
  for (const PairCoefficient& coefficient : pair_coefficients) {
    if (!names.empty()) names += ", ";
    names += coefficient.name;
  }
  return names;
}

PairCheck check_pair(std::string_view material_a, std::string_view material_b, const FrictionPair& pair) {
  PairCheck check;
  const std::string name = pair_name(material_a, material_b);
  for (const PairCoefficient& coefficient : pair_coefficients) {
    check_coefficient(check.errors, name, coefficient, pair.*coefficient.value);
  }
  if (check.errors.empty() && pair.mu_k > pair.mu_s) {
    std::ostringstream message;
    message << "pair " << name << ": mu_k = " << pair.mu_k << " is larger than mu_s = " << pair.mu_s
            << " (allowed, but sliding then needs more force than breaking away)";
    check.warnings.push_back(message.str());
  }
  return check;
}

void PairTable::grow(int new_count) {
  const int old_count = material_count();
  std::vector<FrictionPair> pairs(static_cast<size_t>(new_count * new_count));
  std::vector<char> set(pairs.size(), 0);
  std::vector<PairTreatment> treatments(pairs.size());
  for (int a = 0; a < old_count; ++a) {
    for (int b = 0; b < old_count; ++b) {
      pairs[a * new_count + b] = pairs_[a * old_count + b];
      set[a * new_count + b] = pair_set_[a * old_count + b];
      treatments[a * new_count + b] = treatments_[a * old_count + b];
    }
  }
  pairs_ = std::move(pairs);
  pair_set_ = std::move(set);
  treatments_ = std::move(treatments);
  revise();
}

void PairTable::revise() {
  // One count for every table: a table copied from another keeps its stamp, one changed since
  // gets a new one that no other table has had.
  static std::atomic<unsigned long> revisions{0};
  revision_ = ++revisions;
}

int PairTable::add_material(const Material& material) {
  if (material.name.empty()) throw InvalidInput("material: the name must not be empty");
  for (const Material& known : materials_) {
    if (known.name == material.name) throw InvalidInput("material '" + material.name + "': defined twice");
  }
  // Box2D keeps masses in floats; far below 1e-3 kg/m² a body's mass rounds to nothing.
  if (!(material.density >= 1e-3 && material.density <= 1e6)) {
    std::ostringstream message;
    message << "material " << material.name << ": density = " << material.density
            << " kg/m² is outside the allowed range [0.001, 1e6]";
    throw InvalidInput(message.str());
  }
  grow(material_count() + 1);
  materials_.push_back(material);
  return material_count() - 1;
}

int PairTable::find_material(std::string_view name) const {
  for (int id = 0; id < material_count(); ++id) {
    if (materials_[id].name == name) return id;
  }
  return -1;
}

int PairTable::material_id(std::string_view name) const {
  if (const int id = find_material(name); id >= 0) return id;
  std::string message = "unknown material '" + std::string(name) + "'; known materials:";
  for (const Material& known : materials_) message += " " + known.name;
  throw InvalidInput(message);
}

std::vector<std::string> PairTable::set_pair(std::string_view a, std::string_view b, const FrictionPair& pair) {
  const int id_a = material_id(a);
  const int id_b = material_id(b);
  PairCheck check = check_pair(a, b, pair);
  if (!check.errors.empty()) {
    std::string message = check.errors.front();
    for (size_t i = 1; i < check.errors.size(); ++i) message += "; " + check.errors[i];
    throw InvalidInput(message);
  }
  std::erase_if(shares_, [&](const Share& share) {
    return (share.a == id_a && share.b == id_b) || (share.a == id_b && share.b == id_a);
  });
  store(id_a, id_b, pair);
  return check.warnings;
}

void PairTable::store(int a, int b, const FrictionPair& pair) {
  const int n = material_count();
  pairs_[a * n + b] = pair;
  pairs_[b * n + a] = pair;
  revise();
  pair_set_[a * n + b] = 1;
  pair_set_[b * n + a] = 1;
  for (const Share& share : shares_) {
    const bool led = (share.leader_a == a && share.leader_b == b) || (share.leader_a == b && share.leader_b == a);
    if (led) store(share.a, share.b, pair);
  }
}

bool PairTable::is_shared(int a, int b) const {
  return std::any_of(shares_.begin(), shares_.end(), [&](const Share& share) {
    return (share.a == a && share.b == b) || (share.a == b && share.b == a);
  });
}

void PairTable::share_pair(std::string_view a, std::string_view b, std::string_view leader_a,
                           std::string_view leader_b) {
  const int id_a = material_id(a), id_b = material_id(b);
  const int lead_a = material_id(leader_a), lead_b = material_id(leader_b);
  if (!has_pair(lead_a, lead_b)) {
    throw InvalidInput("pair " + pair_name(a, b) + ": the pair " + pair_name(leader_a, leader_b) +
                       " it takes its values from has none yet; set that one first");
  }
  const bool same = (id_a == lead_a && id_b == lead_b) || (id_a == lead_b && id_b == lead_a);
  if (same) throw InvalidInput("pair " + pair_name(a, b) + ": cannot take its values from itself");
  // A leader never follows another pair, so sharing cannot go round in a circle.
  for (const Share& share : shares_) {
    if ((share.a == lead_a && share.b == lead_b) || (share.a == lead_b && share.b == lead_a)) {
      throw InvalidInput("pair " + pair_name(a, b) + ": " + pair_name(leader_a, leader_b) +
                         " takes its own values from " + pair_name(materials_[share.leader_a].name, materials_[share.leader_b].name) +
                         "; name that pair instead");
    }
  }
  std::erase_if(shares_, [&](const Share& share) {
    return (share.a == id_a && share.b == id_b) || (share.a == id_b && share.b == id_a);
  });
  shares_.push_back({id_a, id_b, lead_a, lead_b});
  store(id_a, id_b, pair(lead_a, lead_b));
}

void PairTable::set_treatment(std::string_view a, std::string_view b, FrictionTreatment treatment,
                              std::optional<double> epsilon) {
  const int id_a = material_id(a);
  const int id_b = material_id(b);
  const std::string name = pair_name(a, b);
  if (!has_pair(id_a, id_b)) throw InvalidInput("pair " + name + ": set its friction values before its treatment");
  if (epsilon && !uses_epsilon(treatment)) {
    throw InvalidInput("pair " + name + ": epsilon is for the threshold and regularized treatments, not " +
                       std::string(treatment_name(treatment)));
  }
  if (epsilon && !(*epsilon > 0.0 && *epsilon <= 100.0)) {
    std::ostringstream message;
    message << "pair " << name << ": epsilon = " << *epsilon << " m/s is outside the allowed range (0, 100]";
    throw InvalidInput(message.str());
  }
  const PairTreatment own{true, treatment, epsilon.value_or(0.0)};
  treatments_[static_cast<size_t>(pair_index(id_a, id_b))] = own;
  treatments_[static_cast<size_t>(pair_index(id_b, id_a))] = own;
  revise();
}

bool PairTable::has_pair(int a, int b) const {
  return a >= 0 && b >= 0 && a < material_count() && b < material_count() && pair_set_[a * material_count() + b];
}

const FrictionPair& PairTable::pair(int a, int b) const {
  if (!has_pair(a, b)) {
    const std::string name_a = (a >= 0 && a < material_count()) ? materials_[a].name : "?";
    const std::string name_b = (b >= 0 && b < material_count()) ? materials_[b].name : "?";
    throw InvalidInput("no friction values for the pair " + pair_name(name_a, name_b) + "; set them with set_pair");
  }
  return pairs_[a * material_count() + b];
}

const FrictionPair& PairTable::pair(std::string_view a, std::string_view b) const {
  return pair(material_id(a), material_id(b));
}

PairTable preset_table() {
  PairTable table;
  // Densities are per unit area of the 2D shape; only their ratios matter for friction,
  // since N = m·g and the friction limit scale together.
  const Material materials[] = {
      {"metal", 7800.0, "steel; tribology article's table"},
      {"wood", 600.0, "dry timber; tribology article's table"},
      {"rubber", 1100.0, "tyre rubber; tribology article's table"},
      {"concrete", 2400.0, "tribology article's table"},
      {"stone", 2600.0, "tribology article's table"},
      {"aluminium", 2700.0, "the spring article's aluminium block"},
      {"plastic", 1200.0, "the spring article's 3D-printed plastic block"},
      {"asphalt", 2300.0, "terrain"},
      {"grass", 1000.0, "terrain"},
      {"ice", 917.0, "terrain"},
  };
  for (const Material& material : materials) table.add_material(material);

  // Static coefficients sit inside the ranges of the tribology article's Table 2; kinetic ones
  // are a little lower, as the article says they usually are.
  table.set_pair("metal", "metal", {0.18, 0.14, 0.0, 0.0});     // table: 0.15–0.20
  table.set_pair("wood", "wood", {0.40, 0.30, 0.0, 0.0});       // table: 0.25–0.50
  table.set_pair("metal", "wood", {0.40, 0.30, 0.0, 0.0});      // table: 0.20–0.60
  table.set_pair("rubber", "concrete", {0.80, 0.65, 0.0, 0.0});  // table: 0.60–0.90
  table.set_pair("metal", "stone", {0.50, 0.40, 0.0, 0.0});     // table: 0.30–0.70
  // The spring article: the aluminium block needs more force than the plastic one both to
  // break away and to keep sliding.
  table.set_pair("aluminium", "wood", {0.45, 0.35, 0.0, 0.0});
  table.set_pair("plastic", "wood", {0.30, 0.22, 0.0, 0.0});
  // Terrain under a rubber tyre and under a wooden crate (the article's game examples).
  table.set_pair("rubber", "asphalt", {0.90, 0.70, 0.0, 0.0});
  table.set_pair("rubber", "grass", {0.45, 0.35, 0.0, 0.0});
  table.set_pair("rubber", "ice", {0.10, 0.05, 0.0, 0.0});
  table.set_pair("wood", "asphalt", {0.55, 0.45, 0.0, 0.0});
  table.set_pair("wood", "grass", {0.45, 0.35, 0.0, 0.0});
  table.set_pair("wood", "ice", {0.08, 0.04, 0.0, 0.0});
  return table;
}

}  // namespace frictionlab
