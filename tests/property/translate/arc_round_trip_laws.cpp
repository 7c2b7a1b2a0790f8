// Arcs through CL data and back: reverse∘post keeps every arc. A generated CL program of arcs
// (`CIRCLE` after the GOTO of its start, the next GOTO its end, in XY, ZX or YZ, either way
// round) is read by the APT reader, posted (`post`, as text) into each NC dialect and read by
// that dialect's reader, then reversed (`reverse`, as text) into CL data and read by the APT
// reader again. Each of the three readings has the drawn arcs: plane, direction, centre (in the
// plane), radius and end point, to the rounding of the written numbers. The 840D applies the
// tool length along Y under G18 and X under G19 (docs/dialects/siemens.md), so its programs
// have XY arcs only; ZX and YZ arcs posted to it are refused, which a second law checks.
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <rapidcheck.h>

#include <kin5/kin5.hpp>

using namespace kin5;
using namespace kin5::program;

namespace {

/// One arc as a reader gives it.
struct arc_seen {
  arc_plane plane = arc_plane::xy;
  bool clockwise = false;
  vec3 centre_mm{};  // in the plane of its start
  double radius_mm = 0;
  vec3 end_mm{};
};

/// The in-plane unit axes (e1, e2) of plane `p`, with e1 × e2 its normal (XY: x, y; ZX: z, x; YZ: y, z).
std::pair<vec3, vec3> axes_of(arc_plane p) {
  if (p == arc_plane::xy) return {unit_x, unit_y};
  if (p == arc_plane::zx) return {unit_z, unit_x};
  return {unit_y, unit_z};
}

/// The arcs of `blocks`, in order, with the centre of a Heidenhain CC block or a signed radius
/// resolved against the start point.
std::vector<arc_seen> arcs_of(const std::vector<block>& blocks) {
  std::vector<arc_seen> out;
  vec3 at{};
  std::optional<vec3> centre;
  for (const block& b : blocks) {
    if (b.arc && b.arc->centre_mm) centre = b.arc->centre_mm;
    if (!b.moves()) continue;
    const vec3 end{b.axes.x_mm.value_or(at.x), b.axes.y_mm.value_or(at.y), b.axes.z_mm.value_or(at.z)};
    if (is_arc(*b.motion)) {
      translate_detail::arc_path path{b.arc ? b.arc->plane : arc_plane::xy, *b.motion == motion_kind::arc_cw,
                                      centre, b.arc ? b.arc->radius_mm : std::nullopt};
      if (path.radius_mm) path.centre_mm.reset();
      const vec3 c = translate_detail::arc_centre_mm(path, at, end).value_or(vec3{1e9, 1e9, 1e9});
      vec3 d = end - c;
      translate_detail::set_normal_component(d, path.plane, 0.0);
      out.push_back({path.plane, path.clockwise, c, norm(d), end});
    }
    at = end;
  }
  return out;
}

bool same(const std::vector<arc_seen>& a, const std::vector<arc_seen>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t k = 0; k < a.size(); ++k)
    if (a[k].plane != b[k].plane || a[k].clockwise != b[k].clockwise || norm(a[k].centre_mm - b[k].centre_mm) > 0.003 ||
        std::fabs(a[k].radius_mm - b[k].radius_mm) > 0.003 || norm(a[k].end_mm - b[k].end_mm) > 0.002)
      return false;
  return true;
}

/// `v` with 3 decimals, as CL text.
std::string num(double v) { return program::format_number(v, 3); }
std::string point(const vec3& p) { return num(p.x) + "," + num(p.y) + "," + num(p.z); }

