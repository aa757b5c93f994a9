// Lua's commonest messages in plain words, said beside Lua's own (which names the file and the
// line): a student who reads "attempt to index a nil value (global 'blok')" learns what to look
// for. The desktop window's messages and the page's editor both say them.
#pragma once

#include <string>

namespace frictionlab::classroom_state {

// "In plain words: ..." for a message Lua gives often (a nil indexed, called, added, compared or
// joined; a missing end or bracket; a line Lua cannot read; an unfinished string); "" for any
// other message.
std::string plain_words(const std::string& lua_message);

}  // namespace frictionlab::classroom_state
