// One name per criterion everywhere a person or a script reads it: `check --help`, the text
// verdict, the JSON criteria and the HTML report's table all call each criterion the same.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

#include "cli/cli_run_support.h"
#include "support/session_test_support.h"
#include "support/temp_dir.h"

namespace ydscope {
namespace {

using namespace test;

struct Criterion {
  std::string id, title;
};

// The "criteria" array of check's JSON, in order.
std::vector<Criterion> json_criteria(const std::string& json) {
  std::vector<Criterion> out;
  const std::regex item(R"re(\{"id":"([a-z_]+)","title":"([^"]*)")re");
  for (auto it = std::sregex_iterator(json.begin(), json.end(), item); it != std::sregex_iterator(); ++it)
    out.push_back({(*it)[1], (*it)[2]});
  return out;
}

TEST(CheckWording, EveryCriterionHasOneNameInHelpTextJsonAndHtml) {
  SimOnPty sim(Model::G6);
  TempDir dir("wording");
  const std::string report = dir.file("unit.html");
  const std::string common = "check --port " + sim.port() +
                             " --baud 512000 --seconds 2 --settle-seconds 0.3 --sector 260:280 --target-mm 2400";
  const CliResult json = run_cli_apart(common + " --format json --report " + report);
  const std::vector<Criterion> criteria = json_criteria(json.out);
  ASSERT_GE(criteria.size(), 10u) << "every criterion, the sector's too: " << json.out;
  const CliResult text = run_cli_apart(common);
  std::ifstream in(report);
  const std::string html((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const CliResult help = run_cli_apart("check --help");

  std::size_t text_lines = 0;
  for (const std::string verdict : {"PASS  ", "FAIL  "}) text_lines += count(text.out, "\n" + verdict);
  EXPECT_EQ(text_lines, criteria.size()) << text.out;
  for (const Criterion& c : criteria) {
    SCOPED_TRACE(c.id + " \"" + c.title + "\"");
    // Text: the verdict, the title padded to the longest, then the measured value.
    const std::regex line("\n(PASS|FAIL)  " + c.title + " *  [^ ]");
    EXPECT_TRUE(std::regex_search(text.out, line)) << text.out;
    // HTML: the row of that id names it the same.
    EXPECT_NE(html.find("<tr data-id=\"" + c.id + "\"><td class=\"v "), std::string::npos);
    const std::regex row("<tr data-id=\"" + c.id + "\"><td class=\"v [a-z]+\">[A-Z]+</td><td>" + c.title + "</td>");
    EXPECT_TRUE(std::regex_search(html, row)) << "the report's row";
    // Help: a line of the criteria list starts with the title (the sector as A:B), and the id is listed.
    const std::string listed = std::regex_replace(c.title, std::regex("260:280"), "A:B");
    EXPECT_NE(help.out.find("\n  " + listed + "  "), std::string::npos) << help.out;
    EXPECT_NE(help.out.find(c.id), std::string::npos) << "the ids listed in --help";
  }
}

}  // namespace
}  // namespace ydscope
