// `postproc plot FILE -o out.svg`: the toolpath seen from above (XY), rapids dashed, feed moves solid,
// XY arcs as SVG arcs. Input: a `.trace` or NC code of a modelled controller (--dialect).
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <ostream>
#include <string>

#include "postproc/cli/cli.hpp"
#include "postproc/cli/cli_support.hpp"
#include "machines/registry/registry.hpp"
#include "postproc/cli/open_input.hpp"
#include "toolpath/command.hpp"
#include "toolpath/error.hpp"
#include "toolpath/value.hpp"

namespace postproc::cli {
namespace {

constexpr double kPi = 3.14159265358979323846;

struct Bounds {
  double x0 = std::numeric_limits<double>::max(), y0 = x0;
  double x1 = std::numeric_limits<double>::lowest(), y1 = x1;
  void add(double x, double y) {
    x0 = std::min(x0, x);
    y0 = std::min(y0, y);
    x1 = std::max(x1, x);
    y1 = std::max(y1, y);
  }
  bool empty() const { return x0 > x1; }
};

// Builds the two SVG paths (feeds, rapids) while following the tool position.
class Plotter {
public:
  void command(const toolpath::Command& c) {
    const bool rapid = c.name == "@rapid_move";
    const bool straight = rapid || c.name == "@line" || c.name == "@thread_move" || c.name == "@line_on";
    const bool arc = c.name == "@arc";
    if (c.name == "@start_program") {
      read_position(c, x_, y_, z_);
      known_ = true;
      return;
    }
    if (!straight && !arc) return;
    double x = x_, y = y_, z = z_;
    read_position(c, x, y, z);
    if (!known_) {  // the first move of a trace without a start position: begin there
      x_ = x, y_ = y, z_ = z, known_ = true;
      bounds_.add(x, y);
    }
    if (!arc && std::hypot(x - x_, y - y_) < 1e-9) {  // along Z only: nothing to draw from above
      z_ = z;
      return;
    }
    std::string& d = rapid ? rapids_ : feeds_;
    bool& pen = rapid ? rapid_pen_ : feed_pen_;
    if (!pen) d += fmt::format("M{} {}", num(x_), num(y_));
    pen = true;
    (rapid ? feed_pen_ : rapid_pen_) = false;
    bounds_.add(x_, y_);
    if (arc && !arc_to(c, x, y, d)) d += fmt::format("L{} {}", num(x), num(y));
    if (!arc) d += fmt::format("L{} {}", num(x), num(y));
    bounds_.add(x, y);
    x_ = x, y_ = y, z_ = z;
  }

  std::string svg() const {
    Bounds b = bounds_;
    if (b.empty()) b.add(0, 0);
    const double w = std::max(b.x1 - b.x0, 1.0), h = std::max(b.y1 - b.y0, 1.0);
    const double m = 0.05 * std::max(w, h);
    std::string out = fmt::format(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"{} {} {} {}\" width=\"800\" height=\"{}\">\n"
        "<!-- toolpath in XY, seen from +Z: feed moves solid, rapids dashed -->\n"
        "<g transform=\"scale(1,-1)\" fill=\"none\" stroke-linejoin=\"round\">\n",
        num(b.x0 - m), num(-(b.y1 + m)), num(w + 2 * m), num(h + 2 * m),
        static_cast<int>(std::lround(800 * (h + 2 * m) / (w + 2 * m))));
    if (!rapids_.empty())
      out += fmt::format("<path class=\"rapid\" stroke=\"#d04030\" stroke-width=\"1\" stroke-dasharray=\"4 3\" "
                         "vector-effect=\"non-scaling-stroke\" d=\"{}\"/>\n", rapids_);
    if (!feeds_.empty())
      out += fmt::format("<path class=\"feed\" stroke=\"#2050c0\" stroke-width=\"1.5\" "
                         "vector-effect=\"non-scaling-stroke\" d=\"{}\"/>\n", feeds_);
    out += "</g>\n</svg>\n";
    return out;
  }

private:
  static std::string num(double v) {
    const double r = std::round(v * 1e6) / 1e6;
    return fmt::format("{}", r == 0 ? 0.0 : r);
  }
  static double get(const toolpath::Command& c, const char* name, double fallback) {
    const toolpath::Value* v = c.find(name);
    return v ? v->as_number() : fallback;
  }
  static void read_position(const toolpath::Command& c, double& x, double& y, double& z) {
    x = get(c, "xpos", x);
    y = get(c, "ypos", y);
    z = get(c, "zpos", z);
  }

