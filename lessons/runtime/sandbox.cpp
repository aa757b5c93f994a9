#include "lessons/runtime/sandbox.h"

#include <cmath>
#include <cstdlib>
#include <cstring>

namespace frictionlab::lessons {
namespace {

// How often (in VM instructions) the budget is checked: often enough to stop a loop within
// microseconds of its budget, rarely enough to cost nothing measurable.
constexpr int instructions_per_check = 1000;

// Lua's own setmetatable, refusing a metatable with __gc.
int set_metatable_without_finalizer(lua_State* state) {
  const int type = lua_type(state, 2);
  luaL_checktype(state, 1, LUA_TTABLE);
  luaL_argexpected(state, type == LUA_TNIL || type == LUA_TTABLE, 2, "nil or table");
  if (luaL_getmetafield(state, 1, "__metatable") != LUA_TNIL) return luaL_error(state, "cannot change a protected metatable");
  if (type == LUA_TTABLE) {
    lua_pushliteral(state, "__gc");
    if (lua_rawget(state, 2) != LUA_TNIL) {
      return luaL_error(state, "setmetatable: a metatable in a lesson cannot have __gc (Lua runs it where the "
                               "sandbox cannot stop it)");
    }
  }
  lua_settop(state, 2);
  lua_setmetatable(state, 1);
  return 1;
}

// Libraries a lesson may use, and from the base library only what cannot reach outside the
// script or outlive its budgets: pcall and xpcall go, since a script that catches the
// budget's error could loop forever. math.random is left out because lessons must be
// deterministic.
void open_safe_libraries(lua_State* state) {
  luaL_requiref(state, LUA_GNAME, luaopen_base, 1);
  luaL_requiref(state, LUA_TABLIBNAME, luaopen_table, 1);
  luaL_requiref(state, LUA_STRLIBNAME, luaopen_string, 1);
  luaL_requiref(state, LUA_MATHLIBNAME, luaopen_math, 1);
  luaL_requiref(state, LUA_UTF8LIBNAME, luaopen_utf8, 1);
  lua_pop(state, 5);
  for (const char* unsafe : {"dofile", "loadfile", "load", "require", "collectgarbage", "pcall", "xpcall"}) {
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
  lua_pop(state, 1);
  lua_getglobal(state, LUA_MATHLIBNAME);
  for (const char* unseeded : {"random", "randomseed"}) {
    lua_pushnil(state);
    lua_setfield(state, -2, unseeded);
  }
  lua_pop(state, 1);
  // setmetatable stays (scripts may use __index), wrapped to refuse __gc: Lua runs finalizers
  // with hooks switched off, so an endless loop in one would hang the program where no budget
  // can stop it (at the latest when the lesson is closed).
  lua_pushcfunction(state, set_metatable_without_finalizer);
  lua_setglobal(state, "setmetatable");
}

}  // namespace

Sandbox::Sandbox(SandboxLimits limits) : limits_(limits) {
  memory_.limit = limits_.memory_bytes;
  state_ = lua_newstate(&Sandbox::allocate, &memory_);
  if (state_ == nullptr) throw ScriptError("cannot start Lua: out of memory");
  *static_cast<Sandbox**>(lua_getextraspace(state_)) = this;
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
  if (sandbox.budget_left_ < 0) {
    // The budget starts over for whatever handles the error, so a message can still be built.
    sandbox.budget_left_ = sandbox.limits_.instructions_per_call;
    luaL_where(state, 0);
    lua_pushfstring(state, "the script ran for more than %d million instructions without finishing (an endless loop?)",
                    static_cast<int>(sandbox.limits_.instructions_per_call / 1'000'000));
    lua_concat(state, 2);
    lua_error(state);
  }
}

void Sandbox::load(std::string_view source, const std::string& chunk_name) {
  chunk_name_ = chunk_name;
  const std::string named = "@" + chunk_name;
  if (luaL_loadbufferx(state_, source.data(), source.size(), named.c_str(), "t") != LUA_OK) {
    std::string message = lua_tostring(state_, -1) ? lua_tostring(state_, -1) : "cannot load the script";
    lua_pop(state_, 1);
    throw ScriptError(full_path(message));
  }
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
  if (outermost) budget_left_ = limits_.instructions_per_call;
  const bool timed = outermost && timing_;
  const auto start = timed ? std::chrono::steady_clock::now() : std::chrono::steady_clock::time_point{};
  ++depth_;
  const int status = lua_pcall(state_, arguments, results, 0);
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

std::string describe(lua_State* state, int index) {
  switch (lua_type(state, index)) {
    case LUA_TNONE:
    case LUA_TNIL: return "nil";
    case LUA_TNUMBER: {
      const double value = lua_tonumber(state, index);
      if (std::isnan(value)) return "not a number (NaN, as 0/0 gives)";
      if (std::isinf(value)) return value > 0 ? "infinity (as 1/0 gives)" : "minus infinity";
      // luaL_tolstring works on a copy; lua_tostring would turn the number itself into text.
      std::string text = luaL_tolstring(state, index, nullptr);
      lua_pop(state, 1);
      return "the number " + text;
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
