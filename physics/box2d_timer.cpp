// Box2D's profiling timer, made to read no clock.
//
// Box2D 2.4.1 times the parts of every step for b2World::GetProfile(): it starts or reads a
// b2Timer, which asks the system clock (gettimeofday), 7 times a step and 7 more for each island
// (each body resting alone on the ground is one). At about 27 ns a reading on this machine,
// that was a fifth of a one-block lesson's step, and a wall clock read inside the physics,
// which nothing here uses: FrictionLab never asks for the profile.
//
// Debian's libbox2d.so calls its timer through the procedure linkage table, so these
// definitions, linked into the program, are the ones it calls (the dynamic linker takes the
// program's definition first). The profile then reads 0 ms for every part; the simulation
// does not read the timer, so its results are unchanged. physics/CMakeLists.txt makes every
// program that links frictionlab_physics link this file (nothing in FrictionLab calls it by
// name, so the linker would otherwise leave it in the archive). test_box2d_timer checks that the
// timer reads no clock.
#include <box2d/b2_timer.h>

b2Timer::b2Timer() { Reset(); }

void b2Timer::Reset() {
  // b2_timer.h gives the timer its fields on Linux and Apple only (and on Windows, which this
  // build is not for); WebAssembly (emscripten) has none to clear.
#if defined(__linux__) || defined(__APPLE__)
  m_start_sec = 0;
  m_start_usec = 0;
#endif
}

float b2Timer::GetMilliseconds() const { return 0.0f; }
