#pragma once
// The `--key value` options of the hand-run benchmarks, written once: each program names its keys
// with a line of help, `--help` lists them with their defaults, and an unknown key, a missing
// value or a value that is not a number ends the program with one sentence (exit 2) before it
// starts anything that takes minutes.
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <string>
#include <vector>

namespace ydscope::bench {

class BenchOptions {
 public:
  BenchOptions(std::string program, std::string summary) : program_(std::move(program)), summary_(std::move(summary)) {}

  BenchOptions& add(const std::string& key, double& value, const std::string& help) {
    return add_key(key, help, format_number(value),
                   [&value](const std::string& text) { return parse_number(text, value); });
  }
  BenchOptions& add(const std::string& key, int& value, const std::string& help) {
    return add_key(key, help, std::to_string(value), [&value](const std::string& text) {
      double number = 0;
      if (!parse_number(text, number) || number != static_cast<int>(number)) return false;
      value = static_cast<int>(number);
      return true;
    });
  }
  BenchOptions& add(const std::string& key, std::string& value, const std::string& help) {
    return add_key(key, help, value.empty() ? "none" : value, [&value](const std::string& text) {
      value = text;
      return true;
    });
  }

  // Sets the values named on the command line; exits on `--help` (0) or a mistake (2).
  void parse(int argc, char** argv) const {
    for (int i = 1; i < argc; ++i) {
      const std::string key = argv[i];
      if (key == "--help" || key == "-h") {
        print_usage(stdout);
        std::exit(0);
      }
      const Key* known = find(key);
      if (!known) fail("does not know the option '" + key + "'");
      if (i + 1 >= argc) fail("needs a value after " + key);
      if (!known->set(argv[++i])) fail("needs a number after " + key + ", not '" + argv[i] + "'");
    }
  }

  // For checks of a value's range after parse(): one sentence and exit 2.
  [[noreturn]] void fail(const std::string& what) const {
    std::fprintf(stderr, "%s %s; try %s --help.\n", program_.c_str(), what.c_str(), program_.c_str());
    std::exit(2);
  }

 private:
  struct Key {
    std::string name, help, default_text;
    std::function<bool(const std::string&)> set;
  };

  BenchOptions& add_key(const std::string& key, const std::string& help, const std::string& default_text,
                        std::function<bool(const std::string&)> set) {
    keys_.push_back({key, help, default_text, std::move(set)});
    return *this;
  }
  const Key* find(const std::string& name) const {
    for (const Key& key : keys_)
      if (key.name == name) return &key;
    return nullptr;
  }
  void print_usage(std::FILE* out) const {
    std::fprintf(out, "%s: %s\noptions:\n", program_.c_str(), summary_.c_str());
    for (const Key& key : keys_)
      std::fprintf(out, "  %-12s %s (default %s)\n", key.name.c_str(), key.help.c_str(), key.default_text.c_str());
  }
  static bool parse_number(const std::string& text, double& value) {
    char* end = nullptr;
    const double number = std::strtod(text.c_str(), &end);
    if (text.empty() || *end != '\0') return false;
    value = number;
    return true;
  }
  static std::string format_number(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", value);
    return text;
  }

  std::string program_, summary_;
  std::vector<Key> keys_;
};

// The scenes `ydscope-cli sim --scene` knows, as the app benches take them.
inline bool is_sim_scene(const std::string& scene) { return scene == "demo" || scene == "room" || scene == "booth"; }

}  // namespace ydscope::bench
