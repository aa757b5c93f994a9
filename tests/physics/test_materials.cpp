#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>

#include "physics/materials.h"
#include "tests/assertions.h"

using namespace frictionlab;

TEST(PairTable, IsSymmetricAndReadsBothWays) {
  PairTable table;
  table.add_material({"wood", 600.0, ""});
  table.add_material({"ice", 917.0, ""});
  table.set_pair("wood", "ice", {0.08, 0.04, 1.5, 0.2});
  EXPECT_DOUBLE_EQ(table.pair("ice", "wood").mu_s, 0.08);
  EXPECT_DOUBLE_EQ(table.pair("wood", "ice").c, 1.5);
  EXPECT_DOUBLE_EQ(table.pair(table.material_id("ice"), table.material_id("wood")).b, 0.2);
}

TEST(PairTable, KeepsPairsWhenMaterialsAreAdded) {
  PairTable table;
  table.add_material({"a", 1.0, ""});
  table.add_material({"b", 1.0, ""});
  table.set_pair("a", "b", {0.5, 0.3, 0.0, 0.0});
  table.add_material({"c", 1.0, ""});
  EXPECT_DOUBLE_EQ(table.pair("b", "a").mu_k, 0.3);
  EXPECT_FALSE(table.has_pair(table.material_id("a"), table.material_id("c")));
}

TEST(PairTable, RejectsBadValuesNamingThePairAndRange) {
  PairTable table;
  table.add_material({"metal", 7800.0, ""});
  table.add_material({"wood", 600.0, ""});
  const FrictionPair bad[] = {{-0.1, 0.1, 0.0, 0.0}, {0.5, NAN, 0.0, 0.0}, {0.5, 0.4, -1.0, 0.0},
                              {0.5, 0.4, 0.0, -2.0}, {11.0, 0.4, 0.0, 0.0}};
  for (const FrictionPair& pair : bad) {
    expect_invalid([&] { table.set_pair("metal", "wood", pair); }, "pair metal–wood", "allowed range");
  }
  EXPECT_FALSE(table.has_pair(0, 1)) << "a rejected pair must leave the table unchanged";
}

// The pair's one table: each coefficient names its own value, distinct from the others, is found
// by its name, and its largest value is the one the table accepts, one step past it refused with
// the coefficient's name and unit in the message.
TEST(PairCoefficients, EachIsItsOwnValueAndItsLargestIsTheOneChecked) {
  std::set<std::string> names;
  for (const PairCoefficient& coefficient : pair_coefficients) {
    names.insert(coefficient.name);
    for (const PairCoefficient& other : pair_coefficients) {
      if (&other != &coefficient) {
        EXPECT_NE(other.value, coefficient.value) << coefficient.name << " and " << other.name;
      }
    }
    EXPECT_EQ(pair_coefficient(coefficient.name), &coefficient);
    EXPECT_GT(coefficient.lesson_largest, 0.0);
    EXPECT_LE(coefficient.lesson_largest, coefficient.largest) << "a slider offers no value the physics refuses";
    FrictionPair pair{0.5, 0.4, 0.0, 0.0};
    pair.*coefficient.value = coefficient.largest;
    if (pair.mu_k > pair.mu_s) pair.mu_s = pair.mu_k;
    EXPECT_TRUE(check_pair("a", "b", pair).errors.empty()) << coefficient.name;
    pair.*coefficient.value = std::nextafter(coefficient.largest, INFINITY);
    const PairCheck past = check_pair("a", "b", pair);
    ASSERT_EQ(past.errors.size(), 1u) << coefficient.name;
    EXPECT_EQ(past.errors[0].find(std::string(coefficient.name) + " = "), past.errors[0].find(": ") + 2) << past.errors[0];
    EXPECT_NE(past.errors[0].find(coefficient.unit), std::string::npos) << past.errors[0];
  }
  EXPECT_EQ(names.size(), std::size(pair_coefficients));
  EXPECT_EQ(pair_coefficient("mu"), nullptr);
  EXPECT_EQ(pair_coefficient_names(), "mu_s, mu_k, c, b");
}

TEST(PairTable, FlagsKineticAboveStaticButAllowsIt) {
  PairTable table;
  table.add_material({"x", 1.0, ""});
  const auto warnings = table.set_pair("x", "x", {0.3, 0.5, 0.0, 0.0});
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("mu_k"), std::string::npos);
  EXPECT_DOUBLE_EQ(table.pair("x", "x").mu_k, 0.5);
}

