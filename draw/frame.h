// One frame of a lesson: the same function draws a window's frame and a headless PNG. It
// only draws: stepping the lesson is the caller's business.
#pragma once

#include <imgui.h>

#include <functional>

#include "draw/camera.h"
#include "draw/chart.h"
#include "draw/drawing.h"
#include "draw/free_body.h"
#include "draw/panels.h"
#include "draw/text_record.h"
#include "draw/theme.h"
#include "lessons/runtime/lesson.h"
#include "lessons/runtime/readings.h"

namespace frictionlab::draw {

// Where each part of the frame goes, for a display of a given size: the world at the top
// left with the plots below it, the panels in a column on the right. Large text (projector
// mode) widens the column, so that sliders and the theory table's names keep their room.
struct FrameLayout {
  ImVec2 title_corner, title_size;
  ImVec2 world_corner, world_size;
  ImVec2 legend_corner, legend_size;
  ImVec2 inset_corner, inset_size;  // the free-body diagram, over the world's top right
  ImVec2 plots_corner, plots_size;
  ImVec2 column_corner, column_size;
  // The frame fills `size` from `origin` (the window keeps a menu bar above it and its
  // transport controls below).
  // `projector` (the window's projector mode, its plots a page at a time): the title is one
  // line and the legend a column beside the plots' row, so that the row, under a world as tall
  // as projector mode's was before (55 % of what is under a two-line title, less the legend's
  // strip; a screen's world has 57 %), is a third of the screen high or more and the key plot's levels read from
  // the back of a room.
  // `lesson`: whether it has plots of its own, which the layout asks of it here and nowhere
  // else. A projector's frame for a lesson with none gives their row to the world, and the
  // legend goes back to its strip under the world (a column beside an empty row left a third of
  // the screen blank).
  static FrameLayout of(ImVec2 size, float scale, ImVec2 origin, bool projector, const lessons::Lesson& lesson);
  // A screen's frame (not a projector's), which is the same for every lesson: the tests'
  // places, and the column's width.
  static FrameLayout of(ImVec2 size, float scale, ImVec2 origin = ImVec2(0.0f, 0.0f));
  // The legend is a column beside the plots' row (projector mode, a lesson with plots), not a
  // strip under the world.
  bool legend_beside_plots = false;
  // The legend's column in projector mode, in points at text scale 1, until a lesson's names
  // say how wide it is (legend_column_width() in legend.h): "friction" after its arrow in 14 pt
  // text, and its margins.
  static constexpr float legend_column_default_points = 95.0f;
  // The title's panel's padding above and below its one line on a projector, in points.
  static constexpr float title_padding = 1.0f;
  // The same with the legend's column `width` pixels wide (projector mode), the plots the rest.
  FrameLayout with_legend_column(float width) const;
  // The same with the column's foot `foot` pixels higher (the window's help strip under it):
  // the world, its legend and the plots keep their places.
  FrameLayout with_column_foot(float foot) const;
};

// Where the frame put things in the world view, for tests of its layout: per lane, the
// camera and what its label placer placed and avoided; and the free-body inset.
struct FrameRecord {
  struct Lane {
    Camera camera;
    std::vector<ImVec4> labels;          // x0, y0, x1, y1
    std::vector<DrawnSegment> arrows;    // as thick as drawn, heads included
    std::vector<ImVec4> avoided;         // contact marks and the inset
    ImVec4 shown{0.0f, 0.0f, 0.0f, 0.0f};  // what of the lane is not clipped away, x0, y0, x1, y1
    std::vector<std::string> texts;        // each label's text, in the order of `labels`
    std::vector<ImVec4> bodies;            // the moving bodies' boxes, which the tools' readings keep off
    std::vector<LabelPlacer::ForceLabel> forces;  // each force's arrow and where its value went
    // Written in its corner: its name among lanes, and whose forces where one body's alone are
    // drawn (FrameStyle::forces_on); empty: nothing.
    std::string caption;
  };
  std::vector<Lane> lanes;
  ImVec4 inset{0.0f, 0.0f, 0.0f, 0.0f};
  // The main body's close-up over the world (draw/close_up.h), where one is drawn: its camera,
  // its place as `shown`, and what it placed.
  std::vector<Lane> close_ups;
  FreeBodyRecord free_body;
  // Every piece of text the panels drew, with what of it could show.
  std::vector<ShownText> texts;
  // Where each of the lesson's plots in view put its data, curves and legend: its number, its
  // layout; the extra plot (FrameStyle::extra_plot) numbered after the lesson's.
  struct Plot {
    std::size_t number;
    ChartLayout layout;
  };
  std::vector<Plot> plots;
};

struct FrameStyle {
  ThemeName theme = ThemeName::light;
  const Fonts* fonts = nullptr;
  ImVec2 origin{0.0f, 0.0f};
  // The theory table and the lesson's duration, when the caller keeps them (the window works
  // them out a few times a second); null: worked out for this frame.
  const lessons::LessonReadings* readings = nullptr;
  // A plot's script error as the class sees it (Classroom::script_words: the web page names a
  // script by its file's name); empty: as Lua gives it.
  std::function<std::string(const std::string&)> script_words;
  // Draws the parameters panel in its place instead of the values as text (the window's
  // sliders), at a step of giving way to a short column (0: every control whole); its heights
  // at steps 0, 1, ... The window then shows the energy ledger and the model card as tabs of
  // one panel, to leave the sliders room.
  std::function<void(ImVec2 corner, ImVec2 size, std::size_t step)> parameters_panel;
  std::vector<float> parameters_heights;
  // How far the parameters may give way for the theory table revealed under the class's
  // predictions (predictions_height): every step that leaves sliders in sight, not the whole
  // panel folded away (a class's sliders gone for a table read at the run's end).
  std::size_t parameters_step_for_the_theory = static_cast<std::size_t>(-1);
  // The window's wheel zoom and drag pan.
  ViewAdjust view_adjust;
  // Filled with the world view's layout when not null.
  FrameRecord* record = nullptr;
  // Pixels under the column kept for the window's help strip (FrameLayout::with_column_foot):
  // the help takes its room from the teacher's column, never from the world and plots the class
  // watches, which stay as they were when F1 opens it.
  float column_foot = 0.0f;
  // More tabs beside the energy ledger and the model card, in the window (BeginTabItem each).
  std::function<void()> more_tabs;
  // The class's predictions (the window), drawn at the top of the theory panel; their heights
  // at the panel's inside width before the reveal and after it (the column is planned for the
  // taller once, with the revealed theory table and the class's answers in it where the column
  // has the room, so that it does not move at the reveal). With `theory_hidden` they take the theory table's place, and
  // nothing that states a theory value is drawn: the table, the plots' theory curves.
  // `lines_in_table`: the class's answers are a column of the theory table (class_answers), where
  // the column holds it whole (projector mode); else their lines go above it, each under its
  // row's name, in sight.
  std::function<void(bool lines_in_table)> predictions;
  struct AnswersHeight {
    float asked = 0.0f;     // before the reveal: the questions and the class's answers
    float revealed_above = 0.0f;  // after it, the class's lines under their rows' names above the table
  };
  std::function<AnswersHeight(float width)> predictions_height;
  // The class's answers, by the predicted rows' names, for their column of a projector's theory
  // table (the rows' names are the table's: the class's rows no longer come a second time above
  // it). Given before the reveal too, at the widest each may read, for the column's plan.
  ClassAnswers class_answers;
  // Whether the answers have grown past the height planned for them (a value changed since the
  // plan): they scroll then, in the room they were given.
  std::function<bool()> predictions_outgrew;
  bool theory_hidden = false;
  // The window's own drawing in each lane of the world (the force gauge, the measuring tools),
  // called three times (WorldToolsPass): to tell the placer what it will draw, to draw what has
  // fixed labels before the lesson's labels are placed, and to draw the rest after the world.
  std::function<void(WorldToolsPass pass, ImDrawList* draw, const Camera& camera, std::size_t lane,
                     float newtons_to_pixels, LabelPlacer& labels)>
      world_tools;
  // One more plot after the lesson's (the force gauge's reading), drawn in its panel's inside,
  // saying where its chart went; its title. None when empty.
  std::string extra_plot_title;
  std::function<ChartLayout(ImVec2 corner, ImVec2 size)> extra_plot;
  // Plots shown a page at a time turn to the extra plot's page: while the hand pulls, the
  // gauge's reading is what the class watches, and the teacher's hand is on the mouse.
  bool show_extra_plot = false;
  // The window's projector mode (FrameLayout::of's `projector`): the title one line, the legend
  // beside the plots, and the plots one a page, each its row's full width: the lesson's key
  // plot, its first, as large as the row allows and read from the back of the room, and the
  // pages the same whatever the run, so that nothing moves as it goes on or at the reveal (how
  // many plots fitted side by side was chosen anew each frame from their axes and legends).
  bool projector = false;
  // The one moving body whose forces and contacts the world draws (the window's View > Forces
  // on, B), the others drawn as bodies only, and the world's corner says so; null: every body's.
  const b2Body* forces_on = nullptr;
  // Pages to turn the plots by in this frame (the ← and → keys: −1, +1), as the buttons do.
  int turn_plot_pages = 0;
  // Values the class must not see yet (a mystery pair's), and the theory that would give them away.
  HiddenValues hidden;
  // Nothing may show the theory yet: kept back for the class's predictions, or giving a mystery away.
  bool theory_kept_back() const { return theory_hidden || hidden.theory(); }
};

// Builds the frame's ImGui windows and draw lists; call between ImGui::NewFrame() and
// ImGui::Render(). `framing` is the one chosen when the lesson was (re)built.
void build_frame(lessons::Lesson& lesson, const lessons::WorldFraming& framing, const FrameStyle& style, ImVec2 display);

// The world view's cameras (one per lane) and arrow scale for this frame, as build_frame draws
// them: the window finds bodies under the mouse with them, tests find the arrows.
std::vector<Camera> world_cameras(const lessons::Lesson& lesson, const lessons::WorldFraming& framing, ImVec2 display,
                                  float scale, ImVec2 origin = ImVec2(0.0f, 0.0f), const ViewAdjust& adjust = {},
                                  bool projector = false);
// The first (or only) of them.
Camera world_camera(const lessons::Lesson& lesson, const lessons::WorldFraming& framing, ImVec2 display, float scale,
                    ImVec2 origin = ImVec2(0.0f, 0.0f));
float arrow_scale(const lessons::Lesson& lesson, const lessons::WorldFraming& framing, ImVec2 display, float scale,
                  bool projector = false);
// The length the arrow of the force arrow_scale is chosen for is drawn, px: 0.4 of the view's
// height (of a lane's), within 30 and 150 pixels at text scale 1.
float scale_force_pixels(const lessons::Lesson& lesson, const lessons::WorldFraming& framing, ImVec2 display, float scale,
                         bool projector = false);
// The longest arrow the world is framed to hold, px: that, or the legible length
// (legible_arrow_pixels) where that is longer, as every arrow is at least.
float longest_arrow_pixels(const lessons::Lesson& lesson, const lessons::WorldFraming& framing, ImVec2 display, float scale,
                           bool projector = false);

}  // namespace frictionlab::draw
