// Writes the translation benchmark's input (spiral.hpp) to a file, for bench/translate/run.sh.
//
//   kin5_bench_gen_program BLOCKS OUT.mpf
#include <cstdio>
#include <cstdlib>
#include <string>

#include "spiral.hpp"

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: %s BLOCKS OUT.mpf\n", argv[0]);
    return 1;
  }
  const long blocks = std::strtol(argv[1], nullptr, 10);
  if (blocks <= 0) {
    std::fprintf(stderr, "%s: BLOCKS must be a positive number\n", argv[0]);
    return 1;
  }
  const std::string text = kin5_bench::spiral_program(blocks);
  std::FILE* f = std::fopen(argv[2], "wb");
  if (!f || std::fwrite(text.data(), 1, text.size(), f) != text.size() || std::fclose(f) != 0) {
    std::perror(argv[2]);
    return 2;
  }
  return 0;
}
