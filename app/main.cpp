// frictionlab: the command line. With no command it opens the classroom window on a lesson.
#if defined(__EMSCRIPTEN__)
#include <emscripten.h>
#include <sys/stat.h>
#endif

#include <algorithm>
#include <iostream>
#include <string>
#include <vector>

#include "app/command_line.h"
#include "app/install_paths.h"
#include "app/modes.h"
#include "files/output_file.h"
#include "lessons/runtime/catalog.h"
#include "physics/materials.h"

namespace {

#if defined(FRICTIONLAB_COMMAND_LINE_ONLY)
// The command line built for node (web/): the commands that need no drawing. The window is the
// page's, and pictures to PNG files are the desktop program's.
constexpr frictionlab::Program program = frictionlab::Program::node;
constexpr const char* command_names = "list, run, check, demo, link, help, --version";
#else
// Every command, and the window. The usage of both is written from app/command_line.cpp's table.
constexpr frictionlab::Program program = frictionlab::Program::desktop;
constexpr const char* commands[] = {"demo", "list", "run", "check", "render", "bench", "link", "--help", "-h", "help", "--version"};
constexpr const char* command_names = "list, run, check, render, demo, bench, link, help, --version; or a lesson to open in the window";
#endif

}  // namespace

int main(int argc, char** argv) {
  const std::vector<std::string> args(argv + 1, argv + argc);
#if defined(__EMSCRIPTEN__)
  // emscripten starts every program with a umask of 0777, so a file it writes (run --csv) would
  // be readable by nobody: take node's own, the user's (in a browser page, the usual 022).
  ::umask(static_cast<mode_t>(EM_ASM_INT({ return globalThis.process && process.umask ? process.umask() : 18; })));
#endif
  try {
    frictionlab::use_installed_lessons();
    // Ctrl-C while a CSV or PNG is being written leaves no temporary file behind.
    frictionlab::files::remove_partial_files_on_interrupt();
    const std::string command = args.empty() ? "" : args[0];
#if defined(FRICTIONLAB_COMMAND_LINE_ONLY)
    if (command.empty()) {
      std::cerr << frictionlab::usage_text(program);
      return 2;
    }
#else
    // Anything but a command is a lesson (a name or a .lua file) or the window's options.
    const bool a_command = std::find(std::begin(commands), std::end(commands), command) != std::end(commands);
    const bool looks_like_lesson = command.empty() || command.rfind("--", 0) == 0 ||
                                   command.find('/') != std::string::npos || command.find(".lua") != std::string::npos ||
                                   frictionlab::lessons::is_builtin_lesson(command);
    if (!a_command && looks_like_lesson) return frictionlab::run_window_mode(args, std::cout);
#endif
    const std::vector<std::string> rest(args.begin() + 1, args.end());
    if (command == "demo") {
      if (!rest.empty()) throw frictionlab::InvalidInput("demo takes no options, got '" + rest[0] + "'; usage: frictionlab demo");
      return frictionlab::run_demo(std::cout);
    }
    if (command == "list") return frictionlab::run_list(rest, std::cout);
    if (command == "run") return frictionlab::run_lesson(rest, std::cout);
    if (command == "check") return frictionlab::run_check(rest, std::cout);
    if (command == "link") return frictionlab::run_link(rest, std::cout);
#if !defined(FRICTIONLAB_COMMAND_LINE_ONLY)
    if (command == "render") return frictionlab::run_render(rest, std::cout);
    if (command == "bench") return frictionlab::run_bench(rest, std::cout);
#endif
    if (command == "--version") {
      if (!rest.empty()) throw frictionlab::InvalidInput("--version takes no options, got '" + rest[0] + "'");
      std::cout << "frictionlab " FRICTIONLAB_VERSION "\n";
      return 0;
    }
    if (command == "--help" || command == "-h" || command == "help") {
      std::cout << frictionlab::usage_text(program);
      return 0;
    }
#if defined(FRICTIONLAB_COMMAND_LINE_ONLY)
    std::cerr << "frictionlab: unknown command '" << command << "'; commands: " << command_names
              << (command == "render" || command == "bench" ? " (render and bench are the desktop program's)" : "") << '\n';
#else
    std::string lessons;
    for (const std::string& name : frictionlab::lessons::builtin_lessons()) lessons += name + ", ";
    std::cerr << "frictionlab: unknown command '" << command << "'; commands: " << command_names << ": " << lessons
              << "or a .lua file\n";
#endif
    return 2;
  } catch (const frictionlab::InvalidInput& error) {
    frictionlab::say_bad_input(std::cerr, "", error.what());
    return 2;
  } catch (const std::exception& error) {
    // Not bad input but something the machine could not do (out of memory, say): still a
    // message and the same exit code, never an abort.
    std::cerr << "frictionlab: could not finish: " << error.what() << '\n';
    return 2;
  }
}
