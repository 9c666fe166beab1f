// The embedded HTML viewer page with a document filled in (viewer/README.md
// describes the page and its build).
#include "cueball/io/viewer_page.hpp"

#include <cmath>
#include <cstddef>
#include <string>

#include <stdexcept>

namespace cueball {

// Defined in the source that cmake/EmbedFile.cmake generates from
// viewer/dist/cueball-viewer.html.
extern const unsigned char kViewerTemplate[];
extern const std::size_t kViewerTemplate_size;

std::string_view viewer_template() {
  return {reinterpret_cast<const char*>(kViewerTemplate), kViewerTemplate_size};
}

std::string viewer_page(std::string_view template_text, std::string_view result_json) {
  const std::size_t at = template_text.find(kViewerResultToken);
  if (at == std::string_view::npos || template_text.find(kViewerResultToken, at + 1) != std::string_view::npos)
    throw std::logic_error("the viewer template must hold the result token exactly once");
  std::string page;
  page.reserve(template_text.size() + result_json.size() + result_json.size() / 16);
  page.append(template_text.substr(0, at));
  for (const char c : result_json) {
    if (c == '<')
      page.append("\\u003c");
    else
      page.push_back(c);
  }
  page.append(template_text.substr(at + kViewerResultToken.size()));
  return page;
}

}  // namespace cueball
