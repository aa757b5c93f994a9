#include "lessons/runtime/sandbox.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <string_view>
#include <vector>

#ifdef __EMSCRIPTEN__
#include <emscripten.h>
#else
#include <time.h>
#endif

namespace frictionlab::lessons {
namespace {

// The processor time the script's own thread has spent. Not the wall clock: on a machine busy
// with other work (a test suite run two at a time beside a compiler) a loop's wall time grows
// with the load, and the time limit would stop a script before its instruction limit, with the
// wrong message. A reading costs a system call (3 µs on the machine this was written on, against
// 60 ns for the wall clock), so the sandbox reads it only when the wall clock says the limit may
// have passed. In WebAssembly under node (the command line, the web test suites) node's own
// count of the process's processor time: read off the wall there, a loop on a machine loaded
// five times over (two engineers' builds and tests beside the web suites) met the 5 s limit
// before its 50 million instructions. In a browser there is none to read, and the page's thread
// is all the script has: its clock is the wall's.
#ifdef __EMSCRIPTEN__
EM_JS(double, script_clock_ms, (), {
  if (typeof process !== 'undefined' && typeof process.cpuUsage === 'function') {
    const used = process.cpuUsage();
    return (used.user + used.system) / 1000;
  }
  return performance.now();
});
#endif
std::chrono::nanoseconds processor_time() {
#ifdef __EMSCRIPTEN__
  return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::duration<double, std::milli>(script_clock_ms()));
#else
  timespec now{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return std::chrono::seconds(now.tv_sec) + std::chrono::nanoseconds(now.tv_nsec);
#endif
}

// How often (in VM instructions) the budget is checked: often enough to stop a loop within
// microseconds of its budget, rarely enough to cost nothing measurable.
constexpr int instructions_per_check = 1000;

// string.rep of an empty string a huge number of times loops inside C, where the budget never
// looks, making nothing; the result is "" whatever the count.
int repeat_text(lua_State* state) {
  std::size_t length = 0, separator = 0;
  luaL_checklstring(state, 1, &length);
  const lua_Integer count = luaL_checkinteger(state, 2);
  luaL_optlstring(state, 3, "", &separator);
  if (count <= 0 || length + separator == 0) {
    lua_pushliteral(state, "");
    return 1;
  }
  lua_pushvalue(state, lua_upvalueindex(1));
  lua_insert(state, 1);
  lua_call(state, lua_gettop(state) - 1, 1);
  return 1;
}

// table.move over a range of a quintillion empty slots also loops inside C. No lesson moves
// more than a table's worth of entries; a range longer than the memory could hold is refused.
int move_entries(lua_State* state) {
  const lua_Integer from = luaL_checkinteger(state, 2), to = luaL_checkinteger(state, 3);
  if (to >= from && (to - from) > 10'000'000) {
    return luaL_error(state, "table.move: a range of more than 10 million entries (%I to %I)", from, to);
  }
  lua_pushvalue(state, lua_upvalueindex(1));
  lua_insert(state, 1);
  lua_call(state, lua_gettop(state) - 1, LUA_MULTRET);
  return lua_gettop(state);
}

// Replaces library function `name` of the table on the stack top by `wrapper`, which gets the
// original as its upvalue.
void wrap(lua_State* state, const char* name, lua_CFunction wrapper) {
  lua_getfield(state, -1, name);
  lua_pushcclosure(state, wrapper, 1);
  lua_setfield(state, -2, name);
}

// pairs in an order that is the same on every run: Lua seeds its string hashing from the
// clock, so the order of a table's keys changes from run to run, and a lesson that builds
// bodies in pairs order would too. Numbers come first in increasing order, then strings in
// byte order (alphabetical for plain words), then the rest in the order Lua gives them.
struct SortKey {
  int rank = 3;  // 0 number, 1 string, 2 boolean, 3 anything else
  bool integer = false;
  lua_Integer whole = 0;
  lua_Number real = 0;
  std::string_view text;  // points into a string the list of keys keeps alive
  lua_Integer position = 0;  // where the key sits in that list
};

// Whether integer `whole` comes before float `real`, exactly (converting either to the other
// could round two different keys together).
bool integer_before_real(lua_Integer whole, lua_Number real) {
  if (real >= 0x1p63) return true;
  if (real < -0x1p63) return false;
  const lua_Number floor = std::floor(real);
  const auto floor_whole = static_cast<lua_Integer>(floor);
  return whole < floor_whole || (whole == floor_whole && floor < real);
}

bool number_before(const SortKey& a, const SortKey& b) {
  if (a.integer && b.integer) return a.whole < b.whole;
  if (!a.integer && !b.integer) return a.real < b.real;
  if (a.integer) return integer_before_real(a.whole, b.real);
  return !integer_before_real(b.whole, a.real);  // a float key is never equal to an integer key
}

bool key_before(const SortKey& a, const SortKey& b) {
  if (a.rank != b.rank) return a.rank < b.rank;
  if (a.rank == 0) return number_before(a, b);
  if (a.rank == 1) return a.text < b.text;
  return false;  // booleans and the rest keep Lua's order (the sort is stable)
}

int ordered_next(lua_State* state) {
  // Upvalue 1: the list of keys in order; upvalue 2: the position reached; upvalue 3: the
  // table walked. Called by hand with anything else, rawget would read a number or a handle
  // as a table.
  if (!lua_rawequal(state, 1, lua_upvalueindex(3))) {
    return luaL_error(state, "the function pairs returns walks the table pairs was given, and is called by for ... in "
                      "pairs(t); it was given %s", describe(state, 1).c_str());
  }
  const lua_Integer position = lua_tointeger(state, lua_upvalueindex(2)) + 1;
  lua_pushinteger(state, position);
  lua_replace(state, lua_upvalueindex(2));
  if (lua_rawgeti(state, lua_upvalueindex(1), position) == LUA_TNIL) return 1;
  lua_pushvalue(state, -1);
  lua_rawget(state, lua_upvalueindex(3));
  return 2;
}

int ordered_pairs(lua_State* state) {
  luaL_checktype(state, 1, LUA_TTABLE);
  lua_settop(state, 1);
  lua_newtable(state);  // the keys, in Lua's order
  std::vector<SortKey> keys;
  lua_pushnil(state);
  while (lua_next(state, 1) != 0) {
    lua_pop(state, 1);
    SortKey key;
    key.position = static_cast<lua_Integer>(keys.size()) + 1;
    switch (lua_type(state, -1)) {
      case LUA_TNUMBER:
        key.rank = 0;
        key.integer = lua_isinteger(state, -1);
        key.whole = lua_tointeger(state, -1);
        key.real = lua_tonumber(state, -1);
        break;
      case LUA_TSTRING: {
        key.rank = 1;
        std::size_t length = 0;
        const char* text = lua_tolstring(state, -1, &length);
        key.text = std::string_view(text, length);
        break;
      }
      case LUA_TBOOLEAN: key.rank = 2; break;
      default: break;
    }
    keys.push_back(key);
    lua_pushvalue(state, -1);
    lua_rawseti(state, 2, key.position);
  }
  // A sort inside one C call is where the instruction budget never looks: charged to it here,
  // so that pairs over a huge table again and again ends like any other long loop.
  const auto count = static_cast<long>(keys.size());
  // Measured: a pairs call costs about as much time as 8·(log2 n + 1) instructions a key.
  sandbox_of(state).spend(state, 8 * count * static_cast<long>(std::log2(static_cast<double>(count) + 1.0) + 1.0));
  std::stable_sort(keys.begin(), keys.end(), key_before);
  lua_createtable(state, static_cast<int>(std::min<std::size_t>(keys.size(), 1u << 24)), 0);  // the keys, in order
  for (std::size_t i = 0; i < keys.size(); ++i) {
    lua_rawgeti(state, 2, keys[i].position);
    lua_rawseti(state, 3, static_cast<lua_Integer>(i) + 1);
  }
  lua_pushinteger(state, 0);
  lua_pushvalue(state, 1);
  lua_pushcclosure(state, ordered_next, 3);
  lua_pushvalue(state, 1);
  lua_pushnil(state);
  return 3;
}

// Reading a global that nothing set: in plain Lua it is nil, so a student's `mass = mas` built
// a 40 kg block beside a slider that said 1 kg, with no word. Here it is an error at the line
// that read it. (A script may still ask whether a name is set with rawget(_G, name).)
// What the sandbox leaves out (open_safe_libraries, and the libraries it never opens): a script
// that reaches for one is told so, not to check its spelling.
constexpr std::string_view left_out[] = {"dofile", "loadfile", "load",         "require",      "collectgarbage",
                                         "pcall",  "xpcall",   "setmetatable", "getmetatable", "io",
                                         "os",     "package",  "debug",        "coroutine"};

int undefined_global(lua_State* state) {
  const char* name = lua_tostring(state, 2);
  const std::string_view named = name != nullptr ? name : "?";
  luaL_where(state, 1);  // the line of the script that read it (level 0 is this function)
  if (std::find(std::begin(left_out), std::end(left_out), named) != std::end(left_out)) {
    lua_pushfstring(state,
                    "'%s' is left out of the lesson sandbox: a lesson reaches no files or programs and runs the "
                    "same every time",
                    named.data());
  } else {
    lua_pushfstring(state,
                    "'%s' is not defined: nothing in the script gave it a value before this line (check its "
                    "spelling; a local must be declared above the line that uses it, a global given a value "
                    "before it is read)",
                    named.data());
  }
  lua_concat(state, 2);
  return lua_error(state);
}

// Libraries a lesson may use, and from the base library only what cannot reach outside the
// script or outlive its budgets: pcall and xpcall go, since a script that catches the
// budget's error could loop forever; setmetatable and getmetatable go, since metatables run
// script code where no budget can stop it (__gc, __close) or make library loops endless
// (__len). math.random is left out because lessons must be deterministic.
void open_safe_libraries(lua_State* state) {
  luaL_requiref(state, LUA_GNAME, luaopen_base, 1);
  luaL_requiref(state, LUA_TABLIBNAME, luaopen_table, 1);
  luaL_requiref(state, LUA_STRLIBNAME, luaopen_string, 1);
  luaL_requiref(state, LUA_MATHLIBNAME, luaopen_math, 1);
  luaL_requiref(state, LUA_UTF8LIBNAME, luaopen_utf8, 1);
  lua_pop(state, 5);
  for (const char* unsafe : {"dofile", "loadfile", "load", "require", "collectgarbage", "pcall", "xpcall", "setmetatable",
                             "getmetatable"}) {
    lua_pushnil(state);
    lua_setglobal(state, unsafe);
  }
  // Lua's pattern matching runs inside one C call, where the instruction budget never looks:
  // a pattern such as ".-.-.-.-b" on a long string runs for minutes. Lessons do not need it.
  lua_getglobal(state, LUA_STRLIBNAME);
  for (const char* pattern_function : {"find", "match", "gmatch", "gsub"}) {
    lua_pushnil(state);
    lua_setfield(state, -2, pattern_function);
  }
  wrap(state, "rep", repeat_text);
  lua_pop(state, 1);
  lua_getglobal(state, LUA_TABLIBNAME);
  wrap(state, "move", move_entries);
  lua_pop(state, 1);
  lua_pushcfunction(state, ordered_pairs);
  lua_setglobal(state, "pairs");
  lua_getglobal(state, LUA_MATHLIBNAME);
  for (const char* unseeded : {"random", "randomseed"}) {
    lua_pushnil(state);
    lua_setfield(state, -2, unseeded);
  }
  lua_pop(state, 1);
  lua_pushglobaltable(state);
  lua_newtable(state);
  lua_pushcfunction(state, undefined_global);
  lua_setfield(state, -2, "__index");
  lua_setmetatable(state, -2);
  lua_pop(state, 1);
}

}  // namespace

Sandbox::Sandbox(SandboxLimits limits) : limits_(limits) {
  memory_.limit = limits_.memory_bytes;
  state_ = lua_newstate(&Sandbox::allocate, &memory_);
  if (state_ == nullptr) throw ScriptError("cannot start Lua: out of memory");
  *static_cast<Sandbox**>(lua_getextraspace(state_)) = this;
  // An error outside any protected call would otherwise end the program (abort).
  lua_atpanic(state_, [](lua_State* state) -> int {
    const char* text = lua_tostring(state, -1);
    throw ScriptError(std::string("the script failed outside a protected call: ") + (text ? text : "?"));
  });
  open_safe_libraries(state_);
  // What garbage lessons make (strings, small tables in their functions) dies young: the
  // generational collector handles that with less work than the incremental one.
  lua_gc(state_, LUA_GCGEN, 0, 0);
  lua_sethook(state_, &Sandbox::count_instructions, LUA_MASKCOUNT, instructions_per_check);
}

Sandbox::~Sandbox() { lua_close(state_); }

Sandbox& sandbox_of(lua_State* state) { return **static_cast<Sandbox**>(lua_getextraspace(state)); }

void* Sandbox::allocate(void* memory, void* block, std::size_t old_size, std::size_t new_size) {
  auto* books = static_cast<Memory*>(memory);
  // For a new block Lua passes the kind of object in old_size, not a size.
  const std::size_t had = block == nullptr ? 0 : old_size;
  if (new_size == 0) {
    std::free(block);
    books->used -= had;
    return nullptr;
  }
  // The instruction hook stops a script soon after it passes the limit, with the line it was
  // on; this hard stop, a little higher, catches one huge allocation in a single instruction.
  if (new_size > had && books->used + (new_size - had) > books->limit + books->limit / 4) return nullptr;
  void* grown = std::realloc(block, new_size);
  if (grown != nullptr) books->used = books->used - had + new_size;
  return grown;
}

void Sandbox::count_instructions(lua_State* state, lua_Debug*) {
  Sandbox& sandbox = sandbox_of(state);
  sandbox.budget_left_ -= instructions_per_check;
  // Inside a hook, level 0 is the script function that was running: the line to report.
  if (sandbox.memory_.used > sandbox.memory_.limit) {
    luaL_where(state, 0);
    lua_pushfstring(state, "the script uses more than %d MB of memory (a table that grows without end, or a function "
                    "that calls itself without end?)",
                    static_cast<int>(sandbox.memory_.limit >> 20));
    lua_concat(state, 2);
    lua_error(state);
  }
  // Instructions are not time: a string grown one character at a time costs more per
  // instruction the longer it gets. The clock bounds what the count cannot.
  const auto now = std::chrono::steady_clock::now();
  const auto limit = std::chrono::duration_cast<std::chrono::nanoseconds>(
      std::chrono::duration<double>(sandbox.limits_.seconds_per_call));
  if (!sandbox.deadline_set_) {
    sandbox.look_again_at_ = now + limit;
    sandbox.processor_time_at_start_ = processor_time();
    sandbox.deadline_set_ = true;
  } else if (now > sandbox.look_again_at_) {
    // The thread cannot have had more of the processor than the wall clock ran: what it has
    // not yet spent is the earliest the limit can pass.
    const std::chrono::nanoseconds spent = processor_time() - sandbox.processor_time_at_start_;
    if (spent >= limit) {
      luaL_where(state, 0);
      // "5 seconds", "1 second", "0.5 seconds" (the fuzzers' limit).
      std::ostringstream limit_words;
      limit_words << sandbox.limits_.seconds_per_call << (sandbox.limits_.seconds_per_call == 1.0 ? " second" : " seconds");
      lua_pushfstring(state, "the script ran for more than %s without finishing (an endless loop, or a string "
                      "grown one piece at a time?)",
                      limit_words.str().c_str());
      lua_concat(state, 2);
      lua_error(state);
    }
    sandbox.look_again_at_ = now + (limit - spent);
  }
  // The budget stays spent: anything still run while the error unwinds stops at once.
  if (sandbox.budget_left_ < 0) sandbox.budget_spent(state, 0);
}

void Sandbox::budget_spent(lua_State* state, int level) const {
  luaL_where(state, level);
  lua_pushfstring(state, "the script ran for more than %d million instructions without finishing (an endless loop?)",
                  static_cast<int>(limits_.instructions_per_call / 1'000'000));
  lua_concat(state, 2);
  lua_error(state);
}

void Sandbox::spend(lua_State* state, long instructions) {
  budget_left_ -= instructions;
  // Level 1: the script line that called the C function doing the work.
  if (budget_left_ < 0) budget_spent(state, 1);
}

// The innermost frame of the script's own code: where a message belongs. C frames (library
// functions, API functions called through them) have no line.
std::string script_place(lua_State* state, int level) {
  lua_Debug frame;
  for (; lua_getstack(state, level, &frame); ++level) {
    if (lua_getinfo(state, "Sl", &frame) && frame.currentline > 0) {
      return std::string(frame.source[0] == '@' ? frame.source + 1 : frame.short_src) + ":" +
             std::to_string(frame.currentline) + ": ";
    }
  }
  return "";
}

// Lua names the operation in arithmetic on a string by its metamethod ("attempt to mul a
// 'number' with a 'string'"): in words, for a student. The hint about strings only where both
// sides are numbers or strings; "2" + nil is the nil's fault. Any other message is kept.
static std::string arithmetic_in_words(const std::string& message) {
  static const std::pair<const char*, const char*> operations[] = {
      {"add", "add"},       {"sub", "subtract"},           {"mul", "multiply"},         {"div", "divide"},
      {"mod", "take the remainder of"}, {"pow", "raise to a power"}, {"idiv", "floor-divide"}, {"unm", "negate"}};
  const std::string opening = "attempt to ";
  const std::size_t at = message.find(opening);
  if (at == std::string::npos) return message;
  const std::size_t name_start = at + opening.size();
  const std::size_t name_end = message.find(" a '", name_start);
  if (name_end == std::string::npos) return message;
  const std::string name = message.substr(name_start, name_end - name_start);
  const char* verb = nullptr;
  for (const auto& [lua_name, words] : operations) {
    if (name == lua_name) verb = words;
  }
  const std::size_t first_end = message.find("' with a '", name_end + 4);
  const std::size_t second_end = first_end == std::string::npos ? first_end : message.find('\'', first_end + 10);
  if (verb == nullptr || second_end == std::string::npos || second_end + 1 != message.size()) return message;
  const std::string first = message.substr(name_end + 4, first_end - name_end - 4);
  const std::string second = message.substr(first_end + 10, second_end - first_end - 10);
  const bool one_operand = name == "unm";
  const auto plain = [](const std::string& type) { return type == "number" || type == "string"; };
  const bool strings_only = plain(first) && (one_operand || plain(second));
  return message.substr(0, at) + "cannot " + verb + " " + (one_operand ? "a " + first : "a " + first + " and a " + second) +
         (strings_only ? ": a string (text in quotes) takes part in arithmetic only if it reads as a number, as \"2.5\" does"
                       : "");
}

int Sandbox::place_error(lua_State* state) {
  const Sandbox& sandbox = sandbox_of(state);
  const char* text = lua_tostring(state, 1);
  std::string message =
      text ? arithmetic_in_words(text) : "the script raised an error that is not a message (" + describe(state, 1) + ")";
  const std::string place = script_place(state, 1);
  const std::string full = sandbox.full_path(message);
  const bool placed = full.rfind(sandbox.chunk_name_ + ":", 0) == 0 || message.rfind("...", 0) == 0;
  if (!placed && !place.empty()) message = place + message;
  lua_pushstring(state, message.c_str());
  return 1;
}

std::string Sandbox::compiled() const {
  std::string bytecode;
  const auto append = [](lua_State*, const void* piece, std::size_t size, void* to) {
    static_cast<std::string*>(to)->append(static_cast<const char*>(piece), size);
    return 0;
  };
  lua_dump(state_, append, &bytecode, 0);
  return bytecode;
}

void Sandbox::load_compiled(std::string_view bytecode, const std::string& chunk_name) {
  chunk_name_ = chunk_name;
  const std::string named = "@" + chunk_name;
  if (luaL_loadbufferx(state_, bytecode.data(), bytecode.size(), named.c_str(), "b") == LUA_OK) return;
  // Only memory can fail here: the bytecode is compiled() of a text that loaded.
  const std::string message = lua_tostring(state_, -1) ? lua_tostring(state_, -1) : "cannot load the script";
  lua_pop(state_, 1);
  throw ScriptError(chunk_name + ": " + message);
}

void Sandbox::load(std::string_view source, const std::string& chunk_name) {
  chunk_name_ = chunk_name;
  // What Lua's own loadfile skips, and editors write: a UTF-8 byte-order mark, and a first line
  // starting with # (#!/usr/bin/env lua). The # line is emptied, not removed, so that every
  // line keeps its number.
  std::string text;
  if (source.substr(0, 3) == "\xEF\xBB\xBF") source.remove_prefix(3);
  if (!source.empty() && source.front() == '#') {
    const std::size_t end = source.find('\n');
    text = end == std::string_view::npos ? std::string() : std::string(source.substr(end));
    source = text;
  }
  const std::string named = "@" + chunk_name;
  const int status = luaL_loadbufferx(state_, source.data(), source.size(), named.c_str(), "t");
  if (status == LUA_OK) return;
  std::string message = lua_tostring(state_, -1) ? lua_tostring(state_, -1) : "cannot load the script";
  lua_pop(state_, 1);
  message = full_path(message);
  if (message.rfind(chunk_name + ":", 0) == 0) throw ScriptError(message);
  // The few load errors Lua gives without a place get the file's name, and what they mean.
  if (status == LUA_ERRMEM) {
    message = "the script is too large to read within " + std::to_string(limits_.memory_bytes >> 20) +
              " MB of memory (a huge string or table written out in the file?)";
  } else if (message.find("C stack overflow") != std::string::npos) {
    message = "the script nests brackets, tables or blocks too deeply for Lua to read (about 200 levels; C stack "
              "overflow)";
  } else if (message.find("binary chunk") != std::string::npos) {
    message = "the file is a precompiled (binary) Lua chunk; a lesson is given as its Lua source text";
  }
  throw ScriptError(chunk_name + ": " + message);
}

// Lua shortens a long file name in its messages to "..." and the last 56 characters; a
// student needs the whole path to find the file.
std::string Sandbox::full_path(const std::string& message) const {
  const std::size_t colon = message.find(':');
  if (message.rfind("...", 0) != 0 || colon == std::string::npos) return message;
  const std::string tail = message.substr(3, colon - 3);
  if (chunk_name_.size() < tail.size() || chunk_name_.compare(chunk_name_.size() - tail.size(), tail.size(), tail) != 0) {
    return message;
  }
  return chunk_name_ + message.substr(colon);
}

void Sandbox::call(int arguments, int results) {
  const bool outermost = depth_ == 0;
  if (outermost) {
    budget_left_ = limits_.instructions_per_call;
    // The clock starts at the first check, instructions_per_check instructions in: most calls
    // (a force's function of time, a probe) finish long before and never read it, and on this
    // machine a reading costs 30 to 160 ns, a tenth of a lesson's step.
    deadline_set_ = false;
  }
  const bool timed = outermost && timing_;
  const auto start = timed ? std::chrono::steady_clock::now() : std::chrono::steady_clock::time_point{};
  ++depth_;
  // The message handler places an error that has no place yet (error("...", 0), error({})).
  const int handler = lua_gettop(state_) - arguments;
  lua_pushcfunction(state_, &Sandbox::place_error);
  lua_insert(state_, handler);
  const int status = lua_pcall(state_, arguments, results, handler);
  lua_remove(state_, status == LUA_OK ? handler : -2);
  --depth_;
  if (timed) time_in_lua_ += std::chrono::steady_clock::now() - start;
  if (status == LUA_OK) return;
  std::string message;
  if (status == LUA_ERRMEM) {
    // Lua reports this one without a line: the file at least says which script it was.
    message = chunk_name_ + ": the script asked for more than " + std::to_string(limits_.memory_bytes >> 20) +
              " MB of memory in one go (a string.rep that large, or a string doubled again and again?)";
  } else if (const char* text = lua_tostring(state_, -1)) {
    message = text;
  } else {
    message = "the script raised an error that is not a message (" + describe(state_, -1) + ")";
  }
  lua_pop(state_, 1);
  if (!outermost) {
    // A call made from inside an API function (a spring's hand read while spring{} runs, or
    // through spring.force_x): its message is placed already, so it goes on to the outer call
    // as a Lua error. As a C++ exception, guarded() would place it a second time, at the line
    // that called the API function.
    lua_pushstring(state_, message.c_str());
    lua_error(state_);
  }
  throw ScriptError(full_path(message));
}

std::string number_text(double value) {
  std::ostringstream text;
  text << value;
  return text.str();
}

std::string describe(lua_State* state, int index) {
  switch (lua_type(state, index)) {
    case LUA_TNONE:
    case LUA_TNIL: return "nil";
    case LUA_TNUMBER: {
      const double value = lua_tonumber(state, index);
      if (std::isnan(value)) return "not a number (NaN, as 0/0 gives)";
      if (std::isinf(value)) return value > 0 ? "infinity (as 1/0 gives)" : "minus infinity";
      // Formatted here rather than by Lua, which may need memory and may run outside any
      // protected call.
      std::ostringstream text;
      if (lua_isinteger(state, index)) {
        text << lua_tointeger(state, index);
      } else {
        text.precision(14);
        text << value;
      }
      return "the number " + text.str();
    }
    case LUA_TBOOLEAN: return lua_toboolean(state, index) ? "true" : "false";
    case LUA_TSTRING: return "the text \"" + std::string(lua_tostring(state, index)) + "\"";
    case LUA_TTABLE: return "a table";
    case LUA_TFUNCTION: return "a function";
    case LUA_TUSERDATA:
      // The runtime's handles carry their type's name: "frictionlab.body" reads as "a body".
      if (luaL_getmetafield(state, index, "__name") == LUA_TSTRING) {
        std::string name = lua_tostring(state, -1);
        lua_pop(state, 1);
        if (name.rfind("frictionlab.", 0) == 0) return "a " + name.substr(12) + " handle";
      }
      return "a userdata";
    default: return std::string("a ") + luaL_typename(state, index);
  }
}

}  // namespace frictionlab::lessons
