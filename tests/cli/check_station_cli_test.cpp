// ydscope-cli check --loop at a test station: units plugged in one after another (virtual lidars
// appearing at one port path, as a unit plugged into the station's socket does) each get a report
// named by serial and one row in the station log with the verdict it earned; a run cut short is
// logged as incomplete, never as a pass.
#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <sys/wait.h>
#include <unistd.h>

#include "cli/cli_run_support.h"
#include "core/sim/sim_server.h"
#include "support/temp_dir.h"
#include "support/text_file.h"

namespace ydscope {
namespace {

using test::lines_of;
using test::read_text;

using namespace test;
using namespace std::chrono_literals;

// A CSV row's fields (the log's fields here hold no quotes or commas but the note, which comes last).
std::vector<std::string> csv_fields(const std::string& line) {
  std::vector<std::string> fields;
  std::string field;
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted && c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
      field += '"';
      ++i;
    } else if (c == '"') {
      quoted = !quoted;
    } else if (c == ',' && !quoted) {
      fields.push_back(field);
      field.clear();
    } else {
      field += c;
    }
  }
  fields.push_back(field);
  return fields;
}

// Waits, up to `patience`, for `done`; false when it never held.
bool eventually(const std::function<bool()>& done, std::chrono::milliseconds patience) {
  const auto deadline = std::chrono::steady_clock::now() + patience;
  while (std::chrono::steady_clock::now() < deadline) {
    if (done()) return true;
    std::this_thread::sleep_for(50ms);
  }
  return done();
}

// One unit at the station's socket: a virtual G6 whose pty link is the station's port path while
// it lives (the link goes when it stops, as a pulled unit's node does).
std::unique_ptr<SimServer> plug_in(const std::string& port, std::uint64_t seed, double scan_hz_offset = 0) {
  SimServerOptions options;
  options.device.model = Model::G6;
  options.device.scene = "room";
  options.device.seed = seed;
  options.device.faults.scan_hz_offset = scan_hz_offset;
  options.transport = SimTransport::Pty;
  options.pty_link = port;
  auto server = std::make_unique<SimServer>(options);
  server->start();
  return server;
}

struct Station {
  TempDir dir{"station"};
  std::string port = dir.file("lidar");
  StartedCli cli;

  bool closed = false;

  ~Station() {  // a test that stopped early leaves no station running
    if (closed || cli.pid < 0) return;
    kill(cli.pid, SIGKILL);
    waitpid(cli.pid, nullptr, 0);
    ::close(cli.out_fd);
  }
  explicit Station(const std::string& seconds) {
    // At the G6's own baud, as check_cli_test.cpp's check() explains.
    cli = start_cli({"check", "--loop", "--station", "bench 1", "--operator", "Ana", "--port", port, "--reports",
                     dir.string(), "--baud", "512000", "--seconds", seconds, "--settle-seconds", "0.3"});
  }
  std::vector<std::string> log_rows() const { return lines_of(read_text(dir / "check-log.csv")); }
  std::vector<std::string> json_rows() const { return lines_of(read_text(dir / "check-log.jsonl")); }
  // Ctrl-C, then what it printed and its exit status.
  std::pair<std::string, int> close() {
    closed = true;
    kill(cli.pid, SIGINT);
    std::string out;
    char buffer[4096];
    ssize_t n;
    while ((n = read(cli.out_fd, buffer, sizeof buffer)) > 0) out.append(buffer, static_cast<std::size_t>(n));
    ::close(cli.out_fd);
    int status = 0;
    waitpid(cli.pid, &status, 0);
    return {out, WIFEXITED(status) ? WEXITSTATUS(status) : -1};
  }
};

