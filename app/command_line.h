// The command line's options in one table: for each, the commands that take it, the kind of
// value it takes and its allowed range, and its line of help. Every command (the window, list,
// run, check, render, link, bench) reads its options through read_options(), and `frictionlab help` and the manual
// page's SYNOPSIS and OPTIONS are written from the table; so an option is added, renamed or given a new
// range in one place.
#pragma once

#include <cstdint>
#include <functional>
#include <ostream>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace frictionlab {

// check --random's seed when --seed is not given; the help and the manual page say it from here.
constexpr std::uint64_t default_random_seed = 1;

// The commands that take options, one bit each, so that an option names all of its commands
// in one word: Command::run | Command::check.
enum class Command : unsigned {
  window = 1u << 0,  // frictionlab [LESSON], frictionlab --setup FILE
  list = 1u << 1,
  run = 1u << 2,
  check = 1u << 3,
  render = 1u << 4,
  link = 1u << 5,
  bench = 1u << 6,
};
constexpr Command operator|(Command a, Command b) {
  return static_cast<Command>(static_cast<unsigned>(a) | static_cast<unsigned>(b));
}
constexpr bool includes(Command commands, Command command) {
  return (static_cast<unsigned>(commands) & static_cast<unsigned>(command)) != 0;
}
// "run", and "the window" for the window: as the help and the messages name them.
std::string_view command_name(Command command);

enum class ValueKind {
  none,          // a switch, given alone: --projector
  number,        // a decimal number within the range: --hz 240
  whole_number,  // a whole number within the range: --substeps 4
  numbers,       // decimal numbers within the range, separated by commas: render's --at 0.5,2
  size,          // WIDTHxHEIGHT, the width within the range, the height within height_range
  text,          // a name, a file, NAME=VALUE or one of a few words, which the command reads
};

// An allowed range, as the out-of-range message gives it: "--hz = 0 steps per second is
// outside the allowed range [1, 100000]".
struct Range {
  double low = 0, high = 0;
  bool low_open = false;  // low itself refused: a run of 0 s would run nothing
  const char* unit = "";  // after the number in the message: " s", " steps per second"
};

// How an option is written beside the one before it in the list an unknown option is answered
// with. (The usage's forms, in app/command_line.cpp, bracket their options themselves.)
enum class Beside {
  apart,     // --hz N, --substeps N
  together,  // --mystery MATERIAL/MATERIAL --seed N: one needs the other
};

struct Option {
  std::string_view name{};   // "--hz"
  Command commands{};        // the commands that take it
  std::string_view value{};  // the value as the help writes it ("N", "NAME=VALUE"); empty for a switch
  ValueKind kind = ValueKind::none;
  Range range{};                 // for the numbers
  Range height_range{};          // --size's height
  std::string_view help{};       // one line; {range} stands for the range in words, {default} for default_value
  double default_value = 0;      // where the help says it with {default}: the value taken when none is given
  std::string_view manual{};     // the manual page's paragraph, where it says more than the help
  std::string_view example{};    // a value every command that takes it accepts, for the tests
  Beside beside = Beside::apart;
  bool repeatable = false;       // --set: one parameter each time
  std::string_view twice_hint{}; // said after "given twice" when giving it twice is a likely slip
  bool held_by_setup = false;    // a setup file holds it, so the window refuses it beside --setup

  // The value as a decimal number within the range; throws InvalidInput naming the option and
  // the range (option_number's message).
  double number(const std::string& text) const;
  // The value as a whole number within the range: "--substeps 2.5: a whole number from 1 to 1000".
  int whole_number(const std::string& text) const;
  // "from 1 to 100000", "above 0, at most 86400": the range as the help writes it.
  std::string range_words() const;
  // The help line, filled_in().
  std::string help_line() const;
  // `text` (the help or the manual's paragraph) with {range}, {default} and {held} (the options a
  // setup holds) written out.
  std::string filled_in(std::string_view text) const;
};

// Every option, in the order the help and the unknown-option messages list them.
std::span<const Option> options_table();
// The option `name` as `command` takes it; throws std::logic_error when it takes none such (a
// mistake in the program, not in the input).
const Option& option_for(Command command, std::string_view name);

// Reads a command's arguments in order: each word that is not an option goes to `operand`, each
// option the command takes to `take` with its value ("" for a switch). Throws InvalidInput for
// an option the command does not take (listing those it does), one without its value, and one
// given twice (but --set and the switches, where twice means the same).
void read_options(Command command, const std::vector<std::string>& args,
                  const std::function<void(const std::string&)>& operand,
                  const std::function<void(const Option&, const std::string&)>& take);
// The message for an option `command` does not take, with the options it does.
std::string unknown_option_message(Command command, const std::string& option);

// The manual page's OPTIONS section, in roff: a subsection for each command (the window, list,
// run, check, render, link, bench), each option under the first command that takes it, with its
// manual paragraph (or its line of help). packaging/ writes it into frictionlab.1 at build time.
std::string manual_options();
// The manual page's SYNOPSIS, in roff: the usage forms `frictionlab help` writes (usage_text),
// one .SY block each, so that an option added to a form, or to the table a form names it from,
// is in the synopsis too. A bracketed group ("[--hz N]") is never broken across lines, as the
// help never breaks one. packaging/ writes it into frictionlab.1 at build time.
std::string manual_synopsis();

// `frictionlab help`: the commands' usage and every option, from the table. The command line
// built for node (web/) has list, run, check, demo and link only, and is run as
// `node frictionlab-cli.js`.
enum class Program { desktop, node };
std::string usage_text(Program program);

// Bad input said on `err`: "frictionlab: " `context` `message`, and for a script's Lua message
// the same in plain words on the next line, as the window and the page say it.
void say_bad_input(std::ostream& err, const std::string& context, const std::string& message);

}  // namespace frictionlab
