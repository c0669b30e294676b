#include "html.hpp"

#include <algorithm>
#include <cstdint>
#include <fstream>
#include <sstream>

namespace hil::rig {
namespace {

// One style for every page: the verdict stands out, tables read as tables.
const char* const style = R"(body{font-family:sans-serif;margin:1.5em;max-width:1500px;color:#222}
h1{margin-bottom:.2em}h2{border-bottom:1px solid #ccc;padding-bottom:.1em;margin-top:1.4em}
.verdict{display:inline-block;font-size:2em;font-weight:bold;padding:.15em .6em;border-radius:.2em;color:#fff}
.PASSED,.PASS{background:#2e7d32}.FAILED,.FAIL,.ERROR{background:#c62828}.SKIPPED{background:#757575}
td.PASSED,td.PASS,td.FAILED,td.FAIL,td.ERROR,td.SKIPPED{color:#fff;font-weight:bold}
table{border-collapse:collapse;margin:.5em 0}th,td{border:1px solid #ccc;padding:.2em .5em;text-align:left;vertical-align:top}
th{background:#f0f0f0}td.num{text-align:right;font-variant-numeric:tabular-nums}
pre{background:#f7f7f7;border:1px solid #ddd;padding:.6em;overflow-x:auto}
img{max-width:100%;border:1px solid #ddd}figure{margin:1em 0}.because{color:#c62828}
tr.violation td,td.over{background:#ffd6d6}td.over{font-weight:bold}
.zoom{overflow:hidden;border:1px solid #ddd;cursor:grab}.zoom img{transform-origin:0 0;border:none;display:block}
)";

// Zoomable figures (issue 37): the wheel zooms about the pointer, a drag
// pans, a double click resets. The figures are SVG: sharp at any zoom.
const char* const zoom_script = R"(<script>
document.querySelectorAll('.zoom').forEach(function (box) {
  var img = box.querySelector('img'), s = 1, x = 0, y = 0, drag = null;
  function apply() { img.style.transform = 'translate(' + x + 'px,' + y + 'px) scale(' + s + ')'; }
  box.addEventListener('wheel', function (ev) {
    ev.preventDefault();
    var r = box.getBoundingClientRect(), mx = ev.clientX - r.left, my = ev.clientY - r.top;
    var n = Math.min(50, Math.max(1, s * (ev.deltaY < 0 ? 1.25 : 0.8)));
    x = mx - (mx - x) * n / s; y = my - (my - y) * n / s; s = n;
    if (s === 1) { x = 0; y = 0; }
    apply();
  }, {passive: false});
  box.addEventListener('mousedown', function (ev) { drag = [ev.clientX - x, ev.clientY - y]; ev.preventDefault(); });
  window.addEventListener('mousemove', function (ev) { if (drag) { x = ev.clientX - drag[0]; y = ev.clientY - drag[1]; apply(); } });
  window.addEventListener('mouseup', function () { drag = null; });
  box.addEventListener('dblclick', function () { s = 1; x = 0; y = 0; apply(); });
});
</script>
)";

}  // namespace

std::string escape_markup(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default:
        if (static_cast<unsigned char>(c) < 0x20 && c != '\t' && c != '\n' && c != '\r') out += "\xEF\xBF\xBD";
        else out += c;
    }
  }
  return out;
}

std::string html_page(const std::string& title, const std::string& body) {
  return "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" + escape_markup(title) +
         "</title>\n<style>\n" + style + "</style>\n</head>\n<body>\n" + body +
         (body.find("class=\"zoom\"") != std::string::npos ? zoom_script : "") + "</body>\n</html>\n";
}

std::string data_uri(const std::string& path, const std::string& media_type) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return "";
  std::ostringstream all;
  all << in.rdbuf();
  const std::string bytes = all.str();
  static const char* const digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out = "data:" + media_type + ";base64,";
  out.reserve(out.size() + (bytes.size() + 2) / 3 * 4);
  for (size_t i = 0; i < bytes.size(); i += 3) {
    const size_t n = std::min<size_t>(3, bytes.size() - i);
    uint32_t v = 0;
    for (size_t k = 0; k < 3; ++k) v = v << 8 | (k < n ? static_cast<unsigned char>(bytes[i + k]) : 0u);
    for (size_t k = 0; k < 4; ++k) out += k <= n ? digits[(v >> (18 - 6 * k)) & 63] : '=';
  }
  return out;
}

std::string html_pre(const std::string& text) { return "<pre>" + escape_markup(text) + "</pre>\n"; }

}  // namespace hil::rig