TEST(CheckStation, ThreeUnitsInTurnGiveThreeReportsAndThreeLogRows) {
  Station station("2");
  ASSERT_GE(station.cli.pid, 0);
  const char* expected[] = {"pass", "fail", "pass"};
  for (std::size_t unit = 0; unit < 3; ++unit) {
    // The second unit's motor runs 0.6 Hz fast: it must fail the scan rate and nothing else.
    auto sim = plug_in(station.port, 100 + unit, unit == 1 ? 0.6 : 0);
    ASSERT_TRUE(eventually([&] { return station.log_rows().size() == unit + 2; }, 90s))
        << "no log row for unit " << unit << "; rows: " << station.log_rows().size();
    sim.reset();  // pulled out
  }
  const auto [out, status] = station.close();
  EXPECT_EQ(status, 0) << "Ctrl-C while waiting closes the station: " << out;

  const std::vector<std::string> rows = station.log_rows();
  ASSERT_EQ(rows.size(), 4u) << read_text(station.dir / "check-log.csv");
  const std::vector<std::string> header = csv_fields(rows[0]);
  const auto column = [&header](const std::string& name) {
    return static_cast<std::size_t>(std::find(header.begin(), header.end(), name) - header.begin());
  };
  ASSERT_LT(column("note"), header.size()) << rows[0];
  std::vector<std::string> serials;
  for (std::size_t unit = 0; unit < 3; ++unit) {
    const std::vector<std::string> row = csv_fields(rows[unit + 1]);
    ASSERT_EQ(row.size(), header.size()) << rows[unit + 1];
    EXPECT_EQ(row[column("verdict")], expected[unit]) << rows[unit + 1];
    EXPECT_EQ(row[column("failed")], unit == 1 ? "scan_rate" : "") << rows[unit + 1];
    EXPECT_EQ(row[column("station")], "bench 1");
    EXPECT_EQ(row[column("operator")], "Ana");
    EXPECT_EQ(row[column("model")], "G6");
    EXPECT_FALSE(row[column("firmware")].empty());
    EXPECT_FALSE(row[column("scan_hz")].empty()) << "key figures are logged: " << rows[unit + 1];
    serials.push_back(row[column("serial")]);
    // The report is named by the serial, and says the verdict the row says.
    const std::filesystem::path report = row[column("report")];
    EXPECT_EQ(report.parent_path(), station.dir.path());
    EXPECT_EQ(report.filename().string().rfind(serials.back() + "-", 0), 0u) << report;
    const std::string html = read_text(report);
    std::string word = expected[unit];
    for (char& c : word) c = static_cast<char>(std::toupper(c));
    EXPECT_NE(html.find(">" + word + "</span>"), std::string::npos) << report;
    EXPECT_NE(html.find("<dt>station</dt><dd>bench 1</dd>"), std::string::npos);
    EXPECT_NE(html.find("<dt>operator</dt><dd>Ana</dd>"), std::string::npos);
  }
  EXPECT_FALSE(serials[0].empty());
  EXPECT_NE(serials[0], serials[1]);
  EXPECT_NE(serials[1], serials[2]);
  EXPECT_NE(serials[0], serials[2]);
  std::size_t reports = 0;
  for (const auto& entry : std::filesystem::directory_iterator(station.dir.path()))
    reports += entry.path().extension() == ".html" ? 1 : 0;
  EXPECT_EQ(reports, 3u);

  const std::vector<std::string> json = station.json_rows();
  ASSERT_EQ(json.size(), 3u);
  for (std::size_t unit = 0; unit < 3; ++unit) {
    EXPECT_NE(json[unit].find(std::string(R"("verdict":")") + expected[unit] + "\""), std::string::npos) << json[unit];
    EXPECT_NE(json[unit].find(R"("serial":")" + serials[unit] + "\""), std::string::npos) << json[unit];
  }
  EXPECT_NE(json[1].find(R"("failed":["scan_rate"])"), std::string::npos) << json[1];
  EXPECT_EQ(count(out, "verdict: "), 3u) << "one verdict per unit on stdout: " << out;
}

TEST(CheckStation, ARunCutShortIsLoggedIncompleteNeverAPass) {
  Station station("60");
  ASSERT_GE(station.cli.pid, 0);
  auto sim = plug_in(station.port, 7);
  // Ctrl-C once the measurement is under way (about 30 laps of the virtual G6 at 8 Hz).
  ASSERT_TRUE(eventually(
      [&] {
        std::uint64_t zero_packets = 0;
        sim->with_device([&](VirtualLidar& d) { zero_packets = d.counters().zero_packets; });
        return zero_packets > 30;
      },
      60s));
  const auto [out, status] = station.close();
  EXPECT_EQ(status, 130) << out;
  const std::vector<std::string> rows = station.log_rows();
  ASSERT_EQ(rows.size(), 2u) << read_text(station.dir / "check-log.csv");
  const std::vector<std::string> header = csv_fields(rows[0]);
  const std::vector<std::string> row = csv_fields(rows[1]);
  ASSERT_EQ(row.size(), header.size());
  const auto at = [&](const std::string& name) {
    return row[static_cast<std::size_t>(std::find(header.begin(), header.end(), name) - header.begin())];
  };
  EXPECT_EQ(at("verdict"), "incomplete") << rows[1];
  EXPECT_EQ(at("note").rfind("interrupted after", 0), 0u) << rows[1];
  const std::vector<std::string> json = station.json_rows();
  ASSERT_EQ(json.size(), 1u);
  EXPECT_NE(json[0].find(R"("verdict":"incomplete")"), std::string::npos) << json[0];
  EXPECT_EQ(json[0].find(R"("verdict":"pass")"), std::string::npos);
  EXPECT_NE(read_text(at("report")).find(R"(id="verdict">INCOMPLETE</span>)"), std::string::npos);
  EXPECT_EQ(out.find("verdict: PASS"), std::string::npos) << out;
}

TEST(CheckStation, AStationNamesItselfAndItsOperator) {
  TempDir dir("station-usage");
  for (const std::string& args : {std::string("check --loop --operator Ana --port /dev/null"),
                                  std::string("check --loop --station s1 --port /dev/null"),
                                  "check --loop --station s1 --operator Ana --reports " + dir.file("missing"),
                                  "check --reports " + dir.string() + " --port /dev/null"}) {
    const CliResult run = run_cli(args);
    EXPECT_EQ(run.status, 2) << args << "\n" << run.out;
    EXPECT_NE(run.out.find("ydscope-cli check: "), std::string::npos) << args << "\n" << run.out;
  }
}

}  // namespace
}  // namespace ydscope
