#include "render/picture.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <sstream>

namespace gridlock {

namespace {

const char* kPalette[] = {"#d62728", "#1f77b4", "#2ca02c", "#9467bd", "#ff7f0e",
                          "#17becf", "#8c564b", "#e377c2", "#bcbd22", "#7f7f7f"};

std::string colour_of(CouplingId q) { return kPalette[q % 10]; }

std::string fmt(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f", v);
  std::string s = buf;
  while (s.back() == '0') s.pop_back();
  if (s.back() == '.') s.pop_back();
  return s == "-0" ? "0" : s;
}

std::string xml_escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '<') out += "&lt;";
    else if (c == '>') out += "&gt;";
    else if (c == '&') out += "&amp;";
    else if (c == '"') out += "&quot;";
    else out += c;
  }
  return out;
}

// A name as LaTeX text: every character that LaTeX treats specially (the
// .grid names allow _ ~ and '; a title may hold anything) written so that it
// prints as itself. Used outside math mode.
std::string tex_escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '\\': out += "\\textbackslash{}"; break;
      case '~': out += "\\textasciitilde{}"; break;
      case '^': out += "\\textasciicircum{}"; break;
      case '_':
      case '{':
      case '}':
      case '#':
      case '$':
      case '%':
      case '&':
        out += '\\';
        out += c;
        break;
      default: out += c;
    }
  }
  return out;
}

std::string op_label(const Instance& inst, OpId k) {
  const Operation& op = inst.ops()[k];
  const Coupling& q = inst.couplings()[op.coupling];
  return q.ops.size() == 1 && q.name == op.name ? op.name : op.name + " [" + q.name + "]";
}

// The rectangles to draw: the configuration at opt.time under opt.schedule,
// or, without a schedule, the initial one (no operation started).
std::vector<RectQ> rects_to_draw(const Instance& inst, const RenderOptions& opt) {
  if (opt.schedule != nullptr) return configuration_at(inst, *opt.schedule, opt.time);
  Schedule none;
  none.start.assign(inst.couplings().size(), Rational(1 << 20));  // nothing has started
  return configuration_at(inst, none, Rational(0));
}

// Where grid units land in the picture: each rectangle's box in grid units,
// the window they span with one unit of margin, S pixels per unit, and a
// title band of title_h pixels above the grid.
struct View {
  struct Box {
    double x0, x1, y0, y1;
  };
  std::vector<Box> box;
  double minx, miny, maxx, maxy;
  double S;
  double title_h;
  // Grid y grows upward; SVG y grows downward.
  double X(double x) const { return (x - minx) * S; }
  double Y(double y) const { return title_h + (maxy - y) * S; }
  std::pair<double, double> centre(NodeId w) const {
    return std::pair<double, double>{(box[w].x0 + box[w].x1) / 2, (box[w].y0 + box[w].y1) / 2};
  }
};

// The boxes of rects and the window around them (title_h is left to the caller).
View view_of(const std::vector<RectQ>& rects, double S) {
  View v;
  v.box.resize(rects.size());
  v.minx = std::numeric_limits<double>::max(), v.miny = v.minx, v.maxx = -v.minx, v.maxy = -v.minx;
  for (size_t r = 0; r < rects.size(); ++r) {
    v.box[r] = {rects[r].xlo.approx(), rects[r].xhi.approx(), rects[r].ylo.approx(), rects[r].yhi.approx()};
    v.minx = std::min(v.minx, v.box[r].x0 - 1), v.maxx = std::max(v.maxx, v.box[r].x1 + 1);
    v.miny = std::min(v.miny, v.box[r].y0 - 1), v.maxy = std::max(v.maxy, v.box[r].y1 + 1);
  }
  v.S = S;
  v.title_h = 0;
  return v;
}

// A light grid line at every whole grid unit in the window.
void draw_grid(std::ostream& o, const View& v) {
  o << "<g stroke=\"#eeeeee\" stroke-width=\"1\">\n";
  for (double x = std::ceil(v.minx); x <= v.maxx; x += 1)
    o << "<line x1=\"" << fmt(v.X(x)) << "\" y1=\"" << fmt(v.Y(v.maxy)) << "\" x2=\"" << fmt(v.X(x)) << "\" y2=\""
      << fmt(v.Y(v.miny)) << "\"/>\n";
  for (double y = std::ceil(v.miny); y <= v.maxy; y += 1)
    o << "<line x1=\"" << fmt(v.X(v.minx)) << "\" y1=\"" << fmt(v.Y(y)) << "\" x2=\"" << fmt(v.X(v.maxx)) << "\" y2=\""
      << fmt(v.Y(y)) << "\"/>\n";
  o << "</g>\n";
}

