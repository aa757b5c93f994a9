// A Lua 5.4 state a student's script cannot escape: no files, OS, packages or debug library,
// text chunks only, and budgets for instructions and memory so that an endless loop or a
// runaway table ends in an error instead of a hang.
#pragma once

#include <lua.hpp>

#include <chrono>
#include <cstddef>
#include <string>
#include <string_view>

#include "physics/materials.h"

namespace frictionlab::lessons {

// A script's mistake, already placed: "path:line: what was wrong and what was expected".
struct ScriptError : InvalidInput {
  using InvalidInput::InvalidInput;
};

struct SandboxLimits {
#ifdef FRICTIONLAB_FUZZING
  // A fuzzer runs thousands of scripts a second: a runaway one must end in milliseconds.
  std::size_t memory_bytes = 16u << 20;
  long instructions_per_call = 1'000'000;
  double seconds_per_call = 0.5;
#else
  std::size_t memory_bytes = 64u << 20;
  // Per call into the script: the build, one frame's probes and every_step functions, one
  // function of time, one expectation. Calls made from inside another share its budget.
  long instructions_per_call = 50'000'000;
  double seconds_per_call = 5.0;
#endif
};

class Sandbox {
 public:
  explicit Sandbox(SandboxLimits limits = {});
  ~Sandbox();
  Sandbox(const Sandbox&) = delete;
  Sandbox& operator=(const Sandbox&) = delete;

  lua_State* state() const { return state_; }
  const SandboxLimits& limits() const { return limits_; }

  // Compiles `source` (text only) under `chunk_name` (the path errors will name) and leaves
  // the function on the stack. Throws ScriptError for a syntax error.
  void load(std::string_view source, const std::string& chunk_name);
  // The function load left on the stack, as Lua bytecode with its lines and names kept, so
  // that its errors read as the text's would. Reading (parsing) a script's text was a sixth of
  // a short lesson's check in WebAssembly, whose number parsing is slow: runs of one text after
  // the first (a slider's rebuild, check --random) load this instead.
  std::string compiled() const;
  // Loads what compiled() gave (bytecode only; never a file's or a script's). Its messages name
  // the chunk it was compiled under (kept in the bytecode): give that same `chunk_name`.
  void load_compiled(std::string_view bytecode, const std::string& chunk_name);
  // Calls the function below `arguments` values on the stack with a fresh instruction budget.
  // Throws ScriptError carrying Lua's message (which starts with path:line). `results` values
  // are left on the stack.
  void call(int arguments, int results);

  // Charges work done inside one C function (a sort) to the running call's instruction budget,
  // and raises the budget's error at once when that spends it.
  void spend(lua_State* state, long instructions);

  std::size_t memory_in_use() const { return memory_.used; }
  // How many calls into the script are running: 1 in the build's own chunk, more inside a
  // function it gave (a hand asked for while spring{} runs).
  int depth() const { return depth_; }
  // Whatever the sandbox runs for (the lesson build), reachable from API functions.
  void* owner() const { return owner_; }
  void set_owner(void* owner) { owner_ = owner; }
  // Wall time spent inside Lua while timing was on, for the benchmark's share of the step.
  // Off by default: reading the clock twice a call is itself a cost worth avoiding.
  void set_timing(bool on) { timing_ = on; }
  std::chrono::nanoseconds time_in_lua() const { return time_in_lua_; }

 private:
  struct Memory {
    std::size_t used = 0;
    std::size_t limit = 0;
  };
  std::string full_path(const std::string& message) const;
  static void* allocate(void* memory, void* block, std::size_t old_size, std::size_t new_size);
  static void count_instructions(lua_State* state, lua_Debug* debug);
  static int place_error(lua_State* state);
  void budget_spent(lua_State* state, int level) const;

  SandboxLimits limits_;
  Memory memory_;
  lua_State* state_ = nullptr;
  std::string chunk_name_;
  void* owner_ = nullptr;
  long budget_left_ = 0;
  // The time limit is on the processor time the script's thread spends (script_clock in
  // sandbox.cpp); the wall clock, cheap to read, only says when to look at it.
  std::chrono::steady_clock::time_point look_again_at_{};
  std::chrono::nanoseconds processor_time_at_start_{0};
  bool deadline_set_ = false;  // the outermost call's clock has started (see call)
  int depth_ = 0;  // a call made from inside another (a hand read while spring{} runs) shares its budget
  bool timing_ = false;
  std::chrono::nanoseconds time_in_lua_{0};
};

// The sandbox that owns `state`.
Sandbox& sandbox_of(lua_State* state);

// "path:line: " of the innermost frame of the script's own code at or above `level` (C frames,
// such as a library function that called an API function, have no line), or "".
std::string script_place(lua_State* state, int level);

// Runs `body` as the C function it is called from; a C++ exception from it becomes a Lua
// error placed at the script line that called the function. Every API function goes through
// here so that no C++ exception crosses Lua's own frames.
template <typename Body>
int guarded(lua_State* state, Body&& body) {
  bool failed = false;
  int results = 0;
  try {
    results = body();
  } catch (const std::exception& error) {
    lua_pushstring(state, (script_place(state, 1) + error.what()).c_str());
    failed = true;
  }
  if (failed) return lua_error(state);
  return results;
}

// Names a Lua value's type the way error messages speak: "a number", "nil", "a table".
std::string describe(lua_State* state, int index);
// A number as an error message shows it: 0.1, 2.5e-07, inf (the stream's shortest form).
std::string number_text(double value);

}  // namespace frictionlab::lessons
