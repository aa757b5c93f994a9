// The chart's legend: its keys (a map's categories, the regimes' colours, the series, the
// shaded spans, the theory curves), where it goes (under the chart, in a free corner of the
// data, in rows above the data or in columns beside it), whether a chart has room for it
// whatever its data, and its drawing.
#include <algorithm>
#include <cmath>

#include "draw/chart.h"
#include "draw/chart_parts.h"

namespace frictionlab::draw {

namespace chart_parts {

std::vector<Key> keys_of(const Chart& chart) {
  std::vector<Key> keys;
  // A map's categories that no cell has are left out of the legend.
  for (std::size_t category = 0; category < chart.categories.size(); ++category) {
    const bool present = std::any_of(chart.cells.begin(), chart.cells.end(), [&](const ChartCell& cell) {
      return cell.category == static_cast<int>(category);
    });
    if (present) keys.push_back({chart.categories[category].first, chart.categories[category].second, Key::Look::band});
  }
  for (const auto& [name, colour] : chart.colour_keys) keys.push_back({name, colour, Key::Look::line});
  for (const ChartSeries& series : chart.series) {
    if (!series.name.empty()) keys.push_back({series.name, series.colour, Key::Look::line, series.dash, series.gap});
  }
  if (!chart.band_name.empty()) keys.push_back({chart.band_name, chart.band_colour, Key::Look::band});
  for (const ChartCurve& curve : chart.theory) keys.push_back({curve.name, curve.colour, Key::Look::theory, curve.dash, curve.gap});
  return keys;
}

float width_of(ImFont* font, const std::string& text) { return font->CalcTextSizeA(font->FontSize, 1e6f, 0.0f, text.c_str()).x; }

ImFont* number_font(const Chart& chart, const Fonts& fonts) { return chart.plain && chart.steady ? fonts.body : fonts.small; }

namespace {

// Where each key goes when the legend runs in rows from `left` to `right`, starting at `top`:
// a key that would cross `right` starts the next row.
std::vector<ImVec2> wrap_keys(const std::vector<Key>& keys, float left, float right, float top, float row_height,
                              ImFont* font, float s) {
  std::vector<ImVec2> at;
  float x = left, y = top;
  for (const Key& key : keys) {
    const float w = width_of(font, key.name) + 32.0f * s;
    if (x > left && x + w > right) {
      x = left;
      y += row_height;
    }
    at.push_back(ImVec2(x, y));
    x += w;
  }
  return at;
}

// The box round an inside legend's keys, each from its place to the end of its name as
// draw_legend writes it (wrapped at the layout's width where it has one; a name holds no line
// break, so one that does not wrap is a line of text high).
void bound_keys(ChartLayout& layout, const std::vector<Key>& keys, ImFont* font, float s) {
  const float text = font->FontSize;
  layout.legend_min = ImVec2(INFINITY, INFINITY), layout.legend_max = ImVec2(-INFINITY, -INFINITY);
  for (std::size_t i = 0; i < keys.size(); ++i) {
    const ImVec2 at = layout.legend_at[i];
    const ImVec2 name = font->CalcTextSizeA(text, INFINITY, layout.legend_wrap, keys[i].name.c_str());
    layout.legend_min = ImVec2(std::min(layout.legend_min.x, at.x), std::min(layout.legend_min.y, at.y));
    layout.legend_max = ImVec2(std::max(layout.legend_max.x, at.x + name.x + 22.0f * s), std::max(layout.legend_max.y, at.y + name.y));
  }
}

// The data area from `top` down, under rows of keys: none, and the chart not drawn, when that
// leaves the data less than 20 px; else the data are placed in it.
bool data_from(float top, ChartLayout& layout, const std::function<void()>& place) {
  layout.high_right.y = top;
  if (layout.low_left.y - layout.high_right.y < 20.0f) {
    layout.drawable = false;
    return false;
  }
  place();
  return true;
}

// The keys a line each, from `top_left` down.
void keys_down_from(ChartLayout& layout, std::size_t count, ImVec2 top_left, float key_height) {
  float y = top_left.y;
  for (std::size_t i = 0; i < count; ++i, y += key_height) layout.legend_at.push_back(ImVec2(top_left.x, y));
}

// A plain, steady chart's legend: a line above the data, the y label first and the keys after
// it in rows as wide as the chart (a column beside the data took up to 40 % of its width). The
// rows are laid out for every key that may ever be in them (`legend_room`: theory curves not
// shown before the reveal), each in its place from the start, the theory's last as keys_of
// gives them: what the run or the reveal adds moves neither a key nor the data. False when the
// data keep no height under the rows.
bool place_steady_rows(const Chart& chart, const std::vector<Key>& keys, ImVec2 corner, ImVec2 size, ImFont* font, float s,
                       float number_text, ChartLayout& layout, const std::function<void()>& place) {
  const float text = font->FontSize;
  std::vector<std::string> names;
  // A room that names every key shown is the legend's whole order: a key that joins in the
  // middle of it (an X–Y plot's "no contact", keyed once the block has left the floor, before
  // the theory's keys) takes its own place and moves no other.
  const bool whole_order = !chart.legend_room.empty() && std::all_of(keys.begin(), keys.end(), [&](const Key& key) {
    return std::find(chart.legend_room.begin(), chart.legend_room.end(), key.name) != chart.legend_room.end();
  });
  if (!whole_order) {
    for (const Key& key : keys) names.push_back(key.name);
  }
  for (const std::string& name : chart.legend_room) {
    if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
  }
  const float left = corner.x + 2.0f * s, right = corner.x + size.x - 8.0f * s;
  // A key longer than a row (pulley's laws written out) wraps in it.
  layout.legend_wrap = right - left - 32.0f * s;
  const float top = corner.y;
  float x = left + (chart.y_label.empty() ? 0.0f : width_of(font, chart.y_label) + 24.0f * s), y = top, row = text;
  std::vector<ImVec2> at;
  for (const std::string& name : names) {
    const ImVec2 wrapped = font->CalcTextSizeA(text, INFINITY, layout.legend_wrap, name.c_str());
    const float w = wrapped.x + 32.0f * s;
    if (x > left && x + w > right + 12.0f * s) {
      x = left;
      y += row + 1.0f * s;
      row = text;
    }
    at.push_back(ImVec2(x, y));
    row = std::max(row, wrapped.y);
    x += w;
  }
  if (names.empty() && chart.y_label.empty()) return true;
  layout.y_label_at = ImVec2(left, top);
  layout.legend_outside = true;
  layout.legend_at.clear();
  for (const Key& key : keys) {
    layout.legend_at.push_back(at[static_cast<std::size_t>(std::find(names.begin(), names.end(), key.name) - names.begin())]);
  }
  // The data under the rows, with room for half the top tick's label (in the numbers' font).
  if (!data_from(y + row + 1.0f * s + 0.5f * number_text, layout, place)) return false;
  bound_keys(layout, keys, font, s);
  return true;
}

// Under a chart that is not plain, where draw_legend writes its keys two a row (none for a
// chart with no legend) and its notes after them.
void place_under(const Chart& chart, const std::vector<Key>& keys, ImVec2 corner, ImVec2 size, ImFont* font, float s,
                 ChartLayout& layout) {
  const float text = font->FontSize;
  const float line = text + 3.0f * s;
  const std::size_t shown = chart.legend == Chart::Legend::under ? keys.size() : 0;
  layout.legend_min = ImVec2(corner.x + 12.0f * s, layout.low_left.y + 2.0f * text + 14.0f * s);
  layout.legend_max = ImVec2(corner.x + size.x - 12.0f * s, layout.legend_min.y + line * static_cast<float>((shown + 1) / 2));
}

// A legend too tall for one column beside the data, in two or more: each column's width, as
// few columns as `data_height` allows, or none when the data would keep less than 30 % of
// `full_width`.
std::vector<float> column_widths(const std::vector<Key>& keys, ImFont* font, float s, float full_width, float data_height) {
  const float key_height = font->FontSize + 2.0f * s;
  for (std::size_t columns = 2; columns <= keys.size(); ++columns) {
    const std::size_t per_column = (keys.size() + columns - 1) / columns;
    if (static_cast<float>(per_column) * key_height > data_height) continue;
    std::vector<float> widths((keys.size() + per_column - 1) / per_column, 0.0f);
    float total = 0.0f;
    for (std::size_t i = 0; i < keys.size(); ++i) {
      widths[i / per_column] = std::max(widths[i / per_column], width_of(font, keys[i].name) + 24.0f * s);
    }
    for (const float w : widths) total += w + 8.0f * s;
    if (full_width - total >= 0.3f * full_width) return widths;
    break;  // more columns are wider still
  }
  return {};
}

// Rows above the data would leave it little height (large text in a small plot, as on a
// projector). Beside it, on the right, a key a line, if the data keeps at least half the width;
// else the rows above all the same while the data keeps 30 px of height (a short plot beats one
// with its data under the keys); else beside it in columns; else, rather than the plot losing
// its data, in the corner it covers least of.
void place_beside_data(const std::vector<Key>& keys, ImFont* font, float s, ImVec2 legend_size, const std::vector<ImVec2>& rows,
                       float row_height, const LegendPlace& least_covered, ChartLayout& layout,
                       const std::function<void()>& place, const std::function<void(float)>& set_x_ticks) {
  const float key_height = font->FontSize + 2.0f * s;
  const float column = legend_size.x + 8.0f * s;
  const float data_width = layout.high_right.x - layout.low_left.x;
  const float rows_height = rows.back().y - rows.front().y + row_height + 4.0f * s;
  if (data_width - column >= 0.5f * data_width && legend_size.y <= layout.low_left.y - layout.high_right.y) {
    layout.high_right.x -= column;
    keys_down_from(layout, keys.size(), ImVec2(layout.high_right.x + 8.0f * s, layout.high_right.y), key_height);
    set_x_ticks(data_width - column);  // fewer for the narrower data
    place();
  } else if (layout.low_left.y - (layout.high_right.y + rows_height) >= 30.0f * s) {
    layout.legend_at = rows;
    layout.high_right.y = rows.back().y + row_height + 4.0f * s;
    place();
  } else if (const std::vector<float> widths = column_widths(keys, font, s, data_width, layout.low_left.y - layout.high_right.y);
             !widths.empty()) {
    // Beside the data in columns, as few as its height allows, keys in order down each.
    const std::size_t per_column = (keys.size() + widths.size() - 1) / widths.size();
    float total = 0.0f;
    for (const float w : widths) total += w + 8.0f * s;
    layout.high_right.x -= total;
    float x = layout.high_right.x + 8.0f * s;
    for (std::size_t i = 0; i < keys.size(); ++i) {
      if (i > 0 && i % per_column == 0) x += widths[i / per_column - 1] + 8.0f * s;
      layout.legend_at.push_back(ImVec2(x, layout.high_right.y + static_cast<float>(i % per_column) * key_height));
    }
    set_x_ticks(data_width - total);
    place();
  } else {
    layout.legend_outside = false;
    layout.legend_on_data = true;
    layout.legend_min = least_covered.min, layout.legend_max = least_covered.max;
    keys_down_from(layout, keys.size(), least_covered.min, key_height);
  }
}

// No corner is free of the data: the legend goes above the data area, in one row beside the y
// label when it fits there, else in as many rows as it needs under the label, the data area
// giving up their height (or beside the data, place_beside_data, when that leaves it too
// little). False when the data keep no height under the rows.
bool place_off_data(const Chart& chart, const std::vector<Key>& keys, ImVec2 corner, ImFont* font, float s, ImVec2 legend_size,
                    float row_width, const LegendPlace& least_covered, ChartLayout& layout, const std::function<void()>& place,
                    const std::function<void(float)>& set_x_ticks) {
  const float text = font->FontSize;
  layout.legend_outside = true;
  const float row_height = text + 4.0f * s;
  const float room = layout.high_right.x - corner.x - width_of(font, chart.y_label) - 12.0f * s;
  if (row_width <= room) {
    float x = layout.high_right.x - row_width;
    for (const Key& key : keys) {
      layout.legend_at.push_back(ImVec2(x, layout.high_right.y - text - 6.0f * s));
      x += width_of(font, key.name) + 32.0f * s;
    }
  } else if (const std::vector<ImVec2> rows = wrap_keys(keys, layout.low_left.x, layout.high_right.x,
                                                        layout.high_right.y - 4.0f * s, row_height, font, s);
             rows.back().y - rows.front().y + row_height > 0.45f * (layout.low_left.y - layout.high_right.y)) {
    place_beside_data(keys, font, s, legend_size, rows, row_height, least_covered, layout, place, set_x_ticks);
  } else {
    layout.legend_at = rows;
    if (!data_from(rows.back().y + row_height + 4.0f * s, layout, place)) return false;
  }
  bound_keys(layout, keys, font, s);
  return true;
}

// An inside legend: in a corner of the data area clear of the data, a key a line, when it fits
// there; else off the data (place_off_data). False when the data keep no height.
bool place_inside(const Chart& chart, const std::vector<Key>& keys, ImVec2 corner, ImFont* font, float s, ChartLayout& layout,
                  const std::function<void()>& place, const std::function<void(float)>& set_x_ticks) {
  const float text = font->FontSize;
  float legend_width = 0.0f, row_width = 0.0f;
  for (const Key& key : keys) {
    legend_width = std::max(legend_width, width_of(font, key.name));
    row_width += width_of(font, key.name) + 32.0f * s;
  }
  const ImVec2 legend_size(legend_width + 24.0f * s, static_cast<float>(keys.size()) * (text + 2.0f * s));
  std::vector<ImVec2> avoid = layout.points;
  for (const auto& curve : layout.theory) {
    for (const auto& piece : curve) avoid.insert(avoid.end(), piece.begin(), piece.end());
  }
  const LegendPlace inside = legend_corner(ImVec2(layout.low_left.x, layout.high_right.y), ImVec2(layout.high_right.x, layout.low_left.y),
                                           legend_size, 5.0f * s, avoid, 3.0f * s);
  // A corner clear of the data holds the legend only if the legend fits in the data area:
  // a tall one would run out over the axis and its labels.
  const bool fits = legend_size.y + 10.0f * s <= layout.low_left.y - layout.high_right.y &&
                    legend_size.x + 10.0f * s <= layout.high_right.x - layout.low_left.x;
  if (!inside.clear || !fits) return place_off_data(chart, keys, corner, font, s, legend_size, row_width, inside, layout, place, set_x_ticks);
  layout.legend_min = inside.min, layout.legend_max = inside.max;
  keys_down_from(layout, keys.size(), inside.min, text + 2.0f * s);
  return true;
}

}  // namespace

bool place_legend(const Chart& chart, const std::vector<Key>& keys, ImVec2 corner, ImVec2 size, const Fonts& fonts,
                  ChartLayout& layout, const std::function<void()>& place, const std::function<void(float)>& set_x_ticks) {
  if (chart.plain && chart.steady && chart.legend == Chart::Legend::inside) {
    return place_steady_rows(chart, keys, corner, size, fonts.small, fonts.scale, number_font(chart, fonts)->FontSize, layout, place);
  }
  if (!chart.plain && chart.legend != Chart::Legend::inside) {
    place_under(chart, keys, corner, size, fonts.small, fonts.scale, layout);
  } else if (chart.legend == Chart::Legend::inside && !keys.empty()) {
    return place_inside(chart, keys, corner, fonts.small, fonts.scale, layout, place, set_x_ticks);
  }
  return true;
}

void draw_legend(ImDrawList* draw, const Chart& chart, const std::vector<Key>& keys, const ChartLayout& layout, ImVec2 size,
                 const Theme& theme, const Fonts& fonts) {
  const float s = fonts.scale;
  ImFont* font = fonts.small;
  const float text = font->FontSize;
  const float line = text + 3.0f * s;
  if (chart.legend == Chart::Legend::under || (chart.legend == Chart::Legend::none && !chart.plain)) {
    // Categories, then series, in two columns; then the notes.
    const float column = 0.5f * (size.x - 24.0f * s);
    const std::size_t shown = chart.legend == Chart::Legend::under ? keys.size() : 0;
    for (std::size_t i = 0; i < shown; ++i) {
      const ImVec2 at(layout.legend_min.x + column * static_cast<float>(i % 2), layout.legend_min.y + line * static_cast<float>(i / 2));
      draw->AddRectFilled(ImVec2(at.x, at.y + 2.0f * s), ImVec2(at.x + 12.0f * s, at.y + text - 2.0f * s), keys[i].colour);
      draw->AddText(font, text, ImVec2(at.x + 18.0f * s, at.y), theme.text, keys[i].name.c_str());
    }
    float y = layout.legend_min.y + line * static_cast<float>((shown + 1) / 2);
    for (const std::string& note : chart.notes) {
      draw->AddText(font, text, ImVec2(layout.legend_min.x, y), theme.faint_text, note.c_str());
      y += line;
    }
  } else if (chart.legend == Chart::Legend::inside) {
    for (std::size_t i = 0; i < keys.size() && i < layout.legend_at.size(); ++i) {
      const Key& key = keys[i];
      const ImVec2 at = layout.legend_at[i];
      const ImVec2 wrapped = font->CalcTextSizeA(text, INFINITY, layout.legend_wrap, key.name.c_str());
      const float w = wrapped.x;
      draw->AddRectFilled(ImVec2(at.x - 2, at.y - 1), ImVec2(at.x + 22.0f * s + w + 2, at.y + wrapped.y + 1),
                          (theme.panel & 0x00FFFFFFu) | (200u << IM_COL32_A_SHIFT));
      const float middle = at.y + 0.5f * text;
      if (key.look == Key::Look::band) {
        draw->AddRectFilled(ImVec2(at.x, at.y + 2), ImVec2(at.x + 16.0f * s, at.y + text - 2), key.colour);
      } else if (key.look == Key::Look::theory) {
        draw_dashed(draw, {ImVec2(at.x, middle), ImVec2(at.x + 16.0f * s, middle)}, key.colour, 2.0f * s, key.dash * s, key.gap * s);
      } else if (key.dash > 0.0f) {
        // A dashed series' swatch: one dash, a gap and the start of the next, shortened to fit
        // the swatch's 16 points so that the gap shows.
        const float dash = std::min(key.dash, 9.0f), gap = std::min(key.gap, 4.0f);
        draw_dashed(draw, {ImVec2(at.x, middle), ImVec2(at.x + 16.0f * s, middle)}, key.colour, 3.0f * s, dash * s, gap * s);
      } else {
        draw->AddLine(ImVec2(at.x, middle), ImVec2(at.x + 16.0f * s, middle), key.colour, 3.0f * s);
      }
      draw->AddText(font, text, ImVec2(at.x + 20.0f * s, at.y), theme.text, key.name.c_str(), nullptr, layout.legend_wrap);
    }
  }
}

}  // namespace chart_parts

bool legend_has_room(const Chart& chart, ImVec2 size, const Fonts& fonts) {
  if (chart.legend != Chart::Legend::inside || chart.log_x || chart.log_y) return true;
  const ChartLayout plain = layout_chart(chart, ImVec2(0.0f, 0.0f), size, fonts);
  if (!plain.drawable) return false;
  // Data everywhere: a nameless series on a grid over the axes' whole range, so that no corner
  // is free. The axes keep their range (fixed by the chart, or its data's with a margin).
  Chart filled = chart;
  filled.fixed_x = filled.fixed_y = true;
  filled.x_low = plain.x_low, filled.x_high = plain.x_high, filled.y_low = plain.y_low, filled.y_high = plain.y_high;
  ChartSeries everywhere;
  everywhere.line = false;
  constexpr int grid = 24;
  for (int i = 0; i <= grid; ++i) {
    for (int j = 0; j <= grid; ++j) {
      everywhere.points.push_back({plain.x_low + (plain.x_high - plain.x_low) * i / grid,
                                   plain.y_low + (plain.y_high - plain.y_low) * j / grid});
    }
  }
  filled.series.push_back(std::move(everywhere));
  const ChartLayout layout = layout_chart(filled, ImVec2(0.0f, 0.0f), size, fonts);
  return layout.drawable && !layout.legend_on_data;
}

LegendPlace legend_corner(ImVec2 area_min, ImVec2 area_max, ImVec2 legend_size, float inset,
                          const std::vector<ImVec2>& points, float radius) {
  const ImVec2 corners[] = {{area_min.x + inset, area_min.y + inset},
                            {area_max.x - inset - legend_size.x, area_min.y + inset},
                            {area_min.x + inset, area_max.y - inset - legend_size.y},
                            {area_max.x - inset - legend_size.x, area_max.y - inset - legend_size.y}};
  LegendPlace best;
  std::size_t fewest = static_cast<std::size_t>(-1);
  for (const ImVec2& corner : corners) {
    std::size_t met = 0;
    for (const ImVec2& p : points) {
      met += p.x + radius >= corner.x && p.x - radius <= corner.x + legend_size.x && p.y + radius >= corner.y &&
             p.y - radius <= corner.y + legend_size.y;
    }
    if (met < fewest) {
      fewest = met;
      best = {corner, ImVec2(corner.x + legend_size.x, corner.y + legend_size.y), met == 0};
    }
  }
  return best;
}

}  // namespace frictionlab::draw
