#include "classroom_state/plain_words.h"

#include <initializer_list>
#include <optional>

namespace frictionlab::classroom_state {
namespace {

// What Lua names after "...a nil value" at `at`: " (KIND 'NAME')", KIND one of `kinds`. Read by
// hand: std::regex would add about 80 KB to the page's WebAssembly, which its single file
// (4 MB at most) has no room for.
struct Named {
  std::string kind, name;
};
std::optional<Named> named_at(const std::string& message, std::size_t at, std::initializer_list<const char*> kinds) {
  if (message.compare(at, 2, " (") != 0) return std::nullopt;
  const std::size_t quote = message.find(" '", at + 2);
  if (quote == std::string::npos) return std::nullopt;
  const std::string kind = message.substr(at + 2, quote - at - 2);
  bool known = false;
  for (const char* k : kinds) known = known || kind == k;
  const std::size_t close = message.find("')", quote + 2);
  if (!known || close == std::string::npos || close == quote + 2) return std::nullopt;
  const std::string name = message.substr(quote + 2, close - quote - 2);
  if (name.find('\'') != std::string::npos) return std::nullopt;
  return Named{kind, name};
}

// Where `words` ends in `message`, or npos.
std::size_t after(const std::string& message, const std::string& words) {
  const std::size_t at = message.find(words);
  return at == std::string::npos ? std::string::npos : at + words.size();
}

bool has(const std::string& message, const char* words) { return message.find(words) != std::string::npos; }

}  // namespace

std::string plain_words(const std::string& lua_message) {
  const std::string& m = lua_message;
  if (const std::size_t at = after(m, "attempt to index a nil value"); at != std::string::npos) {
    if (const auto named = named_at(m, at, {"global", "local", "upvalue"})) {
      return "In plain words: " + named->name + " has no value here, so there is nothing to look inside with \".\" or \"[ ]\". " +
             "Is the name spelt as where it was made, and made above this line (a slider's value is param.NAME)?";
    }
    if (const auto named = named_at(m, at, {"field"})) {
      return "In plain words: the table before \"." + named->name + "\" has nothing called " + named->name +
             ". Check that name's spelling.";
    }
  }
  if (const std::size_t at = after(m, "attempt to call a nil value"); at != std::string::npos) {
    if (const auto named = named_at(m, at, {"global", "local", "field", "method", "upvalue"})) {
      return "In plain words: there is no function called " + named->name + ". Check its spelling, or that it is made above this line.";
    }
  }
  if (const std::size_t at = after(m, "attempt to perform arithmetic on a nil value"); at != std::string::npos) {
    const auto named = named_at(m, at, {"global", "local", "field", "upvalue"});
    return "In plain words: " + (named ? named->name + " has" : std::string("a value in this sum has")) +
           " no value (nil), so it cannot be added, multiplied or divided. Is it spelt right, and given a value before this line?";
  }
  if (const std::size_t at = after(m, "attempt to compare "); at != std::string::npos && m.find("nil", at) != std::string::npos) {
    return "In plain words: one side of a comparison (<, >, <=, >=) has no value (nil). Check the names on this line.";
  }
  if (has(m, "attempt to concatenate a nil value")) {
    return "In plain words: a value joined into text with \"..\" has no value (nil). Check the names on this line.";
  }
  if (has(m, "'end' expected")) return "In plain words: a function, if, for or while that opens above is not closed with end.";
  for (const char* bracket : {")", "}", "]"}) {
    if (has(m, (std::string("'") + bracket + "' expected").c_str())) {
      // Lua names the line where it noticed; "(to close '{' at line 8)" where the bracket opened.
      std::string opened;
      if (const std::size_t at = after(m, "' at line "); at != std::string::npos && has(m, "(to close '")) {
        opened = " The one it closes opened at line " + m.substr(at, m.find(')', at) - at) + ".";
      }
      return std::string("In plain words: a bracket is not closed: Lua expected ") + bracket +
             " here. A missing comma between two entries does this too." + opened;
    }
  }
  if (has(m, "unexpected symbol") || has(m, "'=' expected") || has(m, "syntax error")) {
    return "In plain words: Lua could not read this line as written. Look for a missing comma, bracket, quote or \"then\".";
  }
  if (has(m, "unfinished string")) return "In plain words: a text in quotes is not closed on its line.";
  return "";
}

}  // namespace frictionlab::classroom_state
