/* kin5 from C: a C99 program over kin5_c.h and the kin5_c library (docs/embedding.md, "From C").
 *
 *   kin5_c_consumer MACHINE_FILE [OUT]
 *
 * For every catalog machine, random joints within travel go forward to a pose and back through
 * both inverses, which must hold the joints (rotary angles modulo 360 degrees) among their
 * solutions; MACHINE_FILE (machines/xyzac-trt.toml) read as text must give the catalog
 * machine's poses; a Siemens program translates for a Heidenhain machine, and the refusals
 * (an unknown id, a machine file with a mistake, a program with an error, an unknown dialect)
 * come back as statuses with their messages. OUT, if given, receives the translated program,
 * and OUT.mpf the source, for a comparison with `kin5 translate` (same_as_tool.cmake).
 * Exit 0 when every check holds, 1 otherwise. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "kin5_c.h"

static int failures = 0;

#define CHECK(cond, ...)                              \
  do {                                                \
    if (!(cond)) {                                    \
      ++failures;                                     \
      fprintf(stderr, "%s:%d: ", __FILE__, __LINE__); \
      fprintf(stderr, __VA_ARGS__);                   \
      fputc('\n', stderr);                            \
    }                                                 \
  } while (0)

static const double pi = 3.14159265358979323846;

/* A fixed-seed generator, so that every run checks the same joints. */
static unsigned long long rng_state = 20260u;
static double uniform(double lo, double hi) {
  rng_state = rng_state * 6364136223846793005ull + 1442695040888963407ull;
  return lo + (hi - lo) * (double)(rng_state >> 11) / 9007199254740992.0;
}

static double angle_gap(double a, double b) {
  double d = fmod(fabs(a - b), 2.0 * pi);
  return d > pi ? 2.0 * pi - d : d;
}

