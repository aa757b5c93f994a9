#include "lessons/runtime/class_words.h"

#include <algorithm>
#include <optional>
#include <utility>
#include <vector>

namespace frictionlab::lessons {

namespace {

// The Greek letters a script spells out in its names (theta0 is θ0, omega ω), with any digits
// that follow kept; nothing when the part is no such letter.
std::optional<std::string> greek(std::string_view part) {
  static const std::pair<std::string_view, std::string_view> letters[] = {
      {"alpha", "\u03b1"}, {"epsilon", "\u03b5"}, {"theta", "\u03b8"}, {"omega", "\u03c9"}};
  for (const auto& [spelt, letter] : letters) {
    if (part.substr(0, spelt.size()) != spelt) continue;
    const std::string_view rest = part.substr(spelt.size());
    if (std::all_of(rest.begin(), rest.end(), [](char c) { return c >= '0' && c <= '9'; })) {
      return std::string(letter) + std::string(rest);
    }
  }
  return std::nullopt;
}

// A letter as an index below the line, where Unicode has one (a_x is aₓ); "" where not.
std::string_view subscript(char letter) {
  switch (letter) {
    case 'a': return "\u2090";
    case 'e': return "\u2091";
    case 'o': return "\u2092";
    case 'x': return "\u2093";
    case 'h': return "\u2095";
    case 'k': return "\u2096";
    case 'l': return "\u2097";
    case 'm': return "\u2098";
    case 'n': return "\u2099";
    case 'p': return "\u209a";
    case 's': return "\u209b";
    case 't': return "\u209c";
    default: return "";
  }
}

}  // namespace

std::string class_words(std::string_view name) {
  std::vector<std::string_view> parts;
  for (std::size_t start = 0; start <= name.size();) {
    const std::size_t end = std::min(name.find('_', start), name.size());
    if (end > start) parts.push_back(name.substr(start, end - start));
    start = end + 1;
  }
  std::string words;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    if (!words.empty()) words += ' ';
    const bool index_follows = i + 1 < parts.size() && parts[i + 1].size() == 1;
    // μ, with its index when it has one: mu_s is the static coefficient, written μs beside the
    // sliders; lubricated_mu is the oiled table's μ.
    if (parts[i] == "mu") {
      words += "\u03bc";
      if (index_follows && (parts[i + 1] == "s" || parts[i + 1] == "k")) words += parts[++i];
    } else if (const std::optional<std::string> letter = greek(parts[i])) {
      words += *letter;
    } else if (parts[i].size() == 1 && index_follows && !subscript(parts[i + 1][0]).empty()) {
      // A quantity's letter and its index, as the books write them: a_x is aₓ.
      words += parts[i];
      words += subscript(parts[++i][0]);
    } else {
      words += parts[i];
    }
  }
  return words;
}

std::string parameter_title(const Parameter& parameter) {
  if (parameter.coefficient == nullptr) return class_words(parameter.name);
  return class_words(parameter.coefficient->name) + "  " + parameter.material_a + " / " + parameter.material_b;
}

}  // namespace frictionlab::lessons
