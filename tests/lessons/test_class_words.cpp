// A script's names in the class's words (lessons/runtime/class_words.h), as the window, the
// pictures and the messages say them. That every built-in lesson's names reach the class so,
// in the window and its plots, is tested with the plots (tests/draw/test_plots.cpp).
#include <gtest/gtest.h>

#include "lessons/runtime/class_words.h"

namespace frictionlab::lessons {
namespace {

// A script's names as the class reads them: underscores become spaces, mu_s and mu_k the
// window's μs and μk, theta and omega their letters, a_x as aₓ.
TEST(ClassWords, UnderscoresBecomeSpacesAndMuTheGreekLetter) {
  EXPECT_EQ(class_words("friction_force"), "friction force");
  EXPECT_EQ(class_words("slide_reduced"), "slide reduced");
  EXPECT_EQ(class_words("mu_s"), "\u03bcs");
  EXPECT_EQ(class_words("mu_k_top"), "\u03bck top");
  EXPECT_EQ(class_words("six_feet_load_"), "six feet load");
  EXPECT_EQ(class_words("__a__b"), "a b");
  EXPECT_EQ(class_words("lubricated_mu"), "lubricated \u03bc");
  EXPECT_EQ(class_words("mu_x"), "\u03bc x");
  EXPECT_EQ(class_words("music_k"), "music k") << "mu only as a word of its own";
  EXPECT_EQ(class_words("speed"), "speed");
  // The Greek letters wedge's sliders spelt out, and a letter's index below the line.
  EXPECT_EQ(class_words("theta0"), "\u03b80");
  EXPECT_EQ(class_words("omega"), "\u03c9");
  EXPECT_EQ(class_words("a_x"), "a\u2093");
  EXPECT_EQ(class_words("a_x_omega"), "a\u2093 \u03c9");
  EXPECT_EQ(class_words("large_epsilon_distance"), "large \u03b5 distance") << "where_methods_fail's probes";
  EXPECT_EQ(class_words("thetas"), "thetas") << "the letter's name with only digits after it";
  EXPECT_EQ(class_words("a_b"), "a b") << "no subscript b in Unicode: the letters as words";
  EXPECT_EQ(class_words("x_top"), "x top") << "an index is one letter";
  Parameter push_rate;
  push_rate.name = "push_rate";
  EXPECT_EQ(parameter_title(push_rate), "push rate") << "the values' table and the messages name it so";
}

}  // namespace
}  // namespace frictionlab::lessons
