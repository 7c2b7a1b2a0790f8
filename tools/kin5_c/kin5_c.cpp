// kin5_c: the C ABI of include/kin5_c.h over kin5's headers. Every entry point catches at the
// boundary: a C++ exception (bad_alloc, or a failure of kin5 itself) becomes KIN5_INTERNAL with
// its message, never an unwinding through C frames.
#include "kin5_c.h"

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <memory>
#include <new>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <kin5/kinematics.hpp>
#include <kin5/machines/catalog.hpp>
#include <kin5/machines/machine_file.hpp>
#include <kin5/program/io.hpp>
#include <kin5/translate/pipeline.hpp>
#include <kin5/translate/stream.hpp>

// A machine: a catalog model (static storage) or one read from a machine file (owned).
struct kin5_machine {
  const kin5::machine_model* bundled = nullptr;
  std::optional<kin5::loaded_machine> file;
  const kin5::machine_model& model() const { return bundled ? *bundled : file->model(); }
  std::string id;  // NUL-terminated, for kin5_machine_id
};

namespace {

namespace prog = kin5::program;

// A copy of `s` in memory the caller frees with kin5_free (std::free); null if none is left.
char* c_string(std::string_view s) {
  char* p = static_cast<char*>(std::malloc(s.size() + 1));
  if (!p) return nullptr;
  std::memcpy(p, s.data(), s.size());
  p[s.size()] = '\0';
  return p;
}

// `s` as a kin5_buffer; false when the memory cannot be had.
bool fill(kin5_buffer* b, std::string_view s) {
  if (!b) return true;
  b->data = c_string(s);
  b->size = b->data ? s.size() : 0;
  return b->data != nullptr;
}

void clear(kin5_buffer* b) {
  if (b) b->data = nullptr, b->size = 0;
}

kin5_status fail(char** error, kin5_status status, std::string_view message) {
  if (error) *error = c_string(message);
  return status;
}

// Runs `f` and turns what it throws into KIN5_INTERNAL, with the message in `*error` (if any).
template <class F>
kin5_status guarded(char** error, F&& f) noexcept {
  try {
    return f();
  } catch (const std::bad_alloc&) {
    return fail(error, KIN5_INTERNAL, "kin5: out of memory");
  } catch (const std::exception& e) {
    try {
      return fail(error, KIN5_INTERNAL, std::string("kin5: internal error: ") + e.what());
    } catch (...) {
      return fail(error, KIN5_INTERNAL, "kin5: internal error");
    }
  } catch (...) {
    return fail(error, KIN5_INTERNAL, "kin5: internal error");
  }
}

kin5::run_inputs inputs_of(const kin5_placement* p) {
  kin5::run_inputs in;
  if (!p) return in;
  in.tool_length_mm = p->tool_length_mm;
  in.work_offset.translation_mm = {p->work_offset_mm[0], p->work_offset_mm[1], p->work_offset_mm[2]};
  return in;
}

bool finite(const double* v, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i)
    if (!std::isfinite(v[i])) return false;
  return true;
}

bool placement_ok(const kin5_placement* p) {
  return !p || (std::isfinite(p->tool_length_mm) && p->tool_length_mm >= 0.0 && finite(p->work_offset_mm, 3));
}

kin5_reach reach_of(kin5::reach_status s) {
  switch (s) {
    case kin5::reach_status::reachable: return KIN5_REACHABLE;
    case kin5::reach_status::pole: return KIN5_POLE;
    case kin5::reach_status::unreachable: break;
  }
  return KIN5_NOT_REACHED;
}

// The names in `list`, separated by `separator` (blanks around a name ignored); empty names skipped.
std::vector<std::string> split_names(std::string_view list, char separator = ',') {
  std::vector<std::string> out;
  while (!list.empty()) {
    const std::size_t comma = list.find(separator);
    std::string_view name = list.substr(0, comma);
    while (!name.empty() && name.front() == ' ') name.remove_prefix(1);
    while (!name.empty() && name.back() == ' ') name.remove_suffix(1);
    if (!name.empty()) out.emplace_back(name);
    if (comma == std::string_view::npos) break;
    list.remove_prefix(comma + 1);
  }
  return out;
}