// The plain edges (no operation on them) as lines between node centres.
void draw_edges(std::ostream& o, const Instance& inst, const View& v) {
  o << "<g stroke=\"#555555\" stroke-width=\"2\">\n";
  for (const auto& e : inst.edges()) {
    if (e.op != kNone) continue;
    auto [ax, ay] = v.centre(e.a);
    auto [bx, by] = v.centre(e.b);
    o << "<line x1=\"" << fmt(v.X(ax)) << "\" y1=\"" << fmt(v.Y(ay)) << "\" x2=\"" << fmt(v.X(bx)) << "\" y2=\""
      << fmt(v.Y(by)) << "\"/>\n";
  }
  o << "</g>\n";
}

// Each growth's target cell as a dashed square in its coupling's colour.
void draw_growth_targets(std::ostream& o, const Instance& inst, const View& v) {
  for (const auto& op : inst.ops()) {
    if (op.kind != OpKind::Grow) continue;
    Vec2 c = inst.cells()[op.u] + unit(op.dir);
    o << "<rect x=\"" << fmt(v.X(static_cast<double>(c.x)) + 3) << "\" y=\""
      << fmt(v.Y(static_cast<double>(c.y) + 1) + 3) << "\" width=\"" << fmt(v.S - 6) << "\" height=\"" << fmt(v.S - 6)
      << "\" fill=\"none\" stroke=\"" << colour_of(op.coupling) << "\" stroke-dasharray=\"4 3\"/>\n";
  }
}

// Every region as a rounded rectangle titled with its label; the regions of
// the collision (if any) in red, a width-0 one as a red bar.
void draw_regions(std::ostream& o, const Instance& inst, const Regions& regions, const View& v,
                  const Collision* collision) {
  const auto& box = v.box;
  const double S = v.S;
  std::vector<char> hit(box.size(), 0);
  if (collision && collision->kind == Collision::Kind::Node) hit[collision->a] = hit[collision->b] = 1;
  if (collision && collision->kind == Collision::Kind::Cycle)
    for (NodeId w : collision->cycle) hit[w] = 1;
  for (size_t r = 0; r < box.size(); ++r) {
    double w = box[r].x1 - box[r].x0, h = box[r].y1 - box[r].y0;
    if (w <= 0 || h <= 0) {
      // A region of width 0 is no node yet (or no more); at a collision it is
      // one of the pair (a growth just starting), so show it as a red bar.
      if (hit[r])
        o << "<line x1=\"" << fmt(v.X(box[r].x0)) << "\" y1=\"" << fmt(v.Y(box[r].y0)) << "\" x2=\""
          << fmt(v.X(box[r].x1)) << "\" y2=\"" << fmt(v.Y(box[r].y1))
          << "\" stroke=\"#d62728\" stroke-width=\"6\"><title>"
          << xml_escape(region_label(inst, regions, static_cast<uint32_t>(r))) << " (width 0)</title></line>\n";
      continue;
    }
    bool node = regions.shapes[r].kind == RegionKind::Node;
    double inset = std::min({0.08, w / 4, h / 4});
    std::string fill = hit[r] ? "#ff9896" : node ? "#dddddd" : "#aec7e8";
    std::string stroke = hit[r] ? "#d62728" : "#333333";
    o << "<rect x=\"" << fmt(v.X(box[r].x0 + inset)) << "\" y=\"" << fmt(v.Y(box[r].y1 - inset)) << "\" width=\""
      << fmt((w - 2 * inset) * S) << "\" height=\"" << fmt((h - 2 * inset) * S) << "\" rx=\"3\" fill=\"" << fill
      << "\" fill-opacity=\"0.85\" stroke=\"" << stroke << "\" stroke-width=\"" << (hit[r] ? 3 : 1.5) << "\"><title>"
      << xml_escape(region_label(inst, regions, static_cast<uint32_t>(r))) << "</title></rect>\n";
  }
}