static double distance3(const double* a, const double* b) {
  return sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

/* Whether the pose inverse of `pose` holds `q` (linear to 1e-6 mm, angles to 1e-9 rad modulo 2 pi). */
static int holds_joints(const kin5_joints_result* r, const kin5_joints* q, int rotary) {
  size_t i;
  int k;
  for (i = 0; i < r->count; ++i) {
    const kin5_joints* s = &r->items[i].joints;
    int same = distance3(s->xyz_mm, q->xyz_mm) < 1e-6;
    for (k = 0; k < rotary; ++k) same = same && angle_gap(s->rotary_rad[k], q->rotary_rad[k]) < 1e-9;
    if (same) return 1;
  }
  return 0;
}

static int holds_angles(const kin5_angles_result* r, const kin5_joints* q, int rotary) {
  size_t i;
  int k;
  for (i = 0; i < r->count; ++i) {
    int same = 1;
    for (k = 0; k < rotary; ++k) same = same && angle_gap(r->items[i].rotary_rad[k], q->rotary_rad[k]) < 1e-9;
    if (same) return 1;
  }
  return 0;
}

/* Random joints of moderate size: rotary angles in [-1.2, 1.2] rad (within the travel of the
 * catalog's tilting axes), slides within +-200 mm. */
static kin5_joints random_joints(void) {
  kin5_joints q;
  int k;
  for (k = 0; k < 3; ++k) q.xyz_mm[k] = uniform(-200.0, 200.0);
  q.rotary_rad[0] = uniform(-1.2, 1.2);
  q.rotary_rad[1] = uniform(-1.2, 1.2);
  return q;
}

static void check_round_trips(void) {
  size_t n = kin5_catalog_count(), i;
  CHECK(n >= 10, "catalog: %lu machines", (unsigned long)n);
  CHECK(kin5_catalog_id(n) == NULL, "catalog: an id past the end");
  for (i = 0; i < n; ++i) {
    const char* id = kin5_catalog_id(i);
    kin5_machine* m = NULL;
    char* error = NULL;
    int t, rotary, checked = 0;
    kin5_placement placement = {50.0, {10.0, -20.0, 30.0}};
    if (kin5_machine_from_id(id, &m, &error) != KIN5_OK) {
      CHECK(0, "%s: %s", id, error ? error : "(no message)");
      kin5_free(error);
      continue;
    }
    CHECK(error == NULL, "%s: a message on success", id);
    CHECK(strcmp(kin5_machine_id(m), id) == 0, "%s: id %s", id, kin5_machine_id(m));
    rotary = kin5_machine_rotary_count(m);
    CHECK(rotary == 1 || rotary == 2, "%s: %d rotary axes", id, rotary);
    for (t = 0; t < 200; ++t) {
      kin5_joints q = random_joints();
      kin5_pose p;
      kin5_joints_result joints;
      kin5_angles_result angles;
      kin5_status s;
      if (rotary == 1) q.rotary_rad[1] = 0.0;
      CHECK(kin5_forward(m, &q, &placement, &p) == KIN5_OK, "%s: forward", id);
      CHECK(fabs(sqrt(p.axis[0] * p.axis[0] + p.axis[1] * p.axis[1] + p.axis[2] * p.axis[2]) - 1.0) < 1e-12,
            "%s: the tool axis is not a unit vector", id);
      s = kin5_inverse_pose(m, &p, &placement, &joints);
      if (s == KIN5_UNREACHABLE || joints.reach == KIN5_POLE) continue; /* joints outside travel, or a pole */
      ++checked;
      CHECK(s == KIN5_OK, "%s: inverse_pose status %d", id, (int)s);
      CHECK(holds_joints(&joints, &q, rotary), "%s: joints %g %g %g %g %g not among the %lu solutions", id,
            q.xyz_mm[0], q.xyz_mm[1], q.xyz_mm[2], q.rotary_rad[0], q.rotary_rad[1], (unsigned long)joints.count);
      CHECK(kin5_inverse_axis(m, p.axis, &angles) == KIN5_OK, "%s: inverse_axis", id);
      CHECK(holds_angles(&angles, &q, rotary), "%s: angles %g %g not among the %lu solutions", id, q.rotary_rad[0],
            q.rotary_rad[1], (unsigned long)angles.count);
    }
    CHECK(checked >= 50, "%s: only %d of 200 poses within travel", id, checked);
    kin5_machine_free(m);
  }
}

static char* read_file(const char* path, size_t* size) {
  FILE* f = fopen(path, "rb");
  char* text;
  long n;
  if (!f) return NULL;
  fseek(f, 0, SEEK_END);
  n = ftell(f);
  fseek(f, 0, SEEK_SET);
  text = (char*)malloc((size_t)n + 1);
  if (text && fread(text, 1, (size_t)n, f) != (size_t)n) {
    free(text);
    text = NULL;
  }
  fclose(f);
  if (text) text[n] = '\0', *size = (size_t)n;
  return text;
}

/* The machine file of xyzac-trt, read as text, is the catalog's xyzac-trt. */
static void check_machine_file(const char* path) {
  size_t size = 0;
  char* text = read_file(path, &size);
  kin5_machine *file = NULL, *catalog = NULL;
  char* error = NULL;
  int t;
  CHECK(text != NULL, "cannot read %s", path);
  if (!text) return;
  CHECK(kin5_machine_from_text(text, size, path, &file, &error) == KIN5_OK, "%s: %s", path, error ? error : "");
  kin5_free(error);
  CHECK(kin5_machine_from_id("xyzac-trt", &catalog, NULL) == KIN5_OK, "xyzac-trt");
  if (file && catalog) {
    CHECK(strcmp(kin5_machine_id(file), "xyzac-trt") == 0, "the file's id: %s", kin5_machine_id(file));
    for (t = 0; t < 100; ++t) {
      kin5_joints q = random_joints();
      kin5_pose a, b;
      kin5_forward(file, &q, NULL, &a);
      kin5_forward(catalog, &q, NULL, &b);
      CHECK(distance3(a.tip_mm, b.tip_mm) < 1e-9 && distance3(a.axis, b.axis) < 1e-12, "file and catalog differ");
    }
  }
  kin5_machine_free(file);
  kin5_machine_free(catalog);

  /* One mistake: the message names the file, line and column. */
  text[0] = '[';
  file = NULL;
  CHECK(kin5_machine_from_text(text, size, "broken.toml", &file, &error) == KIN5_INPUT_ERROR, "a broken file read");
  CHECK(file == NULL, "a machine from a broken file");
  CHECK(error && strncmp(error, "broken.toml:", 12) == 0 && strstr(error, ": error: "), "message: %s",
        error ? error : "(none)");
  kin5_free(error);
  free(text);
}

static const char program[] =
    "%_N_CABI_MPF\n"
    "; a program for the SAJO 12000P under TRAORI\n"
    "N10 G17 G40 G71 G90 G94\n"
    "N20 G54\n"
    "N30 T1 D1\n"
    "N40 M6\n"
    "N50 S4000 M3\n"
    "N70 TRAORI\n"
    "N80 G0 X-34.339 Y57.999 Z128.941 A-77.954 B3.536\n"
    "N90 G1 X-34.983 Y9.100 Z118.526 A-77.954 B3.536 F1091\n"
    "N100 G1 X-33.824 Y9.118 Z117.545 A-77.913 B4.027 F1093\n"
    "N130 G0 X-30.594 Y58.104 Z125.952\n"
    "N140 TRAFOOF\n"
    "N170 M30\n";

static void write_file(const char* path, const char* data, size_t size) {
  FILE* f = fopen(path, "wb");
  CHECK(f && fwrite(data, 1, size, f) == size, "cannot write %s", path);
  if (f) fclose(f);
}

static void check_translation(const char* out_path) {
  kin5_machine *from = NULL, *to = NULL;
  kin5_buffer output, messages;
  kin5_translate_options options;
  kin5_status s;
  CHECK(kin5_machine_from_id("sajo-12000p", &from, NULL) == KIN5_OK, "sajo-12000p");
  CHECK(kin5_machine_from_id("dmu-80p", &to, NULL) == KIN5_OK, "dmu-80p");

  /* G54 has no certain Heidenhain equivalent: refused at its line, as the tool refuses it. */
  s = kin5_translate(from, to, program, strlen(program), NULL, &output, &messages);
  CHECK(s == KIN5_INPUT_ERROR && output.data == NULL, "G54 without a map: status %d", (int)s);
  CHECK(messages.data && strstr(messages.data, "<buffer>:4:5: error: G54") && strstr(messages.data, "work-offset-map"),
        "G54 without a map: %s", messages.data ? messages.data : "(no message)");
  kin5_free(messages.data);

  kin5_translate_options_init(&options);
  options.work_offset_map = "G54=1";
  s = kin5_translate(from, to, program, strlen(program), &options, &output, &messages);
  CHECK(s == KIN5_OK, "translate: status %d: %s", (int)s, messages.data ? messages.data : "");
  CHECK(output.data && output.size == strlen(output.data), "translate: no output");
  if (output.data) {
    CHECK(strncmp(output.data, "0 BEGIN PGM", 11) == 0, "not a Heidenhain program: %s", output.data);
    CHECK(strstr(output.data, "M128") != NULL, "no M128 in %s", output.data);
    CHECK(strstr(output.data, "CYCL DEF 247") != NULL, "G54 is not preset 1: %s", output.data);
    CHECK(strstr(output.data, "L X+34.983 Y+118.526 Z+9.1 B+17.067 C+87.479 F1091") != NULL,
          "the first cutting block is not the tool's: %s", output.data);
    if (out_path) {
      char source_path[4096];
      sprintf(source_path, "%.4000s.mpf", out_path);
      write_file(out_path, output.data, output.size);
      write_file(source_path, program, strlen(program));
    }
  }
  kin5_free(output.data);
  kin5_free(messages.data);

  /* An error in the program: nothing written, the error at its line. */
  {
    static const char broken[] = "N10 G1 X10 Y20 Z30 F100\nN20 G1 X=\nN30 M30\n";
    kin5_translate_options_init(&options);
    options.file_name = "broken.mpf";
    options.from_dialect = "siemens";
    s = kin5_translate(from, to, broken, strlen(broken), &options, &output, &messages);
    CHECK(s == KIN5_INPUT_ERROR, "a broken program: status %d", (int)s);
    CHECK(output.data == NULL && output.size == 0, "a broken program gave output");
    CHECK(messages.data && strstr(messages.data, "broken.mpf:2:") && strstr(messages.data, ": error: "),
          "a broken program: %s", messages.data ? messages.data : "(no message)");
    kin5_free(messages.data);
  }

  /* Options the tool refuses. */
  kin5_translate_options_init(&options);
  options.to_dialect = "cobol";
  s = kin5_translate(from, to, program, strlen(program), &options, &output, &messages);
  CHECK(s == KIN5_BAD_ARGUMENT && output.data == NULL, "an unknown dialect: status %d", (int)s);
  CHECK(messages.data && strstr(messages.data, "cobol") && strstr(messages.data, "siemens"), "message: %s",
        messages.data ? messages.data : "(none)");
  kin5_free(messages.data);
  kin5_translate_options_init(&options);
  options.allow = "no-such-refusal";
  s = kin5_translate(from, to, program, strlen(program), &options, &output, NULL);
  CHECK(s == KIN5_BAD_ARGUMENT && output.data == NULL, "an unknown refusal name: status %d", (int)s);
  kin5_translate_options_init(&options);
  options.work_offset_map = "G54=1;G54=2";
  CHECK(kin5_translate(from, to, program, strlen(program), &options, &output, NULL) == KIN5_BAD_ARGUMENT,
        "G54 mapped twice");
  kin5_translate_options_init(&options);
  options.digits = 12;
  CHECK(kin5_translate(from, to, program, strlen(program), &options, &output, NULL) == KIN5_BAD_ARGUMENT,
        "digits 12");
  kin5_translate_options_init(&options);
  options.digits = 2;
  options.work_offset_map = "G54=1";
  s = kin5_translate(from, to, program, strlen(program), &options, &output, NULL);
  CHECK(s == KIN5_OK && output.data && strstr(output.data, "Y+118.53"), "digits 2: %s",
        output.data ? output.data : "(none)");
  kin5_free(output.data);
  CHECK(kin5_translate(NULL, to, program, strlen(program), NULL, &output, NULL) == KIN5_BAD_ARGUMENT, "from NULL");

  kin5_machine_free(from);
  kin5_machine_free(to);
}

static void check_refusals(void) {
  kin5_machine* m = NULL;
  char* error = NULL;
  kin5_joints q = {{0, 0, 0}, {0, 0}};
  kin5_pose p;
  kin5_angles_result angles;
  const double zero[3] = {0, 0, 0}, down[3] = {0, 0, -1};
  CHECK(kin5_machine_from_id("no-such-machine", &m, &error) == KIN5_BAD_ARGUMENT, "an unknown id");
  CHECK(m == NULL && error && strstr(error, "dmu-80p"), "an unknown id: %s", error ? error : "(no message)");
  kin5_free(error);
  CHECK(kin5_machine_from_id("ac-trunnion", &m, NULL) == KIN5_OK, "ac-trunnion");
  CHECK(kin5_forward(m, NULL, NULL, &p) == KIN5_BAD_ARGUMENT, "forward of NULL joints");
  q.xyz_mm[0] = NAN;
  CHECK(kin5_forward(m, &q, NULL, &p) == KIN5_BAD_ARGUMENT, "forward of NaN");
  CHECK(kin5_inverse_axis(m, zero, &angles) == KIN5_BAD_ARGUMENT, "inverse of the zero vector");
  /* A tool pointing up out of the table: no table machine reaches it. */
  CHECK(kin5_inverse_axis(m, down, &angles) == KIN5_UNREACHABLE && angles.reach == KIN5_NOT_REACHED &&
            angles.gap_rad > 0.1,
        "a tool axis out of reach: reach %d, gap %g", (int)angles.reach, angles.gap_rad);
  kin5_machine_free(m);
  kin5_machine_free(NULL);
  kin5_free(NULL);
}

int main(int argc, char** argv) {
  if (argc < 2) {
    fprintf(stderr, "usage: %s MACHINE_FILE [OUT]\n", argv[0]);
    return 2;
  }
  check_round_trips();
  check_machine_file(argv[1]);
  check_translation(argc > 2 ? argv[2] : NULL);
  check_refusals();
  if (failures) fprintf(stderr, "%d checks failed\n", failures);
  else printf("kin5 from C: every check holds\n");
  return failures ? 1 : 0;
}
