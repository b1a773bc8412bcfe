#include "core/bridge/session_parameters.h"

#include <algorithm>
#include <cmath>

#include "core/bridge/foxglove_protocol.h"

namespace ydscope::foxglove {
namespace {

std::optional<double> number_of(const Parameter& p) {
  if (const double* d = std::get_if<double>(&p.value)) return *d;
  return std::nullopt;
}

std::optional<bool> boolean_of(const Parameter& p) {
  if (const bool* b = std::get_if<bool>(&p.value)) return *b;
  if (const double* d = std::get_if<double>(&p.value)) return *d != 0;
  return std::nullopt;
}

}  // namespace

std::vector<Parameter> SessionParameters::current() { return values_of(session_.snapshot()); }

std::vector<Parameter> SessionParameters::values_of(const SessionSnapshot& s) const {
  std::vector<Parameter> out;
  if (s.scan_hz) out.push_back({"scan_hz", *s.scan_hz});
  if (s.ranging_khz) out.push_back({"ranging_khz", static_cast<double>(*s.ranging_khz)});
  if (s.power_down_protection) out.push_back({"power_down_protection", *s.power_down_protection});
  out.push_back({"filter_specular", specular_.load()});
  out.push_back({"filter_ambient", ambient_.load()});
  return out;
}

std::vector<Parameter> SessionParameters::updates(const SessionSnapshot& s) {
  if (s.state != LinkState::Scanning && s.state != LinkState::Ready) return {};
  std::vector<Parameter> now = values_of(s);
  std::lock_guard lock(told_mutex_);
  if (told_connection_ != s.counters.reconnects) {
    told_connection_ = s.counters.reconnects;
    told_ = now;
    return now;
  }
  std::vector<Parameter> changed;
  for (const Parameter& p : now) {
    const auto was = std::find_if(told_.begin(), told_.end(), [&](const Parameter& t) { return t.name == p.name; });
    if (was == told_.end() || was->value != p.value) changed.push_back(p);
  }
  told_ = std::move(now);
  return changed;
}

void SessionParameters::told(const std::vector<Parameter>& values) {
  std::lock_guard lock(told_mutex_);
  for (const Parameter& p : values) {
    const auto was = std::find_if(told_.begin(), told_.end(), [&](const Parameter& t) { return t.name == p.name; });
    if (was != told_.end()) was->value = p.value;
  }
}

void SessionParameters::set(const Parameter& parameter, SetDone done) {
  // Whatever the clients are told here is known to them.
  done = [this, done = std::move(done)](std::vector<Parameter> read_back, std::string error) {
    told(read_back);
    done(std::move(read_back), std::move(error));
  };
  const auto fail = [&](const std::string& why) {
    // The unchanged value is the read-back, so the client's view snaps back.
    std::vector<Parameter> now;
    for (auto& p : current())
      if (p.name == parameter.name) now.push_back(std::move(p));
    done(std::move(now), why);
  };
  if (parameter.name == "filter_specular" || parameter.name == "filter_ambient") {
    const auto on = boolean_of(parameter);
    if (!on) return fail("it takes true or false");
    (parameter.name == "filter_specular" ? specular_ : ambient_).store(*on);
    return done({{parameter.name, *on}}, "");
  }
  if (parameter.name == "scan_hz" || parameter.name == "ranging_khz") {
    const auto value = number_of(parameter);
    if (!value || !std::isfinite(*value)) return fail("it takes a number");
    const std::string name = parameter.name;
    auto on_result = [this, name, done](const CommandResult& r) {
      std::vector<Parameter> read_back;
      if (r.scan_hz) read_back.push_back({"scan_hz", *r.scan_hz});
      if (r.ranging_khz) read_back.push_back({"ranging_khz", static_cast<double>(*r.ranging_khz)});
      if (read_back.empty())
        for (auto& p : current())
          if (p.name == name) read_back.push_back(std::move(p));
      done(std::move(read_back), r.ok ? "" : r.message);
    };
    if (name == "scan_hz") return session_.set_scan_hz(*value, on_result);
    if (*value < 0 || *value > 65535) return fail("it takes a frequency in kHz, e.g. 18");
    return session_.set_ranging_khz(static_cast<std::uint16_t>(std::lround(*value)), on_result);
  }
  if (parameter.name == "power_down_protection") {
    const auto on = boolean_of(parameter);
    if (!on) return fail("it takes true or false");
    return session_.set_power_down_protection(*on, [done](const CommandResult& r) {
      std::vector<Parameter> read_back;
      if (r.power_down_protection) read_back.push_back({"power_down_protection", *r.power_down_protection});
      done(std::move(read_back), r.ok ? "" : r.message);
    });
  }
  // Quoted short: a client's 64 KiB name must not come back whole.
  done({}, "there is no parameter " + quoted_client_text(parameter.name) +
               "; this server has scan_hz, ranging_khz, power_down_protection, filter_specular and filter_ambient");
}

}  // namespace ydscope::foxglove
