// The one CSV format of a lesson's record. The window's export (Ctrl+E) and `frictionlab run
// --csv` both write it through these functions, so the two cannot drift apart: a class that
// opens either in a spreadsheet, or reads it with a few lines of Python, finds the same columns
// under the same names.
//
// The format: UTF-8 with a byte-order mark (a spreadsheet in a cp1252 locale otherwise reads
// "°" as "Â°"), then the header line at once (no comment line before it, which parsers that
// take the first line as the header broke on), then one row a frame, numbers in C's notation
// with a point. What made the run (the lesson, its step settings and parameters) does not fit
// a column, so it goes beside the file in a short text file (settings_path_for).
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <string>

#include "lessons/runtime/lesson.h"

namespace frictionlab::lessons {

inline constexpr char csv_byte_order_mark[] = "\xEF\xBB\xBF";
// The first column's name, the header's start.
inline constexpr char csv_time_column[] = "t (s)";
// The settings file's first words.
inline constexpr char settings_first_words[] = "FrictionLab run of ";

// The mark and the header line, '\n' included: "t (s)", each probe as "name (unit)" ("name"
// alone where it has no unit), then any_contact_slipping (1 or 0), hand_pulled (1 or 0) and
// "gauge (N)" (the size of the force the window's force gauge read, as its dial does, never
// negative; empty where the hand did not pull; a command-line run has no hand, so 0 and empty
// throughout).
std::string csv_header(const Lesson& lesson);

// Row `frame` of the scene's record (Scene::times() and each probe's history), '\n' included,
// with `gauge` as the hand's pull in that frame, or none.
std::string csv_row(const Scene& scene, std::size_t frame, std::optional<double> gauge);

// What made the run, for the text file beside the CSV (or standard error): the lesson's path,
// the step settings in force and each parameter as "name = value" on a line of its own;
// a parameter for which `hidden` is true (a mystery pair's) reads "?".
std::string run_settings(const Lesson& lesson, const std::function<bool(const std::string&)>& hidden);

// The settings file beside a CSV: "run.csv" -> "run_settings.txt" (a name without ".csv" gets
// "_settings.txt" added).
std::string settings_path_for(const std::string& csv_path);

// Whether `first_line` (as read, mark included) starts a CSV FrictionLab wrote (its header,
// from "t (s)" to "gauge (N)", or an earlier version's "# FrictionLab …" line), or a settings
// file FrictionLab wrote: only such files are replaced by a new run.
bool starts_frictionlab_csv(const std::string& first_line);
bool starts_frictionlab_settings(const std::string& first_line);
// The same for the file at `path`, read to its first line: what OutputFile asks before it
// replaces a file (files/output_file.h).
bool frictionlab_csv_file(const std::string& path);
bool frictionlab_settings_file(const std::string& path);

}  // namespace frictionlab::lessons
