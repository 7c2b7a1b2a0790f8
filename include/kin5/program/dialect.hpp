/// @file program/dialect.hpp
/// The NC dialects kin5 reads and writes, as a type list (`dialects`), and the concept each entry
/// satisfies (`nc_dialect`). Everything that works "for every dialect" — `read`, `write`,
/// `block_writer`, `guess_dialect` (io.hpp), the dialect law suite, the fuzz targets — folds
/// over this list, so adding a dialect is one folder `program/<name>/` and one entry here.
///
/// A dialect is one type with static members:
/// | member | what |
/// |---|---|
/// | `name` | its name on the command line and in messages ("siemens") |
/// | `can` | its `capabilities` (program/dialect_id.hpp) |
/// | `reads` | its `controller`: input resolution, comment forms, M functions of its own |
/// | `default_for` | the catalog machines (by id) whose controller reads it |
/// | `lost_as_comment` | an array of `kept_word_effect`s: kept words another dialect cannot carry |
/// | `markers` | an array of `marker`s only it writes, for `guess_dialect` |
/// | `read_blocks(text, file, diagnostics, on_block)` | its streaming reader |
/// | `write_options`, `write(program, options)` | its writer's settings, and the whole-program writer |
/// | `writer` | its block-by-block writer: `writer(source, file, options)`, `write(out, block)` |
///
/// An entry carries no id: at run time a dialect is its place in the list (`program::dialect`,
/// `id_of<D>()`). `dialect_order` (program/dialect_id.hpp) names the entries in the same order, so
/// that a dialect's header needs neither this list nor the other dialects; a static_assert below
/// checks that the two agree.
#pragma once

#include <array>
#include <concepts>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

#include "apt/dialect.hpp"
#include "block.hpp"
#include "dialect_id.hpp"
#include "haas/dialect.hpp"
#include "heidenhain/dialect.hpp"
#include "iso/dialect.hpp"
#include "linuxcnc/dialect.hpp"
#include "siemens/dialect.hpp"

