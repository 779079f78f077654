// GET / and the monitor's scripts and styles (web_files.hpp). The page is
// plain HTML/JS/CSS with no build step; its one third-party library, uPlot
// (the trend plots), is served as its npm package ships it.
#include "control/endpoints/api.hpp"
#include "control/web/web_files.hpp"

namespace slmp::control {

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

}  // namespace slmp::control
