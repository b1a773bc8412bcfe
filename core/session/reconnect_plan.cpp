#include "core/session/reconnect_plan.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "core/link/link_address.h"

namespace ydscope {

ReconnectPlan::ReconnectPlan(const SessionConfig& config)
    : first_(config.first_backoff), max_(config.max_backoff), delay_(config.first_backoff) {
  if (config.open_link) return;  // a test's or a benchmark's own link: nothing to watch, no TCP cap
  std::string ignored;
  const auto address = parse_link_address(config.address, ignored);
  if (address && address->kind == LinkAddress::Kind::Serial)
    watched_path_ = address->path;
  else
    max_ = std::min(max_, kMaxTcpBackoff);
}

bool ReconnectPlan::hopeless() const {
  if (!watched_path_) return false;
  std::error_code ec;
  const auto status = std::filesystem::status(*watched_path_, ec);  // follows links, as open does
  return !ec && std::filesystem::exists(status) && !std::filesystem::is_character_file(status);
}

std::string ReconnectPlan::retry_text(bool watching) const {
  char seconds[16];
  std::snprintf(seconds, sizeof seconds, "%.2g s", static_cast<double>(delay_.count()) / 1000.0);
  if (watching && watched_path_) return "; retrying when " + *watched_path_ + " comes back, or in " + seconds;
  return std::string("; retrying in ") + seconds;
}

}  // namespace ydscope
