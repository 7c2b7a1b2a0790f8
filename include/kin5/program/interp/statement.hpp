/// @file program/interp/statement.hpp
/// What one line of a program is to the executor (executor.hpp), whatever the dialect: an
/// ordinary line (words for the dialect's reader, perhaps with parameter assignments before
/// them) or a control statement — a label, a jump, a call, a return, a branch of an IF, the
/// start or end of a loop — with the expressions it needs, already parsed, and its key.
///
/// Each dialect's syntax (`program/<dialect>/statements.hpp`) makes these from its spelling:
/// | meaning | LinuxCNC | FANUC macro B | Heidenhain | Siemens |
/// |---|---|---|---|---|
/// | jump | — | `GOTO n`, `IF [c] GOTO n` | `FN 9`–`FN 12 … GOTO LBL` | `GOTOF`, `GOTOB`, `GOTO`, `IF c GOTOF` |
/// | call | `o100 call [a]…`, `o<name> call` (another file) | `M98 P L`, `G65 P L` | `CALL LBL n`, `CALL PGM f` (another file) | `L100 P3`, `NAME`, `CALL "NAME"` (another file) |
/// | section repeat | — | — | `CALL LBL n REP m` | `REPEAT label P=n`, `REPEAT a b P=n`, `REPEATB` |
/// | return | `o100 endsub`, `return` | `M99` | `LBL 0` | `RET`, `M17` |
/// | IF branches | `if`/`elseif`/`else`/`endif` | `IF [c] THEN` (one line: an ordinary line's `condition`) | — | `IF`/`ELSE`/`ENDIF` |
/// | loops | `while`, `do`…`while`, `repeat` | `WHILE [c] DOm` … `ENDm` | — | `WHILE`, `REPEAT`…`UNTIL`, `LOOP`, `FOR` |
/// | counting loop | — | — | — | `FOR R1 = a TO b` … `ENDFOR` |
/// Statements matched by a key (LinuxCNC's o-number, FANUC's `DOm`) pair with the statement of
/// the same key; those without one nest (Siemens `IF` … `ENDIF`).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "expression.hpp"
#include "parameter_store.hpp"

namespace kin5::program::interp {

enum class statement_kind : unsigned char {
  ordinary,          ///< words for the dialect's reader (it may also define a label: FANUC `N100 G1 …`)
  label,             ///< only a label (`LBL 1`, `O1000`, Siemens `MARK:` alone): does nothing
  jump,              ///< to `target`, when `condition` holds (none: always)
  call,              ///< runs the part from `target` `count` times, each until its end (`ends`), then goes on
  subprogram,        ///< a subprogram's first line (`o100 sub`): the flow skips the body to its end
  return_from_call,  ///< ends a pass of the innermost subprogram call, and the section repeats inside it (`M99`, `LBL 0`, `o100 endsub`, `o100 return`)
  if_branch,         ///< IF `condition`: its lines run when it holds, else the next branch is tried
  else_if_branch,    ///< ELSEIF `condition`
  else_branch,       ///< ELSE
  end_if,            ///< ENDIF
  loop_begin,        ///< the first line of a loop (`loop`)
  loop_end,          ///< its last line: goes back to the top, or on
  loop_break,        ///< leaves the innermost loop
  loop_continue,     ///< goes to the innermost loop's end statement
};

/// Where a jump or call looks for its label, from the line of the statement.
enum class jump_direction : unsigned char {
  forward,   ///< the nearest after (Siemens `GOTOF`)
  backward,  ///< the nearest before (Siemens `GOTOB`)
  either,    ///< the nearest after, else the nearest before (Siemens `GOTO`, FANUC `GOTO`, calls)
  backward_then_forward,  ///< the nearest before, else the nearest after (Siemens `REPEAT a b`, `REPEATB`)
};

/// When a pass of a called part ends.
enum class call_end : unsigned char {
  return_statement,  ///< at a `return_from_call` (a subprogram)
  calling_line,      ///< on reaching the calling statement again (a section repeat: `CALL LBL 1 REP 2`)
  end_label,         ///< after the line that defines `end_target`, the first after the start (Siemens `REPEAT a b`)
};

/// How a loop decides to run again.
enum class loop_kind : unsigned char {
  test_first,  ///< `condition` tested at the top, before each run (WHILE)
  test_last,   ///< the end statement's `condition` tested after each run (`do … while`, `REPEAT … UNTIL`)
  counted,     ///< `count` runs, evaluated once at the top (LinuxCNC `repeat [n]`)
  endless,     ///< until a break or a jump out (Siemens `LOOP`)
  counting,    ///< `counter` from its first value up by 1 while not past `count`, evaluated once at the top (Siemens `FOR`)
};

/// `target = value`: the target is a parameter node (its number may be an expression: `#[#1+1]`).
struct assignment {
  expression target;
  expression value;
};

/// A call's argument: parameter `key` of the called part, set to `value` when the call begins.
struct argument {
  parameter_key key;
  expression value;
};

/// One line, as the executor sees it (see the file comment).
struct statement {
  statement_kind kind = statement_kind::ordinary;
  /// The label this line defines ("1" for `LBL 1`, "O1000", "N100", "o100"), or empty. A call
  /// starts after a line of kind `label` or `subprogram`, at any other line (which runs).
  std::string label{};
  /// A second label the line defines: its block number ("N40" of Siemens `N40 MARK: …`), or empty.
  std::string block_label{};
  std::string target{};                          ///< the label a jump or call goes to
  bool target_optional = false;                  ///< a jump whose label may be missing: the run goes on (Siemens `GOTOC`)
  std::string end_target{};                      ///< `end_label` call: the label of each pass's last line
  jump_direction direction = jump_direction::either;
  std::string key{};                             ///< pairs IF/loop/subprogram statements; empty: they nest
  /// Jump, IF branches, `test_first` begin, `test_last` end; an ordinary line runs (its
  /// assignments, its words) only when it holds (FANUC `IF [c] THEN #1 = 5`).
  std::optional<expression> condition{};
  std::optional<expression> count{};             ///< a call's passes, a counted loop's runs (none: 1), a counting loop's last value
  std::optional<assignment> counter{};           ///< a counting loop's counter and its first value
  loop_kind loop = loop_kind::test_first;        ///< on `loop_begin` (and `loop_end`, as its begin's)
  bool until = false;                            ///< a `test_last` end runs again while the condition does *not* hold
  call_end ends = call_end::return_statement;    ///< on `call`
  bool call_frame = true;                        ///< on `call`: the called part has its own local parameters
  bool ends_subprogram = false;                  ///< on `return_from_call`: the subprogram's last line (`endsub`)
  /// On `return_from_call`: reached with no call open, it does nothing (Heidenhain `LBL 0` at the
  /// end of a subprogram the program's flow runs into without calling it).
  bool only_in_call = false;
  /// The program ends after this line (M2, M30, END PGM; a return with no call open).
  bool ends_program = false;
  std::vector<assignment> assignments{};         ///< run in order before the line is read
  std::vector<argument> arguments{};             ///< on `call`
  /// On `call`: the names of the files that may hold the target, tried in order, when no label
  /// of this text is the target (executor.hpp); empty: a call within this text only.
  std::vector<std::string> files{};
  std::optional<expression_error> error{};       ///< the line cannot be read as a statement: the run stops here
};

}  // namespace kin5::program::interp
