# The GoogleTest suites that need no window, built for node (scripts/web_test.sh configures
# with FRICTIONLAB_WEB_TESTS=ON): the physics, the lesson runtime and its built-in lessons, and
# the student's lesson folder, run by ctest in build-web/ as node programs. GoogleTest 1.12
# comes from Debian's source package, as Box2D, Lua and ImGui do.
set(gtest_root "${FRICTIONLAB_WEB_SOURCES}/googletest-1.12.1/googletest")
if(NOT IS_DIRECTORY "${gtest_root}")
  message(FATAL_ERROR "googletest-1.12.1 not found in FRICTIONLAB_WEB_SOURCES: scripts/web.sh fetches it")
endif()
add_library(web_gtest STATIC "${gtest_root}/src/gtest-all.cc" "${gtest_root}/src/gtest_main.cc")
target_include_directories(web_gtest SYSTEM PUBLIC "${gtest_root}/include" PRIVATE "${gtest_root}")
# One thread in WebAssembly without workers: GoogleTest's locks are left out.
target_compile_definitions(web_gtest PUBLIC GTEST_HAS_PTHREAD=0)
target_compile_options(web_gtest PRIVATE -w)

set(tests_folder "${PROJECT_SOURCE_DIR}/tests")
# -O1 at the link (after the build type's -O3, so it wins there): the libraries' objects are
# compiled with -O3 all the same (the test files at -O1, below), and the link's -O3 passes
# (wasm-opt) cost 17.5 s a test program against 1.7 s, six minutes of two cores for 23 programs
# that run once.
set(web_test_link_options -sNODERAWFS=1 -sENVIRONMENT=node -sALLOW_MEMORY_GROWTH=1 -sEXIT_RUNTIME=1 -sTOTAL_STACK=4MB
                          -sWASM_ASYNC_COMPILATION=0 -O1)
# FILE is a test file's path under tests/ without .cpp (tests/README.md maps them); the target
# and the test are web_ and the file's name: physics/test_scene builds web_test_scene.
function(frictionlab_web_test file library)
  get_filename_component(name ${file} NAME)
  add_executable(web_${name} "${tests_folder}/${file}.cpp")
  target_link_libraries(web_${name} PRIVATE ${library} frictionlab_flags web_gtest)
  target_link_options(web_${name} PRIVATE ${web_test_link_options})
  # The test file itself at -O1 too, as in the native release build (tests/CMakeLists.txt says why).
  target_compile_options(web_${name} PRIVATE -O1)
  set_target_properties(web_${name} PROPERTIES SUFFIX ".js")
  add_test(NAME web_${name} COMMAND node $<TARGET_FILE:web_${name}>)
  set_tests_properties(web_${name} PROPERTIES TIMEOUT 900)
endfunction()

foreach(file physics/test_materials physics/test_friction_laws physics/test_closed_forms physics/test_reduced_model
             physics/test_wedge_model physics/test_scene physics/test_scene_rest physics/test_box2d_timer
             physics/test_friction_listener physics/test_treatment_stick_slip physics/test_stability bench/test_run_check
             bench/test_problems bench/test_cheapest_setting)
  frictionlab_web_test(${file} frictionlab_physics)
endforeach()
foreach(file lessons/test_lesson lessons/test_sandbox scenarios/test_builtin_lessons lessons/test_script_world
             bench/test_lesson_problem lessons/test_script_predict lessons/test_script_lesson lessons/test_handles
             lessons/test_script_theory lessons/test_class_words)
  frictionlab_web_test(${file} frictionlab_lessons)
endforeach()
# The guide's table of theory.* functions against the runtime's, read from the source tree.
target_compile_definitions(web_test_script_theory PRIVATE FRICTIONLAB_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
target_link_libraries(web_test_stability PRIVATE frictionlab_bench)
target_link_libraries(web_test_run_check PRIVATE frictionlab_bench)
target_link_libraries(web_test_problems PRIVATE frictionlab_bench)
target_link_libraries(web_test_cheapest_setting PRIVATE frictionlab_bench)
target_link_libraries(web_test_lesson_problem PRIVATE frictionlab_bench)
frictionlab_web_test(scenarios/test_lesson_errors frictionlab_lessons)
target_compile_definitions(web_test_lesson_errors PRIVATE FRICTIONLAB_BROKEN_LESSONS="${tests_folder}/broken_lessons")
frictionlab_web_test(classroom_state/test_user_lessons frictionlab_classroom_state)
frictionlab_web_test(classroom_state/test_playback frictionlab_classroom_state)
