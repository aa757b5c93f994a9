// frictionlab: the command line. Until the window exists, running it with no command shows
// the built-in demonstration: every textbook situation, theory beside simulation.
#include <iostream>
#include <string>
#include <vector>

#include "app/modes.h"
#include "physics/materials.h"

int main(int argc, char** argv) {
  const std::vector<std::string> args(argv + 1, argv + argc);
  try {
    if (args.empty() || args[0] == "demo") {
      if (args.size() > 1) {
        throw frictionlab::InvalidInput("demo takes no options, got '" + args[1] + "'; usage: frictionlab [demo]");
      }
      return frictionlab::run_demo(std::cout);
    }
    if (args[0] == "bench") return frictionlab::run_bench(std::vector<std::string>(args.begin() + 1, args.end()), std::cout);
    if (args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
      std::cout << "usage: frictionlab [demo]                      theory beside simulation for every situation\n"
                   "       frictionlab bench [--quick] --out DIR     listener cost and accuracy against cost\n";
      return 0;
    }
    std::cerr << "frictionlab: unknown command '" << args[0] << "'; commands: demo, bench, help\n";
    return 2;
  } catch (const frictionlab::InvalidInput& error) {
    std::cerr << "frictionlab: " << error.what() << '\n';
    return 2;
  }
}
