// The command-line modes. Each returns the process exit code: 0 success, 1 a check failed,
// 2 bad input (InvalidInput thrown with a message naming what and where).
#pragma once

#include <ostream>
#include <string>
#include <vector>

namespace frictionlab {

int run_demo(std::ostream& out);
int run_bench(const std::vector<std::string>& args, std::ostream& out);
int run_list(const std::vector<std::string>& args, std::ostream& out);
int run_lesson(const std::vector<std::string>& args, std::ostream& out);   // frictionlab run
int run_check(const std::vector<std::string>& args, std::ostream& out);
int run_render(const std::vector<std::string>& args, std::ostream& out);  // frictionlab render
int run_window_mode(const std::vector<std::string>& args, std::ostream& out);  // frictionlab [LESSON]
int run_link(const std::vector<std::string>& args, std::ostream& out);  // frictionlab link: setup file <-> web page link

// Each reads `args` as its command does, with every check made before the command starts
// work, and does nothing with them; throws InvalidInput as the command would. For the tests,
// which give each parser every option the options table says its command takes.
void parse_run_arguments(const std::vector<std::string>& args);
void parse_check_arguments(const std::vector<std::string>& args);
void parse_render_arguments(const std::vector<std::string>& args);
void parse_window_arguments(const std::vector<std::string>& args);

}  // namespace frictionlab