  // An XY arc as SVG arc commands (full circles in two halves); other planes as a polyline.
  bool arc_to(const toolpath::Command& c, double x, double y, std::string& d) {
    const toolpath::Value* plane = c.find("arc_plane");
    const toolpath::Value* dir = c.find("arc_direction");
    const bool ccw = dir && toolpath::iequals(dir->text, "CCW");
    double r = get(c, "radius", 0);
    double size = get(c, "arc_size", 0);
    if (r <= 0 || size <= 0) return false;
    if (!plane || toolpath::iequals(plane->text, "XY")) {
      const double cx = get(c, "xcenter", x_), cy = get(c, "ycenter", y_);
      const int sweep = ccw ? 1 : 0;  // positive angles turn counter-clockwise before the flip
      if (size >= 359.999) {
        const double a0 = std::atan2(y_ - cy, x_ - cx);
        const double mx = cx + r * std::cos(a0 + kPi), my = cy + r * std::sin(a0 + kPi);
        d += fmt::format("A{} {} 0 0 {} {} {}A{} {} 0 0 {} {} {}", num(r), num(r), sweep, num(mx), num(my), num(r),
                         num(r), sweep, num(x_), num(y_));
        bounds_.add(cx - r, cy - r);
        bounds_.add(cx + r, cy + r);
        if (std::hypot(x - x_, y - y_) > 1e-9) d += fmt::format("L{} {}", num(x), num(y));
        return true;
      }
      d += fmt::format("A{} {} 0 {} {} {} {}", num(r), num(r), size > 180 ? 1 : 0, sweep, num(x), num(y));
      const double a0 = std::atan2(y_ - cy, x_ - cx);
      for (int i = 1; i < 16; ++i) {  // the arc's extent for the view box
        const double a = a0 + (ccw ? 1 : -1) * size * kPi / 180 * i / 16;
        bounds_.add(cx + r * std::cos(a), cy + r * std::sin(a));
      }
      return true;
    }
    // ZX or YZ: the projection is a line or an ellipse; draw 32 chords.
    const bool zx = toolpath::iequals(plane->text, "ZX");
    const double c1 = get(c, zx ? "zcenter" : "ycenter", 0), c2 = get(c, zx ? "xcenter" : "zcenter", 0);
    const double s1 = zx ? z_ : y_, s2 = zx ? x_ : z_;
    const double a0 = std::atan2(s2 - c2, s1 - c1);
    for (int i = 1; i <= 32; ++i) {
      const double a = a0 + (ccw ? 1 : -1) * size * kPi / 180 * i / 32;
      const double p1 = c1 + r * std::cos(a), p2 = c2 + r * std::sin(a);
      const double px = zx ? p2 : x_ + (x - x_) * i / 32, py = zx ? y_ + (y - y_) * i / 32 : p1;
      d += fmt::format("L{} {}", num(i == 32 ? x : px), num(i == 32 ? y : py));
      bounds_.add(px, py);
    }
    return true;
  }

  std::string feeds_, rapids_;
  bool feed_pen_ = false, rapid_pen_ = false;
  double x_ = 0, y_ = 0, z_ = 0;
  bool known_ = false;
  Bounds bounds_;
};

// A trace by its extension; any other file is NC code of the registry's default controller.
std::string default_dialect(const std::string& path) {
  const std::string ext = std::filesystem::path(path).extension().string();
  return ext == ".trace" || ext == ".txt" ? "trace" : std::string(machines::default_controller().names().front());
}

std::string_view plot_dialect_help() {
  static const std::string help = dialect_help("input format (default: .trace and .txt a trace, else G-code)");
  return help;
}

int run_plot(const Arguments& args, std::ostream& out, std::ostream& err) {
  if (args.positional().size() != 1) throw UsageError{"expected one input file"};
  const std::string& input = args.positional()[0];
  const std::string output = args.value("--output");
  if (output.empty()) throw UsageError{"-o FILE.svg is required"};
  auto source = open_source(input, args.value("--dialect", default_dialect(input)), err, read_options(args));
  Plotter plot;
  toolpath::Command c;
  while (source->next(c)) plot.command(c);
  write_file_replacing(output, plot.svg());
  out << fmt::format("{}: wrote {}\n", input, output);
  return kOk;
}

}  // namespace

Subcommand plot_command() {
  return {
      "plot",
      "postproc plot [--dialect NAME] -o OUT.svg FILE",
      "Draw the toolpath in XY as SVG (rapids dashed, feed moves solid).",
      {
          {"--output", "-o", true, "the SVG file to write (written to a temporary name, then renamed)"},
          {"--dialect", "", true, plot_dialect_help()},
          kToolTableOption,
      },
      run_plot,
  };
}

}  // namespace postproc::cli
