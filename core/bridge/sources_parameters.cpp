#include "core/bridge/sources_parameters.h"

#include "core/bridge/foxglove_protocol.h"

namespace ydscope::foxglove {

std::vector<Parameter> SourcesParameters::current() {
  std::vector<Parameter> out;
  for (const auto& [name, parameters] : sources_)
    for (Parameter p : parameters->current()) out.push_back({source_parameter_name(name, p.name), p.value});
  return out;
}

void SourcesParameters::set(const Parameter& parameter, SetDone done) {
  const std::size_t slash = parameter.name.find('/');
  for (const auto& [name, parameters] : sources_) {
    if (slash != name.size() || parameter.name.compare(0, slash, name) != 0) continue;
    return parameters->set({parameter.name.substr(slash + 1), parameter.value},
                           [name = name, done](std::vector<Parameter> read_back, std::string error) {
                             for (Parameter& p : read_back) p.name = source_parameter_name(name, p.name);
                             done(std::move(read_back), std::move(error));
                           });
  }
  std::string names;
  for (const auto& source : sources_) names += (names.empty() ? "" : ", ") + source.first;
  done({}, "there is no parameter " + quoted_client_text(parameter.name) +
               "; this server's are NAME/scan_hz and the like for " + names);
}

}  // namespace ydscope::foxglove
