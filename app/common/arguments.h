#pragma once
// The one command-line parser of `ydscope` and every `ydscope-cli` command, so both follow the
// same rules: "--name value" and "--name=value", flags without a value, "--" ends the options,
// -h/--help and -V/--version everywhere, a bounded number of positionals (anything beyond is an
// error, never ignored), and a near-miss option gets "did you mean --format?".
// Every mistake throws UsageError with one sentence; callers exit with status 2 for it.
#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace ydscope {

struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class Arguments {
 public:
  // value_options take a value; flags do not (names without the leading "--"). At most
  // max_positionals arguments that are not options are accepted.
  // `repeatable` value options may be given more than once (record --port A --port B); value()
  // gives the first, values() all in order. Any other option given twice is a mistake.
  Arguments(std::span<const std::string> args, std::set<std::string> value_options, std::set<std::string> flags,
            std::size_t max_positionals = 0, std::set<std::string> repeatable = {});

  bool help_requested() const { return help_; }
  bool version_requested() const { return version_; }
  bool has(const std::string& name) const;
  std::optional<std::string> value(const std::string& name) const;
  std::vector<std::string> values(const std::string& name) const;
  std::string required(const std::string& name) const;
  // Numeric values with a range check; the error names the option and the accepted range.
  std::optional<double> number(const std::string& name, double min, double max) const;
  std::optional<std::int64_t> integer(const std::string& name, std::int64_t min, std::int64_t max) const;
  const std::vector<std::string>& positionals() const { return positionals_; }
  // Exactly one positional (e.g. FILE); `what` names it in the error.
  std::string single_positional(const std::string& what) const;

 private:
  std::map<std::string, std::string> values_;
  std::map<std::string, std::vector<std::string>> repeated_;  // every value of a repeatable option
  std::set<std::string> flags_seen_;
  std::vector<std::string> positionals_;
  bool help_ = false;
  bool version_ = false;
};

// Whether args ask for help or the version before any "--": checked before a full parse, so a
// command's help works even next to a mistake.
bool asks_for_help(std::span<const std::string> args);
bool asks_for_version(std::span<const std::string> args);

// A file named on the command line that does not exist is a usage error (exit 2) in every
// command: "<what> '<path>' was not found; check the path". Other failures to read it are not.
void require_existing_file(const std::string& path, std::string_view what);

// The candidate a user most likely meant by `typed` (a misspelling within two edits, or an
// unambiguous prefix), or nothing when none is close.
std::optional<std::string> closest_match(std::string_view typed, std::span<const std::string> candidates);

}  // namespace ydscope
