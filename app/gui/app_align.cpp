// App, aligning its lidars: Align matches each against the first from the walls they share, and
// the answer waits in the Sources tab; Apply sets the poses found, Discard leaves every pose.
#include <vector>

#include "app/gui/app.h"
#include "ui/view/scene/source_alignment.h"

namespace ydscope::gui {

void App::change_sources(const ui::AlignSources&) {
  std::vector<std::vector<Lap>> laps(sources_.size());
  for (std::size_t i = 0; i < sources_.size(); ++i) {
    const ui::LapHistory& recent = sources_[i].recent_laps;
    for (std::size_t age = 0; age < recent.size(); ++age) {
      Lap lap;
      lap.points = recent.at_age(age).points;
      laps[i].push_back(std::move(lap));
    }
  }
  const std::vector<ui::SourceLook> looks = sources_.looks();
  alignment_ = ui::propose_alignment(laps, looks);
}

void App::change_sources(const ui::AnswerAlignment& request) {
  if (request.apply && alignment_) {
    if (alignment_->rows.size() != sources_.size()) {
      model().status_message = "the lidars changed since Align; nothing was moved, align again";
    } else {
      for (std::size_t i = 0; i < sources_.size(); ++i)
        if (alignment_->rows[i].pose) sources_[i].look.pose = *alignment_->rows[i].pose;
      stage_.view().invalidate();
      model().status_message = "aligned poses applied";
    }
  }
  alignment_.reset();
}

}  // namespace ydscope::gui