/// CL text of 1 to 3 arcs, each reached by a straight move, the tool along +Z; in XY only when
/// `xy_only`.
std::string draw_cl(bool xy_only) {
  std::string text = "UNITS/MM\nLOADTL/1\nFEDRAT/MMPM,500\n";
  const int n = *rc::gen::inRange(1, 4);
  for (int k = 0; k < n; ++k) {
    const arc_plane p = xy_only ? arc_plane::xy : *rc::gen::element(arc_plane::xy, arc_plane::zx, arc_plane::yz);
    const bool cw = *rc::gen::arbitrary<bool>();
    const vec3 c{200.0 * k + *rc::gen::inRange(-50, 50), double(*rc::gen::inRange(-50, 50)), double(*rc::gen::inRange(0, 80))};
    const double r = *rc::gen::inRange(2, 40);
    const double from = *rc::gen::inRange(0, 360) * pi / 180, sweep = *rc::gen::inRange(5, 355) * pi / 180;
    const double to = cw ? from - sweep : from + sweep;
    const auto [e1, e2] = axes_of(p);
    const vec3 start = c + r * std::cos(from) * e1 + r * std::sin(from) * e2;
    const vec3 end = c + r * std::cos(to) * e1 + r * std::sin(to) * e2;
    const vec3 n_vec = (cw ? -1.0 : 1.0) * cross(e1, e2);
    text += "GOTO/" + point(start) + ",0,0,1\nCIRCLE/" + point(c) + "," + num(n_vec.x) + "," + num(n_vec.y) + "," +
            num(n_vec.z) + "," + num(r) + "\nGOTO/" + point(end) + "\n";
  }
  return text + "FINI\n";
}

/// `text` in dialect `from` through `t` into dialect `to`.
std::string run(block_translator& t, const std::string& text, dialect from, dialect to) {
  string_sink out;
  const auto r = stream_text(t, text, from, "a", to, out);
  RC_ASSERT(r.ok(t));
  return out.text;
}

}  // namespace

TEST_CASE("arcs: post then reverse keeps each arc, read by every dialect's reader") {
  using M = machines::ac_trunnion;
  const dialect apt_id = id_of<apt::dialect>();
  for (const dialect d : nc_dialect_ids()) {
    const bool xy_only = d == id_of<siemens::dialect>();
    const bool ok = rc::check(std::string("apt -> ") + std::string(name(d)) + " -> apt", [d, apt_id, xy_only] {
      const std::string text = draw_cl(xy_only);
      const read_result cl = read(apt_id, text, "a");
      RC_ASSERT(cl.ok());
      const auto want = arcs_of(cl.parsed.blocks);
      RC_ASSERT(!want.empty());
      const std::string nc_text = run(*make_post<M>(apt_id, d, "a", report_detail::exceptions_only, {}), text, apt_id, d);
      const read_result nc = read(d, nc_text, "n");
      RC_ASSERT(nc.ok());
      RC_ASSERT(same(arcs_of(nc.parsed.blocks), want));
      const std::string cl_text = run(*make_reverse<M>(d, "n", report_detail::exceptions_only, {}), nc_text, d, apt_id);
      const read_result back = read(apt_id, cl_text, "back");
      RC_ASSERT(back.ok());
      RC_ASSERT(same(arcs_of(back.parsed.blocks), want));
    });
    CHECK(ok);
  }
}

TEST_CASE("arcs: a ZX or YZ arc posted to the 840D is refused at its CIRCLE, not written") {
  using M = machines::ac_trunnion;
  const dialect apt_id = id_of<apt::dialect>(), sie = id_of<siemens::dialect>();
  for (const char* arc : {"GOTO/0,0,15\nCIRCLE/0,0,5,0,1,0,10\nGOTO/10,0,5\n", "GOTO/0,10,5\nCIRCLE/0,0,5,-1,0,0,10\nGOTO/0,0,-5\n"}) {
    auto t = make_post<M>(apt_id, sie, "a", report_detail::exceptions_only, {});
    string_sink out;
    const auto r = stream_text(*t, std::string("UNITS/MM\nLOADTL/1\nFEDRAT/MMPM,500\n") + arc + "FINI\n", apt_id, "a", sie, out);
    CHECK(!r.ok(*t));
  }
}
