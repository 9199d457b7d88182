#include "Cli.hpp"

int main(int argc, char** argv) {
  return glint::RunCli(argc, argv);
}
