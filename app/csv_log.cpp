#include "app/csv_log.h"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "physics/materials.h"
#include "physics/validation.h"

namespace frictionlab {
namespace {

// A spreadsheet program that guesses the encoding reads "°" as "Â°" unless the file says it
// is UTF-8, which this byte-order mark does.
constexpr char byte_order_mark[] = "\xEF\xBB\xBF";
constexpr char first_words[] = "# FrictionLab run";

// A body's six columns and their units.
struct Column {
  const char* part;
  const char* unit;
};
constexpr Column body_columns[] = {{"x", "m"}, {"y", "m"}, {"angle", "rad"}, {"vx", "m/s"}, {"vy", "m/s"}, {"omega", "rad/s"}};

// Only what moves has columns: a fixed body's would repeat its first row for ever.
bool moves(const b2Body* body) { return body->GetType() != b2_staticBody; }

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

}  // namespace

bool written_by_frictionlab(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  std::string line;
  if (!std::getline(file, line)) return false;
  if (line.rfind(byte_order_mark, 0) == 0) line.erase(0, sizeof byte_order_mark - 1);
  return line.rfind(first_words, 0) == 0;
}

CsvLog::CsvLog(const std::string& path, const lessons::Lesson& lesson, std::ostream& standard_output)
    : path_(path), standard_output_(standard_output) {
  if (path == "-") return;
  namespace fs = std::filesystem;
  std::error_code same;
  if (fs::path(path).extension() == ".lua" || fs::equivalent(path, lesson.path(), same)) {
    throw InvalidInput("--csv " + path + ": that looks like a lesson script; give a .csv file so no script is overwritten");
  }
  try {
    file_ = std::make_unique<ui::OutputFile>(path, written_by_frictionlab);
  } catch (const std::runtime_error& error) {
    std::string message = "--csv ";
    message += error.what();
    throw InvalidInput(message);
  }
}

void CsvLog::put(const std::string& text) {
  if (file_) {
    file_->write(text);
  } else {
    standard_output_ << text;
  }
}

void CsvLog::header(const lessons::Lesson& lesson, const std::set<std::string>& hidden) {
  // What made the run, so a file found later says which run it is.
  std::ostringstream text;
  text << byte_order_mark << first_words << " of " << lesson.path() << " at " << lesson.settings().hz << " Hz, "
       << lesson.settings().substeps << " sub-step(s), " << treatment_name(lesson.settings().treatment) << ";";
  for (const lessons::Parameter& parameter : lesson.parameters()) {
    text << ' ' << parameter.name << " = " << (hidden.count(parameter.name) > 0 ? "? (a mystery)" : parameter.shown()) << ';';
  }
  std::string settings = text.str();
  for (char& c : settings) {
    if (c == ',') c = ';';  // one field: a spreadsheet shows the line in its first cell
  }
  settings += '\n';
  put(settings);
  std::string names = "t (s)";
  const Scene& scene = lesson.scene();
  for (const auto& [name, body] : scene.bodies()) {
    if (!moves(body)) continue;
    for (const Column& column : body_columns) {
      std::ostringstream title;
      title << name << '.' << column.part << " (" << column.unit << ')';
      names += ',';
      names += field(title.str());
    }
  }
  for (const Probe& probe : scene.probes()) {
    const std::string& unit = lesson.probe_unit(probe.name);
    std::ostringstream title;
    title << probe.name;
    if (!unit.empty()) title << " (" << unit << ')';
    names += ',';
    names += field(title.str());
  }
  names += '\n';
  put(names);
}

void CsvLog::row(const Scene& scene) {
  std::ostringstream text;
  text.precision(9);
  text << scene.time();
  for (const auto& [name, body] : scene.bodies()) {
    if (!moves(body)) continue;
    const b2Vec2 p = body->GetPosition(), v = body->GetLinearVelocity();
    text << ',' << p.x << ',' << p.y << ',' << body->GetAngle() << ',' << v.x << ',' << v.y << ',' << body->GetAngularVelocity();
  }
  for (const Probe& probe : scene.probes()) text << ',' << probe.history.back();
  text << '\n';
  put(text.str());
}

void CsvLog::finish() {
  if (!file_) {
    standard_output_.flush();
    return;
  }
  try {
    file_->commit();
  } catch (const std::runtime_error& error) {
    throw InvalidInput(std::string("--csv ") + error.what());
  }
}

}  // namespace frictionlab
