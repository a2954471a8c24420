#include "render/animation_page.hpp"

#include <nlohmann/json.hpp>
#include <stdexcept>

#include "lattice/motion.hpp"
#include "render/viewer/assets.hpp"

namespace gridlock {

namespace {

std::string escape_html(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '<') out += "&lt;";
    else if (c == '>') out += "&gt;";
    else if (c == '&') out += "&amp;";
    else if (c == '"') out += "&quot;";
    else if (c == '\'') out += "&#39;";
    else out += c;
  }
  return out;
}

// The moving parts: [parent, coupling, then (event, dx, dy) per key frame].
nlohmann::json parts_json(const Animation& a) {
  using nlohmann::json;
  json parts = json::array();
  for (const auto& p : a.parts) {
    json row = json::array({p.parent == kNone ? -1 : static_cast<int64_t>(p.parent),
                            p.coupling == kNone ? -1 : static_cast<int64_t>(p.coupling)});
    for (size_t j = 0; j < p.key_event.size(); ++j)
      row.push_back(p.key_event[j]), row.push_back(p.key_disp[j].x), row.push_back(p.key_disp[j].y);
    parts.push_back(std::move(row));
  }
  return parts;
}

// Regions whose faces follow different nodes or grow: drawn on their own.
nlohmann::json resizing_json(const Regions& regions) {
  using nlohmann::json;
  json resizing = json::array();
  for (uint32_t r = 0; r < regions.size(); ++r) {
    const RegionShape& sh = regions.shapes[r];
    bool rigid = sh.kind == RegionKind::Node && sh.grow_op == kNone;
    for (int f = 0; f < 4; ++f) rigid = rigid && sh.ref[f] == sh.ref[0];
    if (rigid) continue;
    int kind = sh.kind == RegionKind::Node ? 0 : sh.kind == RegionKind::Inserted ? 1 : 2;
    int64_t op = sh.kind == RegionKind::Node ? -1 : static_cast<int64_t>(sh.id);
    resizing.push_back(json::array({r, kind, op, sh.base[0], sh.base[1], sh.base[2], sh.base[3], sh.ref[0], sh.ref[1],
                                    sh.ref[2], sh.ref[3], sh.grow_face, sh.grow_sign}));
  }
  return resizing;
}

// Inside <script>, "</script", and "<!--" followed by "<script", change how
// the element ends (the HTML parser's script data states): the page would
// stop working. In JSON, '<', '>' and '&' occur only inside strings, where
// \u003c, \u003e and \u0026 mean the same: none of them is left in the page.
std::string script_safe(const std::string& data) {
  std::string safe;
  safe.reserve(data.size());
  for (char c : data) {
    if (c == '<') safe += "\\u003c";
    else if (c == '>') safe += "\\u003e";
    else if (c == '&') safe += "\\u0026";
    else safe += c;
  }
  return safe;
}

// Replaces the one occurrence of mark in the viewer's template by text. The
// marks are the template's own (render/viewer/viewer.html): its title, the
// links to the stylesheet and script beside it, the empty data element.
void splice(std::string& page, const std::string& mark, const std::string& text) {
  const size_t at = page.find(mark);
  // A bug in the template, caught by every test that writes a page.
  if (at == std::string::npos) throw std::logic_error("render/viewer/viewer.html lacks " + mark);
  page.replace(at, mark.size(), text);
}

}  // namespace

std::string animation_html(const Instance& inst, const Schedule& s, const Animation& a, const std::string& title) {
  using nlohmann::json;
  Regions regions = Regions::build(inst);
  json d;
  d["title"] = title;
  d["model"] = s.discrete() ? "discrete" : "continuous";
  d["den"] = a.den;
  d["events"] = a.events;
  d["start"] = a.start;
  d["stop"] = a.stop.str();
  json cells = json::array();
  for (const Vec2& c : inst.cells()) cells.push_back(c.x), cells.push_back(c.y);
  d["cells"] = std::move(cells);
  d["anchor"] = inst.anchor();
  d["part_of_node"] = a.part_of_node;
  d["parts"] = parts_json(a);
  d["resizing"] = resizing_json(regions);
  json ops = json::array();
  for (const Operation& op : inst.ops())
    ops.push_back(json::array(
        {op.name, static_cast<int>(op.kind), op.u, op.v == kNone ? -1 : static_cast<int64_t>(op.v), op.coupling}));
  d["ops"] = std::move(ops);
  json names = json::array(), coupling_ops = json::array(), first_op = json::array();
  for (const Coupling& q : inst.couplings()) {
    names.push_back(q.name);
    first_op.push_back(q.ops.front());
    std::string list;
    for (OpId k : q.ops) list += (list.empty() ? "" : " ") + inst.ops()[k].name;
    coupling_ops.push_back(list);
  }
  d["couplings"] = std::move(names);
  d["coupling_ops"] = std::move(coupling_ops);
  d["couplings_first_op"] = std::move(first_op);
  json edges = json::array();
  for (const Edge& e : inst.edges())
    if (e.op == kNone) edges.push_back(e.a), edges.push_back(e.b);
  d["edges"] = std::move(edges);
  if (a.collision) {
    const Collision& c = *a.collision;
    json cj;
    cj["kind"] = c.kind == Collision::Kind::Node ? "node" : "cycle";
    cj["time"] = c.time.str();
    cj["text"] = describe(inst, regions, c);
    if (c.kind == Collision::Kind::Node) cj["a"] = c.a, cj["b"] = c.b;
    cj["cycle"] = c.cycle;
    cj["moving"] = c.moving;
    d["collision"] = std::move(cj);
  } else {
    d["collision"] = nullptr;
  }
  std::string page(viewer::html);
  splice(page, "__GRIDLOCK_TITLE__", escape_html(title));
  splice(page, "<link rel=\"stylesheet\" href=\"viewer.css\">", "<style>\n" + std::string(viewer::css) + "</style>");
  splice(page, "<script type=\"application/json\" id=\"data\"></script>",
         "<script type=\"application/json\" id=\"data\">" + script_safe(d.dump()) + "</script>");
  splice(page, "<script src=\"viewer.js\"></script>", "<script>\n" + std::string(viewer::script) + "</script>");
  return page;
}

}  // namespace gridlock
