#include "app/gui/source_origin.h"

#include <algorithm>

namespace ydscope::gui {
namespace {

// The next space-separated word of `text`, which loses it and the spaces after it.
std::string_view next_word(std::string_view& text) {
  const std::size_t end = std::min(text.find(' '), text.size());
  const std::string_view word = text.substr(0, end);
  text.remove_prefix(end);
  while (!text.empty() && text.front() == ' ') text.remove_prefix(1);
  return word;
}

}  // namespace

std::string origin_of(const ui::ConnectRequest& request) {
  switch (request.kind) {
    case ui::ConnectRequest::Kind::Sim: return "sim " + request.model.value_or("G6") + " " + request.scene;
    case ui::ConnectRequest::Kind::Port: return "port " + request.model.value_or("detect") + " " + request.address;
    case ui::ConnectRequest::Kind::Replay: return {};
  }
  return {};
}

std::optional<SourceChoice> choice_from_origin(std::string_view origin) {
  const std::string_view kind = next_word(origin);
  const std::string_view model = next_word(origin);
  if (model.empty() || origin.empty()) return std::nullopt;
  SourceChoice choice;
  if (kind == "sim") {
    choice.kind = SourceKind::Sim;
    choice.model = std::string(model);
    choice.scene = std::string(next_word(origin));
    if (!origin.empty()) return std::nullopt;  // a scene is one word
  } else if (kind == "port") {
    choice.kind = SourceKind::Port;
    if (model != "detect") choice.model = std::string(model);
    choice.port = std::string(origin);  // the rest: an address may hold spaces
  } else {
    return std::nullopt;
  }
  return choice;
}

std::vector<SourceChoice> last_run_choices(const ui::ViewSettings& settings) {
  std::vector<SourceChoice> choices;
  for (const std::string& name : settings.last_sources) {
    const auto look = std::find_if(settings.sources.begin(), settings.sources.end(),
                                   [&](const ui::SourceLook& l) { return l.name == name; });
    if (look == settings.sources.end()) continue;
    auto choice = choice_from_origin(look->origin);
    if (!choice) continue;
    choice->name = look->name;
    choice->pose = look->pose;
    choices.push_back(std::move(*choice));
  }
  if (choices.size() < 2) choices.clear();
  return choices;
}

}  // namespace ydscope::gui
