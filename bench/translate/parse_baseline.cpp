// The floor for `kin5 translate` (reformat.hpp) as a program: one read of the whole file, the
// numbers parsed and formatted again, one write. For bench/translate/run.sh.
//
//   kin5_bench_parse_baseline IN OUT
#include <cstdio>
#include <string>

#include "reformat.hpp"

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: %s IN OUT\n", argv[0]);
    return 1;
  }
  std::FILE* in = std::fopen(argv[1], "rb");
  if (!in) {
    std::perror(argv[1]);
    return 2;
  }
  std::string text;
  std::fseek(in, 0, SEEK_END);
  const long size = std::ftell(in);
  std::fseek(in, 0, SEEK_SET);
  text.resize(static_cast<std::size_t>(size));
  if (std::fread(text.data(), 1, text.size(), in) != text.size()) {
    std::perror(argv[1]);
    return 2;
  }
  std::fclose(in);

  std::string out;
  const unsigned long long numbers = kin5_bench::reformat_numbers(text, out);
  std::FILE* o = std::fopen(argv[2], "wb");
  if (!o || std::fwrite(out.data(), 1, out.size(), o) != out.size() || std::fclose(o) != 0) {
    std::perror(argv[2]);
    return 2;
  }
  std::fprintf(stderr, "%llu numbers\n", numbers);
  return 0;
}
