#include "app/common/arguments.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <sstream>

namespace ydscope {

namespace {

constexpr std::string_view kEndOfOptions = "--";

bool is_help(std::string_view arg) { return arg == "--help" || arg == "-h"; }
bool is_version(std::string_view arg) { return arg == "--version" || arg == "-V"; }

// "-" is standard input and "-5" a number: both are values, not options.
bool looks_like_option(std::string_view arg) {
  return arg.size() > 1 && arg[0] == '-' && !(arg[1] >= '0' && arg[1] <= '9') && arg[1] != '.';
}

// Edits (insert, delete, substitute, swap two neighbours) turning a into b.
std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::vector<std::size_t>> d(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
  for (std::size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  }
  return d[a.size()][b.size()];
}

class OptionNames {
 public:
  OptionNames(const std::set<std::string>& value_options, const std::set<std::string>& flags) {
    names_.assign(value_options.begin(), value_options.end());
    names_.insert(names_.end(), flags.begin(), flags.end());
    names_.insert(names_.end(), {"help", "version"});
  }

  // "unknown option -p; did you mean --port?" -- or, with nothing close, where to look.
  [[noreturn]] void unknown(const std::string& arg, std::string_view name) const {
    std::string message = "unknown option " + arg + "; ";
    if (const auto guess = suggestion(arg, name))
      message += "did you mean --" + *guess + "?";
    else
      message += "see --help for the options";
    throw UsageError(message);
  }

  // A positional that is an option's name without its dashes.
  std::optional<std::string> option_named(std::string_view word) const {
    for (const auto& name : names_)
      if (name == word) return name;
    return std::nullopt;
  }

 private:
  std::optional<std::string> suggestion(const std::string& arg, std::string_view name) const {
    // A single letter (-p) is the long option of that initial, when only one has it.
    if (arg.size() == 2 && arg[0] == '-') {
      std::optional<std::string> only;
      bool several = false;
      for (const auto& candidate : names_) {
        if (candidate[0] != arg[1]) continue;
        several = only.has_value();
        if (several) break;
        only = candidate;
      }
      // -p is the port in the serial tools people come from, also beside --pose.
      if (several) return arg[1] == 'p' && option_named("port") ? std::optional<std::string>("port") : std::nullopt;
      return only;
    }
    return closest_match(name, names_);
  }

  std::vector<std::string> names_;
};

}  // namespace

Arguments::Arguments(std::span<const std::string> args, std::set<std::string> value_options,
                     std::set<std::string> flags, std::size_t max_positionals, std::set<std::string> repeatable) {
  const OptionNames names(value_options, flags);
  bool options_ended = false;
  const auto add_positional = [&](const std::string& arg) {
    if (positionals_.size() < max_positionals) {
      positionals_.push_back(arg);
      return;
    }
    std::string message = "unexpected argument '" + arg + "'";
    if (const auto option = names.option_named(arg))
      message += "; did you mean --" + *option + "?";
    else if (max_positionals == 0)
      message += ": this command takes only options (see --help)";
    else
      message += " after '" + positionals_.back() + "' (see --help)";
    throw UsageError(message);
  };
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    if (options_ended || !looks_like_option(arg)) {
      add_positional(arg);
      continue;
    }
    if (arg == kEndOfOptions) {
      options_ended = true;
    } else if (is_help(arg)) {
      help_ = true;
    } else if (is_version(arg)) {
      version_ = true;
    } else if (arg.rfind("--", 0) != 0) {
      names.unknown(arg, std::string_view(arg).substr(1));
    } else {
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
        if (values_.count(name) && !repeatable.count(name)) throw UsageError("option --" + name + " is given twice");
        std::string value;
        if (inline_value) {
          value = *inline_value;
        } else if (i + 1 < args.size() && !(looks_like_option(args[i + 1]) && args[i + 1].rfind("--", 0) == 0)) {
          value = args[++i];
        } else {
          throw UsageError("option --" + name + " needs a value (--" + name + " VALUE or --" + name + "=VALUE)");
        }
        values_.emplace(name, value);  // the first stays
        repeated_[name].push_back(std::move(value));
      } else {
        names.unknown(arg.substr(0, arg.find('=')), name);
      }
    }
  }
}

bool Arguments::has(const std::string& name) const { return flags_seen_.count(name) > 0 || values_.count(name) > 0; }

std::optional<std::string> Arguments::value(const std::string& name) const {
  const auto it = values_.find(name);
  if (it == values_.end()) return std::nullopt;
  return it->second;
}

std::vector<std::string> Arguments::values(const std::string& name) const {
  const auto it = repeated_.find(name);
  return it == repeated_.end() ? std::vector<std::string>{} : it->second;
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

bool asks_for_help(std::span<const std::string> args) {
  for (const auto& arg : args) {
    if (arg == kEndOfOptions) return false;
    if (is_help(arg)) return true;
  }
  return false;
}

bool asks_for_version(std::span<const std::string> args) {
  for (const auto& arg : args) {
    if (arg == kEndOfOptions) return false;
    if (is_version(arg)) return true;
  }
  return false;
}

void require_existing_file(const std::string& path, std::string_view what) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec) && !ec)
    throw UsageError(std::string(what) + " '" + path + "' was not found; check the path");
}

std::optional<std::string> closest_match(std::string_view typed, std::span<const std::string> candidates) {
  constexpr std::size_t kMostEdits = 2;
  std::optional<std::string> best;
  std::size_t best_distance = kMostEdits + 1;
  std::size_t at_best = 0;  // two equally close candidates: suggest neither
  for (const auto& candidate : candidates) {
    const bool prefix = !typed.empty() && candidate.rfind(typed, 0) == 0;
    const std::size_t distance = prefix ? 1 : edit_distance(typed, candidate);
    if (distance > kMostEdits || distance >= candidate.size()) continue;
    if (distance < best_distance) {
      best = candidate;
      best_distance = distance;
      at_best = 1;
    } else if (distance == best_distance) {
      ++at_best;
    }
  }
  if (at_best != 1) return std::nullopt;
  return best;
}

}  // namespace ydscope
