#include <unistd.h>

#include <iostream>
#include <string>
#include <vector>

#include "cli/cli_app.h"
#include "cli/interrupt.h"

int main(int argc, char** argv) {
  tsk::cli::catch_interrupts();
  return tsk::cli::run(std::vector<std::string>(argv + 1, argv + argc), std::cout, std::cerr,
                       isatty(STDERR_FILENO) == 1);
}
