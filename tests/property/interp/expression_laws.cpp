// The interpreter's first layer (program/interp/): random expression trees printed in each
// dialect's spelling, read by that dialect's parser and evaluated by kin5, equal the value the
// manuals give them (model.hpp), and are errors exactly where that value is; Heidenhain's FN
// forms; the nesting bound; the parameter store's scopes and refusals.
#include <cmath>
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <kin5/program/heidenhain/expression.hpp>
#include <kin5/program/heidenhain/parameter_rules.hpp>
#include <kin5/program/interp/evaluate.hpp>
#include <kin5/program/iso/expression.hpp>
#include <kin5/program/iso/parameter_rules.hpp>
#include <kin5/program/linuxcnc/expression.hpp>
#include <kin5/program/linuxcnc/parameter_rules.hpp>
#include <kin5/program/siemens/expression.hpp>
#include <kin5/program/siemens/parameter_rules.hpp>

#include "model.hpp"

namespace {

using namespace kin5::program;
using interp_model::spelling;

interp::parameter_store store_for(spelling s, const interp_model::parameters& p) {
  interp::parameter_rules rules;
  switch (s) {
    case spelling::linuxcnc: rules = linuxcnc::parameter_rules(); break;
    case spelling::fanuc: rules = iso::macro_parameter_rules(); break;
    case spelling::siemens: rules = siemens::parameter_rules(); break;
    case spelling::heidenhain: rules = heidenhain::parameter_rules(); break;
  }
  interp::parameter_store store(std::move(rules));
  const auto key = [&](int k) -> interp::parameter_key {
    switch (s) {
      case spelling::linuxcnc: {
        static const interp::parameter_key keys[] = {{"#", 1}, {"#", 31}, {"", 0, "#<depth>"}, {"", 0, "#<_rate>"}, {"#", 4999}};
        return keys[k];
      }
      case spelling::fanuc: {
        static const interp::parameter_key keys[] = {{"#", 1}, {"#", 33}, {"#", 100}, {"#", 500}, {"#", 999}};
        return keys[k];
      }
      case spelling::siemens: {
        static const interp::parameter_key keys[] = {{"R", 1}, {"R", 0}, {"", 0, "_DEPTH"}, {"", 0, "_F_CUT"}, {"R", 99}};
        return keys[k];
      }
      case spelling::heidenhain: {
        static const interp::parameter_key keys[] = {{"Q", 1}, {"QL", 2}, {"QR", 3}, {"Q", 1600}, {"Q", 250}};
        return keys[k];
      }
    }
    return {};
  };
  for (int k = 0; k < 5; ++k) RC_ASSERT(!store.assign(key(k), p.values[k]));
  return store;
}

parsed_expression parse(spelling s, const std::string& text) {
  switch (s) {
    case spelling::linuxcnc: return linuxcnc::read_value("[" + text + "]", 3, 7);
    case spelling::fanuc: return parse_expression(iso::macro_spelling, text, 3, 7);
    case spelling::siemens: return parse_expression(siemens::spelling, text, 3, 7);
    case spelling::heidenhain: return heidenhain::read_assignment("Q9 = " + text, 3, 7).value;
  }
  return {};
}

interp_model::parameters draw_parameters() {
  interp_model::parameters p{};
  for (double& v : p.values)
    v = *rc::gen::arbitrary<bool>() ? *rc::gen::inRange(-5, 12) : *rc::gen::inRange(-50000, 50000) / 1000.0;
  return p;
}

bool near(double a, double b) { return std::abs(a - b) <= 1e-9 * std::max(1.0, std::abs(b)); }

void law(spelling s) {
  const interp_model::tree t = interp_model::draw(s, *rc::gen::inRange(1, 6));
  const bool alternate = *rc::gen::arbitrary<bool>();
  const std::string text = interp_model::print(s, t, alternate);
  const interp_model::parameters p = draw_parameters();
  const interp::parameter_store store = store_for(s, p);
  RC_LOG() << interp_model::name_of(s) << ": " << text << "\n";
  const parsed_expression e = parse(s, text);
  if (!e.ok()) RC_LOG() << "parse error at column " << e.error->where.column << ": " << e.error->message << "\n";
  RC_ASSERT(e.ok());
  const interp::evaluation got = interp::evaluate(e.tree, store);
  const interp_model::value want = interp_model::evaluate(s, t, p);
  if (got.error) RC_LOG() << "kin5: error at line " << got.error->where.line << " column " << got.error->where.column << ": " << got.error->message << "\n";
  else RC_LOG() << "kin5: " << got.value << "\n";
  RC_LOG() << "manual: " << (want ? std::to_string(*want) : std::string("error")) << "\n";
  RC_ASSERT(got.ok() == want.has_value());
  if (want) RC_ASSERT(near(got.value, *want));
  else {  // the error is placed within the expression's line, at a column of its text
    RC_ASSERT(got.error->where.line == 3u);
    RC_ASSERT(got.error->where.column >= 7u);
  }
}

}  // namespace

