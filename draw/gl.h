// OpenGL's declarations for the platform the program is built for: desktop OpenGL 3.3 core
// natively (glvnd's libOpenGL), OpenGL ES 3 in the browser, which is what WebGL 2 offers.
// Everything the project draws with is in both.
#pragma once

#if defined(__EMSCRIPTEN__)
#include <GLES3/gl3.h>
#else
#define GL_GLEXT_PROTOTYPES 1
#include <GL/glcorearb.h>
#endif
