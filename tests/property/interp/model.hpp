// Expression trees for the interpreter's laws, drawn at random, printed in each dialect's spelling
// with the fewest brackets that dialect's manual needs, and evaluated directly here from the
// manuals' definitions (docs/dialects/*.md, "Expressions"), not through kin5's evaluator.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <rapidcheck.h>

#include <kin5/program/interp/expression.hpp>

namespace interp_model {

using kin5::program::interp::binary_op;
using kin5::program::interp::function_kind;

enum class spelling { linuxcnc, fanuc, siemens, heidenhain };

inline const char* name_of(spelling s) {
  switch (s) {
    case spelling::linuxcnc: return "LinuxCNC";
    case spelling::fanuc: return "FANUC";
    case spelling::siemens: return "SINUMERIK";
    case spelling::heidenhain: return "Heidenhain";
  }
  return "";
}

using value = std::optional<double>;

/// A binary operator as the manual gives it: text, level (higher first), meaning.
struct op_row {
  const char* text;
  int level;
  std::function<value(double, double)> apply;
  bool power = false;
};

/// A function as the manual gives it: name, arguments, meaning.
struct fn_row {
  const char* name;
  int arguments;
  std::function<value(double, double)> apply;
};

/// A prefix operator: text and meaning.
struct prefix_row {
  const char* text;
  std::function<value(double)> apply;
};

inline constexpr double pi = 3.14159265358979323846;
inline double rad(double deg) { return deg * (pi / 180.0); }
inline double deg(double r) { return r * (180.0 / pi); }
// The angle functions reduce the angle to one turn and are exact at multiples of 90° (the
// documented rule: COS[90] is 0, SIN[1e20] is the sine of 1e20 mod 360).
inline double sin_d(double a) {
  const double r = std::fmod(a, 360.0);
  if (r == 0 || r == 180 || r == -180) return 0;
  if (r == 90 || r == -270) return 1;
  if (r == -90 || r == 270) return -1;
  return std::sin(rad(r));
}
inline double cos_d(double a) {
  const double r = std::fmod(a, 360.0);
  if (r == 90 || r == -90 || r == 270 || r == -270) return 0;
  if (r == 0) return 1;
  if (r == 180 || r == -180) return -1;
  return std::cos(rad(r));
}
inline value fin(double v) { return std::isfinite(v) ? value(v) : std::nullopt; }
inline value truth(bool t) { return t ? 1.0 : 0.0; }
inline std::optional<long long> bits(double v) {
  if (std::floor(v) != v || v < -2147483648.0 || v > 4294967295.0) return std::nullopt;
  return static_cast<long long>(v);
}
inline value bit(double a, double b, int which) {
  const auto x = bits(a), y = bits(b);
  if (!x || !y) return std::nullopt;
  const auto ux = static_cast<unsigned>(static_cast<unsigned long long>(*x) & 0xffffffffu);
  const auto uy = static_cast<unsigned>(static_cast<unsigned long long>(*y) & 0xffffffffu);
  const unsigned v = which == 0 ? (ux & uy) : which == 1 ? (ux | uy) : (ux ^ uy);
  return (*x < 0 || *y < 0) ? static_cast<double>(static_cast<int>(v)) : static_cast<double>(v);
}
inline value pow_of(double a, double b) {
  if ((a < 0 && std::floor(b) != b) || (a == 0 && b < 0)) return std::nullopt;
  return fin(std::pow(a, b));
}
inline value divide(double a, double b) { return b == 0 ? std::nullopt : fin(a / b); }
inline value remainder_of(double a, double b) {
  if (b == 0 || a < 0 || b < 0) return std::nullopt;
  return std::fmod(a, b);
}
inline value asin_d(double x) { return x < -1 || x > 1 ? std::nullopt : value(deg(std::asin(x))); }
inline value acos_d(double x) { return x < -1 || x > 1 ? std::nullopt : value(deg(std::acos(x))); }
inline value tan_d(double x) { return cos_d(x) == 0 ? std::nullopt : fin(sin_d(x) / cos_d(x)); }
inline value log_of(double x, bool natural) {
  if (x <= 0) return std::nullopt;
  return natural ? std::log(x) : std::log10(x);
}

inline std::vector<op_row> operators(spelling s) {
  const auto add = [](double a, double b) { return fin(a + b); };
  const auto sub = [](double a, double b) { return fin(a - b); };
  const auto mul = [](double a, double b) { return fin(a * b); };
  const auto cmp = [](auto f) { return [f](double a, double b) { return truth(f(a, b)); }; };
  // SINUMERIK compares within a relative tolerance of its own: operands that close are refused
  const auto near_cmp = [](auto f) {
    return [f](double a, double b) -> value {
      if (a != b && std::abs(a - b) <= 1e-12 * std::max(std::abs(a), std::abs(b))) return std::nullopt;
      return truth(f(a, b));
    };
  };
  switch (s) {
    case spelling::linuxcnc: {  // ** ; * / MOD ; + - ; EQ … ; AND OR XOR — left to right
      const auto eq = [](double a, double b) { return std::abs(a - b) < 0.0001; };
      return {{"**", 5, pow_of, true},
              {"*", 4, mul},
              {"/", 4, divide},
              {"MOD", 4, [](double a, double b) -> value {
                 if (b == 0) return std::nullopt;
                 double m = std::fmod(a, b);
                 return m < 0 ? m + std::abs(b) : m;
               }},
              {"+", 3, add},
              {"-", 3, sub},
              {"EQ", 2, cmp(eq)},
              {"NE", 2, cmp([eq](double a, double b) { return !eq(a, b); })},
              {"GT", 2, cmp(std::greater<double>())},
              {"GE", 2, cmp(std::greater_equal<double>())},
              {"LT", 2, cmp(std::less<double>())},
              {"LE", 2, cmp(std::less_equal<double>())},
              {"AND", 1, cmp([](double a, double b) { return a != 0 && b != 0; })},
              {"OR", 1, cmp([](double a, double b) { return a != 0 || b != 0; })},
              {"XOR", 1, cmp([](double a, double b) { return (a != 0) != (b != 0); })}};
    }
    case spelling::fanuc:  // * / AND MOD ; + - OR XOR ; EQ …
      return {{"*", 3, mul},
              {"/", 3, divide},
              {"AND", 3, [](double a, double b) { return bit(a, b, 0); }},
              {"MOD", 3, remainder_of},
              {"+", 2, add},
              {"-", 2, sub},
              {"OR", 2, [](double a, double b) { return bit(a, b, 1); }},
              {"XOR", 2, [](double a, double b) { return bit(a, b, 2); }},
              {"EQ", 1, cmp(std::equal_to<double>())},
              {"NE", 1, cmp(std::not_equal_to<double>())},
              {"GT", 1, cmp(std::greater<double>())},
              {"GE", 1, cmp(std::greater_equal<double>())},
              {"LT", 1, cmp(std::less<double>())},
              {"LE", 1, cmp(std::less_equal<double>())}};
    case spelling::siemens:  // * / DIV MOD ; + - ; B_AND ; B_XOR ; B_OR ; AND ; XOR ; OR ; comparisons
      return {{"*", 10, mul},
              {"/", 10, divide},
              {"DIV", 10, [](double a, double b) -> value {
                 if (b == 0 || a < 0 || b < 0) return std::nullopt;
                 return std::trunc(a / b);
               }},
              {"MOD", 10, remainder_of},
              {"+", 9, add},
              {"-", 9, sub},
              {"B_AND", 8, [](double a, double b) { return bit(a, b, 0); }},
              {"B_XOR", 7, [](double a, double b) { return bit(a, b, 2); }},
              {"B_OR", 6, [](double a, double b) { return bit(a, b, 1); }},
              {"AND", 5, cmp([](double a, double b) { return a != 0 && b != 0; })},
              {"XOR", 4, cmp([](double a, double b) { return (a != 0) != (b != 0); })},
              {"OR", 3, cmp([](double a, double b) { return a != 0 || b != 0; })},
              {"==", 1, near_cmp(std::equal_to<double>())},
              {"<>", 1, near_cmp(std::not_equal_to<double>())},
              {">", 1, near_cmp(std::greater<double>())},
              {">=", 1, near_cmp(std::greater_equal<double>())},
              {"<", 1, near_cmp(std::less<double>())},
              {"<=", 1, near_cmp(std::less_equal<double>())}};
    case spelling::heidenhain:  // ^ ; * / % ; + -
      return {{"^", 3, pow_of, true}, {"*", 2, mul}, {"/", 2, divide}, {"%", 2, remainder_of},
              {"+", 1, add},          {"-", 1, sub}};
  }
  return {};
}

inline std::vector<fn_row> functions(spelling s) {
  const auto f1 = [](auto f) { return [f](double x, double) -> value { return f(x); }; };
  const auto common = [&](const char* sqrt_name) {
    return std::vector<fn_row>{
        {"SIN", 1, f1([](double x) { return fin(sin_d(x)); })},
        {"COS", 1, f1([](double x) { return fin(cos_d(x)); })},
        {"TAN", 1, f1(tan_d)},
        {"ACOS", 1, f1(acos_d)},
        {sqrt_name, 1, f1([](double x) { return x < 0 ? std::nullopt : value(std::sqrt(x)); })},
        {"ABS", 1, f1([](double x) { return value(std::abs(x)); })},
        {"LN", 1, f1([](double x) { return log_of(x, true); })},
        {"EXP", 1, f1([](double x) { return fin(std::exp(x)); })},
    };
  };
  std::vector<fn_row> out = common("SQRT");
  const auto add = [&](fn_row r) { out.push_back(std::move(r)); };
  const auto round_away = [](double x) { return value(std::round(x)); };
  switch (s) {
    case spelling::linuxcnc:
      add({"ASIN", 1, f1(asin_d)});
      add({"ATAN", 2, [](double y, double x) { return value(deg(std::atan2(y, x))); }});
      add({"FIX", 1, f1([](double x) { return value(std::floor(x)); })});
      add({"FUP", 1, f1([](double x) { return value(std::ceil(x)); })});
      add({"ROUND", 1, f1(round_away)});
      break;
    case spelling::fanuc:
      add({"ASIN", 1, f1([](double x) -> value {
             const auto a = asin_d(x);
             return a && *a < 0 ? *a + 360 : a;
           })});
      add({"ATAN", 2, [](double y, double x) -> value {
             if (y == 0 && x == 0) return std::nullopt;
             const double a = deg(std::atan2(y, x));
             return a < 0 ? a + 360 : a;
           }});
      add({"FIX", 1, f1([](double x) { return value(std::trunc(x)); })});
      add({"FUP", 1, f1([](double x) { return value(x < 0 ? -std::ceil(-x) : std::ceil(x)); })});
      add({"ROUND", 1, f1(round_away)});
      add({"POW", 2, [](double x, double y) { return pow_of(x, y); }});
      break;
    case spelling::siemens:
      add({"ASIN", 1, f1(asin_d)});
      add({"ATAN2", 2, [](double y, double x) { return value(deg(std::atan2(y, x))); }});
      add({"POT", 1, f1([](double x) { return fin(x * x); })});
      add({"TRUNC", 1, f1([](double x) { return value(std::trunc(x)); })});
      add({"ROUND", 1, f1(round_away)});
      add({"MINVAL", 2, [](double a, double b) { return value(std::min(a, b)); }});
      add({"MAXVAL", 2, [](double a, double b) { return value(std::max(a, b)); }});
      break;
    case spelling::heidenhain:
      add({"ASIN", 1, f1(asin_d)});
      add({"ATAN", 1, f1([](double x) { return value(deg(std::atan(x))); })});
      add({"SQ", 1, f1([](double x) { return fin(x * x); })});
      add({"LOG", 1, f1([](double x) { return log_of(x, false); })});
      add({"INT", 1, f1([](double x) { return value(std::trunc(x)); })});
      add({"FRAC", 1, f1([](double x) { return value(x - std::trunc(x)); })});
      add({"SGN", 1, f1([](double x) { return value(x >= 0 ? 1.0 : -1.0); })});
      break;
  }
  return out;
}

inline std::vector<prefix_row> prefixes(spelling s) {
  std::vector<prefix_row> out{{"-", [](double x) { return value(-x); }}, {"+", [](double x) { return value(x); }}};
  if (s == spelling::siemens) {
    out.push_back({"NOT ", [](double x) { return truth(x == 0); }});
    out.push_back({"B_NOT ", [](double x) -> value {
                     const auto b = bits(x);
                     if (!b) return std::nullopt;
                     return static_cast<double>(static_cast<int>(~static_cast<unsigned>(static_cast<unsigned long long>(*b) & 0xffffffffu)));
                   }});
  }
  if (s == spelling::heidenhain) out.push_back({"NEG ", [](double x) { return value(-x); }});
  return out;
}

/// The parameters a tree reads: index 0–4 assigned (`values`), 5 never assigned.
struct parameters {
  double values[5];
};

inline std::string parameter_text(spelling s, int k) {
  switch (s) {
    case spelling::linuxcnc: {
      static const char* t[] = {"#1", "#31", "#<depth>", "#<_rate>", "#4999", "#77"};
      return t[k];
    }
    case spelling::fanuc: {
      static const char* t[] = {"#1", "#33", "#100", "#500", "#999", "#2"};
      return t[k];
    }
    case spelling::siemens: {
      static const char* t[] = {"R1", "R0", "_DEPTH", "_F_CUT", "R99", "R7"};
      return t[k];
    }
    case spelling::heidenhain: {
      static const char* t[] = {"Q1", "QL2", "QR3", "Q1600", "Q250", "Q7"};
      return t[k];
    }
  }
  return "";
}

/// What a never-assigned parameter reads as: LinuxCNC's numbered ones are 0; the others have
/// the machine's value (refused).
inline value unassigned(spelling s) { return s == spelling::linuxcnc ? value(0.0) : std::nullopt; }

struct tree {
  enum kind_t { number, parameter, prefix, binary, call } kind = number;
  double number_value = 0;
  std::string number_text;
  int index = 0;  // parameter, operator, prefix or function row
  std::vector<tree> kids;
};

inline std::string fixed3(double v) {
  char b[64];
  std::snprintf(b, sizeof b, "%.3f", v);
  return b;
}

inline tree draw(spelling s, int depth) {
  tree t;
  const int choice = depth <= 0 ? *rc::gen::inRange(0, 2) : *rc::gen::inRange(0, 10);
  if (choice == 0) {
    t.kind = tree::number;
    const int form = *rc::gen::inRange(0, 4);
    if (form == 0) t.number_value = *rc::gen::inRange(0, 11);
    else if (form == 1) t.number_value = *rc::gen::element(30, 45, 60, 90, 180, 270, 360);
    else t.number_value = *rc::gen::inRange(0, 200000) / 1000.0;
    t.number_text = fixed3(t.number_value);
    if (form <= 1 && *rc::gen::arbitrary<bool>()) t.number_text = std::to_string(static_cast<int>(t.number_value));
  } else if (choice == 1) {
    t.kind = tree::parameter;
    t.index = *rc::gen::inRange(0, 6);
  } else if (choice <= 3) {
    t.kind = tree::prefix;
    t.index = *rc::gen::inRange(0, static_cast<int>(prefixes(s).size()));
    t.kids.push_back(draw(s, depth - 1));
  } else if (choice <= 7) {
    t.kind = tree::binary;
    t.index = *rc::gen::inRange(0, static_cast<int>(operators(s).size()));
    t.kids.push_back(draw(s, depth - 1));
    t.kids.push_back(draw(s, depth - 1));
  } else {
    t.kind = tree::call;
    const auto fs = functions(s);
    t.index = *rc::gen::inRange(0, static_cast<int>(fs.size()));
    for (int i = 0; i < fs[t.index].arguments; ++i) t.kids.push_back(draw(s, depth - 1));
  }
  return t;
}

/// The value the manual gives `t`, or nullopt where it is an error.
inline value evaluate(spelling s, const tree& t, const parameters& p) {
  switch (t.kind) {
    case tree::number: return t.number_value;
    case tree::parameter: return t.index < 5 ? value(p.values[t.index]) : unassigned(s);
    case tree::prefix: {
      const value x = evaluate(s, t.kids[0], p);
      return x ? prefixes(s)[t.index].apply(*x) : std::nullopt;
    }
    case tree::binary: {
      const value a = evaluate(s, t.kids[0], p);
      if (!a) return a;
      const value b = evaluate(s, t.kids[1], p);
      if (!b) return b;
      return operators(s)[t.index].apply(*a, *b);
    }
    case tree::call: {
      const fn_row f = functions(s)[t.index];
      const value a = evaluate(s, t.kids[0], p);
      if (!a) return a;
      value b = 0.0;
      if (f.arguments == 2) b = evaluate(s, t.kids[1], p);
      if (!b) return b;
      return f.apply(*a, *b);
    }
  }
  return std::nullopt;
}

/// Whether `t` takes a sine, cosine or tangent where kin5 and a calculation in radians without
/// reduction (rs274's) differ: at an exact multiple of 90°, where kin5 gives the exact value
/// (0, ±1; a refused tangent; rs274's SIN[180] is 1.2e-16, its TAN[90] about -4e19), and at
/// angles beyond 10⁴°, where the product with π/180 loses the digits that kin5's reduction keeps.
inline bool trig_differs_from_radians(spelling s, const tree& t, const parameters& p) {
  for (const tree& k : t.kids)
    if (trig_differs_from_radians(s, k, p)) return true;
  if (t.kind != tree::call) return false;
  const std::string name = functions(s)[t.index].name;
  if (name != "SIN" && name != "COS" && name != "TAN") return false;
  const value a = evaluate(s, t.kids[0], p);
  return a && (std::fmod(*a, 90.0) == 0 || std::abs(*a) > 1e4);
}

/// Whether `t` rounds (`ROUND`) a value of 2³¹ or more in magnitude, where rs274 converts to a
/// 32-bit integer and overflows (`ROUND[3000000000]` is −2147483648); kin5 rounds the double.
inline bool round_overflows_int(spelling s, const tree& t, const parameters& p) {
  for (const tree& k : t.kids)
    if (round_overflows_int(s, k, p)) return true;
  if (t.kind != tree::call || functions(s)[t.index].name != "ROUND") return false;
  const value a = evaluate(s, t.kids[0], p);
  return a && std::abs(*a) >= 2147483648.0;
}

/// Whether `t` takes an `ASIN` or `ACOS` within 1e-6 of ±1, where the last bit of its argument
/// (rs274's `TAN[45]` is 0.9999999999999999, kin5's 1) moves the angle by about 1e-6°: a
/// difference of rounding, beyond the oracle's 1e-9.
inline bool inverse_trig_near_end(spelling s, const tree& t, const parameters& p) {
  for (const tree& k : t.kids)
    if (inverse_trig_near_end(s, k, p)) return true;
  if (t.kind != tree::call) return false;
  const std::string name = functions(s)[t.index].name;
  if (name != "ASIN" && name != "ACOS") return false;
  const value a = evaluate(s, t.kids[0], p);
  return a && std::abs(*a) > 1 - 1e-6;
}

/// Whether `t` takes `a MOD b` with |a| ≥ 10⁶: the remainder of a large quotient turns a last-bit
/// difference in `b` (rs274's `TAN[3]` against kin5's sin/cos) into one far beyond the oracle's 1e-9.
inline bool remainder_of_large(spelling s, const tree& t, const parameters& p) {
  for (const tree& k : t.kids)
    if (remainder_of_large(s, k, p)) return true;
  if (t.kind != tree::binary || std::string_view(operators(s)[t.index].text) != "MOD") return false;
  const value a = evaluate(s, t.kids[0], p);
  return a && std::abs(*a) >= 1e6;
}

inline bool atomic(const tree& t) { return t.kind == tree::number || t.kind == tree::parameter || t.kind == tree::call; }

/// `t` in spelling `s` with the fewest brackets its levels need (`alternate`: FANUC's
/// `ATAN[y,x]` instead of `ATAN[y]/[x]`).
inline std::string print(spelling s, const tree& t, bool alternate = false) {
  const bool square = s == spelling::linuxcnc || s == spelling::fanuc;
  const std::string open = square ? "[" : "(", close = square ? "]" : ")";
  const auto br = [&](const std::string& x) { return open + x + close; };
  switch (t.kind) {
    case tree::number: return t.number_text;
    case tree::parameter: return parameter_text(s, t.index);
    case tree::prefix: {
      const tree& k = t.kids[0];
      const std::string inner = print(s, k, alternate);
      return std::string(prefixes(s)[t.index].text) + (k.kind == tree::number || k.kind == tree::parameter ||
                                                                (k.kind == tree::call && s != spelling::heidenhain)
                                                            ? inner
                                                            : br(inner));
    }
    case tree::binary: {
      const auto ops = operators(s);
      const op_row& o = ops[t.index];
      const tree &l = t.kids[0], &r = t.kids[1];
      std::string ls = print(s, l, alternate), rs = print(s, r, alternate);
      const bool heid_power = o.power && s == spelling::heidenhain;
      if ((l.kind == tree::binary && ops[l.index].level < o.level) ||
          (heid_power && (l.kind == tree::prefix || l.kind == tree::call || l.kind == tree::binary)))
        ls = br(ls);
      if (r.kind == tree::binary && ops[r.index].level <= o.level) rs = br(rs);
      if (heid_power && r.kind == tree::call) rs = br(rs);
      return ls + " " + o.text + " " + rs;
    }
    case tree::call: {
      const fn_row f = functions(s)[t.index];
      const std::string a = print(s, t.kids[0], alternate);
      if (s == spelling::heidenhain)
        return std::string(f.name) + " " + (t.kids[0].kind == tree::number || t.kids[0].kind == tree::parameter ? a : br(a));
      if (f.arguments == 1) return f.name + br(a);
      const std::string b = print(s, t.kids[1], alternate);
      if (s == spelling::siemens || (s == spelling::fanuc && (alternate || std::string(f.name) == "POW")))
        return f.name + open + a + ", " + b + close;
      return f.name + br(a) + "/" + br(b);
    }
  }
  return "";
}

}  // namespace interp_model