TEST_CASE("expressions evaluate as the manuals define them, in every spelling") {
  rc::prop("LinuxCNC", [] { law(spelling::linuxcnc); });
  rc::prop("FANUC macro B", [] { law(spelling::fanuc); });
  rc::prop("SINUMERIK", [] { law(spelling::siemens); });
  rc::prop("Heidenhain formulas", [] { law(spelling::heidenhain); });
}

TEST_CASE("any text: an expression or an error inside the text, never a crash") {
  rc::prop("random text over each spelling's characters", [] {
    const auto pieces = *rc::gen::container<std::vector<std::string>>(rc::gen::oneOf(
        rc::gen::element<std::string>("[", "]", "(", ")", "#", "<", ">", "=", "+", "-", "*", "/", "^", "%", ",", " ",
                                      "1", "0.5", ".", "Q1", "QL2", "R1", "_V", "$A", "#<a>", "SIN", "ATAN", "SQ",
                                      "NOT", "B_NOT", "MOD", "DIV", "AND", "EQ", "**", "==", "<>", "EXISTS", "PI",
                                      "FN 1:", "Q5 =", "LEN"),
        rc::gen::map(rc::gen::character<char>(), [](char c) { return std::string(1, c); })));
    std::string text;
    for (const std::string& p : pieces) text += p;
    RC_LOG() << text << "\n";
    const interp::parameter_store stores[] = {interp::parameter_store(linuxcnc::parameter_rules()),
                                              interp::parameter_store(iso::macro_parameter_rules()),
                                              interp::parameter_store(siemens::parameter_rules()),
                                              interp::parameter_store(heidenhain::parameter_rules())};
    const parsed_expression parsed[] = {linuxcnc::read_value(text), parse_expression(iso::macro_spelling, text),
                                        parse_expression(siemens::spelling, text),
                                        parse_expression(heidenhain::spelling, text),
                                        heidenhain::read_assignment(text).value};
    for (std::size_t k = 0; k < std::size(parsed); ++k) {
      const parsed_expression& e = parsed[k];
      RC_ASSERT(e.end <= text.size());
      if (!e.ok()) {
        RC_ASSERT(e.error->where.line == 1u);
        RC_ASSERT(e.error->where.column >= 1u);
        RC_ASSERT(e.error->where.column <= text.size() + 1);
        RC_ASSERT(!e.error->message.empty());
        RC_ASSERT(e.tree.root == interp::no_node);
        continue;
      }
      RC_ASSERT(e.tree.depth() <= interp::max_expression_depth);
      const interp::evaluation v = interp::evaluate(e.tree, stores[std::min<std::size_t>(k, 3)]);
      if (v.ok()) RC_ASSERT(std::isfinite(v.value));
      else RC_ASSERT(!v.error->message.empty());
    }
  });
}

