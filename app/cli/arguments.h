#pragma once
// A small, strict option parser shared by every subcommand: "--name value", "--name=value",
// boolean flags and positionals. Mistakes throw UsageError with a sentence for the user.
#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

namespace ydscope::cli {

struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class Arguments {
 public:
  // value_options take a value; flags do not. Anything else starting with "--" is a usage error.
  Arguments(std::span<const std::string> args, std::set<std::string> value_options,
            std::set<std::string> flags);

  bool help_requested() const { return help_; }
  bool has(const std::string& name) const;
  std::optional<std::string> value(const std::string& name) const;
  std::string required(const std::string& name) const;
  // Numeric values with a range check; the error names the option and the accepted range.
  std::optional<double> number(const std::string& name, double min, double max) const;
  std::optional<std::int64_t> integer(const std::string& name, std::int64_t min, std::int64_t max) const;
  const std::vector<std::string>& positionals() const { return positionals_; }
  // Exactly one positional (e.g. FILE); `what` names it in the error.
  std::string single_positional(const std::string& what) const;

 private:
  std::map<std::string, std::string> values_;
  std::set<std::string> flags_seen_;
  std::vector<std::string> positionals_;
  bool help_ = false;
};

}  // namespace ydscope::cli