// Each operation as an arrow in its coupling's colour, labelled with its name:
// a double arrow for an expansion, an arrow toward u with a cross for a
// contraction, an arrow into the target (half way at a moment) for a growth.
void draw_operations(std::ostream& o, const Instance& inst, const View& v, bool at_moment) {
  for (OpId k = 0; k < inst.ops().size(); ++k) {
    const Operation& op = inst.ops()[k];
    std::string col = colour_of(op.coupling);
    auto [ux, uy] = v.centre(op.u);
    Vec2 d = unit(op.dir);
    double tx, ty;
    if (op.kind == OpKind::Grow) {
      tx = ux + static_cast<double>(d.x) * (at_moment ? 0.5 : 1.0);
      ty = uy + static_cast<double>(d.y) * (at_moment ? 0.5 : 1.0);
    } else {
      std::tie(tx, ty) = v.centre(op.v);
    }
    double sx = ux + static_cast<double>(d.x) * 0.22, sy = uy + static_cast<double>(d.y) * 0.22;
    double ex = tx - static_cast<double>(d.x) * 0.22, ey = ty - static_cast<double>(d.y) * 0.22;
    if (op.kind == OpKind::Contract) std::swap(sx, ex), std::swap(sy, ey);  // arrow toward u
    o << "<line x1=\"" << fmt(v.X(sx)) << "\" y1=\"" << fmt(v.Y(sy)) << "\" x2=\"" << fmt(v.X(ex)) << "\" y2=\""
      << fmt(v.Y(ey)) << "\" stroke=\"" << col << "\" stroke-width=\"3\" marker-end=\"url(#ah)\""
      << (op.kind == OpKind::Expand ? " marker-start=\"url(#ah)\"" : "") << "/>\n";
    double mx = (ux + tx) / 2, my = (uy + ty) / 2;
    if (op.kind == OpKind::Contract) {
      o << "<path d=\"M" << fmt(v.X(mx) - 5) << "," << fmt(v.Y(my) - 5) << " l10,10 M" << fmt(v.X(mx) - 5) << ","
        << fmt(v.Y(my) + 5) << " l10,-10\" stroke=\"" << col << "\" stroke-width=\"2.5\"/>\n";
    }
    double lx = mx + (d.x == 0 ? 0.12 : 0), ly = my + (d.y == 0 ? 0.12 : 0);
    o << "<text x=\"" << fmt(v.X(lx) + 2) << "\" y=\"" << fmt(v.Y(ly) - 2) << "\" fill=\"" << col
      << "\" font-weight=\"bold\">" << xml_escape(op.name) << "</text>\n";
  }
}

// The legend below the picture, starting at pixel row top: the first 12
// couplings by colour with their operations, "..." if there are more.
void draw_legend(std::ostream& o, const Instance& inst, double top, bool at_moment) {
  double ly = top;
  o << "<text x=\"8\" y=\"" << fmt(ly) << "\" fill=\"#333\">couplings (colour: operations)"
    << (at_moment ? "" : "; dot: anchor; dashed: growth target") << "</text>\n";
  for (CouplingId q = 0; q < inst.couplings().size() && q < 12; ++q) {
    ly += 18;
    std::string ops;
    for (OpId k : inst.couplings()[q].ops) ops += (ops.empty() ? "" : ", ") + inst.ops()[k].name;
    o << "<rect x=\"8\" y=\"" << fmt(ly - 10) << "\" width=\"12\" height=\"12\" fill=\"" << colour_of(q) << "\"/>"
      << "<text x=\"26\" y=\"" << fmt(ly) << "\">" << xml_escape(inst.couplings()[q].name + ": " + ops) << "</text>\n";
  }
  if (inst.couplings().size() > 12) o << "<text x=\"8\" y=\"" << fmt(ly + 18) << "\">...</text>\n";
}

}  // namespace

