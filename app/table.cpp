#include "app/table.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
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

void prepare_output_folder(const std::string& option, const std::string& folder) {
  std::error_code error;
  std::filesystem::create_directories(folder, error);
  if (error) throw InvalidInput(option + " " + folder + ": cannot create the folder: " + error.message());
  const std::string probe = folder + "/.frictionlab-write-test";
  std::ofstream file(probe, std::ios::binary);
  if (!file) {
    throw InvalidInput(option + " " + folder + ": cannot write there: " + std::strerror(errno) +
                       "; give a folder you can write to");
  }
  file.close();
  std::remove(probe.c_str());
}

void write_files_atomically(const std::vector<std::pair<std::string, std::string>>& files) {
  std::vector<std::string> written;
  auto discard = [&] {
    for (const std::string& partial : written) std::remove(partial.c_str());
  };
  for (const auto& [path, text] : files) {
    const std::string temporary = path + ".partial";
    std::ofstream file(temporary, std::ios::binary);
    if (!file) {
      const std::string reason = std::strerror(errno);
      discard();
      throw InvalidInput("cannot write " + path + ": " + reason);
    }
    written.push_back(temporary);
    file << text;
    file.close();
    if (!file) {
      discard();
      throw InvalidInput("cannot write " + path + ": the disk refused the data");
    }
  }
  for (size_t i = 0; i < files.size(); ++i) {
    if (std::rename(written[i].c_str(), files[i].first.c_str()) != 0) {
      const std::string reason = std::strerror(errno);
      // None at all: the files already renamed go too, with the partial ones.
      for (size_t done = 0; done < i; ++done) std::remove(files[done].first.c_str());
      written.erase(written.begin(), written.begin() + static_cast<std::ptrdiff_t>(i));
      discard();
      throw InvalidInput("cannot write " + files[i].first + ": " + reason);
    }
  }
}

}  // namespace frictionlab
