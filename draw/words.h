// Text fitted to the room the drawing has for it. A script's names in the class's words are
// lessons/runtime/class_words.h.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace frictionlab::draw {

// A file's path as it fits in `room` points of the current ImGui font, never cut: the whole
// path; else its first folders, "…" and the whole file name ("/home/ann/…/wedge.lua"); else the
// file name with "…" in its middle ("check_t…article.lua"); "" when not even "…" fits.
std::string path_that_fits(const std::string& path, float room);

// A line of words (the status line: a notice, what was saved where) as it fits in `room` points
// of the current ImGui font: the whole line; else its first words and its last with " … "
// between, cut between words, never inside one (the trial read "Kept from the last sessio…sion
// start"); a path at its end is kept whole as far as it fits (path_that_fits), since the file's
// name is the news. Only a first word wider than the room is cut inside, at characters.
std::string words_that_fit(const std::string& line, float room);

// The same line on at most `most_lines` lines of `room` points each (the status line beside the
// time bar, where a projector leaves 470 px of a 1920 px screen: on one line the trial read
// "Kept from the last … session starts."): broken between words, as many as fit on each line;
// the last line takes what is left as words_that_fit cuts it. No lines for an empty line.
std::vector<std::string> lines_that_fit(const std::string& line, float room, int most_lines);

// `text` whole, with a line break in place of a space wherever the line would grow wider than
// `room` points of the current ImGui font: broken between words only, nothing cut. ImGui's own
// wrapping also breaks after a full stop, which split a script's name in its message
// ("my_incline." and "lua builds" on two lines). A word wider than the room keeps a line of
// its own, and ImGui wraps that.
std::string broken_at_spaces(std::string text, float room);

}  // namespace frictionlab::draw
