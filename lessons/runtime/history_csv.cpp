#include "lessons/runtime/history_csv.h"

#include <fstream>
#include <sstream>

#include "physics/materials.h"

namespace frictionlab::lessons {
namespace {

// A CSV field: quoted when it holds a comma, a quote or a line break.
std::string field(const std::string& text) {
  if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) {
    quoted += c;
    if (c == '"') quoted += c;
  }
  quoted += '"';
  return quoted;
}

bool starts_with(const std::string& text, const std::string& start) { return text.rfind(start, 0) == 0; }

}  // namespace

std::string csv_header(const Lesson& lesson) {
  std::string header = csv_byte_order_mark;
  header += csv_time_column;
  for (const Probe& probe : lesson.scene().probes()) {
    const std::string& unit = lesson.probe_unit(probe.name);
    header += ',';
    header += field(unit.empty() ? probe.name : probe.name + " (" + unit + ")");
  }
  header += ",any_contact_slipping,hand_pulled,gauge (N)\n";
  return header;
}

std::string csv_row(const Scene& scene, std::size_t frame, std::optional<double> gauge) {
  std::ostringstream row;
  row.precision(9);  // a float's every digit, and a double's to well below what is measured
  row << scene.times()[frame];
  for (const Probe& probe : scene.probes()) row << ',' << probe.history[frame];
  row << ',' << static_cast<int>(scene.slipping()[frame]);
  if (gauge) {
    row << ",1," << *gauge;
  } else {
    row << ",0,";
  }
  row << '\n';
  return row.str();
}

std::string run_settings(const Lesson& lesson, const std::function<bool(const std::string&)>& hidden) {
  const StepSettings& settings = lesson.scene().settings();
  std::ostringstream text;
  text << settings_first_words << lesson.path() << '\n'
       << settings.hz << " Hz, " << settings.substeps << " sub-step(s), " << treatment_name(settings.treatment)
       << " friction\n";
  for (const Parameter& parameter : lesson.parameters()) {
    text << parameter.name << " = " << (hidden(parameter.name) ? "? (a mystery)" : parameter.shown()) << '\n';
  }
  return text.str();
}

std::string settings_path_for(const std::string& csv_path) {
  const std::string extension = ".csv";
  std::string stem = csv_path;
  if (stem.size() > extension.size() && stem.compare(stem.size() - extension.size(), extension.size(), extension) == 0) {
    stem.resize(stem.size() - extension.size());
  }
  return stem + "_settings.txt";
}

bool starts_frictionlab_csv(const std::string& first_line) {
  std::string line = first_line;
  while (!line.empty() && (line.back() == '\n' || line.back() == '\r')) line.pop_back();
  if (starts_with(line, csv_byte_order_mark)) line.erase(0, sizeof csv_byte_order_mark - 1);
  // FrictionLab's header from its first column to its last, as csv_header writes it: a file a
  // student saved again with a column of their own at the end is theirs, not to be replaced.
  const std::string last_columns = ",any_contact_slipping,hand_pulled,gauge (N)";
  if (starts_with(line, std::string(csv_time_column) + ",") && line.size() >= last_columns.size() &&
      line.compare(line.size() - last_columns.size(), last_columns.size(), last_columns) == 0) {
    return true;
  }
  // An earlier FrictionLab's file opened with a comment line ("# FrictionLab run of …" from
  // `run --csv`, "# FrictionLab history of …" from the window): a teacher's script that writes
  // the same file every class goes on working after an upgrade.
  return starts_with(line, "# FrictionLab run of ") || starts_with(line, "# FrictionLab history of ");
}

bool starts_frictionlab_settings(const std::string& first_line) { return starts_with(first_line, settings_first_words); }

namespace {

std::string first_line_of(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  std::string line;
  std::getline(file, line);
  return line;
}

}  // namespace

bool frictionlab_csv_file(const std::string& path) { return starts_frictionlab_csv(first_line_of(path)); }
bool frictionlab_settings_file(const std::string& path) { return starts_frictionlab_settings(first_line_of(path)); }

}  // namespace frictionlab::lessons
