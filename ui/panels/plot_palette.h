#pragma once
// The Plots panel's colours in one place: the plot widget's own (time_plot.cpp) and the series the
// panel draws on it (plots_panel.cpp), so a change of one is made beside the others it must suit.
#include <imgui.h>

namespace ydscope::ui::plot_palette {

// The plot: its frame, grid lines, tick labels and the cursor's line.
inline constexpr ImU32 kFrame = IM_COL32(22, 26, 34, 255);
inline constexpr ImU32 kGrid = IM_COL32(70, 78, 92, 110);
inline constexpr ImU32 kTickText = IM_COL32(150, 158, 172, 255);
inline constexpr ImU32 kCursor = IM_COL32(230, 232, 240, 150);

// The series: measured against set scan rate, one-colour values, and the two error counts.
inline constexpr ImU32 kMeasured = IM_COL32(110, 160, 255, 255);
inline constexpr ImU32 kSet = IM_COL32(90, 210, 120, 220);
inline constexpr ImU32 kValue = IM_COL32(150, 180, 235, 255);
inline constexpr ImU32 kChecksum = IM_COL32(255, 153, 89, 255);
inline constexpr ImU32 kCrc8 = IM_COL32(235, 110, 200, 255);

}  // namespace ydscope::ui::plot_palette
