// What `clrender view` answers, route by route (docs/command-line.md, Viewer):
//   GET  /, /viewer.js, /viewer.css   the page, from the binary (view/embedded_assets.h)
//   GET  /frame.png, /frame.rgba      a frame for the query's camera (view/view_camera.h)
//   GET  /scene.json                  the scene's camera, size, samples and path
//   GET  /explain                     the --explain-pixel text of pixel x, y
//   POST /export                      the recorded keys as a scene file in --output-dir
//   POST /render-video, GET /job      that scene rendered to a video, in the background
// Every request passes the RequestGuard first; another method on these paths is 405 (with
// Allow), every other path is 404, and no request reads a file.
#pragma once

#include <httplib.h>

#include <memory>
#include <string>

#include "scene/scene.h"
#include "view/answer_budget.h"
#include "view/path_export.h"
#include "view/render_service.h"
#include "view/request_guard.h"
#include "view/video_job.h"

namespace clr {

struct ViewSession {
    const Scene& scene;
    RenderService& renderer;
    const PathExporter& exporter;
    VideoJobs& videos;
    const RequestGuard& guard;
    AnswerBudget& answers;  // the frame answers' bytes held while clients take them
    // GET /scene.json's text, made once: the scene does not change while the viewer runs, and
    // a path of a million keys makes it 78 MB, which every answer sends from this one copy.
    std::shared_ptr<const std::string> scene_summary;
};

// Installs the guard and the routes on `server`. `session` must outlive the server's requests.
void add_view_routes(httplib::Server& server, ViewSession& session);

// The headers every answer of the viewer carries, refusals included (docs/command-line.md,
// view): nothing for a cache, another site's frame or a content sniffer, no referrer (the
// address holds the token), no ranges, and the page's Content-Security-Policy.
httplib::Headers view_answer_headers();

// Answers 415, with a JSON error naming the header, a request whose body cpp-httplib would
// decode or parse itself before any route sees it, and returns true; false for any other.
// Called before the body is read (the pre-routing handler, and the Expect: 100-continue one).
bool refused_body_format(const httplib::Request& request, httplib::Response& response);

// The guard's facts of an httplib request.
RequestFacts request_facts(const httplib::Request& request);

}  // namespace clr
