// frictionlab: the command line. Until the window exists, running it with no command runs the
// first lesson headlessly and prints its theory-against-simulation table.
#include <iostream>
#include <string>
#include <vector>

#include "app/modes.h"
#include "physics/materials.h"

namespace {

const char* const usage =
    "usage: frictionlab                          run the first lesson (spring_pull) and print its table\n"
    "       frictionlab list                     the built-in lessons with their titles\n"
    "       frictionlab run LESSON [--duration S] [--hz N] [--substeps N]\n"
    "                       [--friction stick-slip|threshold|regularized|box2d]\n"
    "                       [--set NAME=VALUE ...] [--csv FILE]\n"
    "                                            run a lesson (a name from list, or a .lua file)\n"
    "       frictionlab check [LESSON ...]       run lessons and check their expectations; exit 1 if any fails\n"
    "       frictionlab render LESSON --at S[,S...] [--size WxH] [--theme light|dark]\n"
    "                       [--set NAME=VALUE ...] [--hz N] [--substeps N] [--friction T] --out PATH\n"
    "                                            draw the lesson at each time to PNG, with no display\n"
    "       frictionlab demo                     theory beside simulation for every situation\n"
    "       frictionlab bench [--quick] --out DIR     speed and accuracy figures\n";

}  // namespace

int main(int argc, char** argv) {
  const std::vector<std::string> args(argv + 1, argv + argc);
  try {
    if (args.empty()) return frictionlab::run_lesson({"spring_pull"}, std::cout);
    const std::string command = args[0];
    const std::vector<std::string> rest(args.begin() + 1, args.end());
    if (command == "demo") {
      if (!rest.empty()) throw frictionlab::InvalidInput("demo takes no options, got '" + rest[0] + "'; usage: frictionlab demo");
      return frictionlab::run_demo(std::cout);
    }
    if (command == "list") return frictionlab::run_list(rest, std::cout);
    if (command == "run") return frictionlab::run_lesson(rest, std::cout);
    if (command == "check") return frictionlab::run_check(rest, std::cout);
    if (command == "render") return frictionlab::run_render(rest, std::cout);
    if (command == "bench") return frictionlab::run_bench(rest, std::cout);
    if (command == "--help" || command == "-h" || command == "help") {
      std::cout << usage;
      return 0;
    }
    std::cerr << "frictionlab: unknown command '" << command << "'; commands: list, run, check, render, demo, bench, help\n";
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
