// Adding a dialect is one folder and one entry of `program::dialects` (docs/dialects/README.md):
// a small dialect declared here, put in a list with the others, is named, parsed, guessed and
// read by the same folds that serve the real list, with no other edit. Most checks are
// `static_assert`s: if any fold grows a per-dialect case, this file stops compiling.
#include <algorithm>
#include <array>
#include <cstddef>
#include <string>
#include <string_view>
#include <tuple>
#include <utility>

#include <catch2/catch.hpp>

#include <kin5/program/dialect.hpp>
#include <kin5/program/io.hpp>

namespace toy {

using namespace kin5::program;

/// The whole "folder": a reader that keeps every line as it is, and a writer that writes it back.
struct write_options {};

class writer {
 public:
  writer(dialect_id, std::string, const write_options&) {}
  void write(std::string& out, const block& b) { out += b.text + "\n"; }
};

struct dialect {
  static constexpr dialect_id id = static_cast<dialect_id>(100);  // a value no other entry uses
  static constexpr std::string_view name = "toy";
  static constexpr capabilities can{.cl_data = true};
  static constexpr std::array<marker, 1> markers{{{"TOY/", marker::place::block_start}}};
  using write_options = toy::write_options;
  using writer = toy::writer;
  static void read_blocks(std::string_view text, const std::string& file, read_result&, const block_sink& on_block) {
    std::size_t line = 0;
    for (std::size_t start = 0; start < text.size();) {
      const std::size_t end = std::min(text.find('\n', start), text.size());
      block b;
      b.where = {file, ++line, 1};
      b.text = std::string(text.substr(start, end - start));
      b.passthrough = true;
      on_block(std::move(b));
      start = end + 1;
    }
  }
  static std::string write(const program& p, const write_options& options) {
    std::string out;
    writer w(id, p.file, options);
    for (const block& b : p.blocks) w.write(out, b);
    return out;
  }
};

}  // namespace toy

namespace {

using namespace kin5::program;

/// The real list with one entry more.
using with_toy = decltype(std::tuple_cat(std::declval<dialects>(), std::declval<std::tuple<toy::dialect>>()));

static_assert(nc_dialect<toy::dialect>);
static_assert(std::tuple_size_v<with_toy> == dialect_count + 1);
static_assert(name<with_toy>(toy::dialect::id) == "toy");
static_assert(name(toy::dialect::id) == "?", "the real list does not know it");
static_assert(parse_dialect<with_toy>("toy") == toy::dialect::id);
static_assert(parse_dialect<with_toy>("heidenhain") == dialect::heidenhain);
static_assert(!parse_dialect("toy"));
static_assert(capabilities_of<with_toy>(toy::dialect::id).cl_data);
static_assert(guess_dialect<with_toy>("N1 TOY/1\n") == toy::dialect::id);
static_assert(!guess_dialect<with_toy>("TOY/1\nBEGIN PGM P MM\n"), "markers of two dialects give nothing");
static_assert(guess_dialect<with_toy>("BEGIN PGM P MM\n") == dialect::heidenhain);
static_assert(!guess_dialect("TOY/1\n"));

}  // namespace

TEST_CASE("a dialect added to the list is read by the same entry point") {
  const read_result r = read<with_toy>(toy::dialect::id, "TOY/1\nanything\n", "t.toy");
  REQUIRE(r.ok());
  REQUIRE(r.parsed.blocks.size() == 2);
  CHECK(r.parsed.language == toy::dialect::id);
  CHECK(r.parsed.blocks[1].text == "anything");
  CHECK(r.parsed.blocks[1].where.line == 2);
  CHECK(read(toy::dialect::id, "TOY/1\n", "t.toy").parsed.blocks.empty());  // the real list does not know it
}