TEST_CASE("Heidenhain FN 0 to FN 8 compute what the manual says") {
  rc::prop("FN k with random operands", [] {
    const int fn = *rc::gen::inRange(0, 9);
    const double a = *rc::gen::inRange(-20000, 20000) / 1000.0, b = *rc::gen::inRange(-5, 6) * 1.0;
    const auto signed_text = [](double v) { return (v < 0 ? "-" : "+") + interp_model::fixed3(std::abs(v)); };
    const char* shape[] = {"FN 0: Q5 = %a", "FN 1: Q5 = %a + %b", "FN 2: Q5 = %a - %b", "FN 3: Q5 = %a * %b",
                           "FN 4: Q5 = %a DIV %b", "FN 5: Q5 = SQRT %a", "FN 6: Q5 = SIN %a", "FN 7: Q5 = COS %a",
                           "FN 8: Q5 = %a LEN %b"};
    std::string text = shape[fn];
    text.replace(text.find("%a"), 2, signed_text(a));
    if (const auto k = text.find("%b"); k != std::string::npos) text.replace(k, 2, signed_text(b));
    RC_LOG() << text << "\n";
    const auto r = heidenhain::read_assignment(text);
    RC_ASSERT(r.value.ok());
    RC_ASSERT((r.target == interp::parameter_key{"Q", 5}));
    const interp::parameter_store store(heidenhain::parameter_rules());
    const interp::evaluation got = interp::evaluate(r.value.tree, store);
    interp_model::value want;
    switch (fn) {
      case 0: want = a; break;
      case 1: want = a + b; break;
      case 2: want = a - b; break;
      case 3: want = a * b; break;
      case 4: want = interp_model::divide(a, b); break;
      case 5: want = a < 0 ? std::nullopt : interp_model::value(std::sqrt(a)); break;
      case 6: want = interp_model::sin_d(a); break;
      case 7: want = interp_model::cos_d(a); break;
      case 8: want = std::hypot(a, b); break;
    }
    RC_ASSERT(got.ok() == want.has_value());
    if (want) RC_ASSERT(near(got.value, *want));
  });
}

TEST_CASE("examples from the manuals") {
  const interp::parameter_store none(heidenhain::parameter_rules());
  const auto heid = [&](const char* t) {
    const auto e = parse_expression(heidenhain::spelling, t);
    REQUIRE(e.ok());
    return interp::evaluate(e.tree, none).value;
  };
  CHECK(heid("5 * 3 + 2 * 10") == 35);  // "Rules for formulas"
  CHECK(heid("SQ 10 - 3^3") == 73);
  CHECK(heid("400 % 360") == 40);
  const interp::parameter_store lin(linuxcnc::parameter_rules());
  const auto cnc = [&](const char* t) {
    const auto e = linuxcnc::read_value(t);
    REQUIRE(e.ok());
    return interp::evaluate(e.tree, lin);
  };
  CHECK(cnc("[1 + 2 * 3 - 4 / 5]").value == Approx(6.2));
  CHECK(cnc("[15 MOD 4.0]").value == 3);
  CHECK(cnc("[-2**2]").value == 4);  // a sign binds to its value (rs274 agrees)
  CHECK(cnc("[2**3**2]").value == 64);
  CHECK(cnc("atan[1.7321]/[1.0]").value == Approx(60.0).margin(1e-3));
  CHECK(cnc("fix[-0.499]").value == -1);
  CHECK(cnc("fup[-0.5001]").value == 0);
  CHECK(cnc("round[-0.5001]").value == -1);
  CHECK(cnc("[0 OR 1 AND 0]").value == 0);  // one level, left to right
  CHECK(cnc("[1 EQ 1.00009]").value == 1);
  const interp::parameter_store fan(iso::macro_parameter_rules());
  const auto fanuc = [&](const char* t) {
    const auto e = parse_expression(iso::macro_spelling, t);
    REQUIRE(e.ok());
    return interp::evaluate(e.tree, fan);
  };
  CHECK(fanuc("ATAN[-1]/[-1]").value == Approx(225));  // NAT = 0
  CHECK(fanuc("FIX[-1.2]").value == -1);
  CHECK(fanuc("FUP[-1.2]").value == -2);
  CHECK(fanuc("5 AND 3").value == 1);
  const interp::parameter_store sie(siemens::parameter_rules());
  const auto s840 = [&](const char* t) {
    const auto e = parse_expression(siemens::spelling, t);
    REQUIRE(e.ok());
    return interp::evaluate(e.tree, sie);
  };
  CHECK(s840("7 DIV 2").value == 3);
  CHECK(s840("1 == 1 AND 1").value == 1);  // (1 AND 1) is compared, not (1 == 1)
  CHECK(s840("2 == 2 AND 0").value == 0);
  CHECK(s840("0.3 == 0.1 + 0.2").error->message.find("relative tolerance") != std::string::npos);
  CHECK(s840("0.3 == 0.30001").value == 0);
}