TEST(PairTable, UnknownMaterialListsKnownOnes) {
  PairTable table = preset_table();
  expect_invalid([&] { table.material_id("unobtainium"); }, "unknown material 'unobtainium'", "aluminium");
  EXPECT_THROW(table.pair("ice", "metal"), InvalidInput) << "a pair never set is an error, not zero friction";
  EXPECT_THROW(table.add_material({"wood", 1.0, ""}), InvalidInput);
  EXPECT_THROW(table.add_material({"foam", -1.0, ""}), InvalidInput);
  EXPECT_THROW(table.add_material({"", 1.0, ""}), InvalidInput);
}

TEST(Presets, StaticCoefficientsLieInTheTribologyTableRanges) {
  const PairTable table = preset_table();
  struct Range {
    const char* a;
    const char* b;
    double low, high;
  };
  // Table 2 of the tribology article.
  const Range ranges[] = {{"metal", "metal", 0.15, 0.20}, {"wood", "wood", 0.25, 0.50}, {"metal", "wood", 0.20, 0.60},
                          {"rubber", "concrete", 0.60, 0.90}, {"metal", "stone", 0.30, 0.70}};
  for (const Range& r : ranges) {
    const FrictionPair& pair = table.pair(r.a, r.b);
    EXPECT_GE(pair.mu_s, r.low) << r.a << "–" << r.b;
    EXPECT_LE(pair.mu_s, r.high) << r.a << "–" << r.b;
    EXPECT_LT(pair.mu_k, pair.mu_s) << r.a << "–" << r.b;
  }
}

TEST(Presets, AluminiumNeedsMoreForceThanPlasticBothWays) {
  // The spring article's observation, on the same wooden bench.
  const PairTable table = preset_table();
  EXPECT_GT(table.pair("aluminium", "wood").mu_s, table.pair("plastic", "wood").mu_s);
  EXPECT_GT(table.pair("aluminium", "wood").mu_k, table.pair("plastic", "wood").mu_k);
  EXPECT_LT(table.pair("rubber", "ice").mu_s, table.pair("rubber", "grass").mu_s);
  EXPECT_LT(table.pair("rubber", "grass").mu_s, table.pair("rubber", "asphalt").mu_s);
}

// The friction treatments by name, and a pair's own treatment refused (and the pair left as it
// was) until its values are set, with an epsilon for a treatment that has none, or out of range.
TEST(Treatments, NamesRoundTripAndUnknownNamesListTheAllowed) {
  for (FrictionTreatment t : {FrictionTreatment::stick_slip, FrictionTreatment::threshold,
                              FrictionTreatment::regularized, FrictionTreatment::box2d}) {
    EXPECT_EQ(parse_treatment(treatment_name(t)), t);
  }
  expect_invalid([] { parse_treatment("sticky"); }, "sticky", "stick-slip, threshold, regularized, box2d");
}

TEST(PairTreatment, BadTreatmentsAndEpsilonsAreRefusedAndLeaveThePairAsItWas) {
  PairTable table;
  table.add_material({"a", 1.0, ""});
  table.add_material({"b", 1.0, ""});
  auto message = [&](auto&& call) {
    try {
      call();
    } catch (const InvalidInput& error) {
      return std::string(error.what());
    }
    return std::string("(accepted)");
  };
  EXPECT_EQ(message([&] { table.set_treatment("a", "b", FrictionTreatment::regularized, 0.05); }),
            "pair a–b: set its friction values before its treatment");
  table.set_pair("a", "b", {0.6, 0.3, 0.0, 0.0});
  EXPECT_EQ(message([&] { table.set_treatment("a", "b", FrictionTreatment::box2d, 0.05); }),
            "pair a–b: epsilon is for the threshold and regularized treatments, not box2d");
  EXPECT_EQ(message([&] { table.set_treatment("a", "b", FrictionTreatment::threshold, -1.0); }),
            "pair a–b: epsilon = -1 m/s is outside the allowed range (0, 100]");
  EXPECT_EQ(message([&] { parse_treatment("coulomb"); }),
            "unknown friction treatment 'coulomb'; allowed: stick-slip, threshold, regularized, box2d");
  EXPECT_FALSE(table.treatment(0, 1).own);
  table.set_treatment("b", "a", FrictionTreatment::threshold, 0.2);
  EXPECT_TRUE(table.treatment(0, 1).own);
  EXPECT_EQ(table.treatment(0, 1).epsilon, 0.2);
}
