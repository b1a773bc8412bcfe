#pragma once
// The ImGui panels of the sidebar. Each draws one collapsing section; draw_sidebar lays them out.
#include <optional>

#include <imgui.h>

#include "ui/panels/panel_edits.h"
#include "ui/panels/ui_model.h"

namespace ydscope::ui {

void draw_connection_panel(UiModel& model, PanelEdits& edits);
void draw_device_panel(UiModel& model, PanelEdits& edits);
void draw_health_panel(UiModel& model);
// The Health section's header, which also says a blocked sector (blockage_panel.cpp); true when open.
bool draw_health_header(const UiModel& model);
void draw_frequency_panels(UiModel& model, PanelEdits& edits);
// Run check (check_panel.cpp): the button, on the Device panel's last line, and below the Device
// panel its progress, then its verdict.
void draw_run_check_button(UiModel& model);
void draw_check_panel(const UiModel& model);
void draw_view_panel(UiModel& model, ViewSettings& settings);
void draw_filter_panel(UiModel& model, ViewSettings& settings);
void draw_stats_panel(const UiModel& model);
void draw_plots_panel(const UiModel& model, PanelEdits& edits);
void draw_sectors_panel(UiModel& model, PanelEdits& edits);
void draw_zones_panel(UiModel& model, ViewSettings& settings);
// Several sources: the selector over the tabs (which source the panels show and command), and the
// Sources tab (the list, hide/pause, pose, add and remove).
void draw_source_selector(UiModel& model);
void draw_sources_panel(UiModel& model, PanelEdits& edits);
// Several sources: a line per source over the view, its colour and its state in words.
void draw_source_legend(const UiModel& model, float view_left, float view_width);
// Where that legend's box ends, from the view's top (0 with one source): what else sits at the
// top of the view goes below it, so no source's state is hidden.
float source_legend_bottom(const UiModel& model);
// One source's legend line at `top_left` (a tile of the split view); `selected` rings its swatch.
void draw_source_label(const SourceRow& row, ImVec2 top_left, bool selected);

// The colour legend in a dark box with its bottom-right corner at `bottom_right`, in type `px`
// high (the booth view's, or twice the window's font so its words read at the window's size).
void draw_colour_legend(ImDrawList* draw, ImFont* font, const ColourLegend& legend, float px, ImVec2 bottom_right,
                        float bar_width);

// The windowed view's legend for the colour mode in use, at the view's bottom-right corner above
// the status line (the booth view draws the same legend in its large type).
void draw_window_legend(const ColourLegend& legend, float view_left, float view_width, float view_height);

// The whole left sidebar (full window height): it shows `model` and keeps what the user types or
// picks in `edits`. Returns its width in pixels so the polar view can use the rest of the window.
float draw_sidebar(UiModel& model, PanelEdits& edits, ViewSettings& settings);

// Status line over the polar view: model, state, measured rate, health alert, badges, banner.
void draw_view_header(const UiModel& model, float view_left, float view_width);
// The height at the bottom of the view that the status line takes (grid labels keep out).
float status_band_height();
// The booth view (full screen): model, state and rates in large type, and the colour legend.
void draw_booth_overlay(const UiModel& model, float view_left, float view_width, float view_height);
// When model.view_state says the picture is not live: dim the view and say why in large type.
void draw_view_overlay(const UiModel& model, float view_left, float view_width, float view_height,
                       float view_top = 0.0f);

// While it lives, a panel's values are drawn greyed under "last seen 10 s ago" if the source's
// newest lap is stale (UiModel::stale_for_s); live, it draws nothing and changes nothing.
class StaleValues {
 public:
  explicit StaleValues(const UiModel& model);
  ~StaleValues();
  StaleValues(const StaleValues&) = delete;
  StaleValues& operator=(const StaleValues&) = delete;
  bool stale() const { return age_s_.has_value(); }
  // A colour a value would be drawn in when live; grey once stale.
  ImVec4 colour(const ImVec4& live) const;

 private:
  std::optional<double> age_s_;
};

// Small helpers shared by the panels.
// The colour of words of this severity over the view: green, blue, amber, red.
ImU32 severity_colour(Severity severity);
void help_marker(const char* text);
// Text wrapped at the panel edge, unformatted (this ImGui build drops some TextWrapped("%s") text).
void wrapped_text(const char* text);
// A dim title over a thin rule (ImGui 1.86 has no SeparatorText).
void section(const char* title);
void link_state_text(LinkState state, const char* message);
// A session callback that files the command's outcome under `control` (the app passes it with the
// request), and the line beside that control which shows it (a spinner while it runs, then the
// outcome for a few seconds).
CommandCallback track_command(UiModel& model, CommandControl control);
void command_feedback_line(UiModel& model, CommandControl control);
// A combo of the models, 1-based in all_profiles(); `none` names choice 0 ("detect"), or null
// when a model must be chosen. True when the choice changed.
bool model_combo(const char* label, int& choice, const char* none);

}  // namespace ydscope::ui
