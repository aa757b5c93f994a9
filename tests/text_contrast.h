// The contrast of every piece of text a frame drew against what lies under it (WCAG 2.1's
// contrast ratio), read from ImGui's draw data rather than pixels: each glyph's colour from its
// vertices, and the colour under its middle by laying every filled triangle drawn before it,
// in draw order and within its clip rectangle, over the window's clear colour. Anti-aliased
// edges blend by the vertex colours' interpolation, as the GPU does.
#pragma once

#include <imgui.h>
#include <imgui_internal.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace frictionlab::classroom {

// WCAG 2.1's relative luminance of an sRGB colour.
inline double relative_luminance(const ImVec4& colour) {
  const auto linear = [](double c) { return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4); };
  return 0.2126 * linear(colour.x) + 0.7152 * linear(colour.y) + 0.0722 * linear(colour.z);
}

inline double contrast_ratio(const ImVec4& a, const ImVec4& b) {
  const double la = relative_luminance(a), lb = relative_luminance(b);
  return (std::max(la, lb) + 0.05) / (std::min(la, lb) + 0.05);
}

// `top` with its alpha over an opaque `under`.
inline ImVec4 laid_over(const ImVec4& top, const ImVec4& under) {
  const float a = top.w;
  return ImVec4(top.x * a + under.x * (1.0f - a), top.y * a + under.y * (1.0f - a), top.z * a + under.z * (1.0f - a), 1.0f);
}

struct GlyphContrast {
  ImVec2 at;          // the glyph's middle
  ImVec4 text;        // its colour as seen (laid over what is under it)
  ImVec4 background;  // what lies under it
  double ratio;
};

namespace text_contrast_detail {

struct Triangle {
  ImVec2 p[3];
  ImVec4 colour[3];
  ImVec4 clip;
};

// The triangle's colour at `point` by barycentric interpolation; alpha 0 when outside.
inline bool colour_at(const Triangle& t, ImVec2 point, ImVec4& colour) {
  if (point.x < t.clip.x || point.y < t.clip.y || point.x >= t.clip.z || point.y >= t.clip.w) return false;
  const ImVec2 a = t.p[0], b = t.p[1], c = t.p[2];
  const float area = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
  if (std::fabs(area) < 1e-6f) return false;
  const float wb = ((point.x - a.x) * (c.y - a.y) - (c.x - a.x) * (point.y - a.y)) / area;
  const float wc = ((b.x - a.x) * (point.y - a.y) - (point.x - a.x) * (b.y - a.y)) / area;
  const float wa = 1.0f - wb - wc;
  if (wa < 0.0f || wb < 0.0f || wc < 0.0f) return false;
  const auto mix = [&](float ImVec4::*channel) {
    return wa * (t.colour[0].*channel) + wb * (t.colour[1].*channel) + wc * (t.colour[2].*channel);
  };
  colour = ImVec4(mix(&ImVec4::x), mix(&ImVec4::y), mix(&ImVec4::z), mix(&ImVec4::w));
  return true;
}

}  // namespace text_contrast_detail

