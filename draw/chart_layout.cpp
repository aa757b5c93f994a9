// Where a chart's parts land, worked out before anything is drawn (and by tests): the data
// area, the points as drawn, the theory curves, the ticks, the legend's place (chart_legend.cpp)
// and the levels' texts.
#include <algorithm>
#include <cmath>
#include <optional>

#include "draw/chart.h"
#include "draw/chart_parts.h"
#include "draw/drawing.h"

namespace frictionlab::draw {

using namespace chart_parts;

namespace {

// The widest x tick label a steady chart keeps room for beyond its data's right end.
constexpr const char* x_tick_room = "\u22128888";

float widest_label(const std::vector<std::string>& labels, ImFont* font) {
  float widest = 0.0f;
  for (const std::string& label : labels) widest = std::max(widest, width_of(font, label));
  return widest;
}


// Whether the segment from a to b comes within `reach` of the box (x0, y0, x1, y1): the box
// widened by `reach` clips the segment (Liang–Barsky).
bool segment_meets(ImVec2 a, ImVec2 b, const ImVec4& box, float reach) {
  const float x0 = box.x - reach, y0 = box.y - reach, x1 = box.z + reach, y1 = box.w + reach;
  float t0 = 0.0f, t1 = 1.0f;
  const float dx = b.x - a.x, dy = b.y - a.y;
  const float p[4] = {-dx, dx, -dy, dy}, q[4] = {a.x - x0, x1 - a.x, a.y - y0, y1 - a.y};
  for (int i = 0; i < 4; ++i) {
    if (p[i] == 0.0f) {
      if (q[i] < 0.0f) return false;
      continue;
    }
    const float t = q[i] / p[i];
    if (p[i] < 0.0f) t0 = std::max(t0, t);
    else t1 = std::min(t1, t);
    if (t0 > t1) return false;
  }
  return true;
}

// Whether a polyline (one point alone too) comes within `reach` of the box.
bool line_meets(const std::vector<ImVec2>& points, const ImVec4& box, float reach) {
  if (points.size() == 1) return segment_meets(points[0], points[0], box, reach);
  for (std::size_t i = 1; i < points.size(); ++i) {
    if (segment_meets(points[i - 1], points[i], box, reach)) return true;
  }
  return false;
}

// Each level's text by its line, inside the data area, where it meets no line of the data (the
// series as drawn, the rest of the run as planned: Chart::planned_points), no theory curve and no
// text placed before it: at the line's right end, then its left end, then anywhere along it,
// above the line before under it; then on its line, which its box breaks. Where no such place
// is, where it crosses the fewest pieces of the data's lines, drawn under the series
// (ChartLayout::Level::beneath), where it meets no text placed before it (else none: the line
// alone). Always level_clearance() off every other level's line and off the axes' texts, and off
// its own unless written on it. None for a level off the axis. (At the right end over the data, push's −μk·N text hid the present's dot and
// spring_pull's the last second and a half of its record: a teacher's trial.)
// How far a level's text stands past its line's end in the column beside the data: the short
// line that leads to it.
constexpr float level_lead = 10.0f;

// How far a level's text keeps clear of every level's line and of the axes' texts, its box as
// drawn (a pixel above and below the text) to the line's edge or the other text's: a third of a
// line of the level's font. A text 2 px off its line was read as lying on it (the README's
// incline at 1280 × 720), and a projector's column put "= −5.63 N" 3 px over "time (s)" (issue 31).
float level_clearance(ImFont* font) { return font->FontSize / 3.0f; }

// The levels' lines are 1.5 points thick (draw_level_lines).
float level_line_half(float s) { return 0.75f * s; }

}  // namespace

std::string level_text_in_column(const std::string& text) {
  const std::size_t equals = text.rfind(" = ");
  return equals == std::string::npos ? text : text.substr(0, equals) + "\n" + text.substr(equals + 1);
}

std::string level_text_as_written(const ChartLayout::Level& placed, const std::string& text) {
  return placed.beside && placed.in_two_lines ? level_text_in_column(text) : text;
}

namespace {

// A text's width and height as drawn, its lines one under the other.
ImVec2 size_of(ImFont* font, const std::string& text) { return font->CalcTextSizeA(font->FontSize, 1e6f, 0.0f, text.c_str()); }

// The width of the column beside a steady chart's data that its levels' texts take
// (Chart::level_room), sized for each in two lines, its label over its value
// (level_text_in_column), though one that fits is written in one (place_level_texts_beside): 0
// where there is none, or where it would take more than a third of the chart's width (a small
// picture's plot: the texts go by their lines).
float level_column(const Chart& chart, ImFont* font, float s, float chart_width) {
  if (!chart.plain || !chart.steady) return 0.0f;
  float widest = 0.0f;
  for (const std::string& room : chart.level_room) widest = std::max(widest, size_of(font, level_text_in_column(room)).x);
  if (widest == 0.0f) return 0.0f;
  for (const ChartLevel& level : chart.levels) widest = std::max(widest, size_of(font, level_text_in_column(level.text)).x);
  const float column = level_lead * s + widest;
  return column <= chart_width / 3.0f ? column : 0.0f;
}

// Each level's text in the column beside the data, its middle at its line's height where the
// texts before it leave room, else moved the least up or down to keep a gap between them, all
// within the data's height (half a line above its top, where the top tick's label has room;
// down to 2 points under its bottom) and level_clearance() clear of the axes' texts beside the
// column (the x axis' name under it). A text that finds no room (more levels than the data's
// height holds) leaves its line alone. Each in one line where the column, up to `column_right`,
// is wide enough for it, else its label over its value.
void place_level_texts_beside(const Chart& chart, const Axis& y_axis, float s, ImFont* font, float column_right,
                              ChartLayout& layout) {
  struct Wanted {
    std::size_t index;
    float y;
    ImVec2 size;
    bool in_two_lines;
  };
  const float left = layout.high_right.x + level_lead * s;
  std::vector<Wanted> wanted;
  for (std::size_t i = 0; i < chart.levels.size(); ++i) {
    if (!y_axis.shows(chart.levels[i].y)) continue;
    const float y = layout.to_screen(layout.log_x ? std::pow(10.0, layout.x_low) : layout.x_low, chart.levels[i].y).y;
    if (y < layout.high_right.y - 0.5f || y > layout.low_left.y + 0.5f) continue;
    const ImVec2 one_line = size_of(font, chart.levels[i].text);
    const bool in_two_lines = left + one_line.x > column_right;
    wanted.push_back({i, y, in_two_lines ? size_of(font, level_text_in_column(chart.levels[i].text)) : one_line, in_two_lines});
  }
  std::stable_sort(wanted.begin(), wanted.end(), [](const Wanted& a, const Wanted& b) { return a.y < b.y; });
  // Each text's box is drawn a pixel above and below it (draw_level_texts): two more apart.
  const float gap = 2.0f * s + 2.0f;
  float highest = layout.high_right.y - 0.5f * font->FontSize, lowest_bottom = layout.low_left.y + 2.0f * s;
  // Clear of the axes' texts beside the column (the x axis' name under it, the last x tick's
  // label by its left edge), by level_clearance() from each text's box as drawn.
  float widest = 0.0f;
  for (const Wanted& level : wanted) widest = std::max(widest, level.size.x);
  const float clearance = level_clearance(font), middle = 0.5f * (layout.high_right.y + layout.low_left.y);
  for (const ChartLayout::AxisText& text : layout.axis_texts) {
    if (text.text.empty() || text.at.z <= left - 2.0f * s - clearance || text.at.x >= left + widest + 2.0f * s + clearance) continue;
    if (0.5f * (text.at.y + text.at.w) > middle) {
      lowest_bottom = std::min(lowest_bottom, text.at.y - clearance - 1.0f);
    } else {
      highest = std::max(highest, text.at.w + clearance + 1.0f);
    }
  }
  std::vector<float> tops;
  for (const Wanted& level : wanted) {
    tops.push_back(std::clamp(level.y - 0.5f * level.size.y, highest, std::max(highest, lowest_bottom - level.size.y)));
  }
  for (std::size_t k = 1; k < tops.size(); ++k) tops[k] = std::max(tops[k], tops[k - 1] + wanted[k - 1].size.y + gap);
  if (!tops.empty()) tops.back() = std::min(tops.back(), std::max(highest, lowest_bottom - wanted.back().size.y));
  for (std::size_t k = tops.size(); k-- > 1;) tops[k - 1] = std::min(tops[k - 1], tops[k] - wanted[k - 1].size.y - gap);
  std::vector<ChartLayout::Level> placed;
  for (std::size_t k = 0; k < wanted.size(); ++k) {
    // Pushed above the top by the texts under it: no room for this one.
    if (tops[k] < highest - 0.5f) {
      placed.push_back({wanted[k].index, "", ImVec4(0.0f, 0.0f, 0.0f, 0.0f), wanted[k].y, false, false});
      continue;
    }
    placed.push_back({wanted[k].index, chart.levels[wanted[k].index].text,
                      ImVec4(left, tops[k], left + wanted[k].size.x, tops[k] + wanted[k].size.y), wanted[k].y, false, true,
                      wanted[k].in_two_lines});
  }
  std::sort(placed.begin(), placed.end(), [](const ChartLayout::Level& a, const ChartLayout::Level& b) { return a.index < b.index; });
  layout.levels.insert(layout.levels.end(), placed.begin(), placed.end());
}

// The tick labels and the axes' names, where draw_chart writes them (draw_axes), known before the
// levels' texts are placed so that those keep clear of them: the x ticks' labels under their
// tick marks in the small text, the y ticks' beside theirs in the numbers' font, the x axis'
// name under the data's middle (a steady chart's beyond its right end, on the ticks' line), the
// y axis' over the tick column (a steady chart's heading its legend's rows).
void place_axis_texts(const Chart& chart, ImVec2 corner, const Fonts& fonts, ChartLayout& layout) {
  using TextKind = ChartLayout::AxisText::Kind;
  const float s = fonts.scale;
  ImFont* small = fonts.small;
  ImFont* numbers = number_font(chart, fonts);
  const float width = layout.high_right.x - layout.low_left.x, height = layout.low_left.y - layout.high_right.y;
  const auto x_at = [&](double tick) { return layout.low_left.x + static_cast<float>(share(tick, layout.x_low, layout.x_high)) * width; };
  const auto y_at = [&](double tick) { return layout.low_left.y - static_cast<float>(share(tick, layout.y_low, layout.y_high)) * height; };
  const auto add_text = [&](TextKind kind, const std::string& words, ImVec2 at, ImFont* font) {
    layout.axis_texts.push_back({kind, words, ImVec4(at.x, at.y, at.x + width_of(font, words), at.y + font->FontSize)});
  };
  layout.axis_texts.clear();
  const float gap = (chart.plain ? 5.0f : 4.0f) * s;
  const float x_labels_below = (chart.steady ? 4.0f : 3.0f) * s;  // under the tick marks
  for (std::size_t i = 0; i < layout.x_ticks.size(); ++i) {
    const std::string& label = layout.x_tick_labels[i];
    add_text(TextKind::x_tick, label, ImVec2(x_at(layout.x_ticks[i]) - 0.5f * width_of(small, label), layout.low_left.y + x_labels_below),
             small);
  }
  for (std::size_t i = 0; i < layout.y_ticks.size(); ++i) {
    const std::string& label = layout.y_tick_labels[i];
    add_text(TextKind::y_tick, label,
             ImVec2(layout.low_left.x - width_of(numbers, label) - gap, y_at(layout.y_ticks[i]) - 0.5f * numbers->FontSize), numbers);
  }
  const float text = small->FontSize;
  const ImVec2 x_label_at = chart.steady && std::isfinite(layout.x_label_at.x)
                                ? layout.x_label_at
                                : ImVec2(layout.low_left.x + 0.5f * (width - width_of(small, chart.x_label)),
                                         layout.low_left.y + text + (chart.plain ? 5.0f : 6.0f) * s);
  add_text(TextKind::x_name, chart.x_label, x_label_at, small);
  const ImVec2 y_label_at = chart.steady && std::isfinite(layout.y_label_at.x) ? layout.y_label_at
                            : chart.plain ? ImVec2(corner.x + 2.0f * s, corner.y + 2.0f * s)
                                          : ImVec2(corner.x + 8.0f * s, layout.high_right.y - text - 4.0f * s);
  add_text(TextKind::y_name, chart.y_label, y_label_at, small);
}

// The run's lines to come, on the screen, at most about two points a pixel as place() keeps.
std::vector<std::vector<ImVec2>> planned_lines(const Chart& chart, const Axis& x_axis, const Axis& y_axis,
                                               const ChartLayout& layout) {
  std::vector<std::vector<ImVec2>> planned;
  const float width = layout.high_right.x - layout.low_left.x;
  if (!chart.planned_points.empty()) {
    const std::size_t stride = std::max<std::size_t>(1, chart.planned_points.size() / static_cast<std::size_t>(std::max(1.0f, 8.0f * width)));
    planned.emplace_back();
    for (std::size_t i = 0; i < chart.planned_points.size(); ++i) {
      const auto [x, y] = chart.planned_points[i];
      // A point not shown parts the line (a new series begins with one: NaN between them), so
      // every one is looked at, the thinning taking only every stride-th of those shown: a
      // parting skipped would join one series' end to the next one's start.
      if (!x_axis.shows(x) || !y_axis.shows(y)) {
        if (!planned.back().empty()) planned.emplace_back();
        continue;
      }
      if (i % stride == 0) planned.back().push_back(layout.to_screen(x, y));
    }
  }
  return planned;
}

// What a level's text keeps off in the data area: the texts placed before it, the record's
// lines, the run's to come and the theory's curves. The series' lines are 2.5 points thick at
// most, the theory's 3.5 (draw_series, draw_theory_curves): a text keeps a pixel clear of their
// edges.
struct LevelTextRoom {
  const ChartLayout& layout;
  const std::vector<std::vector<ImVec2>>& planned;
  float series_reach, theory_reach;
  const std::vector<float>& level_lines;  // every level's line's y on the screen
  float line_half, clearance;             // level_line_half(), level_clearance()