TEST_CASE("errors name the place and the reason") {
  const interp::parameter_store lin(linuxcnc::parameter_rules());
  const auto error_of = [&](const char* t) {
    const auto e = linuxcnc::read_value(t, 4, 10);
    if (!e.ok()) return *e.error;
    const auto r = interp::evaluate(e.tree, lin);
    REQUIRE(r.error);
    return *r.error;
  };
  auto e = error_of("[2 + 1/0]");
  CHECK(e.where == interp::span{4, 16, 1});
  CHECK(e.message == "division by zero");
  e = error_of("[sqrt[-1]]");
  CHECK(e.where.column == 11);
  CHECK(e.message == "the square root of a negative number");
  e = error_of("[#<nope> + 1]");
  CHECK(e.where == interp::span{4, 11, 7});
  CHECK(e.message == "parameter #<nope> is read before it is assigned in the main program");
  e = error_of("[#5221]");
  CHECK(e.message.find("#5221 is set by the control") != std::string::npos);
  e = error_of("[1 + 2");
  CHECK(e.message == "expected ']' to close the '[' at column 10");
  e = error_of("atan[1]");
  CHECK(e.message == "ATAN takes two arguments: ATAN[y]/[x]");
  CHECK(parse_expression(heidenhain::spelling, "2^3^2").error->message.find("write brackets") != std::string::npos);
  CHECK(parse_expression(siemens::spelling, "$AA_IM[X] + 1").error->message ==
        "system variable $AA_IM is the machine's state, not fixed by the program");
  CHECK_FALSE(parse_expression(iso::macro_spelling, "ATAN[1]").ok());  // one argument: range not fixed
  CHECK_FALSE(parse_expression(iso::macro_spelling, "BCD[1]").ok());
}

TEST_CASE("nesting is bounded, whatever the input") {
  const interp::parameter_store lin(linuxcnc::parameter_rules());
  const auto nested = [](std::size_t n, std::string_view open, std::string_view inner, std::string_view close) {
    std::string t;
    for (std::size_t i = 0; i < n; ++i) t += open;
    t += inner;
    for (std::size_t i = 0; i < n; ++i) t += close;
    return t;
  };
  const std::size_t most = interp::max_expression_depth;
  CHECK(linuxcnc::read_value(nested(most, "[", "1", "]")).ok());
  CHECK(linuxcnc::read_value(nested(most / 2, "sin[", "1", "]")).ok());
  const auto deep = linuxcnc::read_value(nested(most + 1, "[", "1", "]"));
  REQUIRE_FALSE(deep.ok());
  CHECK(deep.error->message == "expression nested more than 100 levels deep");
  // hostile sizes: a million brackets, signs, functions, a long chain of operators
  CHECK_FALSE(linuxcnc::read_value(nested(1000000, "[", "1", "]")).ok());
  CHECK_FALSE(linuxcnc::read_value(std::string(1000000, '-') + "1").ok());
  CHECK_FALSE(linuxcnc::read_value(nested(200000, "sin[", "1", "]")).ok());
  CHECK_FALSE(parse_expression(heidenhain::spelling, nested(200000, "SIN ", "1", "")).ok());
  CHECK_FALSE(parse_expression(siemens::spelling, nested(200000, "NOT ", "1", "")).ok());
  std::string chain = "1";
  for (int i = 0; i < 100000; ++i) chain += "+1";
  const auto long_chain = parse_expression(siemens::spelling, chain);
  REQUIRE_FALSE(long_chain.ok());
  CHECK(long_chain.error->message == "expression nested more than 100 levels deep");
  std::string short_chain = "1";
  for (int i = 0; i < 99; ++i) short_chain += "+1";  // 100 deep
  const auto fits = parse_expression(siemens::spelling, short_chain);
  REQUIRE(fits.ok());
  CHECK(interp::evaluate(fits.tree, interp::parameter_store(siemens::parameter_rules())).value == 100);
  CHECK_FALSE(parse_expression(siemens::spelling, short_chain + "+1").ok());
  // a tree built by hand past the bound is refused by the evaluator too
  interp::expression built;
  built.root = built.number(1, {});
  for (std::size_t i = 0; i < most; ++i) built.root = built.unary(interp::unary_op::negate, built.root, {1, 1, 1});
  CHECK(interp::evaluate(built, lin).error->message == "expression nested more than 100 levels deep");
}

