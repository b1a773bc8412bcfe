#include "app/common/check_report.h"

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <stdexcept>

#include "app/common/svg_charts.h"
#include "core/analysis/text_format.h"
#include "core/version.h"

namespace ydscope {

namespace {

// Print-friendly, readable on a phone, no web fonts: the file must look right offline forever.
constexpr const char* kStyle = R"(
body{font-family:sans-serif;color:#1f2933;max-width:980px;margin:24px auto;padding:0 16px;line-height:1.4}
h1{font-size:1.6em;margin:0 0 4px} h2{font-size:1.15em;margin:28px 0 8px}
.verdict{display:inline-block;padding:4px 14px;border-radius:6px;color:#fff;font-weight:bold;font-size:1.1em}
.pass{background:#2e7d32} .fail{background:#c62828} .incomplete{background:#6b7280}
.note{background:#fff4e5;border-left:4px solid #ef6c00;padding:8px 12px;margin:12px 0}
table{border-collapse:collapse;width:100%} th,td{text-align:left;padding:6px 10px;border-bottom:1px solid #d9dee3}
th{background:#f3f5f7} td.v{font-weight:bold} td.v.pass{color:#2e7d32;background:none} td.v.fail{color:#c62828;background:none}
dl{display:grid;grid-template-columns:max-content 1fr;gap:2px 16px;margin:0} dt{color:#52606d}
.charts svg{width:100%;height:auto;border:1px solid #d9dee3;border-radius:4px;margin:6px 0}
.polar svg{max-width:480px}
footer{margin-top:32px;color:#52606d;font-size:.85em}
)";

std::string field(std::string_view name, std::string_view value) {
  return "<dt>" + markup_escaped(name) + "</dt><dd>" + markup_escaped(value) + "</dd>";
}

std::string identity_block(const CheckRecord& record) {
  const SessionSnapshot& s = record.started;
  const ModelProfile* profile = record.observations.profile;
  std::string html = "<dl>";
  html += field("model", profile ? std::string(profile->name) : "unknown");
  if (s.device) {
    html += field("serial", s.device->serial);
    html +=
        field("firmware", std::to_string(s.device->firmware.major) + "." + std::to_string(s.device->firmware.minor));
    html += field("hardware", std::to_string(s.device->hardware));
  }
  html += field("link", s.link);
  html += field("started", utc_text(record.started_unix_s, "%Y-%m-%d %H:%M:%S UTC"));
  html += field("measured", format_text("%.1f s, %llu laps", record.measured_seconds,
                                        static_cast<unsigned long long>(record.observations.timing.laps)));
  if (record.observations.ranging_khz)
    html += field("ranging frequency", std::to_string(record.observations.ranging_khz) + " kHz");
  if (const UnitConventions* c = record.observations.conventions)
    html += field("conventions", std::string(c->id) + " — " + std::string(c->label) +
                                     format_text(", %g mm per count", s.distance_scale));
  if (record.observations.sector_name) html += field("sector", *record.observations.sector_name + " degrees");
  if (record.observations.target_mm) html += field("target", format_text("%.0f mm", *record.observations.target_mm));
  const std::size_t gaps = record.observations.timing.gaps.size();
  html += field("interruptions", gaps == 0 ? std::string("none")
                                           : format_text("%zu, listed under the scan rate and left out of the per-lap "
                                                         "figures",
                                                         gaps));
  const CheckContext& c = record.context;
  if (!c.operator_name.empty()) html += field("operator", c.operator_name);
  if (!c.station.empty()) html += field("station", c.station);
  html += field("ydscope", kVersion);
  if (!c.command_line.empty()) html += field("command", c.command_line);
  return html + "</dl>";
}

std::string criteria_table(const CheckRecord& record) {
  std::string html = R"(<table id="criteria"><thead><tr><th>verdict</th><th>criterion</th><th>measured</th>)"
                     R"(<th>limit</th></tr></thead><tbody>)";
  for (const CriterionResult& r : record.results) {
    const bool pass = r.verdict == Verdict::Pass;
    html += format_text(R"(<tr data-id="%s"><td class="v %s">%s</td><td>%s</td><td>%s</td><td>%s</td></tr>)",
                        markup_escaped(r.id).c_str(), pass ? "pass" : "fail", pass ? "PASS" : "FAIL",
                        markup_escaped(r.title).c_str(), markup_escaped(r.measured).c_str(),
                        markup_escaped(r.limit).c_str());
  }
  return html + "</tbody></table>";
}

std::string charts(const CheckRecord& record) {
  const CheckObservations& o = record.observations;
  std::string html = R"(<section class="charts"><h2>Scan rate</h2>)";
  html += svg_scan_rate_chart(o.timing.series, o.timing.gaps, record.limits.scan_hz_target,
                              record.limits.scan_hz_tolerance_pct);
  if (!o.timing.gaps.empty()) {
    html += format_text(R"(<p class="note">%zu interruption%s, shaded red above and left out of the per-lap )"
                        R"(figures:</p><ul id="gaps">)",
                        o.timing.gaps.size(), o.timing.gaps.size() == 1 ? "" : "s");
    for (const TimingGap& gap : o.timing.gaps) html += "<li>" + markup_escaped(describe_timing_gap(gap)) + "</li>";
    html += "</ul>";
  }
  if (record.sector) {
    const SectorStatistics& s = *record.sector;
    html += "<h2>Sector " + markup_escaped(o.sector_name.value_or("")) + "</h2>";
    std::optional<TargetMark> target;
    if (o.target_mm) {
      const double tolerance = record.limits.bias_tolerance_mm.value_or(default_bias_tolerance_mm(*o.target_mm));
      target = TargetMark{*o.target_mm, tolerance,
                          format_text("target %.0f mm ± %.1f mm (range bias limit)", *o.target_mm, tolerance)};
    }
    html += svg_histogram_chart(s.histogram, "range (mm)", target);
    html += svg_valid_share_chart(s.valid_share_by_angle, record.sector_region ? record.sector_region->from_deg : 0,
                                  s.angle_bin_deg, record.limits.min_sector_valid_share);
  }
  html += R"(</section><section class="polar"><h2>The last lap, from above</h2>)";
  html += svg_polar_snapshot(record.last_lap, record.sector_region);
  return html + "</section>";
}

}  // namespace

std::string check_report_html(const CheckRecord& record) {
  const CheckOutcome outcome = check_outcome(record);
  const char* style = outcome_word(outcome);
  const char* word = outcome == CheckOutcome::Incomplete ? "INCOMPLETE"
                     : outcome == CheckOutcome::Pass     ? "PASS"
                                                         : "FAIL";
  const ModelProfile* profile = record.observations.profile;
  const std::string unit = (profile ? std::string(profile->name) : "lidar") +
                           (record.started.device ? " " + record.started.device->serial : std::string());
  std::string html =
      "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"/>"
      "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\"/>";
  html += "<title>ydscope check: " + markup_escaped(unit) + " " + word + "</title>";
  html += "<style>" + std::string(kStyle) + "</style></head><body>";
  html += "<h1>Acceptance check of " + markup_escaped(unit) + "</h1>";
  std::string failed;
  for (const CriterionResult& r : record.results)
    if (r.verdict == Verdict::Fail) failed += (failed.empty() ? "" : ", ") + r.title;
  const std::string why =
      failed.empty() ? format_text("all %zu criteria passed", record.results.size()) : "failed: " + failed;
  html += format_text(R"(<p><span class="verdict %s" id="verdict">%s</span> %s</p>)", style, word,
                      markup_escaped(why).c_str());
  if (record.interrupted)
    html += format_text(R"(<p class="note">Interrupted after %.1f s: the verdict covers only that time.</p>)",
                        record.measured_seconds);
  if (!record.failure.empty())
    html += R"(<p class="note">The run stopped early: )" + markup_escaped(record.failure) + "</p>";
  html += identity_block(record);
  html += "<h2>Criteria</h2>" + criteria_table(record);
  html += charts(record);
  html += "<footer>Written by ydscope " + std::string(kVersion) +
          ". Limits and where they come from: docs/check.md, \"Acceptance limits\".</footer></body></html>\n";
  return html;
}

std::string report_output_problem(const std::string& path) {
  struct stat info {};
  if (::stat(path.c_str(), &info) == 0 && S_ISDIR(info.st_mode))
    return "--report " + path + " is a folder; give a file name such as " +
           (std::filesystem::path(path) / "check.html").string();
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  const std::string folder = parent.empty() ? "." : parent.string();
  if (::stat(folder.c_str(), &info) != 0 || !S_ISDIR(info.st_mode))
    return "--report " + path + ": the folder " + folder + " does not exist; create it or choose another";
  if (::access(folder.c_str(), W_OK) != 0)
    return "--report " + path + ": the folder " + folder + " is not writable; choose a folder you can write to";
  return {};
}

std::string reports_folder_problem(const std::string& folder) {
  std::error_code ec;
  if (!std::filesystem::is_directory(folder, ec))
    return "--reports " + folder + ": there is no such folder; create it or choose another";
  if (::access(folder.c_str(), W_OK) != 0)
    return "--reports " + folder + ": the folder is not writable; choose one you can write to";
  return {};
}

std::string utc_text(std::int64_t unix_s, const char* format) {
  const std::time_t t = static_cast<std::time_t>(unix_s);
  std::tm tm{};
  gmtime_r(&t, &tm);
  char text[64];
  return std::strftime(text, sizeof text, format, &tm) > 0 ? text : "";
}

std::string check_report_path(const std::string& folder, const CheckRecord& record) {
  std::string serial = record.started.device ? record.started.device->serial : std::string();
  for (char& c : serial)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_') c = '_';
  if (serial.empty()) serial = "no-serial";
  const std::filesystem::path base =
      std::filesystem::path(folder) / (serial + "-" + utc_text(record.started_unix_s, "%Y%m%d-%H%M%S"));
  std::string path = base.string() + ".html";
  std::error_code ec;
  for (int n = 2; std::filesystem::exists(path, ec); ++n) path = base.string() + "-" + std::to_string(n) + ".html";
  return path;
}

void write_check_report(const std::string& path, const CheckRecord& record) {
  const std::string html = check_report_html(record);
  struct stat info {};
  if (::stat(path.c_str(), &info) == 0 && !S_ISREG(info.st_mode)) {  // /dev/stdout, a pipe: no rename
    std::FILE* stream = std::fopen(path.c_str(), "wb");
    const bool ok = stream && std::fwrite(html.data(), 1, html.size(), stream) == html.size();
    if (stream && std::fclose(stream) == 0 && ok) return;
    throw std::runtime_error("could not write the report to " + path + ": " + std::strerror(errno ? errno : EIO));
  }
  const std::string partial = path + ".partial";
  std::FILE* file = std::fopen(partial.c_str(), "wb");
  bool ok = file && std::fwrite(html.data(), 1, html.size(), file) == html.size();
  const int error = errno;
  if (file && std::fclose(file) != 0) ok = false;
  if (ok && std::rename(partial.c_str(), path.c_str()) == 0) return;
  std::remove(partial.c_str());
  throw std::runtime_error("could not write the report " + path + ": " + std::strerror(error ? error : EIO));
}

}  // namespace ydscope
