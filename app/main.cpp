// frictionlab: the command line. With no command it opens the classroom window on a lesson.
#if defined(__EMSCRIPTEN__)
#include <emscripten.h>
#include <sys/stat.h>
#endif

#include <algorithm>
#include <iostream>
#include <string>
#include <vector>

#include "app/install_paths.h"
#include "app/modes.h"
#include "lessons/runtime/catalog.h"
#include "physics/materials.h"
#include "ui/output_file.h"

namespace {

#if defined(FRICTIONLAB_COMMAND_LINE_ONLY)
// The command line built for node (web/): the commands that need no drawing. The window is the
// page's, and pictures to PNG files are the desktop program's.
const char* const usage =
    "usage: node frictionlab-cli.js list [--tsv]   the built-in lessons with their titles and moments\n"
    "       node frictionlab-cli.js run LESSON [--duration S] [--hz N] [--substeps N]\n"
    "                       [--friction stick-slip|threshold|regularized|box2d]\n"
    "                       [--set NAME=VALUE ...] [--csv FILE] [--mystery MATERIAL/MATERIAL --seed N]\n"
    "                                            run a lesson (a name from list, or a .lua file)\n"
    "       node frictionlab-cli.js check [LESSON ...] [--set NAME=VALUE ...] [--hz N] [--substeps N] [--friction T]\n"
    "                                            run lessons and check their expectations; exit 1 if any fails\n"
    "       node frictionlab-cli.js check LESSON --random N [--seed S]\n"
    "                                            the lesson at N settings drawn inside its sliders' ranges\n"
    "       node frictionlab-cli.js demo         theory beside simulation for every situation\n"
    "       node frictionlab-cli.js link FILE.setup [--page ADDRESS] | link LINK\n"
    "                                            a setup file as a link to the web page, or back\n"
    "       node frictionlab-cli.js help | --version\n"
    "Exit status: 0 done; 1 check or demo found simulation and theory disagreeing; 2 bad input (the\n"
    "message names what and where) or the program could not finish.\n"
    "This is FrictionLab's WebAssembly build for node: the classroom is the web page, and render and\n"
    "bench are the desktop program's.\n";
constexpr const char* command_names = "list, run, check, demo, link, help, --version";
#else
const char* const usage =
    "usage: frictionlab [LESSON] [--lock NAME[,NAME...]] [--set NAME=VALUE ...] [--hz N] [--substeps N]\n"
    "                   [--friction T] [--theme light|dark] [--projector] [--at S --screenshot FILE.png]\n"
    "                   [--mystery MATERIAL/MATERIAL --seed N]\n"
    "                                            the classroom window on a lesson (the first one if none is\n"
    "                                            named); --lock shows only the named controls; --projector\n"
    "                                            fills the screen with larger text; --at and --screenshot save\n"
    "                                            the window at that time and close it;\n"
    "                                            --mystery hides a pair's mu_s and mu_k, drawn from the seed\n"
    "                                            (0 to 999999), until the teacher reveals them.\n"
    "       frictionlab --setup FILE [--theme light|dark] [--projector] [--at S --screenshot FILE.png]\n"
    "                                            the window on a prepared setup (Lesson > Save as a setup):\n"
    "                                            its lesson, values, lock, mystery and step settings\n"
    "                                            Without a display it draws the lesson to a PNG instead.\n"
    "       frictionlab list [--tsv]             the built-in lessons with their titles and moments (--tsv: for\n"
    "                                            scripts, name, title, README moment and moments, tab-separated)\n"
    "       frictionlab run LESSON [--duration S] [--hz N] [--substeps N]\n"
    "                       [--friction stick-slip|threshold|regularized|box2d]\n"
    "                       [--set NAME=VALUE ...] [--csv FILE] [--mystery MATERIAL/MATERIAL --seed N]\n"
    "                                            run a lesson (a name from list, or a .lua file)\n"
    "       frictionlab check [LESSON ...] [--set NAME=VALUE ...] [--hz N] [--substeps N] [--friction T]\n"
    "                         [--random N [--seed S]]\n"
    "                                            run lessons and check their expectations; exit 1 if any fails;\n"
    "                                            --random checks each lesson at N settings (1 to 100000) drawn\n"
    "                                            inside its sliders' ranges, ends included, from seed S (0 to\n"
    "                                            999999, default 1), and prints each failing one as the\n"
    "                                            command line that reproduces it\n"
    "       frictionlab render LESSON --at S[,S...] [--size WxH] [--theme light|dark]\n"
    "                       [--set NAME=VALUE ...] [--hz N] [--substeps N] [--friction T]\n"
    "                       [--mystery MATERIAL/MATERIAL --seed N] --out PATH\n"
    "                                            draw the lesson at each time to PNG, with no display; PATH is\n"
    "                                            a .png file for one time, a folder for several (LESSON_tS.png)\n"
    "       frictionlab render LESSON --moment NAME [--size WxH] --out PATH\n"
    "                                            draw one of the lesson's moments (its time, values and theme)\n"
    "       frictionlab demo                     theory beside simulation for every situation\n"
    "       frictionlab link FILE.setup [--page ADDRESS]\n"
    "                                            the setup as a link to the web page (ADDRESS#setup=...;\n"
    "                                            without --page, the part to put after the page's address)\n"
    "       frictionlab link LINK | -            the setup file a link holds, printed (--setup takes a link too;\n"
    "                                            - reads the link from the standard input); a lesson the link\n"
    "                                            carries is kept among your lessons, and the setup names it\n"
    "       frictionlab bench [--quick] --out DIR     speed and accuracy figures, CSV files and charts\n"
    "       frictionlab bench --recommend LESSON --tol X [--set NAME=VALUE]\n"
    "                                            the cheapest setting whose run of the lesson meets its\n"
    "                                            table within X times the rows' tolerances at 240 Hz\n"
    "                                            (1: the table passes; 0.1: ten times tighter; measured\n"
    "                                            now; exit 1 if none does)\n"
    "       frictionlab help | --help | -h       this text\n"
    "       frictionlab --version                the version\n"
    "Exit status: 0 done; 1 check or demo found simulation and theory disagreeing, or\n"
    "bench --recommend found no setting; 2 bad input (the message names what and where) or the\n"
    "program could not finish.\n"
    "The built-in lessons are in $FRICTIONLAB_LESSONS if set, else installed beside the program.\n"
    "More in the manual: man frictionlab\n";
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
    frictionlab::ui::remove_partial_files_on_interrupt();
    const std::string command = args.empty() ? "" : args[0];
#if defined(FRICTIONLAB_COMMAND_LINE_ONLY)
    if (command.empty()) {
      std::cerr << usage;
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
      std::cout << usage;
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
    std::cerr << "frictionlab: " << error.what() << '\n';
    return 2;
  } catch (const std::exception& error) {
    // Not bad input but something the machine could not do (out of memory, say): still a
    // message and the same exit code, never an abort.
    std::cerr << "frictionlab: could not finish: " << error.what() << '\n';
    return 2;
  }
}
