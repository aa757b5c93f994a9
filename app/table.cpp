#include "app/table.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <memory>
#include <sstream>
#include <stdexcept>

#include <unistd.h>

#include "files/output_file.h"

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
  std::vector<std::vector<std::string>> table{{"quantity", "unit", "theory", "measured", "error", "tolerance", "pass"}};
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
  namespace fs = std::filesystem;
  // Every file is written in full to its own temporary file first; a target that is not a
  // regular file (a folder, a device, a link) is refused before anything is replaced.
  std::vector<std::unique_ptr<files::OutputFile>> written;
  try {
    for (const auto& [path, text] : files) {
      written.push_back(std::make_unique<files::OutputFile>(path));
      written.back()->write(text);
    }
  } catch (const std::runtime_error& error) {
    throw InvalidInput(std::string("cannot write ") + error.what());
  }
  // Then each is put in place. An older file there is kept under a hidden second name (a hard
  // link, no copy) until all are in place, so that a failure part way puts back what was there
  // before instead of leaving some new files and deleting the old ones they replaced.
  std::vector<std::string> kept(files.size());
  std::size_t placed = 0;
  std::error_code ignored;
  try {
    for (; placed < files.size(); ++placed) {
      const fs::path target(files[placed].first);
      if (fs::is_regular_file(fs::symlink_status(target, ignored))) {
        std::string hidden = ".";  // built in steps: GCC 12 warns wrongly about one long sum
        hidden += target.filename().string();
        hidden += ".old-";
        hidden += std::to_string(::getpid());
        const fs::path old = target.parent_path() / hidden;
        fs::remove(old, ignored);
        std::error_code linked;
        fs::create_hard_link(target, old, linked);
        if (linked) fs::copy_file(target, old, linked);
        if (linked) throw std::runtime_error(target.string() + ": cannot keep the older file while replacing it (" +
                                             linked.message() + ")");
        kept[placed] = old.string();
      }
      written[placed]->commit();
    }
  } catch (const std::runtime_error& error) {
    for (std::size_t i = 0; i <= placed && i < files.size(); ++i) {
      if (i < placed && kept[i].empty()) fs::remove(files[i].first, ignored);  // new: nothing was there
      if (!kept[i].empty()) fs::rename(kept[i], files[i].first, ignored);     // put the older one back
    }
    throw InvalidInput(std::string("cannot write ") + error.what());
  }
  for (const std::string& old : kept) {
    if (!old.empty()) fs::remove(old, ignored);
  }
}

}  // namespace frictionlab
