// The floor for `kin5 translate`: reads an NC program and writes it back, parsing every number
// and formatting it again, with no kinematics and no program model. Written for speed only:
// one read of the whole file, one pass over its bytes, numbers through std::from_chars and
// std::to_chars, one output buffer, one write.
//
//   kin5_bench_parse_baseline IN OUT
//
// Every word `LETTER NUMBER` becomes `LETTER` and the number, integers as integers, others with
// 3 decimals (trailing zeros kept: the cheapest correct form); comments and words without
// numbers are copied unchanged.
#include <charconv>
#include <cstdio>
#include <string>
#include <system_error>

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
  out.resize(text.size() + text.size() / 2 + 64);
  char* w = out.data();
  const char* p = text.data();
  const char* const end = p + text.size();
  unsigned long long numbers = 0;
  while (p < end) {
    if (static_cast<std::size_t>(w - out.data()) + 64 > out.size()) {  // room for one number
      const std::size_t used = static_cast<std::size_t>(w - out.data());
      out.resize(out.size() * 2);
      w = out.data() + used;
    }
    const char c = *p;
    if (c == ';') {  // comment to the end of the line
      const char* nl = p;
      while (nl < end && *nl != '\n') ++nl;
      const std::size_t used = static_cast<std::size_t>(w - out.data());
      if (used + static_cast<std::size_t>(nl - p) + 64 > out.size()) {
        out.resize(2 * (used + static_cast<std::size_t>(nl - p)) + 64);
        w = out.data() + used;
      }
      while (p < nl) *w++ = *p++;
      continue;
    }
    const bool letter = (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z');
    if (letter && p + 1 < end && (p[1] == '-' || p[1] == '+' || p[1] == '.' || (p[1] >= '0' && p[1] <= '9'))) {
      double v = 0;
      const char* q = p + 1;
      if (*q == '+') ++q;
      const auto r = std::from_chars(q, end, v);
      if (r.ec == std::errc{}) {
        bool integer = true;  // N10, G1, M30: written back as integers
        for (const char* d = q; d < r.ptr; ++d) integer = integer && *d != '.';
        *w++ = c;
        w = integer ? std::to_chars(w, w + 40, static_cast<long long>(v)).ptr
                    : std::to_chars(w, w + 40, v, std::chars_format::fixed, 3).ptr;
        p = r.ptr;
        ++numbers;
        continue;
      }
    }
    *w++ = *p++;
  }
  out.resize(static_cast<std::size_t>(w - out.data()));
  std::FILE* o = std::fopen(argv[2], "wb");
  if (!o || std::fwrite(out.data(), 1, out.size(), o) != out.size() || std::fclose(o) != 0) {
    std::perror(argv[2]);
    return 2;
  }
  std::fprintf(stderr, "%llu numbers\n", numbers);
  return 0;
}
