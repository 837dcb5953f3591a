#include "cli/commands.h"

int main(int argc, char** argv) {
  return sdfreel::run_cli(argc, argv);
}
