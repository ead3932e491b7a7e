// tsk-man-page TEMPLATE OUTPUT: writes the manual page, its commands and options taken from the
// command line's own tables (a build step: the page installed with the program).
#include <fstream>
#include <iostream>
#include <sstream>

#include "cli/man_page.h"
#include "core/base/errors.h"

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: tsk-man-page TEMPLATE OUTPUT\n";
    return 2;
  }
  try {
    std::ifstream in(argv[1]);
    if (!in.is_open()) throw tsk::Error(std::string("cannot read the template ") + argv[1]);
    std::stringstream page_template;
    page_template << in.rdbuf();
    std::ofstream out(argv[2], std::ios::binary | std::ios::trunc);
    out << tsk::cli::man_page(page_template.str());
    out.close();
    if (!out) throw tsk::Error(std::string("cannot write ") + argv[2]);
  } catch (const std::exception& e) {
    std::cerr << "tsk-man-page: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
