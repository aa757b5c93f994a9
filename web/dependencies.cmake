# The browser build's Box2D, Lua and Dear ImGui, compiled by emscripten from Debian's source
# packages (scripts/web.sh fetches and unpacks them, Debian's patches applied, into
# FRICTIONLAB_WEB_SOURCES). Each is made under the name the native build finds it by
# (box2d::box2d, LUA_CXX_LIBRARY, PkgConfig::IMGUI), so the project's own CMake files stay one.
set(FRICTIONLAB_WEB_SOURCES "" CACHE PATH "Folder holding box2d-2.4.1/, lua5.4-5.4.4/ and imgui-1.86+ds/ (scripts/web.sh)")
foreach(source box2d-2.4.1 lua5.4-5.4.4 imgui-1.86+ds)
  if(NOT IS_DIRECTORY "${FRICTIONLAB_WEB_SOURCES}/${source}")
    message(FATAL_ERROR "${source} not found in FRICTIONLAB_WEB_SOURCES='${FRICTIONLAB_WEB_SOURCES}': build the web version with scripts/web.sh, which fetches it")
  endif()
endforeach()

# Box2D 2.4.1. b2_timer.cpp is left out: it has members for Linux and Apple only, and the
# physics library brings its own clock-free b2Timer (physics/box2d_timer.cpp) anyway.
set(box2d_root "${FRICTIONLAB_WEB_SOURCES}/box2d-2.4.1")
file(GLOB_RECURSE box2d_sources CONFIGURE_DEPENDS "${box2d_root}/src/*.cpp")
list(FILTER box2d_sources EXCLUDE REGEX "b2_timer\\.cpp$")
add_library(web_box2d STATIC ${box2d_sources})
target_include_directories(web_box2d SYSTEM PUBLIC "${box2d_root}/include" PRIVATE "${box2d_root}/src")
add_library(box2d::box2d ALIAS web_box2d)

# Lua 5.4 as C++, as Debian's liblua5.4-c++ is: a script's error unwinds the C++ frames it
# crosses as an exception rather than a longjmp over them.
set(lua_root "${FRICTIONLAB_WEB_SOURCES}/lua5.4-5.4.4/src")
set(lua_sources)
foreach(unit lapi lcode lctype ldebug ldo ldump lfunc lgc llex lmem lobject lopcodes lparser lstate lstring ltable ltm
             lundump lvm lzio lauxlib lbaselib lcorolib ldblib liolib lmathlib loadlib loslib lstrlib ltablib lutf8lib linit)
  list(APPEND lua_sources "${lua_root}/${unit}.c")
endforeach()
set_source_files_properties(${lua_sources} PROPERTIES LANGUAGE CXX)
add_library(web_lua STATIC ${lua_sources})
# Debian's luaconf.h includes a header its build writes, naming the architecture for the
# folders of compiled modules (which the sandbox never loads).
file(WRITE "${CMAKE_BINARY_DIR}/lua-multiarch/lua5.4-deb-multiarch.h" "#define DEB_HOST_MULTIARCH \"wasm32-emscripten\"\n")
target_include_directories(web_lua SYSTEM PUBLIC "${CMAKE_BINARY_DIR}/lua-multiarch")
target_compile_definitions(web_lua PUBLIC LUA_COMPAT_5_3 PRIVATE LUA_USE_POSIX)
target_compile_options(web_lua PRIVATE -w)
# The interpreter counts the sandbox's instructions in line rather than calling luaG_traceexec
# before each one (web/lua_count_hook.h says why that changes nothing a script can see).
set(lua_count_hook "${CMAKE_CURRENT_LIST_DIR}/lua_count_hook.h")
set_source_files_properties("${lua_root}/lvm.c" PROPERTIES COMPILE_OPTIONS "-include;${lua_count_hook}"
                                                           OBJECT_DEPENDS "${lua_count_hook}")
target_include_directories(web_lua PRIVATE "${lua_root}")
set(LUA_INCLUDE_DIR "${lua_root}" CACHE PATH "" FORCE)
set(LUA_CXX_LIBRARY web_lua CACHE STRING "" FORCE)

# Dear ImGui 1.86 with its GLFW and OpenGL 3 backends. WebGL 2 is OpenGL ES 3: "#version 300 es"
# shaders (the backend would guess ES 2 under emscripten).
set(imgui_root "${FRICTIONLAB_WEB_SOURCES}/imgui-1.86+ds")
add_library(web_imgui STATIC
  ${imgui_root}/imgui.cpp ${imgui_root}/imgui_draw.cpp ${imgui_root}/imgui_tables.cpp ${imgui_root}/imgui_widgets.cpp
  ${imgui_root}/backends/imgui_impl_glfw.cpp ${imgui_root}/backends/imgui_impl_opengl3.cpp)
target_include_directories(web_imgui SYSTEM PUBLIC "${imgui_root}")
target_compile_definitions(web_imgui PUBLIC IMGUI_IMPL_OPENGL_ES3)
target_compile_options(web_imgui PRIVATE -w)
target_link_options(web_imgui PUBLIC -sUSE_GLFW=3)
add_library(PkgConfig::IMGUI ALIAS web_imgui)
