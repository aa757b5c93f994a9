// ImVec2 arithmetic for ImRect.
#define IMGUI_DEFINE_MATH_OPERATORS
#include "ui/sandbox.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui_internal.h>
#include <sys/stat.h>

#include <cstdio>
#include <filesystem>
#include <sstream>

#include "lessons/runtime/catalog.h"
#include "ui/frame.h"
#include "ui/image.h"

namespace frictionlab::ui {
namespace {

long long modified(const std::string& path) {
  struct stat status {};
  if (stat(path.c_str(), &status) != 0) return -1;
  return static_cast<long long>(status.st_mtim.tv_sec) * 1'000'000'000LL + status.st_mtim.tv_nsec;
}

bool pressed(int key) { return ImGui::IsKeyPressed(key, false); }

std::string lesson_stem(const std::string& path) { return std::filesystem::path(path).stem().string(); }

}  // namespace

Sandbox::Sandbox(SandboxOptions options)
    : window_(options.window), lock_(options.lock.begin(), options.lock.end()), output_folder_(options.output_folder) {
  try {
    playback_ = std::make_unique<Playback>(options.lesson, options.overrides, options.settings);
  } catch (const lessons::ScriptError& error) {
    // A student's broken script: show why beside a working lesson, and open it once it builds.
    failed_script_ = options.lesson;
    failed_error_ = error.what();
    failed_stamp_ = modified(failed_script_);
    playback_ = std::make_unique<Playback>(lessons::resolve_lesson(lessons::builtin_lessons().front()),
                                           std::map<std::string, std::string>{}, options.settings);
  }
  playback_->set_speed(window_.speed);
  playback_->play();  // a lesson opens running: what moves is what the class looks at first
  for (const std::string& name : lock_) {
    bool known = false;
    for (const char* setting : lockable_settings) known = known || name == setting;
    for (const lessons::Parameter& parameter : playback_->lesson().parameters()) known = known || name == parameter.name;
    if (!known) {
      std::string controls;
      for (const lessons::Parameter& parameter : playback_->lesson().parameters()) controls += parameter.name + ", ";
      throw InvalidInput("--lock " + name + ": " + playback_->lesson().path() +
                         " has no control of that name; its controls: " + controls + "hz, substeps, friction");
    }
  }
}

float Sandbox::ui_scale(ImVec2 display) const {
  const float fit = frame_scale(static_cast<int>(display.x), static_cast<int>(display.y));
  // Projector mode: a third larger, text and lines alike, for the back of the room.
  return std::max(0.5f, fit) * (window_.projector ? 1.35f : 1.0f);
}

bool Sandbox::shown(const std::string& control_name) const { return lock_.empty() || lock_.count(control_name) > 0; }

std::optional<ImRect> Sandbox::control(const std::string& name) const {
  const auto found = controls_.find(name);
  if (found == controls_.end()) return std::nullopt;
  return found->second;
}

void Sandbox::frame(const Fonts& fonts, ImVec2 display, double wall_seconds) {
  fonts_ = &fonts;
  controls_.clear();
  const float s = fonts.scale;
  handle_keys();
  playback_->advance(wall_seconds);
  playback_->watch_file(wall_seconds);
  try_failed_script(wall_seconds);

  ImGui::PushFont(fonts.body);
  menu_bar();
  const float menu_height = ImGui::GetFrameHeight();
  const float transport_height = ImGui::GetFrameHeight() + 2.0f * ImGui::GetStyle().WindowPadding.y + 2.0f * s;
  ImGui::PopFont();
  const ImVec2 origin(0.0f, menu_height);
  const ImVec2 area(display.x, std::max(1.0f, display.y - menu_height - transport_height));

  FrameStyle style;
  style.theme = window_.theme;
  style.fonts = &fonts;
  style.origin = origin;
  style.readings = &playback_->readings();
  style.parameters_panel = [this](ImVec2 corner, ImVec2 size) { parameters_panel(corner, size); };
  ImGui::PushFont(fonts.body);
  style.parameters_height = parameters_height();
  ImGui::PopFont();
  build_frame(playback_->lesson(), playback_->framing(), style, area);

  ImGui::PushFont(fonts.body);
  handle_mouse(origin, area, s);
  const FrameLayout layout = FrameLayout::of(area, s, origin);
  messages(ImVec2(layout.world_corner.x + 6.0f * s, layout.world_corner.y + 6.0f * s),
           layout.world_size.x - layout.inset_size.x - 18.0f * s);
  transport_bar(ImVec2(0.0f, display.y - transport_height), ImVec2(display.x, transport_height));
  help_panel();
  open_script_popup();
  ImGui::PopFont();

  // Values asked for while the panels were drawn: applied now, since a rebuild replaces what
  // the panels were reading.
  for (const auto& [name, text] : pending_values_) set_value(name, text);
  pending_values_.clear();
}

void Sandbox::handle_keys() {
  const ImGuiIO& io = ImGui::GetIO();
  if (io.WantTextInput) return;  // typing a value: the keys are the text's
  if (io.KeyCtrl) {
    if (pressed(GLFW_KEY_S)) screenshot_request_ = unused_path("frictionlab_" + lesson_stem(playback_->lesson().path()), ".png");
    if (pressed(GLFW_KEY_E)) {
      try {
        status_ = "History saved to " + export_history();
      } catch (const std::exception& error) {
        status_ = std::string("Could not save the history: ") + error.what();
      }
    }
    return;
  }
  if (pressed(GLFW_KEY_SPACE)) playback_->toggle();
  if (pressed(GLFW_KEY_PERIOD)) playback_->step_once();
  if (pressed(GLFW_KEY_COMMA)) playback_->scrub_to(playback_->lesson().scene().time() - playback_->lesson().scene().frame_step());
  if (pressed(GLFW_KEY_R)) playback_->reset();
  if (pressed(GLFW_KEY_F5)) playback_->reload();
  if (pressed(GLFW_KEY_F11)) full_screen_toggle_ = true;
  if (pressed(GLFW_KEY_F1)) window_.help = !window_.help;
  if (pressed(GLFW_KEY_P)) window_.projector = !window_.projector;
  if (pressed(GLFW_KEY_D)) window_.theme = window_.theme == ThemeName::dark ? ThemeName::light : ThemeName::dark;
}

void Sandbox::handle_mouse(ImVec2 origin, ImVec2 size, float scale) {
  ImGuiContext& context = *ImGui::GetCurrentContext();
  const ImGuiIO& io = ImGui::GetIO();
  lessons::Lesson& lesson = playback_->lesson();
  Scene& scene = lesson.scene();
  const FrameLayout layout = FrameLayout::of(size, scale, origin);
  camera_ = ui::world_camera(lesson, playback_->framing(), size, scale, origin);
  const Camera& camera = camera_;
  const ImRect world(layout.world_corner, layout.world_corner + layout.world_size);
  const ImRect inset(layout.inset_corner, layout.inset_corner + layout.inset_size);
  const bool over_world = context.HoveredWindow != nullptr && context.HoveredWindow == ImGui::FindWindowByName("###world") &&
                          world.Contains(io.MousePos) && !inset.Contains(io.MousePos);
  if (scene.grabbed() == nullptr && over_world && ImGui::IsMouseClicked(ImGuiMouseButton_Left)) {
    const b2Vec2 point = camera.to_world(io.MousePos);
    for (const auto& [name, body] : scene.bodies()) {
      if (body->GetType() != b2_dynamicBody) continue;
      for (const b2Fixture* fixture = body->GetFixtureList(); fixture != nullptr; fixture = fixture->GetNext()) {
        if (fixture->TestPoint(point)) {
          playback_->grab(name, body->GetLocalPoint(point), point);
          break;
        }
      }
      if (scene.grabbed() != nullptr) break;
    }
  }
  if (b2Body* body = scene.grabbed()) {
    if (!io.MouseDown[ImGuiMouseButton_Left]) {
      playback_->release();
      return;
    }
    const b2Vec2 target = camera.to_world(io.MousePos);
    if (target.x != scene.grab_target().x || target.y != scene.grab_target().y) playback_->move_grab(target);
    // The hand: a line from the point held to the pointer, where it pulls towards.
    const Theme& colours = theme(window_.theme);
    const b2Vec2 held = body->GetWorldPoint(scene.applied_forces().back().local_point);
    ImDrawList* draw = ImGui::GetForegroundDrawList();
    draw->AddLine(camera.to_screen(held), io.MousePos, colours.hand, 2.0f * scale);
    draw->AddCircleFilled(camera.to_screen(held), 4.0f * scale, colours.hand);
    draw->AddCircle(io.MousePos, 7.0f * scale, colours.hand, 0, 2.0f * scale);
  }
}

void Sandbox::menu_bar() {
  if (!ImGui::BeginMainMenuBar()) return;
  if (ImGui::BeginMenu("Lesson")) {
    for (const std::string& name : lessons::builtin_lessons()) {
      const bool current = lesson_stem(playback_->lesson().path()) == name;
      if (ImGui::MenuItem(name.c_str(), nullptr, current)) status_ = open(name);
    }
    ImGui::Separator();
    if (ImGui::MenuItem("Open a script...")) open_popup_ = true;
    if (ImGui::MenuItem("Reload the script", "F5")) playback_->reload();
    ImGui::Separator();
    if (ImGui::MenuItem("Screenshot (PNG)", "Ctrl+S")) {
      screenshot_request_ = unused_path("frictionlab_" + lesson_stem(playback_->lesson().path()), ".png");
    }
    if (ImGui::MenuItem("Export the history (CSV)", "Ctrl+E")) {
      try {
        status_ = "History saved to " + export_history();
      } catch (const std::exception& error) {
        status_ = std::string("Could not save the history: ") + error.what();
      }
    }
    ImGui::Separator();
    if (ImGui::MenuItem("Quit")) quit_ = true;
    ImGui::EndMenu();
  }
  const bool simulation = ImGui::BeginMenu("Simulation");
  remember("Simulation menu");
  if (simulation) {
    StepSettings settings = playback_->lesson().settings();
    const bool may_treat = shown("friction"), may_rate = shown("hz"), may_substep = shown("substeps");
    ImGui::TextDisabled("Friction treatment");
    const std::pair<FrictionTreatment, const char*> treatments[] = {
        {FrictionTreatment::stick_slip, "stick-slip (converges to Coulomb)"},
        {FrictionTreatment::threshold, "threshold (games' speed switch)"},
        {FrictionTreatment::regularized, "regularized (smooth, creeps)"},
        {FrictionTreatment::box2d, "box2d (one coefficient)"}};
    for (const auto& [treatment, label] : treatments) {
      const bool chosen = ImGui::MenuItem(label, nullptr, settings.treatment == treatment, may_treat);
      remember("treatment " + std::string(treatment_name(treatment)));
      if (chosen && settings.treatment != treatment) {
        settings.treatment = treatment;
        change_settings(settings);
      }
    }
    ImGui::Separator();
    ImGui::TextDisabled("Step rate");
    for (const double hz : {30.0, 60.0, 120.0, 240.0, 480.0, 960.0, 1920.0}) {
      const std::string label = std::to_string(static_cast<int>(hz)) + " Hz";
      const bool chosen = ImGui::MenuItem(label.c_str(), nullptr, settings.hz == hz, may_rate);
      remember("hz " + label.substr(0, label.size() - 3));
      if (chosen && settings.hz != hz) {
        settings.hz = hz;
        change_settings(settings);
      }
    }
    ImGui::Separator();
    ImGui::TextDisabled("Sub-steps per frame");
    for (const int substeps : {1, 2, 4, 8, 16}) {
      const std::string label = std::to_string(substeps);
      const bool chosen = ImGui::MenuItem(label.c_str(), nullptr, settings.substeps == substeps, may_substep);
      remember("substeps " + label);
      if (chosen && settings.substeps != substeps) {
        settings.substeps = substeps;
        change_settings(settings);
      }
    }
    ImGui::Separator();
    if (ImGui::MenuItem("Reset to t = 0", "R")) playback_->reset();
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("View")) {
    bool dark = window_.theme == ThemeName::dark;
    if (ImGui::MenuItem("Dark theme", "D", &dark)) window_.theme = dark ? ThemeName::dark : ThemeName::light;
    ImGui::MenuItem("Projector mode", "P", &window_.projector);
    if (ImGui::MenuItem("Full screen", "F11")) full_screen_toggle_ = true;
    ImGui::MenuItem("Help", "F1", &window_.help);
    ImGui::EndMenu();
  }
  // Which file is running, so a student knows which script to edit.
  const std::string& path = playback_->lesson().path();
  const float width = ImGui::CalcTextSize(path.c_str()).x;
  ImGui::SameLine(std::max(ImGui::GetCursorPosX() + 20.0f, ImGui::GetWindowWidth() - width - 16.0f));
  ImGui::TextDisabled("%s", path.c_str());
  ImGui::EndMainMenuBar();
}

void Sandbox::change_settings(const StepSettings& settings) {
  try {
    playback_->set_settings(settings);
  } catch (const InvalidInput& error) {
    status_ = error.what();
  }
}

void Sandbox::set_value(const std::string& name, const std::string& text) {
  try {
    playback_->set_parameter(name, text);
    control_errors_.erase(name);
  } catch (const InvalidInput& error) {
    control_errors_[name] = error.what();
  }
}

void Sandbox::messages(ImVec2 corner, float width) {
  std::vector<std::pair<std::string, bool>> lines;  // text, is it a fault
  if (!failed_script_.empty()) lines.push_back({failed_error_ + "  (showing " + lesson_stem(playback_->lesson().path()) +
                                                    " until " + lesson_stem(failed_script_) + ".lua builds)", true});
  if (!playback_->script_error().empty()) {
    lines.push_back({playback_->script_error() + "  (the last good version keeps running)", true});
  }
  if (!playback_->problem().empty()) lines.push_back({playback_->problem(), true});
  if (!playback_->readings().error.empty()) lines.push_back({playback_->readings().error, true});
  if (!playback_->notice().empty()) lines.push_back({playback_->notice(), false});
  if (lines.empty()) return;
  const Theme& colours = theme(window_.theme);
  ImGui::SetNextWindowPos(corner);
  ImGui::SetNextWindowSizeConstraints(ImVec2(width, 0.0f), ImVec2(width, FLT_MAX));
  ImGui::SetNextWindowBgAlpha(0.92f);
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                                 ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
                                 ImGuiWindowFlags_NoMove;
  if (ImGui::Begin("###messages", nullptr, flags)) {
    ImGui::PushTextWrapPos(0.0f);
    for (const auto& [text, fault] : lines) {
      ImGui::PushStyleColor(ImGuiCol_Text, fault ? colours.bad : ImGui::GetColorU32(ImGuiCol_Text));
      ImGui::TextUnformatted(text.c_str());
      ImGui::PopStyleColor();
    }
    ImGui::PopTextWrapPos();
    controls_["messages"] = ImRect(ImGui::GetWindowPos(), ImGui::GetWindowPos() + ImGui::GetWindowSize());
  }
  ImGui::End();
}

void Sandbox::help_panel() {
  if (!window_.help) return;
  const float s = fonts_->scale;
  ImGui::SetNextWindowPos(ImVec2(ImGui::GetIO().DisplaySize.x * 0.5f, ImGui::GetIO().DisplaySize.y * 0.5f),
                          ImGuiCond_FirstUseEver, ImVec2(0.5f, 0.5f));
  ImGui::SetNextWindowSize(ImVec2(520.0f * s, 0.0f), ImGuiCond_FirstUseEver);
  if (ImGui::Begin("Help (F1 shows and hides it)", &window_.help)) {
    static const char* const keys[][2] = {
        {"Space", "play / pause"},
        {". (period)", "one step of the lesson (1/hz s), paused"},
        {", (comma)", "one step back (replays the record)"},
        {"R", "reset to t = 0, keeping the values set"},
        {"F5", "reload the script from its file (saving it does too)"},
        {"Ctrl+S", "screenshot of the window (PNG)"},
        {"Ctrl+E", "export the history (CSV)"},
        {"P", "projector mode: larger text, thicker lines"},
        {"D", "dark or light theme"},
        {"F11", "full screen"},
        {"F1", "this help"},
    };
    if (ImGui::BeginTable("keys", 2, ImGuiTableFlags_SizingFixedFit)) {
      for (const auto& row : keys) {
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(row[0]);
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(row[1]);
      }
      ImGui::EndTable();
    }
    ImGui::Separator();
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextUnformatted(
        "Mouse: drag a body to pull it with your hand; let go while it moves to give it a push. Drag a slider, or "
        "type an exact value in the box beside it and press Enter; the arrow resets it to the script's value. "
        "Drag the time bar to go back through the run: it is replayed exactly, and playing on from there repeats it "
        "until you change something.");
    ImGui::TextUnformatted(("Files are saved in " + std::filesystem::absolute(output_folder_).lexically_normal().string() +
                            ". Settings are kept in " + settings_folder() + ".")
                               .c_str());
    ImGui::PopTextWrapPos();
  }
  ImGui::End();
}

void Sandbox::open_script_popup() {
  if (open_popup_) {
    ImGui::OpenPopup("Open a lesson script");
    open_popup_ = false;
    open_error_.clear();
  }
  const float s = fonts_->scale;
  ImGui::SetNextWindowSize(ImVec2(640.0f * s, 0.0f), ImGuiCond_Appearing);
  if (!ImGui::BeginPopupModal("Open a lesson script", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
  ImGui::TextUnformatted("A .lua file (path from the folder FrictionLab was started in, or from /):");
  ImGui::SetNextItemWidth(560.0f * s);
  if (ImGui::IsWindowAppearing()) ImGui::SetKeyboardFocusHere();
  bool go = ImGui::InputText("##path", open_path_, sizeof open_path_, ImGuiInputTextFlags_EnterReturnsTrue);
  // Scripts in the current folder, one click each.
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(".", error)) {
    if (entry.path().extension() != ".lua") continue;
    const std::string name = entry.path().filename().string();
    if (ImGui::Selectable(name.c_str())) {
      std::snprintf(open_path_, sizeof open_path_, "%s", name.c_str());
      go = true;
    }
  }
  if (ImGui::Button("Open")) go = true;
  ImGui::SameLine();
  if (ImGui::Button("Cancel")) ImGui::CloseCurrentPopup();
  if (go) {
    open_error_ = open(open_path_);
    if (open_error_.empty()) ImGui::CloseCurrentPopup();
  }
  if (!open_error_.empty()) {
    ImGui::PushTextWrapPos(560.0f * s);
    ImGui::TextColored(ImGui::ColorConvertU32ToFloat4(theme(window_.theme).bad), "%s", open_error_.c_str());
    ImGui::PopTextWrapPos();
  }
  ImGui::EndPopup();
}

std::string Sandbox::open(const std::string& name_or_path) {
  try {
    auto next = std::make_unique<Playback>(lessons::resolve_lesson(name_or_path), std::map<std::string, std::string>{},
                                           playback_->lesson().settings());
    next->set_speed(playback_->speed());
    next->play();
    playback_ = std::move(next);
    control_errors_.clear();
    sliding_.reset();
    failed_script_.clear();
    return "";
  } catch (const InvalidInput& error) {
    return error.what();
  }
}

void Sandbox::try_failed_script(double wall_seconds) {
  if (failed_script_.empty()) return;
  since_failed_check_ += wall_seconds;
  if (since_failed_check_ < 0.25) return;
  since_failed_check_ = 0.0;
  const long long stamp = modified(failed_script_);
  if (stamp == failed_stamp_) return;
  failed_stamp_ = stamp;
  const std::string script = failed_script_;
  if (std::string error = open(script); !error.empty()) {
    failed_script_ = script;
    failed_error_ = error;
  }
}

std::optional<std::string> Sandbox::take_screenshot_request() {
  auto request = std::move(screenshot_request_);
  screenshot_request_.reset();
  return request;
}

void Sandbox::screenshot_done(const std::string& path, const std::string& error) {
  status_ = error.empty() ? "Screenshot saved to " + path : "Could not save the screenshot: " + error;
}

bool Sandbox::take_full_screen_toggle() {
  const bool toggle = full_screen_toggle_;
  full_screen_toggle_ = false;
  return toggle;
}

std::string Sandbox::unused_path(const std::string& stem, const std::string& extension) const {
  char time[32];
  std::snprintf(time, sizeof time, "_t%.2f", playback_->lesson().scene().time());
  const std::filesystem::path folder(output_folder_);
  std::filesystem::path path = folder / (stem + time + extension);
  // Never over an earlier file: a second screenshot at the same moment gets a number.
  for (int n = 2; std::filesystem::exists(path); ++n) path = folder / (stem + time + "_" + std::to_string(n) + extension);
  return path.string();
}

std::string Sandbox::export_history() {
  const lessons::Lesson& lesson = playback_->lesson();
  const Scene& scene = lesson.scene();
  std::ostringstream csv;
  csv.precision(9);
  csv << "t";
  for (const Probe& probe : scene.probes()) {
    const std::string& unit = lesson.probe_unit(probe.name);
    csv << ',' << probe.name << (unit.empty() ? "" : " (" + unit + ")");
  }
  csv << ",slipping\n";
  for (std::size_t i = 0; i < scene.times().size(); ++i) {
    csv << scene.times()[i];
    for (const Probe& probe : scene.probes()) csv << ',' << probe.history[i];
    csv << ',' << static_cast<int>(scene.slipping()[i]) << '\n';
  }
  const std::string path = unused_path(lesson_stem(lesson.path()) + "_history", ".csv");
  const std::string text = csv.str();
  write_whole_file(path, text.data(), text.size());
  return path;
}

}  // namespace frictionlab::ui