std::string render_svg(const Instance& inst, const RenderOptions& opt) {
  Regions regions = Regions::build(inst);
  bool at_moment = opt.schedule != nullptr;
  View v = view_of(rects_to_draw(inst, opt), opt.cell_px);
  double legend_h = 18.0 * static_cast<double>(std::min<size_t>(inst.couplings().size(), 12) + 1) + 8;
  v.title_h = opt.title.empty() && !at_moment ? 0 : 26;
  double W = (v.maxx - v.minx) * v.S, H = (v.maxy - v.miny) * v.S;
  std::ostringstream o;
  o << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << fmt(std::max(W, 440.0)) << "\" height=\""
    << fmt(H + legend_h + v.title_h) << "\" font-family=\"Helvetica, Arial, sans-serif\" font-size=\"12\">\n";
  o << "<defs><marker id=\"ah\" viewBox=\"0 0 10 10\" refX=\"9\" refY=\"5\" markerWidth=\"5\" markerHeight=\"5\" "
       "orient=\"auto-start-reverse\"><path d=\"M0,0 L10,5 L0,10 z\" fill=\"context-stroke\"/></marker></defs>\n";
  o << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  std::string title = opt.title;
  if (at_moment && title.empty()) title = "configuration at time " + opt.time.str();
  if (!title.empty()) o << "<text x=\"8\" y=\"18\" font-size=\"14\">" << xml_escape(title) << "</text>\n";
  draw_grid(o, v);
  draw_edges(o, inst, v);
  if (!at_moment) draw_growth_targets(o, inst, v);  // initial picture only
  draw_regions(o, inst, regions, v, opt.collision);
  draw_operations(o, inst, v, at_moment);
  auto [ax, ay] = v.centre(inst.anchor());
  o << "<circle cx=\"" << fmt(v.X(ax - 0.25)) << "\" cy=\"" << fmt(v.Y(ay + 0.25))
    << "\" r=\"4\" fill=\"black\"><title>anchor</title></circle>\n";
  draw_legend(o, inst, v.title_h + H + 18, at_moment);
  o << "</svg>\n";
  return o.str();
}

std::string render_tikz(const Instance& inst) {
  std::ostringstream o;
  o << "% gridlock instance: " << inst.num_nodes() << " nodes, " << inst.ops().size() << " operations\n";
  o << "% needs \\usetikzlibrary{arrows.meta}\n";
  o << "\\begin{tikzpicture}[x=0.8cm,y=0.8cm,>={Stealth[length=2mm]}]\n";
  for (CouplingId q = 0; q < inst.couplings().size() && q < 10; ++q) {
    unsigned rgb = static_cast<unsigned>(std::stoul(std::string(kPalette[q]).substr(1), nullptr, 16));
    o << "\\definecolor{q" << q << "}{RGB}{" << (rgb >> 16) << "," << ((rgb >> 8) & 255) << "," << (rgb & 255) << "}\n";
  }
  const auto& c = inst.cells();
  for (const auto& e : inst.edges())
    if (e.op == kNone)
      o << "\\draw[gray!70!black,line width=1pt] (" << c[e.a].x << ".5," << c[e.a].y << ".5) -- (" << c[e.b].x << ".5,"
        << c[e.b].y << ".5);\n";
  for (NodeId w = 0; w < inst.num_nodes(); ++w)
    o << "\\draw[fill=gray!20,rounded corners=1pt] (" << c[w].x << ".08," << c[w].y << ".08) rectangle +(0.84,0.84);\n";
  for (OpId k = 0; k < inst.ops().size(); ++k) {
    const Operation& op = inst.ops()[k];
    Vec2 d = unit(op.dir);
    std::string col = "q" + std::to_string(op.coupling % 10);
    double ux = static_cast<double>(c[op.u].x) + 0.5, uy = static_cast<double>(c[op.u].y) + 0.5;
    double tx = ux + static_cast<double>(d.x), ty = uy + static_cast<double>(d.y);
    const char* arrow = op.kind == OpKind::Expand ? "<->" : op.kind == OpKind::Contract ? "<-" : "->";
    if (op.kind == OpKind::Grow)
      o << "\\draw[" << col << ",dashed] (" << fmt(tx - 0.42) << "," << fmt(ty - 0.42) << ") rectangle +(0.84,0.84);\n";
    o << "\\draw[" << col << ",very thick," << arrow << "] (" << fmt(ux + 0.2 * static_cast<double>(d.x)) << ","
      << fmt(uy + 0.2 * static_cast<double>(d.y)) << ") -- node[above,font=\\scriptsize]{" << tex_escape(op.name)
      << "} (" << fmt(tx - 0.2 * static_cast<double>(d.x)) << "," << fmt(ty - 0.2 * static_cast<double>(d.y)) << ");\n";
  }
  o << "\\fill (" << c[inst.anchor()].x << ".25," << c[inst.anchor()].y << ".75) circle (2pt);\n";
  o << "\\end{tikzpicture}\n";
  return o.str();
}

