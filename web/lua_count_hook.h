/* Included ahead of Lua's lvm.c in the web build (web/dependencies.cmake), nowhere else.
 *
 * The sandbox's instruction budget is a count hook (lua_sethook with LUA_MASKCOUNT, every 1000
 * instructions). While any hook is set, Lua 5.4's interpreter calls luaG_traceexec before
 * every instruction; with only a count hook, 999 calls in 1000 just count down L->hookcount
 * and return. Under node, the hook cost check_the_article 11 % of its time (measured with no
 * hook set), most of it in those calls; counting in line takes back about half of that.
 * Here the countdown is done in line, and luaG_traceexec is called as before whenever it has
 * more to do than count: any other hook, or the count reaching its last instruction (the call
 * that runs the hook, on the same instruction as ever, and resets the count).
 *
 * What the skipped calls did besides counting: stored the instruction's pc in ci->u.l.savedpc.
 * Without hooks Lua never does that per instruction; it saves pc itself before anything that
 * can raise an error, collect garbage or call out (savepc, Protect), so between those points
 * the state is the one hook-free Lua always runs with. The base is still refreshed (vmfetch
 * goes on to updatebase), as the trap is also how a stack reallocation is signalled. */
#ifndef FRICTIONLAB_LUA_COUNT_HOOK_H
#define FRICTIONLAB_LUA_COUNT_HOOK_H

/* As lvm.c itself begins (its definitions repeat these, to the same). */
#define lvm_c
#define LUA_CORE

#include "lprefix.h"

#include "lua.h"

#include "ldebug.h"
#include "lstate.h"

static inline int frictionlab_traceexec(lua_State *L, const Instruction *pc) {
  if (l_likely(L->hookmask == LUA_MASKCOUNT && L->hookcount > 1)) {
    L->hookcount--;
    return 1; /* keep 'trap' on, as luaG_traceexec would */
  }
  return luaG_traceexec(L, pc);
}

/* lvm.c calls luaG_traceexec in one place, its vmfetch; ldebug.h, declaring the real one, has
 * been read above and is not read again. */
#define luaG_traceexec frictionlab_traceexec

#endif
