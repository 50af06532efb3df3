#include "postproc/cli/explain_html.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "postproc/engine/slot_marker.hpp"
#include "toolpath/geometry.hpp"
#include "toolpath/value.hpp"

namespace postproc::cli {
namespace {

namespace geo = toolpath::geometry;

// The page: styles, the layout, and the script that reads the data block. Everything inline.
constexpr std::string_view kHead = R"html(<!doctype html>
<html lang="en"><head><meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<title>postproc explain</title>
<style>
:root { --row: 18px; font: 13px/1.4 system-ui, sans-serif; color: #222; }
body { margin: 0; display: grid; grid-template-rows: auto 1fr; height: 100vh; }
header { padding: 6px 10px; background: #f3f3f3; border-bottom: 1px solid #ccc; }
header b { margin-right: 1em; }
main { display: grid; grid-template-columns: 1fr 1fr 1fr; min-height: 0; }
section { display: grid; grid-template-rows: auto 1fr; min-height: 0; border-right: 1px solid #ddd; }
h2 { font-size: 13px; margin: 0; padding: 4px 8px; background: #fafafa; border-bottom: 1px solid #eee; }
.list { overflow: auto; position: relative; font: 12px/var(--row) ui-monospace, monospace; }
.row { position: absolute; left: 0; right: 0; white-space: pre; padding: 0 6px; cursor: pointer; height: var(--row); }
.row .n { color: #999; display: inline-block; min-width: 5ch; text-align: right; margin-right: 1ch; }
.row.wrote { background: #eef6ff; }
.row.sel { background: #ffd54f; }
.row:hover { outline: 1px solid #bbb; }
#plots { display: grid; grid-template-rows: 1fr 1fr auto; min-height: 0; }
canvas { width: 100%; height: 100%; display: block; cursor: crosshair; border-bottom: 1px solid #eee; }
#info { padding: 4px 8px; font: 12px ui-monospace, monospace; min-height: 3em; }
</style></head><body>
<header><b>postproc explain</b><span id="what"></span></header>
<main>
<section><h2>NC program <select id="file"></select></h2><div class="list" id="nc"></div></section>
<section><h2 id="srcname">post</h2><div class="list" id="src"></div></section>
<section id="plots"><canvas id="xy" title="XY"></canvas><canvas id="xz" title="XZ"></canvas><div id="info">Click an NC line or a segment.</div></section>
</main>
<script id="data" type="application/json">)html";

constexpr std::string_view kTail = R"html(</script>
<script>
"use strict";
const D = JSON.parse(document.getElementById('data').textContent);
const $ = (id) => document.getElementById(id);
$('what').textContent = D.job + '  ·  ' + D.post;
const ROW = 18;
// A list that draws only the rows in view (and a margin): a 200 000-line program keeps ~100 nodes.
function VList(el, count, render) {
  const spacer = document.createElement('div');
  spacer.style.height = (count * ROW) + 'px';
  spacer.style.position = 'relative';
  el.textContent = '';
  el.appendChild(spacer);
  let first = -1, last = -1;
  const rows = new Map();
  function draw(force) {
    const a = Math.max(0, Math.floor(el.scrollTop / ROW) - 30);
    const b = Math.min(count, Math.ceil((el.scrollTop + el.clientHeight) / ROW) + 30);
    if (!force && a === first && b === last) return;
    first = a; last = b;
    spacer.textContent = '';
    rows.clear();
    for (let i = a; i < b; i++) {
      const r = render(i);
      r.style.top = (i * ROW) + 'px';
      spacer.appendChild(r);
      rows.set(i, r);
    }
  }
  el.onscroll = () => draw(false);  // a list made again for the same pane replaces the old one's handler
  return {
    draw, row: (i) => rows.get(i),
    show(i) { const top = i * ROW; if (top < el.scrollTop || top > el.scrollTop + el.clientHeight - ROW) el.scrollTop = Math.max(0, top - el.clientHeight / 2); draw(true); },
  };
}
let file = 0, selLine = -1, selCommand = -1, selGpp = 0, source = -1;
// Where each command's segments are, and its first NC line (per file).
const segOf = new Map();
for (let s = 0; s < D.segCommand.length; s++) {
  const c = D.segCommand[s];
  if (!segOf.has(c)) segOf.set(c, []);
  segOf.get(c).push(s);
}
let lineOf = new Map();  // command -> its first line in the file shown
function firstLineOf(command) { const l = lineOf.get(command); return l === undefined ? -1 : l; }
// The GPP lines that wrote output, as 'source:line'.
const wrote = new Set();
for (const f of D.files) for (const l of f.lines) if (l[3]) wrote.add(l[4] + ':' + l[3]);
const written = (l) => D.procedures[l[2]] + ' (' + D.sources[l[4]].name + ':' + l[3] + ')';
let nc;
function showFile(f) {
  file = f;
  lineOf = new Map();
  D.files[f].lines.forEach((l, i) => { if (l[1] >= 0 && !lineOf.has(l[1])) lineOf.set(l[1], i); });
  nc = VList($('nc'), D.files[f].lines.length, (i) => {
    const l = D.files[file].lines[i];
    const r = document.createElement('div');
    r.className = 'row' + (i === selLine ? ' sel' : '');
    r.dataset.line = i + 1;
    r.innerHTML = '<span class="n"></span>';
    r.firstChild.textContent = i + 1;
    r.appendChild(document.createTextNode(l[0]));
    r.title = l[1] >= 0 ? ('#' + l[1] + ' ' + written(l)) : '';
    r.addEventListener('click', () => select(i));
    return r;
  });
  nc.draw(true);
}
// The source pane shows one file: the post, or the include file of the line selected last.
let src;
function showSource(s) {
  source = s;
  $('srcname').textContent = D.sources[s].name;
  const text = D.sources[s].lines;
  src = VList($('src'), text.length, (i) => {
    const r = document.createElement('div');
    r.className = 'row' + (wrote.has(s + ':' + (i + 1)) ? ' wrote' : '') + (i + 1 === selGpp ? ' sel' : '');
    r.innerHTML = '<span class="n"></span>';
    r.firstChild.textContent = i + 1;
    r.appendChild(document.createTextNode(text[i]));
    r.addEventListener('click', () => { const l = D.files[file].lines.findIndex((x) => x[3] === i + 1 && x[4] === s); if (l >= 0) select(l); });
    return r;
  });
}
showSource(0);
D.files.forEach((f, i) => { const o = document.createElement('option'); o.value = i; o.textContent = f.name; $('file').appendChild(o); });
$('file').addEventListener('change', (e) => { selLine = -1; showFile(Number(e.target.value)); });
// Plots: XY (top) and XZ, each fitted to the toolpath.
const views = [{ el: $('xy'), a: 0, b: 1 }, { el: $('xz'), a: 0, b: 2 }];
function fit(v) {
  const w = v.el.clientWidth || 400, h = v.el.clientHeight || 300;
  v.el.width = w; v.el.height = h;
  let lo = [Infinity, Infinity], hi = [-Infinity, -Infinity];
  const S = D.segments;
  for (let i = 0; i < S.length; i += 3) {
    lo[0] = Math.min(lo[0], S[i + v.a]); hi[0] = Math.max(hi[0], S[i + v.a]);
    lo[1] = Math.min(lo[1], S[i + v.b]); hi[1] = Math.max(hi[1], S[i + v.b]);
  }
  if (!isFinite(lo[0])) { lo = [0, 0]; hi = [1, 1]; }
  const k = Math.min((w - 20) / Math.max(hi[0] - lo[0], 1e-9), (h - 20) / Math.max(hi[1] - lo[1], 1e-9));
  v.x = (p) => 10 + (p - lo[0]) * k;
  v.y = (p) => h - 10 - (p - lo[1]) * k;
}
function drawPlot(v) {
  const g = v.el.getContext('2d'), S = D.segments;
  g.clearRect(0, 0, v.el.width, v.el.height);
  for (const rapid of [1, 0]) {
    g.beginPath();
    g.strokeStyle = rapid ? '#bbb' : '#1565c0';
    g.setLineDash(rapid ? [4, 3] : []);
    g.lineWidth = 1;
    for (let s = 0; s < D.segCommand.length; s++) {
      if (D.segRapid[s] !== rapid) continue;
      const i = s * 6;
      g.moveTo(v.x(S[i + v.a]), v.y(S[i + v.b]));
      g.lineTo(v.x(S[i + 3 + v.a]), v.y(S[i + 3 + v.b]));
    }
    g.stroke();
  }
  g.setLineDash([]);
  const sel = segOf.get(selCommand) || [];
  g.beginPath(); g.strokeStyle = '#e53935'; g.lineWidth = 3;
  for (const s of sel) { const i = s * 6; g.moveTo(v.x(S[i + v.a]), v.y(S[i + v.b])); g.lineTo(v.x(S[i + 3 + v.a]), v.y(S[i + 3 + v.b])); }
  g.stroke();
}
function redraw() { for (const v of views) drawPlot(v); }
// The segment nearest to a click, in screen space.
function pick(v, px, py) {
  const S = D.segments;
  let best = -1, bestD = 36;
  for (let s = 0; s < D.segCommand.length; s++) {
    if (!lineOf.has(D.segCommand[s])) continue;  // a command that wrote nothing in this file
    const i = s * 6;
    const x0 = v.x(S[i + v.a]), y0 = v.y(S[i + v.b]), x1 = v.x(S[i + 3 + v.a]), y1 = v.y(S[i + 3 + v.b]);
    const dx = x1 - x0, dy = y1 - y0, l2 = dx * dx + dy * dy;
    const t = l2 > 0 ? Math.max(0, Math.min(1, ((px - x0) * dx + (py - y0) * dy) / l2)) : 0;
    const ex = x0 + t * dx - px, ey = y0 + t * dy - py, d = ex * ex + ey * ey;
    if (d < bestD) { bestD = d; best = s; }
  }
  return best;
}
for (const v of views) v.el.addEventListener('click', (e) => {
  const r = v.el.getBoundingClientRect();
  const s = pick(v, e.clientX - r.left, e.clientY - r.top);
  if (s < 0) return;
  const line = firstLineOf(D.segCommand[s]);
  if (line >= 0) select(line); else { selCommand = D.segCommand[s]; redraw(); }
});
function select(i) {
  const l = D.files[file].lines[i];
  selLine = i; selCommand = l[1]; selGpp = l[3];
  nc.show(i);
  if (selGpp && l[4] !== source) showSource(l[4]);
  if (selGpp) src.show(selGpp - 1); else src.draw(true);
  $('info').textContent = D.files[file].name + ':' + (i + 1) + '  ' + l[0] + '\n' +
    (l[1] >= 0 ? 'toolpath command #' + l[1] + ', written by ' + written(l) : 'no toolpath command');
  redraw();
  document.body.dataset.selected = JSON.stringify({ line: i + 1, command: selCommand, gpp: selGpp, segments: (segOf.get(selCommand) || []).length });
}
showFile(0);
for (const v of views) fit(v);
redraw();
addEventListener('resize', () => { for (const v of views) fit(v); redraw(); });
// Self-test hooks for the browser test: #select=N clicks NC line N, #plotclick=C clicks the middle
// of command C's first segment in the XY plot; the result lands in body[data-selftest].
(function selftest() {
  const m = /^#(select|plotclick)=(\d+)$/.exec(location.hash);
  if (!m) return;
  const n = Number(m[2]);
  if (m[1] === 'select') {
    nc.show(n - 1);
    const row = nc.row(n - 1);
    if (row) row.click();
  } else {  // the middle of the command's longest segment, in the view where it is longest
    const S = D.segments;
    let best = null;
    for (const s of segOf.get(n) || []) for (const v of views) {
      const i = s * 6, dx = v.x(S[i + 3 + v.a]) - v.x(S[i + v.a]), dy = v.y(S[i + 3 + v.b]) - v.y(S[i + v.b]);
      const len = Math.hypot(dx, dy);
      if (!best || len > best.len) best = { len, v, x: (v.x(S[i + v.a]) + v.x(S[i + 3 + v.a])) / 2, y: (v.y(S[i + v.b]) + v.y(S[i + 3 + v.b])) / 2 };
    }
    if (best) {
      const r = best.v.el.getBoundingClientRect();
      best.v.el.dispatchEvent(new MouseEvent('click', { clientX: r.left + best.x, clientY: r.top + best.y }));
    }
  }
  const selRow = document.querySelector('#nc .row.sel'), srcRow = document.querySelector('#src .row.sel');
  document.body.dataset.selftest = JSON.stringify({
    selected: document.body.dataset.selected ? JSON.parse(document.body.dataset.selected) : null,
    ncHighlighted: selRow ? Number(selRow.dataset.line) : 0,
    srcHighlighted: srcRow ? Number(srcRow.firstChild.textContent) : 0,
    srcFile: D.sources[source].name,
    elements: document.getElementsByTagName('*').length,
  });
})();
</script></body></html>
)html";

}  // namespace

ExplainPage::ExplainPage(std::string job, std::string post_path) : job_(std::move(job)), post_path_(std::move(post_path)) {}

void ExplainPage::on_line(const LineEvent& e) {
  if (e.directive) return;
  if (files_.empty() || files_[current_].name != e.file) {  // the main program first, then as opened
    auto it = std::find_if(files_.begin(), files_.end(), [&](const File& f) { return f.name == e.file; });
    if (it == files_.end()) it = files_.insert(files_.end(), File{std::string(e.file), {}});
    current_ = static_cast<std::size_t>(it - files_.begin());
  }
  Line line;
  line.text = slot::readable(e.text);
  if (!e.origin.command.empty()) line.command = static_cast<std::int64_t>(e.origin.command_index);
  if (!e.origin.procedure.empty()) {
    auto [it, added] = procedure_ids_.emplace(std::string(e.origin.procedure), static_cast<std::uint32_t>(procedures_.size()));
    if (added) procedures_.emplace_back(e.origin.procedure);
    line.procedure = it->second;
    line.gpp_line = static_cast<std::uint32_t>(std::max(0, e.origin.source_line));
    auto [source, new_source] = source_ids_.emplace(std::string(e.origin.include_file), static_cast<std::uint32_t>(sources_.size()));
    if (new_source) sources_.emplace_back(e.origin.include_file);
    line.source = source->second;
  }
  files_[current_].lines.push_back(std::move(line));
}

void ExplainPage::on_slot_filled(std::uint32_t slot, std::string_view text) { slots_[slot] = std::string(text); }

void ExplainPage::segment(const Eigen::Vector3d& from, const Eigen::Vector3d& to, bool rapid, std::size_t command) {
  // Micrometres are enough for a plot, and keep the page's numbers short.
  for (int a = 0; a < 3; ++a) segments_.push_back(std::round(from[a] * 1000) / 1000);
  for (int a = 0; a < 3; ++a) segments_.push_back(std::round(to[a] * 1000) / 1000);
  segment_commands_.push_back(static_cast<std::uint32_t>(command));
  segment_rapid_.push_back(rapid ? 1 : 0);
}

void ExplainPage::posted(const toolpath::Command& c) {
  const bool rapid = toolpath::iequals(c.name, "@rapid_move"), line = toolpath::iequals(c.name, "@line"),
             arc = toolpath::iequals(c.name, "@arc");
  if (!rapid && !line && !arc && !toolpath::iequals(c.name, "@drill_point")) {
    if (auto x = c.number("xpos"), y = c.number("ypos"), z = c.number("zpos"); x && y && z && toolpath::iequals(c.name, "@change_tool")) {
      position_ = {*x, *y, *z};  // where the machine is after the change (no motion drawn)
      position_known_ = true;
    }
    return;
  }
  Eigen::Vector3d to = position_;
  static constexpr std::array<std::string_view, 3> kAxes = {"xpos", "ypos", "zpos"};
  for (int a = 0; a < 3; ++a)
    if (auto v = c.number(kAxes[static_cast<std::size_t>(a)])) to[a] = *v;
  if (!position_known_) {  // the first position: nothing to draw from
    position_ = to;
    position_known_ = true;
    return;
  }
  if (arc) {
    const geo::Arc a = geo::arc_of(c, position_, to);
    const int n = std::clamp(geo::chord_count(a, 22.5, 0.0), 1, 16);  // enough for a plot
    Eigen::Vector3d from = position_;
    for (int i = 1; i <= n; ++i) {
      const Eigen::Vector3d p = i == n ? to : a.point_at(a.sweep * i / n);
      segment(from, p, false, c.index);
      from = p;
    }
  } else if ((to - position_).norm() > 1e-9) {
    segment(position_, to, rapid, c.index);
  }
  position_ = to;
}

std::string ExplainPage::html() const {
  using json = nlohmann::json;
  json data;
  data["job"] = job_;
  data["post"] = std::filesystem::path(post_path_).filename().string();
  data["procedures"] = procedures_;
  json files = json::array();
  for (const File& f : files_) {
    json lines = json::array();
    for (const Line& l : f.lines) {
      std::string text = l.text;
      for (const auto& [slot, value] : slots_) {  // {?N}: a number known only later
        const std::string marker = fmt::format("{{?{}}}", slot);
        for (std::size_t at = text.find(marker); at != std::string::npos; at = text.find(marker, at + value.size()))
          text.replace(at, marker.size(), value);
      }
      lines.push_back(json::array({text, l.command, l.procedure, l.gpp_line, l.source}));
    }
    files.push_back({{"name", f.name}, {"lines", std::move(lines)}});
  }
  data["files"] = std::move(files);
  // The post, then each include file that wrote a line (named relative to the post's folder).
  json sources = json::array();
  for (const std::string& name : sources_) {
    const std::filesystem::path path = name.empty() ? std::filesystem::path(post_path_)
                                                    : std::filesystem::path(post_path_).parent_path() / name;
    json text = json::array();
    std::ifstream in(path, std::ios::binary);
    for (std::string line; std::getline(in, line);) {
      if (!line.empty() && line.back() == '\r') line.pop_back();
      text.push_back(std::move(line));
    }
    sources.push_back({{"name", name.empty() ? data["post"].get<std::string>() : name}, {"lines", std::move(text)}});
  }
  data["sources"] = std::move(sources);
  data["segments"] = segments_;
  data["segCommand"] = segment_commands_;
  data["segRapid"] = segment_rapid_;
  // Inside <script>, "</" would end the block: written as "<\/", which JSON reads as "</".
  std::string text = data.dump(-1, ' ', false, json::error_handler_t::replace);
  std::string escaped;
  escaped.reserve(text.size());
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '<' && i + 1 < text.size() && text[i + 1] == '/') escaped += "<\\";
    else escaped += text[i];
  }
  return std::string(kHead) + escaped + std::string(kTail);
}

}  // namespace postproc::cli