// Every glyph of `data` (drawn with `atlas`, whose white pixel marks filled shapes) with its
// contrast against what lies under it; `clear` is the colour the frame was cleared to.
inline std::vector<GlyphContrast> glyph_contrasts(const ImDrawData& data, const ImFontAtlas& atlas, ImVec4 clear) {
  using text_contrast_detail::Triangle;
  // Which texels of the atlas are a glyph's: a triangle sampling one is text, any other
  // texture coordinate is a filled shape (the white pixel) or a line's baked edge.
  const int atlas_width = atlas.TexWidth, atlas_height = atlas.TexHeight;
  const float width_texels = static_cast<float>(atlas_width), height_texels = static_cast<float>(atlas_height);
  std::vector<bool> glyph_texel(static_cast<std::size_t>(atlas_width) * static_cast<std::size_t>(atlas_height), false);
  for (const ImFont* font : atlas.Fonts) {
    for (const ImFontGlyph& glyph : font->Glyphs) {
      const int x0 = static_cast<int>(glyph.U0 * width_texels), x1 = static_cast<int>(std::ceil(glyph.U1 * width_texels));
      const int y0 = static_cast<int>(glyph.V0 * height_texels), y1 = static_cast<int>(std::ceil(glyph.V1 * height_texels));
      for (int y = std::max(0, y0); y < std::min(atlas_height, y1); ++y) {
        for (int x = std::max(0, x0); x < std::min(atlas_width, x1); ++x) {
          glyph_texel[static_cast<std::size_t>(y) * atlas_width + x] = true;
        }
      }
    }
  }
  const ImVec2 white = atlas.TexUvWhitePixel;
  const auto is_white = [&](ImVec2 uv) { return std::fabs(uv.x - white.x) < 1e-6f && std::fabs(uv.y - white.y) < 1e-6f; };
  const auto is_glyph = [&](ImVec2 uv) {
    const int x = std::clamp(static_cast<int>(uv.x * width_texels), 0, atlas_width - 1);
    const int y = std::clamp(static_cast<int>(uv.y * height_texels), 0, atlas_height - 1);
    return static_cast<bool>(glyph_texel[static_cast<std::size_t>(y) * atlas_width + x]);
  };

  // Filled triangles binned by a coarse grid, each bin in draw order, so a glyph looks only at
  // what could lie under it.
  constexpr float cell = 32.0f;
  const int columns = static_cast<int>(std::ceil(data.DisplaySize.x / cell)) + 1;
  const int rows = static_cast<int>(std::ceil(data.DisplaySize.y / cell)) + 1;
  std::vector<Triangle> filled;
  std::vector<std::vector<std::size_t>> bins(static_cast<std::size_t>(columns) * static_cast<std::size_t>(rows));
  std::vector<GlyphContrast> glyphs;
  const auto background_at = [&](ImVec2 point) {
    ImVec4 under = clear;
    const int column = std::clamp(static_cast<int>(point.x / cell), 0, columns - 1);
    const int row = std::clamp(static_cast<int>(point.y / cell), 0, rows - 1);
    for (const std::size_t index : bins[static_cast<std::size_t>(row) * columns + column]) {
      ImVec4 colour;
      if (text_contrast_detail::colour_at(filled[index], point, colour)) under = laid_over(colour, under);
    }
    return under;
  };

  for (int list_index = 0; list_index < data.CmdListsCount; ++list_index) {
    const ImDrawList& list = *data.CmdLists[list_index];
    unsigned int last_glyph_corner = ~0u;
    for (const ImDrawCmd& command : list.CmdBuffer) {
      if (command.UserCallback != nullptr) continue;
      for (unsigned int i = 0; i + 2 < command.ElemCount; i += 3) {
        Triangle triangle;
        ImVec2 uv[3];
        for (int k = 0; k < 3; ++k) {
          const ImDrawVert& vertex = list.VtxBuffer[static_cast<int>(command.VtxOffset + list.IdxBuffer[static_cast<int>(command.IdxOffset + i + k)])];
          triangle.p[k] = vertex.pos;
          triangle.colour[k] = ImGui::ColorConvertU32ToFloat4(vertex.col);
          uv[k] = vertex.uv;
        }
        triangle.clip = command.ClipRect;
        const ImVec2 uv_middle((uv[0].x + uv[1].x + uv[2].x) / 3.0f, (uv[0].y + uv[1].y + uv[2].y) / 3.0f);
        if (!is_white(uv[0]) && is_glyph(uv_middle)) {
          // A glyph is two triangles sharing corner 0, (0, 1, 2) then (0, 2, 3): the first one
          // carries the quad's opposite corners 0 and 2, whose middle is the glyph's.
          const unsigned int first = command.VtxOffset + list.IdxBuffer[static_cast<int>(command.IdxOffset + i)];
          if (first == last_glyph_corner) continue;
          last_glyph_corner = first;
          const ImVec2 middle(0.5f * (triangle.p[0].x + triangle.p[2].x), 0.5f * (triangle.p[0].y + triangle.p[2].y));
          const ImVec4& clip = command.ClipRect;
          if (middle.x < clip.x || middle.y < clip.y || middle.x >= clip.z || middle.y >= clip.w) continue;  // clipped away
          const ImVec4 colour = triangle.colour[0];
          if (colour.w <= 0.0f) continue;
          const ImVec4 under = background_at(middle);
          const ImVec4 seen = laid_over(colour, under);
          glyphs.push_back({middle, seen, under, contrast_ratio(seen, under)});
          continue;
        }
        if (!is_white(uv[0])) continue;  // a line's baked edge: thin, and never a text's background
        const float x0 = std::max(std::min({triangle.p[0].x, triangle.p[1].x, triangle.p[2].x}), triangle.clip.x);
        const float x1 = std::min(std::max({triangle.p[0].x, triangle.p[1].x, triangle.p[2].x}), triangle.clip.z);
        const float y0 = std::max(std::min({triangle.p[0].y, triangle.p[1].y, triangle.p[2].y}), triangle.clip.y);
        const float y1 = std::min(std::max({triangle.p[0].y, triangle.p[1].y, triangle.p[2].y}), triangle.clip.w);
        if (x1 < x0 || y1 < y0) continue;
        filled.push_back(triangle);
        const int c0 = std::clamp(static_cast<int>(x0 / cell), 0, columns - 1), c1 = std::clamp(static_cast<int>(x1 / cell), 0, columns - 1);
        const int r0 = std::clamp(static_cast<int>(y0 / cell), 0, rows - 1), r1 = std::clamp(static_cast<int>(y1 / cell), 0, rows - 1);
        for (int r = r0; r <= r1; ++r) {
          for (int c = c0; c <= c1; ++c) bins[static_cast<std::size_t>(r) * columns + c].push_back(filled.size() - 1);
        }
      }
    }
  }
  return glyphs;
}

}  // namespace frictionlab::classroom
