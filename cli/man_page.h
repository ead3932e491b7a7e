// The manual page's reference part, made from the tables the command line parses with, so that
// the page lists every command and option as --help does and cannot drift from it.
#pragma once

#include <string>

namespace tsk::cli {

// Roff (man macros) for the sections COMMANDS and OPTIONS: every command with what it makes, and
// every option under its heading with its help and the commands that take it.
std::string man_page_reference();

// The page: `page_template` with its line "@REFERENCE@" replaced by man_page_reference(). Throws
// Error when the template holds no such line.
std::string man_page(const std::string& page_template);

}  // namespace tsk::cli
