// The manual page made from the command line's tables: it must list what each command's --help
// lists, as a person reading `man terrain-sketch` would look it up.
#include <map>
#include <regex>
#include <set>
#include <sstream>

#include "catch_compat.h"
#include "cli/man_page.h"
#include "cli_run.h"
#include "core/base/errors.h"

using namespace tsk;
using test::run_cli;

namespace {

const std::vector<std::string> kCommands = {"silhouettes", "profiles", "classify", "row-slope",
                                            "pstrokes",    "drape",    "panorama", "filter-plot"};

// The options a command's --help lists: each one starts a line, two spaces in.
std::set<std::string> help_options(const std::string& command) {
  std::set<std::string> options;
  std::istringstream help(run_cli({command, "--help"}).out);
  static const std::regex option_line("^  (--[a-z0-9-]+)( |$).*");
  std::smatch m;
  for (std::string line; std::getline(help, line);)
    if (std::regex_match(line, m, option_line)) options.insert(m[1]);
  return options;
}

// Roff as typed back into plain text: escaped hyphens and unbreakable spaces.
std::string plain(std::string text) {
  text = std::regex_replace(text, std::regex(R"(\\-)"), "-");
  return std::regex_replace(text, std::regex(R"(\\~)"), " ");
}

// The page's option entries: each option's name and the commands its "Taken by:" line names.
std::map<std::string, std::set<std::string>> page_options(const std::string& page) {
  std::map<std::string, std::set<std::string>> options;
  const std::string options_part = page.substr(page.find(".SH OPTIONS"));
  static const std::regex name_line(R"(^\.BI? (\S+).*)");
  std::istringstream lines(plain(options_part));
  std::string current;
  std::smatch m;
  for (std::string line; std::getline(lines, line);) {
    if (std::regex_match(line, m, name_line)) {
      current = m[1];
      options[current];
    } else if (line.rfind("Taken by: ", 0) == 0 && !current.empty()) {
      std::istringstream names(line.substr(10, line.size() - 11));  // without the full stop
      for (std::string name; std::getline(names >> std::ws, name, ',');)
        options[current].insert(name);
    }
  }
  return options;
}

}  // namespace

TEST_CASE("the manual page lists every command, and every option with the commands taking it",
          "[cli][man]") {
  const std::string page = cli::man_page_reference();
  const auto options = page_options(page);
  std::set<std::string> in_some_help;
  for (const std::string& command : kCommands) {
    CAPTURE(command);
    CHECK_THAT(page, Catch::Contains(".TP\n.B " +
                                     std::regex_replace(command, std::regex("-"), R"(\-)") + "\n"));
    const std::set<std::string> listed = help_options(command);
    CHECK(listed.size() >= 3);
    for (const std::string& option : listed) {
      CAPTURE(option);
      in_some_help.insert(option);
      const auto entry = options.find(option);
      REQUIRE(entry != options.end());
      CHECK(entry->second.count(command) == 1);
    }
  }
  // And nothing the help does not list: an entry's commands are exactly those listing it.
  for (const auto& [option, commands] : options) {
    CAPTURE(option);
    CHECK(in_some_help.count(option) == 1);
    for (const std::string& command : commands) CHECK(help_options(command).count(option) == 1);
  }
  // Lines the help breaks for a terminal run on as one paragraph: "24 %" is one phrase.
  CHECK_THAT(page, Catch::Contains(R"(24\~%)"));
  CHECK(page.find("\n%") == std::string::npos);
}

TEST_CASE("the manual page is its template with the reference filled in", "[cli][man]") {
  const std::string page = cli::man_page(".TH X 1\n.SH NAME\nx\n@REFERENCE@\n.SH SEE ALSO\n");
  CHECK_THAT(page, Catch::StartsWith(".TH X 1\n.SH NAME\nx\n.SH COMMANDS\n"));
  CHECK_THAT(page, Catch::EndsWith(".SH SEE ALSO\n"));
  CHECK(page.find("@REFERENCE@") == std::string::npos);
  CHECK_THROWS_AS(cli::man_page(".TH X 1\n"), Error);
  CHECK_THROWS_AS(cli::man_page(".TH X 1\nsee @REFERENCE@\n"), Error);
}

TEST_CASE("every line of the help fits 96 columns", "[cli][man]") {
  std::vector<std::vector<std::string>> helps = {{"--help"}};
  for (const std::string& command : kCommands) helps.push_back({command, "--help"});
  for (const auto& args : helps) {
    std::istringstream help(run_cli(args).out);
    for (std::string line; std::getline(help, line);) {
      CAPTURE(args.front(), line);
      CHECK(line.size() <= 96);
    }
  }
}
