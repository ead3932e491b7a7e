#include "cli/man_page.h"

#include <vector>

#include "cli/option_table.h"
#include "core/base/errors.h"

namespace tsk::cli {
namespace {

constexpr const char* kReferenceLine = "@REFERENCE@\n";

// `text` as roff running text: backslashes and hyphens escaped, the help's own line breaks
// (laid out for a terminal) joined into one paragraph, "24 %" kept on one line, and no line
// starting as a request.
std::string roff_text(const std::string& text) {
  std::string out;
  for (std::size_t k = 0; k < text.size(); ++k) {
    const char c = text[k];
    if (c == '\n' || c == ' ') {
      out += k + 1 < text.size() && text[k + 1] == '%' ? "\\~" : " ";
    } else if (c == '\\') {
      out += "\\e";
    } else if (c == '-') {
      out += "\\-";
    } else {
      if (k == 0 && (c == '.' || c == '\'')) out += "\\&";
      out += c;
    }
  }
  return out;
}

// The names of the commands that take an option with these CommandBits.
std::string command_names(unsigned commands) {
  std::string names;
  for (const CommandSpec& command : command_table()) {
    if ((commands & command.bit) == 0) continue;
    names += (names.empty() ? "" : ", ") + std::string(command.name);
  }
  return names;
}

std::string option_entry(const OptionSpec& option) {
  std::string entry = ".TP\n";
  entry += option.value
               ? ".BI " + roff_text(option.name) + " \" " + roff_text(option.value) + "\"\n"
               : ".B " + roff_text(option.name) + "\n";
  entry += roff_text(option.help) + ".\n";
  entry += ".br\n" + roff_text("Taken by: " + command_names(option.commands)) + ".\n";
  return entry;
}

}  // namespace

std::string man_page_reference() {
  std::string page = ".SH COMMANDS\n";
  for (const CommandSpec& command : command_table())
    page += ".TP\n.B " + roff_text(command.name) + "\n" + roff_text(command.summary) + ".\n";
  page += ".SH OPTIONS\n";
  // Headings in the order they first come; the table may come back to one.
  std::vector<std::string> headings;
  for (const OptionSpec& option : option_table()) {
    bool known = false;
    for (const std::string& heading : headings) known = known || heading == option.section;
    if (!known) headings.emplace_back(option.section);
  }
  for (const std::string& heading : headings) {
    page += ".SS \"" + roff_text(heading) + "\"\n";
    for (const OptionSpec& option : option_table())
      if (heading == option.section) page += option_entry(option);
  }
  return page;
}

std::string man_page(const std::string& page_template) {
  const std::size_t at = page_template.find(kReferenceLine);
  if (at == std::string::npos || (at > 0 && page_template[at - 1] != '\n'))
    throw Error("the manual page's template has no line @REFERENCE@ for the commands and options");
  return page_template.substr(0, at) + man_page_reference() +
         page_template.substr(at + std::string(kReferenceLine).size());
}

}  // namespace tsk::cli
