#pragma once
// What the user is typing or choosing in the panels, kept between frames: an address not yet
// connected to, a model picked for the next virtual lidar, a frequency on its slider. It belongs
// to the panels (each source has its own, beside its view model), not to the view model the app
// fills from measurements; the app only prefills a few fields with what runs (the port it
// started, the last replay file) and clears the sector field once a sector is watched.
#include "core/sim/faults.h"
#include "ui/view/history/plot_window.h"
#include "ui/view/history/run_plots.h"

namespace ydscope::ui {

struct PanelEdits {
  char port_text[256] = "";
  int port_model_choice = 0;  // 0 = detect, then model_names() order
  int port_baud_choice = 0;   // 0 = model default
  int sim_model_choice = 2;   // 1-based in all_profiles(): G6
  int sim_scene_choice = 1;   // demo
  FaultConfig sim_faults;
  int sim_host_choice = 0;       // 0 manual, 1 YDLidar-SDK
  int sim_firmware[2] = {1, 2};  // major, minor
  int sim_delivery_choice = 0;   // 0 whole, 1 USB bursts, 2 random splits
  int sim_burst_bytes = 64;
  int sim_burst_interval_us = 1000;
  int sim_random_max = 17;
  char replay_text[512] = "";
  int replay_model_choice = 0;  // 0 = as the recording says, then model_names() order
  char record_text[512] = "";
  int record_format = 0;  // RecordFormat (ui/view/export/file_names.h)
  char sector_text[64] = "";
  float scan_target_hz = 10.0f;
  bool distance_scale_override = false;
  float distance_scale_value = 1.0f;
  int add_source_kind = 0;            // the Sources panel's "add": 0 virtual lidar, 1 port, 2 recording
  int add_source_model_choice = 2;    // 1-based in all_profiles(): G6
  int add_source_scene_choice = 1;    // demo
  char add_source_address[512] = "";  // the port, tcp:// address or recording to add
  // The Sources panel's "click straight ahead": the view's next left click sets this source's yaw.
  bool forward_click_armed = false;
  // The Plots panel's time window (zoom, pause) and, while paused, the plots as they were then.
  PlotWindow plot_window;
  RunPlots paused_plots;
};

}  // namespace ydscope::ui
