// The committed sphere maps of docs/tables in a real browser: one page tiles every ordered
// pair's SVG, headless Chromium takes one screenshot of it, and each tile is checked:
//   * it is drawn (not blank: most pixels not white);
//   * its legend shows every class colour (the swatches, exact colours);
//   * on its two discs, the share of each class colour among the pixels of class colours
//     matches the sphere share the pair's table gives (the map shows what the table says), to
//     3 percentage points (curves and markers are not class colours and are left out; cells on
//     the rim, the line of a one-rotary source and antialiased edges account for the rest);
//   * its discs are filled to the rim (under 0.5 % white in the band 1.5 to 3 pixels inside it,
//     pole markers left out).
// The screenshot stays in the build directory (maps.png) for a human to look at.
//   match_maps_test CHROMIUM DOCS_TABLES_DIR WORK_DIR      (exit 0 when every check holds)
// A plain program, not a Catch2 suite: it runs one browser and needs no test framework.
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include <png.h>

#include <kin5/machines/catalog.hpp>
#include <kin5/reach/pair_table.hpp>
#include <kin5/reach/sphere_svg.hpp>
#include <kin5/translate/setup.hpp>

namespace {

using namespace kin5;

std::string chromium, tables_dir, work_dir;

constexpr int columns = 4;
constexpr double scale = 0.5;
const int tile_w = static_cast<int>(reach::svg_detail::width_px * scale);
const int tile_h = static_cast<int>(reach::svg_detail::height_px * scale);

struct pair_info {
  std::string stem;
  std::array<double, reach::map_colour_count> share{};
  std::vector<std::array<double, 2>> markers_px;  ///< where pole markers sit, map pixels
};

std::vector<pair_info> pairs() {
  std::vector<pair_info> out;
  for (const machine_model* from : machines::catalog_models)
    for (const machine_model* to : machines::catalog_models) {
      const rigid_transform setup = default_setup(from->geometry.id, to->geometry.id);
      const auto t = reach::make_pair_table(*from, *to, setup, true, false);
      out.push_back({"match-" + t.from + "-to-" + t.to, t.sphere_share, {}});
      for (const auto& m : t.markers)
        for (bool upper : {true, false})
          out.back().markers_px.push_back(reach::svg_detail::to_px(reach::project(m.u, upper)));
    }
  return out;
}

/// An RGBA image read with libpng's simplified API.
struct image {
  int width = 0, height = 0;
  std::vector<unsigned char> rgba;
  std::array<int, 3> at(int x, int y) const {
    const auto* p = &rgba[static_cast<std::size_t>((y * width + x) * 4)];
    return {p[0], p[1], p[2]};
  }
};

image read_png(const std::string& path) {
  png_image png{};
  png.version = PNG_IMAGE_VERSION;
  image out;
  if (!png_image_begin_read_from_file(&png, path.c_str())) return out;
  png.format = PNG_FORMAT_RGBA;
  out.rgba.resize(PNG_IMAGE_SIZE(png));
  if (!png_image_finish_read(&png, nullptr, out.rgba.data(), 0, nullptr)) return {};
  out.width = static_cast<int>(png.width), out.height = static_cast<int>(png.height);
  return out;
}

std::array<int, 3> rgb(const char* hex) {
  const long v = std::strtol(hex + 1, nullptr, 16);
  return {static_cast<int>((v >> 16) & 255), static_cast<int>((v >> 8) & 255), static_cast<int>(v & 255)};
}

int failures = 0;
void check(bool ok, const std::string& what) {
  if (ok) return;
  ++failures;
  std::fprintf(stderr, "FAIL: %s\n", what.c_str());
}

bool same(const std::array<int, 3>& a, const std::array<int, 3>& b) {
  return std::abs(a[0] - b[0]) <= 2 && std::abs(a[1] - b[1]) <= 2 && std::abs(a[2] - b[2]) <= 2;
}

/// The index page: every map at `scale`, `columns` per row, no margins.
std::string page(const std::vector<pair_info>& ps) {
  std::string html = "<!DOCTYPE html><html><head><meta charset=\"utf-8\"><style>body{margin:0;background:#fff}"
                     "img{position:absolute;width:" + std::to_string(tile_w) + "px;height:" + std::to_string(tile_h) +
                     "px}</style></head><body>\n";
  for (std::size_t i = 0; i < ps.size(); ++i)
    html += "<img style=\"left:" + std::to_string(static_cast<int>(i % columns) * tile_w) + "px;top:" +
            std::to_string(static_cast<int>(i / columns) * tile_h) + "px\" src=\"file://" + tables_dir + "/" + ps[i].stem +
            ".svg\">\n";
  return html + "</body></html>\n";
}

/// Screenshots the page of every map and checks each tile; returns the number of failures.
int check_maps() {
  const auto ps = pairs();
  const std::string html = work_dir + "/maps.html", shot = work_dir + "/maps.png";
  std::ofstream(html) << page(ps);
  std::remove(shot.c_str());
  const int rows = static_cast<int>((ps.size() + columns - 1) / columns);
  const std::string command = "\"" + chromium + "\" --headless --no-sandbox --disable-gpu --disable-dev-shm-usage " +
                              "--hide-scrollbars --force-device-scale-factor=1 --user-data-dir=\"" + work_dir +
                              "/chromium-profile\" --window-size=" + std::to_string(columns * tile_w) + "," +
                              std::to_string(rows * tile_h) + " --screenshot=\"" + shot + "\" \"file://" + html +
                              "\" > \"" + work_dir + "/chromium.log\" 2>&1";
  if (std::system(command.c_str()) != 0) {
    std::fprintf(stderr, "FAIL: chromium did not run; see %s/chromium.log\n", work_dir.c_str());
    return 1;
  }
  const image img = read_png(shot);
  if (img.width != columns * tile_w || img.height != rows * tile_h) {
    std::fprintf(stderr, "FAIL: screenshot %s is %dx%d, expected %dx%d\n", shot.c_str(), img.width, img.height,
                 columns * tile_w, rows * tile_h);
    return 1;
  }
  double worst_share = 0.0;
  std::string worst_stem;
  double worst_rim = 0.0;
  for (std::size_t i = 0; i < ps.size(); ++i) {
    const int x0 = static_cast<int>(i % columns) * tile_w, y0 = static_cast<int>(i / columns) * tile_h;
    std::array<long, reach::map_colour_count> on_discs{};
    std::array<long, reach::map_colour_count> anywhere{};
    long white = 0, rim = 0, rim_white = 0;
    for (int y = y0; y < y0 + tile_h; ++y)
      for (int x = x0; x < x0 + tile_w; ++x) {
        const auto c = img.at(x, y);
        white += c[0] == 255 && c[1] == 255 && c[2] == 255;
        bool on_disc = false, on_rim = false;
        for (double cx : reach::svg_detail::disc_x_px) {
          const double dx = (x + 0.5 - x0) / scale - cx, dy = (y + 0.5 - y0) / scale - reach::svg_detail::disc_y_px;
          const double r2 = dx * dx + dy * dy;
          on_disc = on_disc || r2 < std::pow(reach::svg_detail::disc_radius_px - 3.0, 2);
          on_rim = on_rim || (r2 >= std::pow(reach::svg_detail::disc_radius_px - 3.0, 2) &&
                              r2 < std::pow(reach::svg_detail::disc_radius_px - 1.5, 2));
        }
        for (const auto& m : ps[i].markers_px)  // a pole's open circle on the equator is white
          on_rim = on_rim && std::hypot((x + 0.5 - x0) / scale - m[0], (y + 0.5 - y0) / scale - m[1]) > 9.0;
        rim += on_rim, rim_white += on_rim && c[0] == 255 && c[1] == 255 && c[2] == 255;
        for (std::size_t k = 1; k < reach::map_colour_count; ++k)
          if (same(c, rgb(reach::map_palette[k].fill))) (on_disc ? on_discs : anywhere)[k]++;
      }
    check(static_cast<double>(white) < 0.8 * tile_w * tile_h, ps[i].stem + ": blank");
    // The discs are filled to the rim: no white in the band just inside it (away from the pole
    // markers, whose open circle is white).
    worst_rim = std::max(worst_rim, static_cast<double>(rim_white) / static_cast<double>(rim));
    check(rim_white * 200 < rim, ps[i].stem + ": white at the rim (" + std::to_string(rim_white) + " of " +
                                    std::to_string(rim) + " pixels)");
    long disc_pixels = 0;
    for (long n : on_discs) disc_pixels += n;
    for (std::size_t k = 1; k < reach::map_colour_count; ++k) {
      const std::string what = ps[i].stem + ", colour " + reach::map_palette[k].fill;
      // Its legend swatch: 11 x 7 pixels at half scale, less the border.
      check(anywhere[k] >= 40, what + ": not in the legend (" + std::to_string(anywhere[k]) + " pixels)");
      const double seen = static_cast<double>(on_discs[k]) / static_cast<double>(disc_pixels);
      if (std::abs(seen - ps[i].share[k]) > worst_share) worst_share = std::abs(seen - ps[i].share[k]), worst_stem = what;
      check(std::abs(seen - ps[i].share[k]) < 0.03, what + ": " + std::to_string(100 * seen) + " % of the discs, table " +
                                                        std::to_string(100 * ps[i].share[k]) + " %");
    }
  }
  std::printf("%zu maps checked in %s; largest share difference %.2f percentage points (%s); white at the rim "
              "%.2f %% at most; %d failures\n",
              ps.size(), shot.c_str(), 100 * worst_share, worst_stem.c_str(), 100 * worst_rim, failures);
  return failures;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 4) {
    std::fprintf(stderr, "usage: %s CHROMIUM DOCS_TABLES_DIR WORK_DIR\n", argv[0]);
    return 2;
  }
  chromium = argv[1], tables_dir = argv[2], work_dir = argv[3];
  return check_maps() == 0 ? 0 : 1;
}
