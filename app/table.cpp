#include "app/table.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace frictionlab {

std::string format_number(double value, int significant) {
  std::ostringstream text;
  text << std::setprecision(significant) << (value == 0.0 ? 0.0 : value);  // no "-0" in a table
  return text.str();
}

namespace {
// Columns line up by characters on screen, and units such as m/s² are UTF-8.
size_t display_width(const std::string& text) {
  size_t width = 0;
  for (unsigned char c : text) width += (c & 0xC0) != 0x80;
  return width;
}
}  // namespace

void print_table(std::ostream& out, const std::vector<std::vector<std::string>>& rows) {
  std::vector<size_t> widths;
  for (const auto& row : rows) {
    widths.resize(std::max(widths.size(), row.size()), 0);
    for (size_t i = 0; i < row.size(); ++i) widths[i] = std::max(widths[i], display_width(row[i]));
  }
  for (size_t r = 0; r < rows.size(); ++r) {
    for (size_t i = 0; i < rows[r].size(); ++i) {
      out << (i == 0 ? "" : "  ") << rows[r][i];
      if (i + 1 < rows[r].size()) out << std::string(widths[i] - display_width(rows[r][i]), ' ');
    }
    out << '\n';
    if (r == 0) {
      size_t total = 0;
      for (size_t w : widths) total += w + 2;
      out << std::string(total > 2 ? total - 2 : total, '-') << '\n';
    }
  }
}

int print_measurements(std::ostream& out, const std::vector<Measurement>& rows) {
  std::vector<std::vector<std::string>> table{{"quantity", "unit", "predicted", "measured", "error", "tolerance", "pass"}};
  int failed = 0;
  for (const Measurement& m : rows) {
    table.push_back({m.name, m.unit, format_number(m.predicted), format_number(m.measured), format_number(m.error(), 2),
                     format_number(m.tolerance, 2), m.passes() ? "yes" : "NO"});
    if (!m.passes()) ++failed;
  }
  print_table(out, table);
  return failed;
}

void write_file_atomically(const std::string& path, const std::string& text) {
  const std::string temporary = path + ".partial";
  {
    std::ofstream file(temporary, std::ios::binary);
    if (!file) throw InvalidInput("cannot write " + path + ": " + std::strerror(errno));
    file << text;
    file.close();
    if (!file) {
      std::remove(temporary.c_str());
      throw InvalidInput("cannot write " + path + ": the disk refused the data");
    }
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    const std::string reason = std::strerror(errno);
    std::remove(temporary.c_str());
    throw InvalidInput("cannot write " + path + ": " + reason);
  }
}

}  // namespace frictionlab
