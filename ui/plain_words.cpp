#include "ui/plain_words.h"

#include <regex>

namespace frictionlab::ui {

std::string plain_words(const std::string& lua_message) {
  // Built once: a message is read only when a script fails, but a failing lesson may say it
  // every frame.
  static const std::regex indexed_name(R"(attempt to index a nil value \((global|local|upvalue) '([^']+)'\))");
  static const std::regex indexed_field(R"(attempt to index a nil value \(field '([^']+)'\))");
  static const std::regex called(R"(attempt to call a nil value \((global|local|field|method|upvalue) '([^']+)'\))");
  static const std::regex added(R"(attempt to perform arithmetic on a nil value(?: \((?:global|local|field|upvalue) '([^']+)'\))?)");
  static const std::regex compared(R"(attempt to compare .*nil)");
  static const std::regex joined(R"(attempt to concatenate a nil value)");
  static const std::regex no_end(R"('end' expected)");
  static const std::regex no_bracket(R"('([)}\]])' expected)");
  static const std::regex unreadable(R"(unexpected symbol|'=' expected|syntax error)");
  static const std::regex unfinished(R"(unfinished string)");
  std::smatch found;
  const std::string& m = lua_message;
  if (std::regex_search(m, found, indexed_name)) {
    return "In plain words: " + found[2].str() + " has no value here, so there is nothing to look inside with \".\" or \"[ ]\". " +
           "Is the name spelt as where it was made, and made above this line (a slider's value is param.NAME)?";
  }
  if (std::regex_search(m, found, indexed_field)) {
    return "In plain words: the table before \"." + found[1].str() + "\" has nothing called " + found[1].str() +
           ". Check that name's spelling.";
  }
  if (std::regex_search(m, found, called)) {
    return "In plain words: there is no function called " + found[2].str() + ". Check its spelling, or that it is made above this line.";
  }
  if (std::regex_search(m, found, added)) {
    return "In plain words: " + (found[1].matched ? found[1].str() + " has" : std::string("a value in this sum has")) +
           " no value (nil), so it cannot be added, multiplied or divided. Is it spelt right, and given a value before this line?";
  }
  if (std::regex_search(m, compared)) {
    return "In plain words: one side of a comparison (<, >, <=, >=) has no value (nil). Check the names on this line.";
  }
  if (std::regex_search(m, joined)) {
    return "In plain words: a value joined into text with \"..\" has no value (nil). Check the names on this line.";
  }
  if (std::regex_search(m, no_end)) return "In plain words: a function, if, for or while that opens above is not closed with end.";
  if (std::regex_search(m, found, no_bracket)) {
    return "In plain words: a bracket is not closed: Lua expected " + found[1].str() +
           " here. A missing comma between two entries does this too.";
  }
  if (std::regex_search(m, unreadable)) {
    return "In plain words: Lua could not read this line as written. Look for a missing comma, bracket, quote or \"then\".";
  }
  if (std::regex_search(m, unfinished)) return "In plain words: a text in quotes is not closed on its line.";
  return "";
}

}  // namespace frictionlab::ui