// The NC dialect named `name` (translate neither reads nor writes CL data), or nothing.
std::optional<prog::dialect> nc_dialect(const char* name) {
  const auto d = prog::parse_dialect(name);
  if (!d || prog::capabilities_of(*d).cl_data) return std::nullopt;
  return d;
}

std::string nc_dialect_list() {
  std::string out;
  for (auto n : prog::dialect_names([](const prog::capabilities& can) { return !can.cl_data; }))
    out += (out.empty() ? "" : ", ") + std::string(n);
  return out;
}

// The message lines of a translation, as the tool prints them: the reader's diagnostics, then
// the translation's errors, warnings and allowed refusals, each in source order.
void add_lines(std::string& to, const std::vector<prog::diagnostic>& ds, const char* severity) {
  for (const auto& d : ds) {
    if (d.where.line == 0)
      to += prog::printable(d.where.file.str()) + ": " + severity + ": " + prog::printable(d.message);
    else
      to += d.to_string(severity);
    to += '\n';
  }
}

kin5_status translate(const kin5_machine& from, const kin5_machine& to, std::string text,
                      const kin5_translate_options& o, std::string& output, std::string& messages) {
  const std::string file = o.file_name ? o.file_name : "<buffer>";
  const kin5::machine_model& from_model = from.model();
  const kin5::machine_model& to_model = to.model();
  const auto usage = [&](const std::string& why) {
    messages += "kin5 translate: " + why + '\n';
    return KIN5_BAD_ARGUMENT;
  };

  // The options, checked as the tool checks its own.
  prog::dialect input = prog::default_dialect(from_model.geometry.id).value_or(prog::dialect{});
  if (o.from_dialect) {
    const auto d = nc_dialect(o.from_dialect);
    if (!d) return usage(std::string("from_dialect: unknown dialect '") + o.from_dialect + "'; valid: " + nc_dialect_list());
    input = *d;
  }
  kin5::translate_options options;
  options.output_dialect = prog::default_dialect(to_model.geometry.id).value_or(prog::dialect{});
  if (o.to_dialect) {
    const auto d = nc_dialect(o.to_dialect);
    if (!d) return usage(std::string("to_dialect: unknown dialect '") + o.to_dialect + "'; valid: " + nc_dialect_list());
    options.output_dialect = *d;
  }
  const auto feed = kin5::parse_feed_policy(o.feed ? o.feed : "tcp");
  if (!feed) return usage(std::string("feed: unknown feed policy '") + o.feed + "'; valid: tcp, block-time, inverse-time");
  options.feed = *feed;
  if (const auto refusal = kin5::feed_refusal(options.feed, *options.output_dialect))
    return usage(std::string("feed ") + o.feed + ": " + *refusal + "; choose another to_dialect, or another feed");
  options.setup = kin5::default_setup(from_model.geometry.id, to_model.geometry.id);
  if (o.angle_tolerance_deg >= 0.0 || std::isnan(o.angle_tolerance_deg)) {
    if (!(o.angle_tolerance_deg >= 0.0 && o.angle_tolerance_deg <= 1.0))
      return usage("angle_tolerance_deg: give degrees in [0, 1], or a negative value for the default");
    options.common.angle_tolerance = kin5::degrees{o.angle_tolerance_deg};
  }
  if (o.digits != -1) {
    if (o.digits < 0 || o.digits > 9) return usage("digits: give 0 to 9 decimals, or -1 for the source's");
    options.common.digits = o.digits;
  }
  if (o.allow)
    for (const auto& name : split_names(o.allow))
      if (!options.common.allow.add(name))
        return usage("allow: no refusal is named '" + name + "'; valid: " + kin5::allowable_names());
  if (o.work_offset_map)
    for (const auto& entries : split_names(o.work_offset_map, ';'))
      if (!options.common.work_offsets.add(entries))
        return usage("work_offset_map: '" + entries +
                     "' is not FROM=TO[,FROM=TO…] (FROM, TO: G54 … G59, G54.1P n, G500, G505 … G599, or a "
                     "Heidenhain preset number; TO empty drops it), or maps a work offset twice");
  if (o.m_map)
    for (const auto& entry : split_names(o.m_map, ';'))
      if (!options.common.m_codes.add(entry))
        return usage("m_map: '" + entry + "' is neither N=M (rename) nor N= (drop)");
  if (o.tool_map)
    for (const auto& entry : split_names(o.tool_map, ';'))
      if (!options.common.tool_numbers.add(entry))
        return usage("tool_map: '" + entry +
                     "' is not NAME=N (N a whole number of at most 8 digits), or maps a tool twice");
  if (const auto why = kin5::translate_detail::output_mode_refusal(options.common, *options.output_dialect))
    return usage(*why);

  // A dialect recognised by its markers wins over the machine's, as in the tool.
  if (!o.from_dialect)
    if (const auto guessed = prog::guess_dialect(text); guessed && *guessed != input) {
      messages += "kin5 translate: note: reading " + prog::printable(file) + " as " + std::string(prog::name(*guessed)) +
                  " (recognised by its markers), not as " + std::string(prog::name(input)) +
                  "; choose with from_dialect\n";
      input = *guessed;
    }

  const auto translator =
      kin5::make_translator(from_model, to_model, input, file, options, kin5::report_detail::exceptions_only);
  kin5::string_sink sink;
  const kin5::stream_result run = kin5::stream_text(*translator, std::move(text), input, file, *options.output_dialect, sink);
  const kin5::translation& result = translator->result();
  add_lines(messages, run.input.errors, "error");
  add_lines(messages, run.input.warnings, "warning");
  if (!run.input.ok()) return KIN5_INPUT_ERROR;
  add_lines(messages, std::vector<prog::diagnostic>(result.errors.begin(), result.errors.end()), "error");
  add_lines(messages, std::vector<prog::diagnostic>(result.warnings.begin(), result.warnings.end()), "warning");
  for (auto d : result.allowed) {
    d.message += " [allowed by " + d.option + "]";
    add_lines(messages, {d}, "warning");
  }
  const std::size_t unreachable = result.per_class[static_cast<std::size_t>(kin5::matchability::unreachable)];
  if (result.errors.count() > unreachable) return KIN5_INPUT_ERROR;
  if (unreachable > 0) return KIN5_UNREACHABLE;
  if (run.writer_error) {
    prog::diagnostic d = *run.writer_error;
    d.message = "cannot write the program as " + std::string(prog::name(*options.output_dialect)) + ": " + d.message;
    messages += d.to_string("error") + '\n';
    return KIN5_INPUT_ERROR;
  }
  if (!run.ok(*translator)) return KIN5_INTERNAL;  // every failure above is named; none is left
  output = std::move(sink.text);
  return KIN5_OK;
}

}  // namespace

