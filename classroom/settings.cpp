#include "classroom/settings.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include "draw/image.h"
#include "files/output_file.h"

namespace frictionlab::classroom {

std::string settings_folder() {
  std::filesystem::path folder;
  if (const char* config = std::getenv("XDG_CONFIG_HOME"); config != nullptr && *config == '/') {
    folder = config;
  } else if (const char* home = std::getenv("HOME"); home != nullptr && *home == '/') {
    folder = std::filesystem::path(home) / ".config";
  } else {
    return "";
  }
  folder /= "frictionlab";
  std::error_code error;
  std::filesystem::create_directories(folder, error);
  return error ? "" : folder.string();
}

WindowSettings load_settings(const std::string& path) {
  WindowSettings settings;
  std::ifstream file(path);
  std::string line;
  while (std::getline(file, line)) {
    const auto equals = line.find('=');
    if (equals == std::string::npos) continue;
    const auto trim = [](std::string text) {
      const auto first = text.find_first_not_of(" \t\r"), last = text.find_last_not_of(" \t\r");
      return first == std::string::npos ? std::string() : text.substr(first, last - first + 1);
    };
    const std::string name = trim(line.substr(0, equals)), value = trim(line.substr(equals + 1));
    std::istringstream number(value);
    double x = 0.0;
    const bool numeric = static_cast<bool>(number >> x) && number.eof();
    if (name == "theme" && (value == "light" || value == "dark")) {
      settings.theme = value == "dark" ? draw::ThemeName::dark : draw::ThemeName::light;
    } else if (name == "projector" && (value == "on" || value == "off")) {
      settings.projector = value == "on";
    } else if (name == "help" && (value == "on" || value == "off")) {
      settings.help = value == "on";
    } else if (name == "predictions" && (value == "on" || value == "off")) {
      settings.predictions = value == "on";
    } else if (name == "full_screen" && (value == "on" || value == "off")) {
      settings.full_screen = value == "on";
    } else if (name == "width" && numeric && x >= 320 && x <= 16384) {
      settings.width = static_cast<int>(x);
    } else if (name == "height" && numeric && x >= 240 && x <= 16384) {
      settings.height = static_cast<int>(x);
    }
  }
  return settings;
}

std::string kept_settings_text(const WindowSettings& settings) {
  std::ostringstream text;
  text << "# FrictionLab's window settings, written as they change.\n"
       << "theme = " << theme_name(settings.theme) << "\n"
       << "projector = " << (settings.projector ? "on" : "off") << "\n"
       << "help = " << (settings.help ? "on" : "off") << "\n"
       << "predictions = " << (settings.predictions ? "on" : "off") << "\n"
       << "full_screen = " << (settings.full_screen ? "on" : "off") << "\n"
       << "width = " << settings.width << "\n"
       << "height = " << settings.height << "\n";
  return text.str();
}

bool save_settings(const WindowSettings& settings, const std::string& path) {
  try {
    const std::string bytes = kept_settings_text(settings);
    files::write_whole_file(path, bytes.data(), bytes.size());
    return true;
  } catch (const std::exception&) {
    return false;
  }
}

bool opens_with_help(bool kept, bool first_window, bool projector, bool picture) {
  if (first_window && (projector || picture)) return false;
  return kept;
}

std::string kept_from_last_session(const WindowSettings& settings) {
  const WindowSettings fresh;
  std::vector<std::string> kept;
  if (settings.theme != fresh.theme) kept.push_back(std::string(theme_name(settings.theme)) + " theme");
  if (settings.projector != fresh.projector) kept.push_back(settings.projector ? "projector mode" : "projector mode off");
  if (settings.full_screen != fresh.full_screen) kept.push_back(settings.full_screen ? "full screen" : "windowed");
  if (settings.help != fresh.help) kept.push_back(settings.help ? "help" : "no help");
  if (settings.predictions != fresh.predictions) kept.push_back(settings.predictions ? "predictions" : "no predictions");
  if (kept.empty()) return "";
  // Short, to be read whole on the status line: two lines of the 470 px a projector's 1920 leave
  // beside the time bar hold about 90 characters. The speed and the tools are not kept: the
  // speed's slider and the Tools menu show them as every session starts (×1, off).
  std::string words = "As last time: ";
  for (std::size_t i = 0; i < kept.size(); ++i) words += (i == 0 ? "" : ", ") + kept[i];
  return words + ".";
}

}  // namespace frictionlab::classroom
