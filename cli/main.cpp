#include <iostream>
#include <string>
#include <vector>

#include "cli_app.h"

int main(int argc, char** argv) {
  return tsk::cli::run(std::vector<std::string>(argv + 1, argv + argc), std::cout, std::cerr);
}
