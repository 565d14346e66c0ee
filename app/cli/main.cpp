// mozzi-cli: the batch face of Mozzi. Links core and devices only.
#include <iostream>
#include <string>
#include <vector>

#include "app/cli/command.h"

int main(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  return mozzi::cli::runCli(args, std::cout, std::cerr);
}