namespace kin5::program {

/// What an entry of `dialects` provides (see the table above).
template <class D>
concept nc_dialect = requires(std::string_view text, const std::string& file, read_result& diagnostics,
                              const block_sink& on_block, const program& p, std::string& out, const block& b,
                              typename D::writer& w) {
  { D::name } -> std::convertible_to<std::string_view>;
  { D::can } -> std::convertible_to<capabilities>;
  { D::markers.size() } -> std::convertible_to<std::size_t>;
  { D::markers[0] } -> std::convertible_to<marker>;
  { D::reads } -> std::convertible_to<controller>;
  { D::default_for.size() } -> std::convertible_to<std::size_t>;
  { D::lost_as_comment.size() } -> std::convertible_to<std::size_t>;
  D::read_blocks(text, file, diagnostics, on_block);
  { D::write(p, typename D::write_options{}) } -> std::same_as<std::string>;
  requires std::constructible_from<typename D::writer, dialect_id, std::string, const typename D::write_options&>;
  w.write(out, b);
};

/// Every dialect, in the order `kin5 --help` lists them.
using dialects = std::tuple<siemens::dialect, heidenhain::dialect, iso::dialect, linuxcnc::dialect, haas::dialect,
                            apt::dialect>;

/// How many dialects there are.
inline constexpr std::size_t dialect_count = std::tuple_size_v<dialects>;

namespace detail {
template <class D, class List>
struct index_in;
template <class D, class... E>
struct index_in<D, std::tuple<E...>> {
  static constexpr std::size_t value = [] {
    constexpr bool is[] = {std::is_same_v<D, E>...};
    std::size_t i = 0;
    while (i < sizeof...(E) && !is[i]) ++i;
    return i;
  }();
  static_assert(value < sizeof...(E), "the dialect is an entry of the list");
};
}  // namespace detail

/// Entry D of `List` as a run-time value: its index there.
template <class D, class List>
inline constexpr dialect id_in{detail::index_in<D, List>::value};

/// Calls `f(std::type_identity<D>{}, index)` for every dialect D of the list, in order. Every
/// fold below takes the list as a template argument, `dialects` by default, so a test can run
/// them on the list with one entry more (tests/property/dialects/adding_a_dialect.cpp).
template <class List = dialects, class F>
constexpr void for_each_dialect(F&& f) {
  [&]<std::size_t... I>(std::index_sequence<I...>) {
    (f(std::type_identity<std::tuple_element_t<I, List>>{}, I), ...);
  }(std::make_index_sequence<std::tuple_size_v<List>>{});
}

/// `f(std::type_identity<D>{})` for the dialect D whose id is `d`; `otherwise()` if none is.
template <class List = dialects, class F, class Otherwise>
constexpr auto visit_dialect(dialect d, F&& f, Otherwise&& otherwise) -> decltype(otherwise()) {
  std::optional<decltype(otherwise())> result;
  for_each_dialect<List>([&]<class D>(std::type_identity<D> type, std::size_t i) {
    if (!result && dialect(i) == d) result.emplace(f(type));
  });
  return result ? std::move(*result) : otherwise();
}

/// The name of dialect `d` ("siemens", "heidenhain", …); "?" for a value that names no dialect.
template <class List = dialects>
constexpr std::string_view name(dialect d) {
  return visit_dialect<List>(d, []<class D>(std::type_identity<D>) { return D::name; }, [] { return std::string_view("?"); });
}

namespace detail {
template <class List>
struct all_dialects;
template <class... D>
struct all_dialects<std::tuple<D...>> : std::bool_constant<(nc_dialect<D> && ...)> {};

/// Whether no two entries share a name.
constexpr bool distinct_names() {
  bool distinct = true;
  for_each_dialect([&]<class A>(std::type_identity<A>, std::size_t i) {
    for_each_dialect([&]<class B>(std::type_identity<B>, std::size_t j) {
      if (i != j && A::name == B::name) distinct = false;
    });
  });
  return distinct;
}

/// Whether `dialect_order` (program/dialect_id.hpp) names the entries in the list's order, so
/// that `id_of<D>()` is D's place in the list.
constexpr bool ids_follow_the_list() {
  bool agree = dialect_order.size() == dialect_count;
  for_each_dialect([&]<class D>(std::type_identity<D>, std::size_t i) {
    if (i >= dialect_order.size() || dialect_order[i] != D::name || id_of<D>() != dialect(i)) agree = false;
  });
  return agree;
}
}  // namespace detail

static_assert(detail::all_dialects<dialects>::value, "every entry of program::dialects is an nc_dialect");
static_assert(detail::distinct_names(), "every dialect has its own name");
static_assert(detail::ids_follow_the_list(),
              "dialect_order (program/dialect_id.hpp) names the entries of program::dialects in its order");
static_assert(dialect_count < 256, "a dialect's index fits its byte");

/// The capabilities of dialect `d` (all false for a value that names no dialect).
template <class List = dialects>
constexpr capabilities capabilities_of(dialect d) {
  return visit_dialect<List>(d, []<class D>(std::type_identity<D>) { return D::can; }, [] { return capabilities{}; });
}

/// The dialect named `s` ("siemens", "heidenhain", …), if any.
template <class List = dialects>
constexpr std::optional<dialect> parse_dialect(std::string_view s) {
  std::optional<dialect> found;
  for_each_dialect<List>([&]<class D>(std::type_identity<D>, std::size_t i) {
    if (D::name == s) found = dialect(i);
  });
  return found;
}

/// The names of the dialects whose `capabilities` satisfy `keep`, in list order (e.g. every NC
/// dialect: `dialect_names([](const capabilities& can) { return !can.cl_data; })`).
template <class List = dialects, class Keep>
std::vector<std::string_view> dialect_names(Keep keep) {
  std::vector<std::string_view> names;
  for_each_dialect<List>([&]<class D>(std::type_identity<D>, std::size_t) {
    if (keep(D::can)) names.push_back(D::name);
  });
  return names;
}

/// What the controller of dialect `d` reads (the first entry's for a value that names no dialect).
template <class List = dialects>
constexpr controller controller_of(dialect d) {
  return visit_dialect<List>(d, []<class D>(std::type_identity<D>) { return D::reads; },
                             [] { return std::tuple_element_t<0, List>::reads; });
}

/// `controller_of(d)` for the folder of entry `Self` (program/dialect_id.hpp).
template <class Self>
constexpr controller controller_from(dialect d) {
  return controller_of(d);
}

/// The dialect of cutter-location data (the one entry whose `can.cl_data` is set): what
/// `reverse` writes and `post` reads.
template <class List = dialects>
constexpr dialect cl_data_dialect() {
  std::size_t found = std::tuple_size_v<List>, count = 0;
  for_each_dialect<List>([&]<class D>(std::type_identity<D>, std::size_t i) {
    if (D::can.cl_data) found = i, ++count;
  });
  return count == 1 ? dialect(found) : dialect(std::tuple_size_v<List>);
}
static_assert(cl_data_dialect().index() < dialect_count, "exactly one dialect of the list is CL data");

/// The dialect the controller of catalog machine `machine_id` reads (the entry whose
/// `default_for` names it), or nothing for an id no entry names.
template <class List = dialects>
constexpr std::optional<dialect> default_dialect(std::string_view machine_id) {
  std::optional<dialect> found;
  for_each_dialect<List>([&]<class D>(std::type_identity<D>, std::size_t i) {
    for (std::string_view id : D::default_for)
      if (id == machine_id) found = dialect(i);
  });
  return found;
}

/// What kept word `word` (upper case, no spaces) of a program in dialect `d` does that a comment
/// would lose (the entry's `lost_as_comment`); empty when it is harmless as a comment.
template <class List = dialects>
constexpr std::string_view lost_as_comment(dialect d, std::string_view word) {
  return visit_dialect<List>(
      d,
      [&]<class D>(std::type_identity<D>) {
        for (const kept_word_effect& k : D::lost_as_comment)
          if (k.matches(word)) return k.effect;
        return std::string_view{};
      },
      [] { return std::string_view{}; });
}

/// `lost_as_comment(d, word)` for the folder of entry `Self` (program/dialect_id.hpp).
template <class Self>
constexpr std::string_view lost_from(dialect d, std::string_view word) {
  return lost_as_comment(d, word);
}

/// The dialects of `List` that are not CL data, in list order: those `translate` reads and writes.
template <class List = dialects>
constexpr auto nc_dialect_ids() {
  constexpr std::size_t count = [] {
    std::size_t n = 0;
    for_each_dialect<List>([&]<class D>(std::type_identity<D>, std::size_t) { n += D::can.cl_data ? 0 : 1; });
    return n;
  }();
  std::array<dialect, count> ids{};
  std::size_t n = 0;
  for_each_dialect<List>([&]<class D>(std::type_identity<D>, std::size_t i) {
    if (!D::can.cl_data) ids[n++] = dialect(i);
  });
  return ids;
}

}  // namespace kin5::program
