#include "app/cli/arguments.h"

#include <charconv>
#include <cmath>
#include <sstream>

namespace ydscope::cli {

Arguments::Arguments(std::span<const std::string> args, std::set<std::string> value_options,
                     std::set<std::string> flags) {
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    if (arg == "--help" || arg == "-h") {
      help_ = true;
      continue;
    }
    if (arg.rfind("--", 0) != 0 || arg == "-" ) {
      positionals_.push_back(arg);
      continue;
    }
    std::string name = arg.substr(2);
    std::optional<std::string> inline_value;
    if (const auto eq = name.find('='); eq != std::string::npos) {
      inline_value = name.substr(eq + 1);
      name = name.substr(0, eq);
    }
    if (flags.count(name)) {
      if (inline_value) throw UsageError("option --" + name + " takes no value");
      flags_seen_.insert(name);
    } else if (value_options.count(name)) {
      if (values_.count(name)) throw UsageError("option --" + name + " is given twice");
      if (inline_value) {
        values_[name] = *inline_value;
      } else if (i + 1 < args.size()) {
        values_[name] = args[++i];
      } else {
        throw UsageError("option --" + name + " needs a value");
      }
    } else {
      throw UsageError("unknown option --" + name + " (see --help)");
    }
  }
}

bool Arguments::has(const std::string& name) const {
  return flags_seen_.count(name) > 0 || values_.count(name) > 0;
}

std::optional<std::string> Arguments::value(const std::string& name) const {
  const auto it = values_.find(name);
  if (it == values_.end()) return std::nullopt;
  return it->second;
}

std::string Arguments::required(const std::string& name) const {
  auto v = value(name);
  if (!v) throw UsageError("missing required option --" + name + " (see --help)");
  return *v;
}

std::optional<double> Arguments::number(const std::string& name, double min, double max) const {
  const auto text = value(name);
  if (!text) return std::nullopt;
  double parsed = 0;
  const auto* end = text->data() + text->size();
  const auto [ptr, ec] = std::from_chars(text->data(), end, parsed);
  if (ec != std::errc() || ptr != end || !std::isfinite(parsed) || parsed < min || parsed > max) {
    std::ostringstream message;
    message << "--" << name << " must be a number from " << min << " to " << max << ", not '" << *text << "'";
    throw UsageError(message.str());
  }
  return parsed;
}

std::optional<std::int64_t> Arguments::integer(const std::string& name, std::int64_t min, std::int64_t max) const {
  const auto text = value(name);
  if (!text) return std::nullopt;
  std::int64_t parsed = 0;
  const auto* end = text->data() + text->size();
  const auto [ptr, ec] = std::from_chars(text->data(), end, parsed);
  if (ec != std::errc() || ptr != end || parsed < min || parsed > max) {
    throw UsageError("--" + name + " must be a whole number from " + std::to_string(min) + " to " +
                     std::to_string(max) + ", not '" + *text + "'");
  }
  return parsed;
}

std::string Arguments::single_positional(const std::string& what) const {
  if (positionals_.empty()) throw UsageError("missing " + what + " (see --help)");
  if (positionals_.size() > 1) throw UsageError("expected one " + what + ", got '" + positionals_[1] + "' as well");
  return positionals_.front();
}

}  // namespace ydscope::cli
