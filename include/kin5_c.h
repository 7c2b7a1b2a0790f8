/* kin5_c.h: kin5 from C (C99). The library `kin5_c` implements it over kin5's headers.
 *
 * Machines by catalog id or machine-file text; forward and inverse kinematics (the tool axis
 * alone, or the whole pose and every joint); an NC program translated from one machine to
 * another, buffer to buffer, as `kin5 translate` does. Plain structs, no C++; every call
 * returns a `kin5_status` (the `kin5` tool's exit codes where they apply), and no C++
 * exception leaves the library. Lengths are millimetres, angles radians, unless a name says
 * otherwise; positions and directions are in the frame their name gives.
 *
 *     kin5_machine* m = NULL;
 *     char* error = NULL;
 *     if (kin5_machine_from_id("dmu-80p", &m, &error) != KIN5_OK) { puts(error); kin5_free(error); }
 *     kin5_joints q = {{10, 20, -30}, {0.5, 1.0}};
 *     kin5_pose p;
 *     kin5_forward(m, &q, NULL, &p);
 *     kin5_machine_free(m);
 *
 * See docs/embedding.md, "From C". */
#ifndef KIN5_C_H
#define KIN5_C_H

#include <stddef.h>

/* What the library exports (its build defines KIN5_C_BUILDING and hides everything else). */
#if defined(_WIN32) && defined(KIN5_C_BUILDING)
#define KIN5_C_API __declspec(dllexport)
#elif defined(_WIN32)
#define KIN5_C_API __declspec(dllimport)
#elif defined(__GNUC__)
#define KIN5_C_API __attribute__((visibility("default")))
#else
#define KIN5_C_API
#endif

