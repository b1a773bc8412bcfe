#pragma once
// The recent past of one measured quantity for the Plots panel: a fixed ring of samples, allocated
// once, read oldest first through ImGui's ring-buffer offset (PlotLines' values_offset).
#include <cstddef>
#include <optional>
#include <vector>

namespace ydscope::ui {

class MetricHistory {
 public:
  explicit MetricHistory(std::size_t capacity = 300);

  void add(float value);
  void clear();

  // size() samples from data(); the oldest sits at offset() and they wrap around the end.
  const float* data() const { return values_.data(); }
  std::size_t size() const { return count_; }
  std::size_t offset() const { return count_ < values_.size() ? 0 : next_; }
  // Sample i, oldest first (i < size()).
  float at(std::size_t i) const { return values_[(offset() + i) % values_.size()]; }
  std::optional<float> last() const;
  // Over the samples held; 0 when there are none.
  float min() const;
  float max() const;

 private:
  std::vector<float> values_;
  std::size_t next_ = 0;
  std::size_t count_ = 0;
};

}  // namespace ydscope::ui
