// Plain-text tables for the terminal: theory beside simulation, and benchmark figures.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "physics/scenarios.h"

namespace frictionlab {

// Prints theory, measured, error, tolerance and pass for each row; returns how many failed.
int print_measurements(std::ostream& out, const std::vector<Measurement>& rows);

// A simple aligned table: the first row is the header.
void print_table(std::ostream& out, const std::vector<std::vector<std::string>>& rows);

std::string format_number(double value, int significant = 4);

// Makes `folder` if needed and checks that a file can be written in it, so that a long run
// is not wasted on an output place that refuses it. Throws InvalidInput naming `option`.
void prepare_output_folder(const std::string& option, const std::string& folder);

// Writes every (path, text) whole or none at all: each to a temporary file beside it, then
// all renamed. Throws InvalidInput naming the path that could not be written.
void write_files_atomically(const std::vector<std::pair<std::string, std::string>>& files);

}  // namespace frictionlab
