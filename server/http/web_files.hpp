// The web monitor's files (server/http/web/), compiled into the binary by
// embed_web.cmake so slmp-sim serves them with nothing installed beside it.
#pragma once

#include <string_view>
#include <vector>

namespace slmp::server::http {

struct WebFile {
    std::string_view name;           // "index.html"
    std::string_view content_type;
    std::string_view body;
};

const std::vector<WebFile>& web_files();

}  // namespace slmp::server::http