#ifdef __cplusplus
extern "C" {
#endif

/** What a call returns. 0 to 3 are the `kin5` tool's exit codes. */
typedef enum kin5_status {
  KIN5_OK = 0,
  KIN5_BAD_ARGUMENT = 1, /**< a null pointer, an unknown id, dialect or feed policy, a value out of range */
  KIN5_INPUT_ERROR = 2,  /**< a machine file or program with errors (each `FILE:LINE:COL: error: ...`) */
  KIN5_UNREACHABLE = 3,  /**< a tool axis, or blocks of a program, the machine cannot reach */
  KIN5_INTERNAL = 4      /**< out of memory, or a failure of kin5 itself (the message says which) */
} kin5_status;

/** A machine: a catalog machine or one read from a machine file. Opaque; free with
 *  `kin5_machine_free`. Calls only read it, so one machine may serve several threads. */
typedef struct kin5_machine kin5_machine;

/** The values of a machine's axes: X, Y, Z (slides, mm) and the commanded rotary angles in
 *  chain order, workpiece to tool (radians). A 4-axis machine uses `rotary_rad[0]` only. */
typedef struct kin5_joints {
  double xyz_mm[3];
  double rotary_rad[2];
} kin5_joints;

/** A tool pose in the workpiece frame: the tool tip (mm) and the unit tool axis, from the tip
 *  towards the spindle. */
typedef struct kin5_pose {
  double tip_mm[3];
  double axis[3];
} kin5_pose;

/** Where the part sits and the tool length. NULL where a call takes one: all zero. */
typedef struct kin5_placement {
  double tool_length_mm;    /**< gauge point to tool tip, along the tool axis, 0 or more */
  double work_offset_mm[3]; /**< the workpiece zero in machine coordinates at the zero pose (G54) */
} kin5_placement;

/** Most solutions any machine has for one tool axis: two branches, four 360-degree shifts of
 *  each of two bounded axes. */
#define KIN5_MAX_SOLUTIONS 32

/** How a tool axis relates to what the machine reaches. */
typedef enum kin5_reach {
  KIN5_REACHABLE = 0, /**< solutions within travel */
  KIN5_POLE = 1,      /**< reachable, at a pole: the free angle was chosen (0 for the fixed axis) */
  KIN5_NOT_REACHED = 2 /**< no solution within travel; `gap_rad` says how far */
} kin5_reach;

/** One set of rotary angles for a tool axis. */
typedef struct kin5_angles_solution {
  double rotary_rad[2]; /**< commanded angles in chain order; [1] is 0 on a 4-axis machine */
  int within_travel;    /**< 1: every rotary axis within its travel */
  int branch;           /**< 0: the + branch, 1: the - branch */
} kin5_angles_solution;

/** Every set of rotary angles for a tool axis (`kin5_inverse_axis`). */
typedef struct kin5_angles_result {
  kin5_reach reach;
  double gap_rad; /**< angle from the asked axis to what the machine reaches; 0 when reachable */
  size_t count;
  kin5_angles_solution items[KIN5_MAX_SOLUTIONS];
} kin5_angles_result;

/** One set of joints for a tool pose. */
typedef struct kin5_joints_solution {
  kin5_joints joints;
  int within_travel;        /**< 1: every rotary and linear axis within its travel */
  int rotary_within_travel; /**< 1: every rotary axis within its travel */
  double linear_excess_mm;  /**< the largest excess of a slide over its travel; 0 within */
  int branch;               /**< 0: the + branch, 1: the - branch */
} kin5_joints_solution;

/** Every set of joints for a tool pose (`kin5_inverse_pose`). */
typedef struct kin5_joints_result {
  kin5_reach reach;
  double gap_rad;          /**< as in `kin5_angles_result` */
  double linear_excess_mm; /**< tool axis reachable but no solution keeps the slides within travel: the least excess */
  size_t count;
  kin5_joints_solution items[KIN5_MAX_SOLUTIONS];
} kin5_joints_result;

/** Frees a string or buffer the library gave (NULL does nothing). */
KIN5_C_API void kin5_free(void* p);

/** The number of catalog machines, and the id of the `index`-th (NULL past the end). */
KIN5_C_API size_t kin5_catalog_count(void);
KIN5_C_API const char* kin5_catalog_id(size_t index);

/** The catalog machine `id` into `*out`. `error`, if not NULL, receives the message of a
 *  failure (free it with `kin5_free`; NULL on success). KIN5_BAD_ARGUMENT for an unknown id. */
KIN5_C_API kin5_status kin5_machine_from_id(const char* id, kin5_machine** out, char** error);

/** The machine described by the machine-file text `text` (`size` bytes; TOML, see
 *  docs/machine-files.md) into `*out`; `file_name` names it in messages (NULL: "<machine>").
 *  KIN5_INPUT_ERROR with every mistake, one `FILE:LINE:COL: error: ...` line each, in `*error`. */
KIN5_C_API kin5_status kin5_machine_from_text(const char* text, size_t size, const char* file_name, kin5_machine** out,
                                   char** error);

/** Frees a machine (NULL does nothing). */
KIN5_C_API void kin5_machine_free(kin5_machine* m);

/** The machine's id (valid while `m` is), and its number of rotary axes (1 or 2). */
KIN5_C_API const char* kin5_machine_id(const kin5_machine* m);
KIN5_C_API int kin5_machine_rotary_count(const kin5_machine* m);

/** Forward kinematics: the joints `q` to the tool pose in the workpiece frame. */
KIN5_C_API kin5_status kin5_forward(const kin5_machine* m, const kin5_joints* q, const kin5_placement* placement, kin5_pose* out);

/** Every set of rotary angles that points the tool along `axis` (workpiece frame; normalised
 *  here). KIN5_UNREACHABLE when none is within travel (`out` says how far, and holds them). */
KIN5_C_API kin5_status kin5_inverse_axis(const kin5_machine* m, const double axis[3], kin5_angles_result* out);

/** Every set of joints that puts the tool at `target`. KIN5_UNREACHABLE when none is within
 *  the travel of every axis (`out` holds them, with the gap or the linear excess). */
KIN5_C_API kin5_status kin5_inverse_pose(const kin5_machine* m, const kin5_pose* target, const kin5_placement* placement,
                              kin5_joints_result* out);

/** How to translate; `kin5_translate_options_init` fills the tool's defaults. */
typedef struct kin5_translate_options {
  const char* from_dialect; /**< NULL: recognised by its markers, else the source machine's (--from-dialect) */
  const char* to_dialect;   /**< NULL: the target machine's (--to-dialect) */
  const char* feed;         /**< "tcp", "block-time", "inverse-time" (--feed) */
  int digits;               /**< decimals of every position word, 0 to 9; -1: the source's (--digits) */
  double angle_tolerance_deg; /**< 0 to 1; negative: half the program's angular resolution (--angle-tolerance) */
  const char* allow;        /**< refusals turned into warnings, names separated by commas; NULL: none (--allow) */
  const char* work_offset_map; /**< work offsets mapped, the tool's entries separated by ';', e.g. "G54=1"; NULL: none (--work-offset-map) */
  const char* m_map;        /**< M functions renamed or dropped, entries N=M or N= separated by ';'; NULL: none (--m-map) */
  const char* tool_map;     /**< tool numbers for named tools, entries NAME=N separated by ';'; NULL: none (--tool-map) */
  const char* file_name;    /**< the program's name in messages; NULL: "<buffer>" */
} kin5_translate_options;

/** The defaults: what `kin5 translate` does without options. */
KIN5_C_API void kin5_translate_options_init(kin5_translate_options* options);

/** A buffer the library gave: `size` bytes at `data`, followed by a NUL. Free with `kin5_free(data)`. */
typedef struct kin5_buffer {
  char* data;
  size_t size;
} kin5_buffer;

/** Translates the program `text` (`size` bytes) written for `from` into one for `to`, as
 *  `kin5 translate --from ... --to ...` with `options` (NULL: the defaults) writes it to stdout.
 *  `*output` receives the program only when the result is KIN5_OK (else data NULL, size 0);
 *  `*messages` (if not NULL) receives every error, warning and note, one per line, as the tool
 *  prints them (`FILE:LINE:COL: error: ...`). Returns the tool's exit code: KIN5_BAD_ARGUMENT
 *  for options the tool would refuse, KIN5_INPUT_ERROR for a program with errors,
 *  KIN5_UNREACHABLE for blocks the target cannot reach. */
KIN5_C_API kin5_status kin5_translate(const kin5_machine* from, const kin5_machine* to, const char* text, size_t size,
                           const kin5_translate_options* options, kin5_buffer* output, kin5_buffer* messages);

#ifdef __cplusplus
}
#endif

#endif /* KIN5_C_H */