TEST_CASE("parameters: scopes of calls, defaults, the control's ranges") {
  interp::parameter_store l(linuxcnc::parameter_rules());
  CHECK(l.read({"#", 7}).value == 0.0);       // LinuxCNC: numbered parameters read 0
  CHECK(l.read({"#", 4000}).value == 0.0);
  CHECK_FALSE(l.read({"", 0, "#<x>"}).value);  // a named one never assigned is an error
  CHECK(l.assign({"#", 5221}, 1)->find("set by the control") != std::string::npos);
  CHECK(l.read({"", 0, "#<_x>"}).why.find("set by the control") != std::string::npos);
  CHECK(l.assign({"", 0, "#<_abs_x>"}, 1));
  REQUIRE_FALSE(l.assign({"#", 1}, 2.5));
  REQUIRE_FALSE(l.assign({"#", 31}, 8));
  REQUIRE_FALSE(l.assign({"", 0, "#<_g>"}, 3));
  REQUIRE_FALSE(l.assign({"", 0, "#<loc>"}, 4));
  REQUIRE(l.enter_call());
  CHECK(l.read({"#", 1}).value == 0.0);  // o-call: locals start afresh
  CHECK(l.read({"#", 31}).value == 8);   // globals are shared
  CHECK(l.read({"", 0, "#<_g>"}).value == 3);
  CHECK_FALSE(l.read({"", 0, "#<loc>"}).value);
  REQUIRE_FALSE(l.assign({"#", 1}, 7));
  REQUIRE_FALSE(l.assign({"#", 31}, 9));
  CHECK(l.read({"#", 1}).value == 7);
  REQUIRE(l.leave_call());
  CHECK(l.read({"#", 1}).value == 2.5);
  CHECK(l.read({"#", 31}).value == 9);
  CHECK(l.read({"", 0, "#<loc>"}).value == 4);
  CHECK_FALSE(l.leave_call());

  interp::parameter_store f(iso::macro_parameter_rules());
  CHECK(f.read({"#", 1}).why == "parameter #1 is read before it is assigned in the main program");
  CHECK(f.read({"#", 100}).why == "parameter #100 is read before it is assigned: its value is the machine's");
  CHECK(f.read({"#", 5021}).why.find("system variable") != std::string::npos);
  CHECK(f.read({"#", 50}).why == "parameter #50 does not exist in this dialect");
  CHECK(f.read({"#", 0}).why.find("null variable") != std::string::npos);
  REQUIRE(f.enter_call());
  REQUIRE_FALSE(f.assign({"#", 1}, 1));  // a G65 argument A
  CHECK(f.read({"#", 1}).value == 1);
  f.leave_call();
  CHECK_FALSE(f.read({"#", 1}).value);

  interp::parameter_store h(heidenhain::parameter_rules());
  CHECK(h.assign({"Q", 108}, 1)->find("Q100-Q199") != std::string::npos);
  CHECK_FALSE(h.read({"QR", 1}).value);
  interp::parameter_store s(siemens::parameter_rules());
  CHECK(s.read({"R", 5}).why == "parameter R5 is read before it is assigned: its value is the machine's");

  interp::parameter_store deep(iso::macro_parameter_rules());
  std::size_t calls = 0;
  while (deep.enter_call()) ++calls;
  CHECK(calls == interp::parameter_store::max_call_depth);
}