extern "C" {

void kin5_free(void* p) { std::free(p); }

size_t kin5_catalog_count(void) { return kin5::machines::catalog_models.size(); }

const char* kin5_catalog_id(size_t index) {
  if (index >= kin5::machines::catalog_models.size()) return nullptr;
  return kin5::machines::catalog_models[index]->geometry.id.data();  // ids are string literals
}

kin5_status kin5_machine_from_id(const char* id, kin5_machine** out, char** error) {
  if (error) *error = nullptr;
  if (!out) return fail(error, KIN5_BAD_ARGUMENT, "kin5_machine_from_id: out is NULL");
  *out = nullptr;
  return guarded(error, [&] {
    if (!id) return fail(error, KIN5_BAD_ARGUMENT, "kin5_machine_from_id: id is NULL");
    const kin5::machine_model* m = kin5::machines::find_machine(id);
    if (!m) {
      std::string ids;
      for (const auto* c : kin5::machines::catalog_models) ids += (ids.empty() ? "" : ", ") + std::string(c->geometry.id);
      return fail(error, KIN5_BAD_ARGUMENT,
                  std::string("unknown machine '") + id + "'; valid ids: " + ids + "; or give a machine file's text");
    }
    auto made = std::make_unique<kin5_machine>();
    made->bundled = m;
    made->id = std::string(m->geometry.id);
    *out = made.release();
    return KIN5_OK;
  });
}

kin5_status kin5_machine_from_text(const char* text, size_t size, const char* file_name, kin5_machine** out,
                                   char** error) {
  if (error) *error = nullptr;
  if (!out) return fail(error, KIN5_BAD_ARGUMENT, "kin5_machine_from_text: out is NULL");
  *out = nullptr;
  return guarded(error, [&] {
    if (!text && size) return fail(error, KIN5_BAD_ARGUMENT, "kin5_machine_from_text: text is NULL");
    kin5::machine_file_result r =
        kin5::parse_machine_file(std::string_view(text ? text : "", size), file_name ? file_name : "<machine>");
    if (!r.ok()) {
      std::string all;
      for (const auto& e : r.errors) all += e.to_string() + '\n';
      return fail(error, KIN5_INPUT_ERROR, all);
    }
    auto made = std::make_unique<kin5_machine>();
    made->file.emplace(std::move(*r.machine));
    made->id = std::string(made->file->model().geometry.id);
    *out = made.release();
    return KIN5_OK;
  });
}

void kin5_machine_free(kin5_machine* m) { delete m; }

const char* kin5_machine_id(const kin5_machine* m) { return m ? m->id.c_str() : nullptr; }

int kin5_machine_rotary_count(const kin5_machine* m) { return m ? static_cast<int>(m->model().rotary_count) : 0; }

kin5_status kin5_forward(const kin5_machine* m, const kin5_joints* q, const kin5_placement* placement, kin5_pose* out) {
  if (!m || !q || !out || !finite(q->xyz_mm, 3) || !finite(q->rotary_rad, 2) || !placement_ok(placement))
    return KIN5_BAD_ARGUMENT;
  const kin5::axis_values joints{{q->xyz_mm[0], q->xyz_mm[1], q->xyz_mm[2]},
                                 {kin5::radians{q->rotary_rad[0]}, kin5::radians{q->rotary_rad[1]}}};
  const kin5::tool_pose p = kin5::forward(m->model(), joints, inputs_of(placement));  // noexcept
  *out = {{p.tip_mm.x, p.tip_mm.y, p.tip_mm.z}, {p.axis.x, p.axis.y, p.axis.z}};
  return KIN5_OK;
}

kin5_status kin5_inverse_axis(const kin5_machine* m, const double axis[3], kin5_angles_result* out) {
  if (!m || !axis || !out || !finite(axis, 3)) return KIN5_BAD_ARGUMENT;
  const kin5::vec3 u{axis[0], axis[1], axis[2]};
  if (!(kin5::norm(u) > 0.0)) return KIN5_BAD_ARGUMENT;
  kin5::inverse_values r{};
  kin5::inverse_into(m->model(), kin5::normalized(u), {}, r);  // noexcept
  static_assert(kin5::inverse_values::capacity == KIN5_MAX_SOLUTIONS);
  *out = {};
  out->reach = reach_of(r.status);
  out->gap_rad = r.gap.value;
  out->count = r.size();
  for (std::size_t i = 0; i < r.size(); ++i)
    out->items[i] = {{r[i].angles[0].value, r[i].angles[1].value}, r[i].within_travel ? 1 : 0, r[i].branch};
  return r.reachable() ? KIN5_OK : KIN5_UNREACHABLE;
}

kin5_status kin5_inverse_pose(const kin5_machine* m, const kin5_pose* target, const kin5_placement* placement,
                              kin5_joints_result* out) {
  if (!m || !target || !out || !finite(target->tip_mm, 3) || !finite(target->axis, 3) || !placement_ok(placement))
    return KIN5_BAD_ARGUMENT;
  const kin5::tool_pose pose{{target->tip_mm[0], target->tip_mm[1], target->tip_mm[2]},
                             {target->axis[0], target->axis[1], target->axis[2]}};
  if (!(kin5::norm(pose.axis) > 0.0)) return KIN5_BAD_ARGUMENT;
  kin5::pose_values r{};
  kin5::inverse_into(m->model(), pose, inputs_of(placement), {}, r);  // noexcept
  static_assert(kin5::pose_values::capacity == KIN5_MAX_SOLUTIONS);
  *out = {};
  out->reach = reach_of(r.status);
  out->gap_rad = r.gap.value;
  out->linear_excess_mm = r.linear_excess_mm;
  out->count = r.size();
  for (std::size_t i = 0; i < r.size(); ++i) {
    const auto& s = r[i];
    out->items[i].joints = {{s.joints.xyz_mm.x, s.joints.xyz_mm.y, s.joints.xyz_mm.z},
                            {s.joints.rotary[0].value, s.joints.rotary[1].value}};
    out->items[i].within_travel = s.within_travel ? 1 : 0;
    out->items[i].rotary_within_travel = s.rotary_within_travel ? 1 : 0;
    out->items[i].linear_excess_mm = s.linear_excess_mm;
    out->items[i].branch = s.branch;
  }
  return r.reachable() ? KIN5_OK : KIN5_UNREACHABLE;
}

void kin5_translate_options_init(kin5_translate_options* options) {
  if (!options) return;
  *options = {};
  options->feed = "tcp";
  options->digits = -1;
  options->angle_tolerance_deg = -1.0;
}

kin5_status kin5_translate(const kin5_machine* from, const kin5_machine* to, const char* text, size_t size,
                           const kin5_translate_options* options, kin5_buffer* output, kin5_buffer* messages) {
  clear(output);
  clear(messages);
  std::string said;
  const char* failure = nullptr;  // what was thrown, said once the handler has returned
  std::string thrown;
  kin5_status status = KIN5_INTERNAL;
  try {
    if (!from || !to || !output || (!text && size)) {
      said = "kin5_translate: from, to and output must not be NULL, nor text unless size is 0\n";
      status = KIN5_BAD_ARGUMENT;
    } else {
      kin5_translate_options defaults;
      kin5_translate_options_init(&defaults);
      std::string out;
      status = translate(*from, *to, std::string(text ? text : "", size), options ? *options : defaults, out, said);
      if (status == KIN5_OK && !fill(output, out)) failure = "kin5: out of memory", status = KIN5_INTERNAL;
    }
  } catch (const std::bad_alloc&) {
    failure = "kin5: out of memory", status = KIN5_INTERNAL;
  } catch (const std::exception& e) {
    failure = "kin5: internal error: ", status = KIN5_INTERNAL;
    try {
      thrown = e.what();
    } catch (...) {
    }
  } catch (...) {
    failure = "kin5: internal error", status = KIN5_INTERNAL;
  }
  if (status != KIN5_OK && output) kin5_free(output->data), clear(output);
  if (!messages) return status;
  try {
    if (failure) said += std::string(failure) + thrown + '\n';
    if (!fill(messages, said)) return KIN5_INTERNAL;
  } catch (...) {
    if (!fill(messages, "kin5: out of memory\n")) return KIN5_INTERNAL;
  }
  return status;
}

}  // extern "C"
