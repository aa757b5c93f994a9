// Plain-text tables for the terminal: theory beside simulation, and benchmark figures.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "physics/scenarios.h"

namespace frictionlab {

// Prints predicted, measured, error, tolerance and pass for each row; returns how many failed.
int print_measurements(std::ostream& out, const std::vector<Measurement>& rows);

// A simple aligned table: the first row is the header.
void print_table(std::ostream& out, const std::vector<std::vector<std::string>>& rows);

std::string format_number(double value, int significant = 4);

// Writes `text` to `path` whole or not at all: a temporary file beside it, then a rename.
// Throws InvalidInput naming the path when it cannot be written.
void write_file_atomically(const std::string& path, const std::string& text);

}  // namespace frictionlab