  // The legend's keys count as a text: tipping_box's "slides" level at 1280 × 720 was written
  // under the legend in the data's corner, its value hidden by "slipping". So do the levels'
  // lines and the axes' texts, which a text keeps level_clearance() off: a text on another
  // level's line, or touching its own, is read as lying on it. `box` is the text's as drawn
  // in height (a pixel above and below it).
  bool meets_texts(const ImVec4& box) const {
    for (const ChartLayout::Level& other : layout.levels) {
      if (overlaps(other.at, box)) return true;
    }
    // (A hundredth of a pixel for the floats of a text placed just that far off its line.)
    for (const float y : level_lines) {
      if (box.y - clearance < y + line_half - 0.01f && box.w + clearance > y - line_half + 0.01f) return true;
    }
    const ImVec4 wide(box.x - clearance, box.y - clearance, box.z + clearance, box.w + clearance);
    for (const ChartLayout::AxisText& text : layout.axis_texts) {
      if (!text.text.empty() && overlaps(wide, text.at)) return true;
    }
    const ImVec4 legend(layout.legend_min.x, layout.legend_min.y, layout.legend_max.x, layout.legend_max.y);
    return !layout.legend_at.empty() && overlaps(legend, box);
  }
  bool clear(const ImVec4& box) const {
    if (meets_texts(box)) return false;
    for (const std::vector<ImVec2>& line : layout.series_points) {
      if (line_meets(line, box, series_reach)) return false;
    }
    for (const std::vector<ImVec2>& line : planned) {
      if (line_meets(line, box, series_reach)) return false;
    }
    for (const auto& curve : layout.theory) {
      for (const auto& piece : curve) {
        if (line_meets(piece, box, theory_reach)) return false;
      }
    }
    return true;
  }
  // How many pieces of a line a box meets, each counted once.
  std::size_t pieces_met(const std::vector<ImVec2>& line, const ImVec4& box) const {
    std::size_t met = 0;
    bool in = false;
    for (std::size_t k = 0; k < line.size(); ++k) {
      const bool meets = segment_meets(line[k], line[k + 1 < line.size() ? k + 1 : k], box, series_reach);
      met += meets && !in;
      in = meets;
    }
    return met;
  }
  // Where it meets the fewest pieces of the data's lines (the record's and the run's to come,
  // counted once each) and no text placed before it (the first of equals in the order given),
  // under the data; nullopt where every place meets a text.
  template <typename BoxAt>
  std::optional<ImVec4> least_crossed(const std::vector<float>& lefts, const float (&tops)[2], float w, float text,
                                      const BoxAt& box_at) const {
    ImVec4 best;
    std::size_t fewest = static_cast<std::size_t>(-1);
    for (const float left : lefts) {
      for (const float top : tops) {
        if (top < layout.high_right.y || top + text > layout.low_left.y) continue;
        const ImVec4 box = box_at(left, top);
        std::size_t met = 1000 * meets_texts(box);
        for (const auto& line : planned.empty() ? layout.series_points : planned) met += pieces_met(line, box);
        if (met < fewest) fewest = met, best = ImVec4(left, top, left + w, top + text);
      }
    }
    if (fewest >= 1000) return std::nullopt;
    return best;
  }
};

void place_level_texts(const Chart& chart, const Axis& x_axis, const Axis& y_axis, float s, ImFont* font, ChartLayout& layout) {
  const auto line_y = [&](const ChartLevel& level) {
    return layout.to_screen(layout.log_x ? std::pow(10.0, layout.x_low) : layout.x_low, level.y).y;
  };
  const auto in_data = [&](float y) { return y >= layout.high_right.y - 0.5f && y <= layout.low_left.y + 0.5f; };
  std::vector<float> level_lines;
  for (const ChartLevel& level : chart.levels) {
    if (y_axis.shows(level.y) && in_data(line_y(level))) level_lines.push_back(line_y(level));
  }
  // A text's box as drawn stands level_clearance() off its own line's edge (its pixel above and
  // below the text, and half the line's width), clear of a series drawn along the level too
  // (push's slide at −μk·N).
  const float clearance = level_clearance(font), line_half = level_line_half(s);
  const float off_line = line_half + clearance + 1.0f;
  const std::vector<std::vector<ImVec2>> planned = planned_lines(chart, x_axis, y_axis, layout);
  const LevelTextRoom room{layout, planned, 1.25f * s + 1.0f, 1.75f * s + 1.0f, level_lines, line_half, clearance};
  for (std::size_t i = 0; i < chart.levels.size(); ++i) {
    const ChartLevel& level = chart.levels[i];
    if (!y_axis.shows(level.y)) continue;
    const float y = line_y(level);
    if (!in_data(y)) continue;
    // As high as its lines: tipping_box's tipping level is written on two ("tips: −m·g·width"
    // over "/(2·push height) = …"), and placed a line high its second ran over the legend and the
    // "slides" level's text at 1280 × 720.
    const ImVec2 size = size_of(font, level.text);
    const float w = size.x, high = size.y;
    const auto box_at = [&](float left, float top) { return ImVec4(left - 3.0f * s, top - 1.0f, left + w + 3.0f * s, top + high + 1.0f); };
    const float right_end = layout.high_right.x - w - 4.0f * s, left_end = layout.low_left.x + 4.0f * s;
    if (right_end < left_end) {  // wider than the data area (a small picture's plot): its line alone
      layout.levels.push_back({i, "", ImVec4(0.0f, 0.0f, 0.0f, 0.0f), y, true});
      continue;
    }
    std::vector<float> lefts{right_end, left_end};
    for (float left = right_end - 6.0f * s; left > left_end; left -= 6.0f * s) lefts.push_back(left);
    const float tops[2] = {y - high - off_line, y + off_line};
    std::optional<ImVec4> found;
    for (const float left : lefts) {
      for (const float top : tops) {
        if (top < layout.high_right.y || top + high > layout.low_left.y) continue;
        if (room.clear(box_at(left, top))) {
          found = ImVec4(left, top, left + w, top + high);
          break;
        }
      }
      if (found) break;
    }
    if (found) {
      layout.levels.push_back({i, level.text, *found, y, false});
      continue;
    }
    // No room above or below its line (levels closer than a text and its clearances, or one near
    // the axis' end: spring_pull's −μs·N at 1280 × 720, 22 px under −μk·N and 14 over the axis):
    // on its own line, which its box breaks, as a map writes a contour's height, clear of the
    // other levels' lines, the data and the texts. (Beside its line with no room it was left out.)
    std::vector<float> other_lines;
    for (const float line : level_lines) {
      if (std::abs(line - y) > 0.01f) other_lines.push_back(line);
    }
    const LevelTextRoom on_line{layout, planned, room.series_reach, room.theory_reach, other_lines, line_half, clearance};
    const float on_top = y - 0.5f * high;
    if (on_top >= layout.high_right.y && on_top + high <= layout.low_left.y) {
      for (const float left : lefts) {
        if (on_line.clear(box_at(left, on_top))) {
          found = ImVec4(left, on_top, left + w, on_top + high);
          break;
        }
      }
    }
    if (found) {
      layout.levels.push_back({i, level.text, *found, y, false});
      continue;
    }
    // None where the data area is too short for it beside the texts placed before it (a small
    // picture's plot): its line alone, rather than two texts over each other.
    const std::optional<ImVec4> least = room.least_crossed(lefts, tops, w, high, box_at);
    if (!least) {
      layout.levels.push_back({i, "", ImVec4(0.0f, 0.0f, 0.0f, 0.0f), y, true});
      continue;
    }
    layout.levels.push_back({i, level.text, *least, y, true});
  }
}

// The data area inside the chart's corner and size (layout.low_left, layout.high_right), before
// the legend has its say: a plain chart's tick column as wide as its labels, a steady one's
// x label and level texts beside the data; other charts' legend under them. Returns the width of
// the level texts' column beside the data (0: none); `label_width` becomes the tick column's.
float frame_data_area(const Chart& chart, const ChartAxes& axes, const std::vector<Key>& keys, ImVec2 corner, ImVec2 size,
                      const Fonts& fonts, float& label_width, ChartLayout& layout) {
  const float s = fonts.scale;
  ImFont* font = layout.level_font;
  const float text = font->FontSize;
  const float line = text + 3.0f * s;
  float levels_beside = 0.0f;
  if (chart.plain) {
    layout.low_left = ImVec2(corner.x + label_width + 10.0f * s, corner.y + size.y - 2.0f * text - 8.0f * s);
    layout.high_right = ImVec2(layout.right_end, corner.y + text + 10.0f * s);
    if (chart.steady) {
      // The y label heads the legend's column and the x label ends the x ticks' line: the data
      // has the two lines of text they took (a plot on a page of its own, made tall).
      // The tick marks' 4 pt, then the x labels, in the small text: the y labels are the ones the
      // levels are read against, and the key plot keeps a third of a projector's height.
      layout.low_left.y = corner.y + size.y - fonts.small->FontSize - 4.0f * s;
      layout.high_right.y = corner.y + 0.5f * text + 1.0f * s;  // room for half the top tick's label
      // The x label beyond the data's right end, on the tick labels' line, where no tick label
      // is: over the data's end it stood where the last tick's number goes (push's "10" under
      // "push (N)"). The room is the same whatever the data (the plot holds still as the run
      // widens its range): half a tick label as wide as "−8888" past the end, then the name.
      // The levels' texts share that room, above it, beside the data (level_column).
      const float past_end = 0.5f * width_of(fonts.small, x_tick_room) + 6.0f * s;
      const float x_label_room = chart.x_label.empty() ? 0.0f : past_end + width_of(fonts.small, chart.x_label);
      levels_beside = level_column(chart, font, s, size.x);
      if (levels_beside == 0.0f && font != fonts.small) {
        levels_beside = level_column(chart, fonts.small, s, size.x);
        if (levels_beside > 0.0f) layout.level_font = fonts.small;
      }
      layout.high_right.x -= std::max(x_label_room, levels_beside);
      if (!chart.x_label.empty()) layout.x_label_at = ImVec2(layout.high_right.x + past_end, layout.low_left.y + 4.0f * s);
    }
    // The tick column as wide as the labels the data area's height leads to (fit_y_ticks): the
    // first ticks' labels may be narrower ("−5" where "−4.5" is drawn). No more: a steady
    // chart kept the room of "−8888.88" whatever its ticks, and push's key plot on a projector
    // gave a tenth of its width to blank space beside "−5"; its axes hold still (plot_chart), so
    // its labels do too.
    ChartLayout trial = layout;
    fit_y_ticks(chart, axes.y, text, s, trial);
    const float widest = widest_label(trial.y_tick_labels, font);
    layout.low_left.x += widest - label_width;
    label_width = widest;
  } else {
    // The legend goes under the chart, in two columns, so it hides none of it.
    const std::size_t rows = chart.legend == Chart::Legend::under ? (keys.size() + 1) / 2 : 0;
    const float legend_height =
        line * static_cast<float>(rows + chart.notes.size()) + (rows == 0 ? 0.0f : 6.0f * s);
    const float top = corner.y + fonts.body->FontSize + text + 16.0f * s;
    layout.low_left = ImVec2(corner.x + label_width + 16.0f * s, corner.y + size.y - 2.0f * text - 14.0f * s - legend_height);
    // Room on the right for the labels beside the last points (a step rate, say).
    const bool labelled = std::any_of(chart.series.begin(), chart.series.end(), [](const ChartSeries& series) { return !series.labels.empty(); });
    layout.high_right = ImVec2(corner.x + size.x - (labelled ? 60.0f : 10.0f) * s, top);
  }
  return levels_beside;
}

// As many x ticks as the data area's width holds, unless the chart says how many.
void set_x_ticks(const Chart& chart, const Axis& x_axis, float data_width, float s, ChartLayout& layout) {
  const int count = chart.x_tick_count > 0 ? chart.x_tick_count : std::max(2, static_cast<int>(data_width / (70.0f * s)));
  layout.x_ticks.clear(), layout.x_tick_labels.clear();
  for (const Tick& tick : ticks_every(x_axis, count)) {
    layout.x_ticks.push_back(tick.value);
    layout.x_tick_labels.push_back(tick.label);
  }
}

// The points where they land in the data area; at most about two a pixel, the rest would be
// drawn over each other. The theory's curves likewise, whole.
void place_points(const Chart& chart, const ChartAxes& axes, ChartLayout& layout) {
  const float w = layout.high_right.x - layout.low_left.x;
  layout.points.clear();
  layout.series_points.assign(chart.series.size(), {});
  layout.series_indices.assign(chart.series.size(), {});
  for (std::size_t k = 0; k < chart.series.size(); ++k) {
    const auto& points = chart.series[k].points;
    const std::size_t stride = std::max<std::size_t>(1, points.size() / static_cast<std::size_t>(std::max(1.0f, 2.0f * w)));
    const auto add = [&](std::size_t i) {
      const auto [x, y] = points[i];
      if (!axes.x.shows(x) || !axes.y.shows(y)) return;
      layout.series_points[k].push_back(layout.to_screen(x, y));
      layout.series_indices[k].push_back(i);
      layout.points.push_back(layout.series_points[k].back());
    };
    for (std::size_t i = 0; i < points.size(); i += stride) add(i);
    if (!points.empty() && (points.size() - 1) % stride != 0) add(points.size() - 1);  // the latest point always
  }
  layout.theory.clear();
  for (const ChartCurve& curve : chart.theory) {
    layout.theory.emplace_back();
    for (const auto& piece : curve.pieces) {
      layout.theory.back().emplace_back();
      for (const auto& [x, y] : piece) layout.theory.back().back().push_back(layout.to_screen(x, y));
    }
  }
}

}  // namespace

ChartLayout layout_chart(const Chart& chart, ImVec2 corner, ImVec2 size, const Fonts& fonts) {
  const float s = fonts.scale;
  // The ticks' labels and the levels' texts in the numbers' font: all that `font` measures
  // below, but the x axis' name (the small text's, as the y axis' name and the legend).
  ImFont* font = number_font(chart, fonts);
  const float text = font->FontSize;
  ChartLayout layout;
  layout.level_font = font;
  const ChartAxes axes = axes_of(chart);
  layout.log_x = axes.x.log, layout.log_y = axes.y.log;
  layout.x_low = axes.x.low, layout.x_high = axes.x.high, layout.y_low = axes.y.low, layout.y_high = axes.y.high;
  for (const Tick& tick : ticks_every(axes.y, chart.y_tick_count)) {
    layout.y_ticks.push_back(tick.value);
    layout.y_tick_labels.push_back(tick.label);
  }
  float label_width = 0.0f;
  for (const std::string& label : layout.y_tick_labels) label_width = std::max(label_width, width_of(font, label));
  const std::vector<Key> keys = keys_of(chart);
  if (chart.legend == Chart::Legend::only) return layout;

  layout.right_end = corner.x + size.x - 8.0f * s;
  const float levels_beside = frame_data_area(chart, axes, keys, corner, size, fonts, label_width, layout);
  const float width = layout.high_right.x - layout.low_left.x, height = layout.low_left.y - layout.high_right.y;
  layout.drawable = width >= 20.0f && height >= 20.0f;
  if (!layout.drawable) return layout;
  const auto choose_x_ticks = [&](float data_width) { set_x_ticks(chart, axes.x, data_width, s, layout); };
  const auto place = [&] { place_points(chart, axes, layout); };
  choose_x_ticks(width);
  place();

  if (!place_legend(chart, keys, corner, size, fonts, layout, place, choose_x_ticks)) return layout;
  fit_y_ticks(chart, axes.y, text, s, layout);
  // A steady chart's legend rows above the data may have left it another height, and other
  // ticks: the column takes their width, narrower too (push's key plot on a projector was
  // measured with ticks every 0.5 N, "−4.5", and draws them every 1 N, "−5"), its legend being
  // off the data, so nothing else moves.
  if (chart.plain && chart.steady && widest_label(layout.y_tick_labels, font) != label_width) {
    layout.low_left.x += widest_label(layout.y_tick_labels, font) - label_width;
    if (layout.high_right.x - layout.low_left.x < 20.0f) {
      layout.drawable = false;
      return layout;
    }
    choose_x_ticks(layout.high_right.x - layout.low_left.x);
    place();
  }
  if (chart.plain && chart.steady && !axes.x.log) {
    layout.x_minor_ticks = minor_ticks(layout.x_ticks, layout.x_low, layout.x_high,
                                       (layout.high_right.x - layout.low_left.x) / static_cast<float>(layout.x_high - layout.x_low), s);
  }
  place_axis_texts(chart, corner, fonts, layout);
  if (levels_beside > 0.0f) place_level_texts_beside(chart, axes.y, s, layout.level_font, layout.right_end, layout);
  else place_level_texts(chart, axes.x, axes.y, s, layout.level_font, layout);
  layout.active = chart.active_theory;
  if (layout.active == Chart::nearest) {
    layout.active = -1;
    if (!layout.series_points.empty() && !layout.series_points.front().empty()) {
      layout.active = nearest_curve(layout.theory, layout.series_points.front().back());
    }
  }
  return layout;
}

}  // namespace frictionlab::draw
