// lagoon: the command-line front of the Lagoon ocean simulator and renderer.
#include <string>
#include <vector>

#include "run_lagoon.h"

int main(int argc, char** argv) {
  const std::vector<std::string> args(argv + 1, argv + argc);
  return lagoon::cli::run_lagoon(args);
}
