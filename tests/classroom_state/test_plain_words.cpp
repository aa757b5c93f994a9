// Lua's commonest messages in plain words (classroom_state/plain_words.h), as the window's
// script messages and the page's editor say them beside Lua's own; the window's side is
// tests/classroom/test_script_messages.cpp.
#include <gtest/gtest.h>

#include <string>

#include "classroom_state/plain_words.h"

namespace frictionlab::classroom_state {
namespace {

TEST(PlainWords, EachMessageLuaGivesOftenAndNoneOfTheOthers) {
  EXPECT_EQ(plain_words("incline.lua:3: mass must be positive"), "");
  // Each of the messages it knows, as Lua words them.
  EXPECT_EQ(plain_words("a.lua:4: attempt to index a nil value (global 'blok')").rfind("In plain words: blok has no value here", 0), 0u);
  EXPECT_EQ(plain_words("a.lua:4: attempt to call a nil value (method 'pushh')"),
            "In plain words: there is no function called pushh. Check its spelling, or that it is made above this line.");
  EXPECT_EQ(plain_words("a.lua:4: attempt to perform arithmetic on a nil value (local 'mass')").rfind("In plain words: mass has no value", 0), 0u);
  EXPECT_EQ(plain_words("a.lua:4: attempt to perform arithmetic on a nil value").rfind("In plain words: a value in this sum has", 0), 0u);
  EXPECT_EQ(plain_words("a.lua:4: attempt to compare nil with number").rfind("In plain words: one side of a comparison", 0), 0u);
  EXPECT_EQ(plain_words("a.lua:4: attempt to compare two table values"), "");
  EXPECT_EQ(plain_words("a.lua:4: attempt to concatenate a nil value (field 'x')").rfind("In plain words: a value joined", 0), 0u);
  EXPECT_EQ(plain_words("a.lua:9: 'end' expected (to close 'function' at line 4) near <eof>").rfind("In plain words: a function, if", 0), 0u);
  EXPECT_EQ(plain_words("a.lua:9: '}' expected (to close '{' at line 4) near 'mass'"),
            "In plain words: a bracket is not closed: Lua expected } here. A missing comma between two entries does this too. "
            "The one it closes opened at line 4.");
  EXPECT_EQ(plain_words("a.lua:9: unexpected symbol near '='").rfind("In plain words: Lua could not read", 0), 0u);
  EXPECT_EQ(plain_words("a.lua:9: unfinished string near '\"push'"), "In plain words: a text in quotes is not closed on its line.");
  EXPECT_EQ(plain_words("a.lua:4: attempt to index a nil value (constant 'x')"), "");
}

}  // namespace
}  // namespace frictionlab::classroom_state
