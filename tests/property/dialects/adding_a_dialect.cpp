// Adding a dialect is one folder and one entry of `program::dialects` (docs/dialects/README.md):
// a small dialect declared here, put in a list with the others, is named, parsed, guessed and
// read by the same folds that serve the real list, with no other edit. Most checks are
// `static_assert`s: if any fold grows a per-dialect case, this file stops compiling. The entry
// declares no id: its run-time value is its place in the list (`id_in`), so no enum or switch
// outside the folder and the list names a dialect (the real list's names are also in
// `dialect_order`, so that a dialect's header needs no other; a toy list needs no such table).
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
  static constexpr std::string_view name = "toy";
  static constexpr capabilities can{.inverse_time_feed = true};
  static constexpr controller reads{.usual = {2, 2, 0, 5}, .finest = {5, 5, 2, 8}, .paren_comments = true,
                                    .m7_mist_coolant = false};
  static constexpr std::array<std::string_view, 1> default_for{"toy-mill"};
  static constexpr std::array<marker, 1> markers{{{"TOY/", marker::place::block_start}}};
  static constexpr std::array<kept_word_effect, 2> lost_as_comment{
      {{"G99", kept_word_effect::match::code, "a toy return"}, {"Q=", kept_word_effect::match::prefix, "a toy queue"}}};
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
    writer w(p.language, p.file, options);
    for (const block& b : p.blocks) w.write(out, b);
    return out;
  }
};

}  // namespace toy

namespace {

using namespace kin5::program;

/// The real list with one entry more.
using with_toy = decltype(std::tuple_cat(std::declval<dialects>(), std::declval<std::tuple<toy::dialect>>()));

/// The toy's run-time value: its place in the longer list, given by the list alone.
constexpr dialect toy_id = id_in<toy::dialect, with_toy>;

static_assert(nc_dialect<toy::dialect>);
static_assert(!std::is_enum_v<dialect>, "no enum of dialects to extend");
static_assert(std::tuple_size_v<with_toy> == dialect_count + 1);
static_assert(toy_id == dialect(dialect_count), "an appended entry's id is its index");
static_assert(id_in<heidenhain::dialect, with_toy> == id_of<heidenhain::dialect>(), "the others keep theirs");
static_assert(name<with_toy>(toy_id) == "toy");
static_assert(name(toy_id) == "?", "the real list does not know it");
static_assert(parse_dialect<with_toy>("toy") == toy_id);
static_assert(parse_dialect<with_toy>("heidenhain") == id_of<heidenhain::dialect>());
static_assert(!parse_dialect("toy"));
static_assert(capabilities_of<with_toy>(toy_id).inverse_time_feed);
static_assert(!capabilities_of(toy_id).inverse_time_feed);
static_assert(controller_of<with_toy>(toy_id).finest.linear == 5 && controller_of<with_toy>(toy_id).paren_comments);
static_assert(!controller_of<with_toy>(toy_id).m7_mist_coolant);
static_assert(default_dialect<with_toy>("toy-mill") == toy_id, "a machine's default dialect comes from the entry");
static_assert(!default_dialect("toy-mill"));
static_assert(default_dialect<with_toy>("dmu-80p") == default_dialect("dmu-80p"));
static_assert(cl_data_dialect<with_toy>() == cl_data_dialect());
static_assert(guess_dialect<with_toy>("N1 TOY/1\n") == toy_id);
static_assert(!guess_dialect<with_toy>("TOY/1\nBEGIN PGM P MM\n"), "markers of two dialects give nothing");
static_assert(guess_dialect<with_toy>("BEGIN PGM P MM\n") == id_of<heidenhain::dialect>());
static_assert(!guess_dialect("TOY/1\n"));
static_assert(lost_as_comment<with_toy>(toy_id, "G099.0") == "a toy return", "the entry's kept words are refused");
static_assert(lost_as_comment<with_toy>(toy_id, "Q=7") == "a toy queue");
static_assert(lost_as_comment<with_toy>(toy_id, "G990").empty() && lost_as_comment<with_toy>(toy_id, "G9.9").empty());
static_assert(lost_as_comment(toy_id, "G99").empty(), "the real list does not know it");
static_assert(nc_dialect_ids<with_toy>().size() == nc_dialect_ids().size() + 1, "translate reads and writes it");
static_assert(nc_dialect_ids<with_toy>().back() == toy_id);

}  // namespace

TEST_CASE("a dialect added to the list is read by the same entry point") {
  const read_result r = read<with_toy>(toy_id, "TOY/1\nanything\n", "t.toy");
  REQUIRE(r.ok());
  REQUIRE(r.parsed.blocks.size() == 2);
  CHECK(r.parsed.language == toy_id);
  CHECK(r.parsed.blocks[1].text == "anything");
  CHECK(r.parsed.blocks[1].where.line == 2);
  CHECK(read(toy_id, "TOY/1\n", "t.toy").parsed.blocks.empty());  // the real list does not know it
  const auto inverse_time = [](const capabilities& can) { return can.inverse_time_feed; };
  const auto names = dialect_names<with_toy>(inverse_time);
  CHECK(names.back() == "toy");
  CHECK(names.size() == dialect_names(inverse_time).size() + 1);
}
