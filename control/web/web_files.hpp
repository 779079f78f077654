// The web monitor's files (control/web/), compiled into the binary by
// embed_web.cmake so slmp-sim serves them with nothing installed beside it.
#pragma once

#include <string_view>
#include <vector>

namespace slmp::control {

struct WebFile {
    std::string_view name;           // "index.html"
    std::string_view content_type;
    std::string_view body;
};

const std::vector<WebFile>& web_files();

}  // namespace slmp::control
