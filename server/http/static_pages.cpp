// GET / and the monitor's scripts and styles (web_files.hpp). The page is
// plain HTML/JS/CSS: no build step, no third-party code.
#include "server/http/api.hpp"
#include "server/http/web_files.hpp"

namespace slmp::server::http {

void add_static_pages(Router& router) {
    for (const auto& file : web_files()) {
        auto serve = [&file](const ApiRequest&) {
            Reply reply;
            reply.content_type = std::string(file.content_type);
            reply.body = std::string(file.body);
            return reply;
        };
        router.add(Verb::get, "/" + std::string(file.name), {}, serve);
        if (file.name == "index.html") router.add(Verb::get, "/", {}, serve);
    }
}

}  // namespace slmp::server::http
