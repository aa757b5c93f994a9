// Debian's libstb-dev ships stb's implementations as a native library only; the browser build
// compiles them from the same headers, once, here.
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb_image.h>
#include <stb_image_write.h>
