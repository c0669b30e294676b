#pragma once
// Markup shared by the rig's XML and HTML outputs (JUnit, report.html): text
// escaped, a page that stands alone (inline CSS, images as data: URIs).
#include <string>

namespace hil::rig {

// Text for XML/HTML: & < > " ' as entities; control characters XML 1.0
// does not allow (all but tab, LF, CR) become U+FFFD.
std::string escape_markup(const std::string& text);

// A whole HTML5 page: `title` (escaped here), the rig's inline style sheet,
// `body` as given (markup).
std::string html_page(const std::string& title, const std::string& body);

// A file's bytes as a data: URI ("data:image/png;base64,..."); "" if it
// cannot be read.
std::string data_uri(const std::string& path, const std::string& media_type);

// <pre> of escaped text.
std::string html_pre(const std::string& text);

}  // namespace hil::rig
