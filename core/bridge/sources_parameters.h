#pragma once
// The parameters of several shared lidars: each lidar's own (SessionParameters) under its name,
// "front/scan_hz", "back/filter_ambient", each forwarded to that lidar's session.
#include <string>
#include <utility>
#include <vector>

#include "core/bridge/foxglove_server.h"
#include "core/bridge/session_parameters.h"

namespace ydscope::foxglove {

// "front/scan_hz": one of several lidars' parameter, as its clients see it.
inline std::string source_parameter_name(const std::string& source, const std::string& name) {
  return source + "/" + name;
}

class SourcesParameters final : public ParameterBackend {
 public:
  // `parameters` must outlive this.
  void add(std::string name, SessionParameters* parameters) { sources_.emplace_back(std::move(name), parameters); }
  std::vector<Parameter> current() override;
  // A name without a lidar's "NAME/" in front, or an unknown NAME, is refused with a sentence
  // naming the lidars.
  void set(const Parameter& parameter, SetDone done) override;

 private:
  std::vector<std::pair<std::string, SessionParameters*>> sources_;
};

}  // namespace ydscope::foxglove
