#include <unistd.h>

#include <exception>
#include <iostream>

#include "cli/app.h"

int main(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  try {
    return assetlint::cli::run(args, std::cin, std::cout, std::cerr, isatty(STDOUT_FILENO) != 0);
  } catch (const std::exception& error) {
    std::cerr << "asset-lint: internal error: " << error.what() << "\n";
    return 2;
  }
}