namespace {
struct CellBox {
  int64_t minx, maxx, miny, maxy;
};
CellBox ascii_box(const Instance& inst) {
  const auto& c = inst.cells();
  CellBox b{c[0].x, c[0].x, c[0].y, c[0].y};
  auto grow_box = [&](Vec2 p) {
    b.minx = std::min(b.minx, p.x), b.maxx = std::max(b.maxx, p.x);
    b.miny = std::min(b.miny, p.y), b.maxy = std::max(b.maxy, p.y);
  };
  for (const auto& p : c) grow_box(p);
  for (const auto& op : inst.ops())
    if (op.kind == OpKind::Grow) grow_box(c[op.u] + unit(op.dir));
  return b;
}
}  // namespace

std::string ascii_too_large(const Instance& inst) {
  const CellBox b = ascii_box(inst);
  if (b.maxx - b.minx <= 400 && b.maxy - b.miny <= 400) return "";
  return "too large for ASCII: " + std::to_string(b.maxx - b.minx + 1) + " x " + std::to_string(b.maxy - b.miny + 1) +
         " cells (at most 401 x 401; draw it as SVG)";
}

std::string render_ascii(const Instance& inst) {
  const auto& c = inst.cells();
  int64_t minx = c[0].x, maxx = c[0].x, miny = c[0].y, maxy = c[0].y;
  auto grow_box = [&](Vec2 p) {
    minx = std::min(minx, p.x), maxx = std::max(maxx, p.x), miny = std::min(miny, p.y), maxy = std::max(maxy, p.y);
  };
  for (const auto& p : c) grow_box(p);
  for (const auto& op : inst.ops())
    if (op.kind == OpKind::Grow) grow_box(c[op.u] + unit(op.dir));
  if (maxx - minx > 400 || maxy - miny > 400)
    return "(too large for ASCII: " + std::to_string(maxx - minx + 1) + " x " + std::to_string(maxy - miny + 1) +
           " cells)\n";
  size_t W = static_cast<size_t>(2 * (maxx - minx) + 1), H = static_cast<size_t>(2 * (maxy - miny) + 1);
  std::vector<std::string> canvas(H, std::string(W, ' '));
  auto at = [&](int64_t x2, int64_t y2) -> char& {  // doubled coordinates
    return canvas[static_cast<size_t>(2 * maxy - y2)][static_cast<size_t>(x2 - 2 * minx)];
  };
  for (NodeId w = 0; w < inst.num_nodes(); ++w) at(2 * c[w].x, 2 * c[w].y) = w == inst.anchor() ? '@' : 'o';
  for (const auto& e : inst.edges()) {
    int64_t x2 = c[e.a].x + c[e.b].x, y2 = c[e.a].y + c[e.b].y;
    char ch = c[e.a].y == c[e.b].y ? '-' : '|';
    if (e.op != kNone) ch = inst.ops()[e.op].kind == OpKind::Expand ? 'E' : 'C';
    at(x2, y2) = ch;
  }
  for (const auto& op : inst.ops()) {
    if (op.kind != OpKind::Grow) continue;
    Vec2 t = c[op.u] + unit(op.dir);
    char& ch = at(2 * t.x, 2 * t.y);
    ch = ch != ' ' ? '!' : op.dir == Dir::PosX ? '>' : op.dir == Dir::NegX ? '<' : op.dir == Dir::PosY ? '^' : 'v';
  }
  std::ostringstream o;
  for (auto& row : canvas) {
    while (!row.empty() && row.back() == ' ') row.pop_back();
    o << row << '\n';
  }
  o << "anchor @ " << inst.node_label(inst.anchor()) << "; operations:\n";
  for (OpId k = 0; k < inst.ops().size(); ++k) {
    const Operation& op = inst.ops()[k];
    o << "  " << op_label(inst, k) << ": " << op_kind_name(op.kind) << ' ' << inst.node_label(op.u) << ' '
      << dir_name(op.dir) << '\n';
  }
  return o.str();
}

}  // namespace gridlock
