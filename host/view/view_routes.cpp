#include "view/view_routes.h"

#include <algorithm>
#include <cctype>
#include <memory>
#include <new>
#include <optional>
#include <regex>
#include <stdexcept>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/errors.h"
#include "core/interruption.h"
#include "core/printable_text.h"
#include "output/image_writer.h"
#include "view/bounded_server.h"
#include "view/camera_keys.h"
#include "view/client_connection.h"
#include "view/embedded_assets.h"
#include "view/query_tokens.h"
#include "view/render_cost.h"
#include "view/scene_summary.h"
#include "view/view_camera.h"
#include "view/view_parameters.h"
#include "view/view_server.h"

namespace clr {
namespace {

using httplib::Request;
using httplib::Response;

// `body` as the answers' JSON text: invalid UTF-8 in a string replaced, never a throw.
std::string json_text(const nlohmann::json& body) {
    return body.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

void send_json(Response& response, int status, const nlohmann::json& body) {
    response.status = status;
    response.set_content(json_text(body), "application/json");
}

void send_error(Response& response, int status, const std::string& message, const std::string& parameter = "") {
    nlohmann::json body = {{"error", message}};
    if (!parameter.empty()) body["parameter"] = parameter;
    send_json(response, status, body);
}

// What the page loads, and nothing more: its own scripts, style and requests, and its icon (an
// empty data: image). No inline script, no handler attribute, no script from data: or blob:,
// no plugin, frame or form: text that ever reached the page as markup could run nothing. (A
// dropped image is decoded from its bytes, and the download is a blob: link, not an image.)
const char* const kContentSecurityPolicy =
    "default-src 'none'; script-src 'self'; style-src 'self'; img-src 'self' data:; connect-src 'self'; "
    "frame-ancestors 'none'; base-uri 'none'; form-action 'none'";

// A frame refused because the answers still being sent hold the answer budget (503).
class FramesInFlight : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Runs a route, turning every failure into a JSON answer: the server keeps serving whatever
// one request did.
template <typename Route>
void answer(Response& response, Route&& route) {
    try {
        route();
    } catch (const ParameterError& error) {
        send_error(response, 400, error.what(), error.parameter());
    } catch (const FrameAbandoned& error) {
        send_error(response, 503, error.what());  // nobody reads it
    } catch (const FramesInFlight& error) {
        response.set_header("Retry-After", "1");
        send_error(response, 503, error.what());
    } catch (const Interrupted&) {
        send_error(response, 503, "the viewer is stopping");
    } catch (const DeviceError& error) {
        send_error(response, 500, std::string("OpenCL: ") + error.what());
    } catch (const OutputError& error) {
        send_error(response, 409, error.what(), "name");
    } catch (const std::bad_alloc&) {
        send_error(response, 503, "out of memory");
    } catch (const std::exception& error) {
        send_error(response, 500, std::string("internal error: ") + error.what());
    }
}

const char* content_type_of(const std::string& path) {
    const auto ends_with = [&path](const std::string& suffix) {
        return path.size() >= suffix.size() && path.compare(path.size() - suffix.size(), suffix.size(), suffix) == 0;
    };
    if (ends_with(".html")) return "text/html; charset=utf-8";
    if (ends_with(".js")) return "text/javascript; charset=utf-8";
    if (ends_with(".css")) return "text/css; charset=utf-8";
    if (ends_with(".svg")) return "image/svg+xml";
    if (ends_with(".png")) return "image/png";
    return "application/octet-stream";
}

// index.html with the token in the addresses of the page's own files (src="viewer.js" becomes
// src="viewer.js?token=..."): the browser loads them with the token, as every request must
// carry it (there is no cookie, view/request_guard.h).
std::string page_with_token(std::string page, const std::string& token) {
    for (const EmbeddedAsset& asset : embedded_viewer_assets()) {
        for (const char* attribute : {"src=\"", "href=\""}) {
            const std::string reference = attribute + std::string(asset.path) + "\"";
            const std::string with_token = attribute + std::string(asset.path) + "?token=" + token + "\"";
            for (std::size_t at = page.find(reference); at != std::string::npos; at = page.find(reference, at + with_token.size()))
                page.replace(at, reference.size(), with_token);
        }
    }
    return page;
}

// The query parameters each route takes, token= aside (/camera.json takes a frame's and reads
// only frame=): any other is refused (query_parameters()).
const std::vector<std::string> kNoParameters;
const std::vector<std::string> kPageParameters = {"channel"};  // read by the page itself (viewer.js)
const std::vector<std::string> kFrameParameters = {"eye", "lookat", "up", "fov", "size", "spp", "frame"};
const std::vector<std::string> kExplainParameters = {"eye", "lookat", "up", "fov", "size", "spp", "frame", "x", "y"};
const std::vector<std::string> kJobParameters = {"id"};

// Routes are patterns: the name's dots must match only dots.
std::string asset_pattern(const std::string& path) {
    std::string pattern = "/";
    for (char c : path) pattern += c == '.' ? std::string("\\.") : std::string(1, c);
    return pattern;
}

void add_assets(httplib::Server& server, const std::string& token) {
    for (const EmbeddedAsset& asset : embedded_viewer_assets()) {
        const std::string path = asset.path;
        const std::string content = path == "index.html" ? page_with_token(std::string(asset.content()), token)
                                                         : std::string(asset.content());
        const std::vector<std::string>& known = path == "index.html" ? kPageParameters : kNoParameters;
        const auto serve = [content, path, &known](const Request& request, Response& response) {
            answer(response, [&] {
                (void)query_parameters(request.target, known);
                response.set_content(content, content_type_of(path));
            });
        };
        server.Get(asset_pattern(path), serve);
        if (path == "index.html") server.Get("/", serve);
    }
}

// Whether the request's client is gone: asked between the bands of its frame (and the samples of
// an explanation). The connection is looked up at the second question, so that the live view's
// frames of one band never look.
std::function<bool()> abandonment_of(const Request& request) {
    struct Watch {
        std::string local_addr, remote_addr;
        int local_port, remote_port;
        bool asked = false;
        std::optional<ClientConnection> connection;
    };
    auto watch = std::make_shared<Watch>(
        Watch{request.local_addr, request.remote_addr, request.local_port, request.remote_port, false, std::nullopt});
    return [watch] {
        if (!watch->asked) {
            watch->asked = true;  // before the first band: the client has just asked
            return false;
        }
        if (!watch->connection)
            watch->connection.emplace(watch->local_addr, watch->local_port, watch->remote_addr, watch->remote_port);
        return watch->connection->gone();
    };
}

ViewCamera camera_of(const ViewSession& session, const QueryParameters& parameters) {
    const ViewQuery query = parse_view_query(parameters);
    const ViewCamera view = resolve_view_camera(session.scene, query);
    check_render_cost(session.scene, view, query);
    return view;
}

// A hold on the answer budget for a frame of `view`'s size (its RGBA bytes; its PNG is no
// larger, give or take its headers); FramesInFlight (503) where the answers still being sent
// leave no room for it.
std::shared_ptr<const void> hold_for_frame(ViewSession& session, const ViewCamera& view) {
    const std::uint64_t bytes = std::uint64_t(view.width) * std::uint64_t(view.height) * 4 + 64 * 1024;
    std::shared_ptr<const void> hold = session.answers.hold(bytes);
    if (!hold)
        throw FramesInFlight("frames of " + std::to_string(session.answers.in_flight() >> 20) +
                             " MiB are still being sent to other clients; ask again when they have them");
    return hold;
}

// Answers `bytes` from memory the answer keeps (with the budget's hold) until it is sent, in
// pieces rather than copied whole into the answer.
template <typename Bytes>  // std::vector<std::uint8_t> (a frame) or std::string (an export's JSON)
void send_held(Response& response, std::shared_ptr<const Bytes> bytes, const char* content_type,
               std::shared_ptr<const void> hold) {
    const std::size_t size = bytes->size();
    response.set_content_provider(
        size, content_type, [bytes, hold](std::size_t offset, std::size_t length, httplib::DataSink& sink) {
            return sink.write(reinterpret_cast<const char*>(bytes->data()) + offset, length);
        });
}

// A hold on the answer budget for the answer to an export of `text`: the text escaped as a JSON
// string (at most twice its bytes: its newlines and quotes escaped) and the names; the whole
// budget at most, so that an export of the largest scene is answered once nothing else is in
// flight. FramesInFlight (503) where the answers still being sent leave no room for it: each
// answer keeps its scene's text until its client has it (up to the answer's 60 s), 16 clients
// that took theirs slowly 16 texts (of a scene of the largest size, 64 MiB, 32 would keep 2 GB).
std::shared_ptr<const void> hold_for_export(ViewSession& session, const std::string& text) {
    const std::uint64_t bytes =
        std::min<std::uint64_t>(2 * std::uint64_t(text.size()) + 64 * 1024, session.answers.total());
    std::shared_ptr<const void> hold = session.answers.hold(bytes);
    if (!hold)
        throw FramesInFlight("answers of " + std::to_string(session.answers.in_flight() >> 20) +
                             " MiB are still being sent to other clients; export again when they have them");
    return hold;
}

void add_frame_routes(httplib::Server& server, ViewSession& session) {
    server.Get("/frame\\.png", [&session](const Request& request, Response& response) {
        answer(response, [&] {
            const ViewCamera view = camera_of(session, query_parameters(request.target, kFrameParameters));
            std::shared_ptr<const void> hold = hold_for_frame(session, view);
            Image frame = session.renderer.render(view, abandonment_of(request));
            auto png = std::make_shared<const std::vector<std::uint8_t>>(png_bytes(frame));
            session.renderer.recycle(std::move(frame));
            send_held(response, std::move(png), "image/png", std::move(hold));
        });
    });
    // The live channel: raw RGBA rows, top row first, no encoding on either side.
    server.Get("/frame\\.rgba", [&session](const Request& request, Response& response) {
        answer(response, [&] {
            const ViewCamera view = camera_of(session, query_parameters(request.target, kFrameParameters));
            std::shared_ptr<const void> hold = hold_for_frame(session, view);
            Image frame = session.renderer.render(view, abandonment_of(request));
            response.set_header("X-Width", std::to_string(frame.width));
            response.set_header("X-Height", std::to_string(frame.height));
            send_held(response, std::make_shared<const std::vector<std::uint8_t>>(std::move(frame.rgba)),
                      "application/octet-stream", std::move(hold));
        });
    });
    server.Get("/explain", [&session](const Request& request, Response& response) {
        answer(response, [&] {
            const QueryParameters parameters = query_parameters(request.target, kExplainParameters);
            const ViewCamera view = camera_of(session, parameters);
            const PixelQuery pixel = parse_pixel_query(parameters);
            if (pixel.x >= view.width)
                throw ParameterError("x", "x " + std::to_string(pixel.x) + " is outside the " + std::to_string(view.width) +
                                              "-pixel-wide frame (0 to " + std::to_string(view.width - 1) + ")");
            if (pixel.y >= view.height)
                throw ParameterError("y", "y " + std::to_string(pixel.y) + " is outside the " + std::to_string(view.height) +
                                              "-pixel-high frame (0 to " + std::to_string(view.height - 1) + ")");
            response.set_content(session.renderer.explain(view, pixel.x, pixel.y, abandonment_of(request)),
                                 "text/plain; charset=utf-8");
        });
    });
    server.Get("/scene\\.json", [&session](const Request& request, Response& response) {
        answer(response, [&] {
            (void)query_parameters(request.target, kNoParameters);
            // Sent from the text made at start, in pieces: made for each request, 8 at once of a
            // path of a million keys took the viewer to 14 GB.
            const std::shared_ptr<const std::string> summary = session.scene_summary;
            response.set_content_provider(summary->size(), "application/json",
                                          [summary](std::size_t offset, std::size_t length, httplib::DataSink& sink) {
                                              return sink.write(summary->data() + offset, length);
                                          });
        });
    });
    server.Get("/camera\\.json", [&session](const Request& request, Response& response) {
        answer(response, [&] {
            // Only frame= is read: the answer is the frame's own camera, checked as /frame.png's.
            // The frame's other parameters (eye=, size=: a frame's query) are taken and not read.
            const QueryParameters parameters = query_parameters(request.target, kFrameParameters);
            const auto [first, last] = parameters.equal_range("frame");
            ViewQuery frame_only;
            frame_only.frame = parse_view_query(QueryParameters(first, last)).frame;
            const ViewCamera view = resolve_view_camera(session.scene, frame_only);
            response.set_content(frame_camera_json(session.scene, view.frame), "application/json");
        });
    });
}

void add_path_routes(httplib::Server& server, ViewSession& session) {
    server.Post("/export", [&session](const Request& request, Response& response) {
        answer(response, [&] {
            (void)query_parameters(request.target, kNoParameters);
            // The answer's room is taken before the file is written: a refusal writes nothing.
            std::shared_ptr<const void> hold;
            const auto take_room = [&](const std::string& text) { hold = hold_for_export(session, text); };
            ExportedScene exported = session.exporter.export_keys(parse_camera_keys(request.body), {}, take_room);
            // Names are for the reader: escaped as clrender's messages escape them (shown_name).
            // The text is moved, not copied, into the answer: it may be as large as the scene.
            nlohmann::json body = {{"scene", std::move(exported.text)}, {"file", shown_name(exported.path)},
                                   {"name", shown_name(exported.name)}};
            auto text = std::make_shared<const std::string>(json_text(body));
            body = nullptr;  // the tree's memory back before the answer is sent
            send_held(response, std::move(text), "application/json", std::move(hold));
        });
    });
    server.Post("/render-video", [&session](const Request& request, Response& response) {
        answer(response, [&] {
            (void)query_parameters(request.target, kNoParameters);
            const CameraKeysRequest keys = parse_camera_keys(request.body);
            // A video moves from key to key: one key is a still, whose render would fail after
            // its scene was written. Refused before anything is written.
            if (keys.keys.size() < 2)
                throw ParameterError("keys", "a video needs two or more keys; one key is a still (Export scene writes it)");
            // The place is taken before the scene is written: a refused request writes nothing.
            std::optional<VideoJobs::Place> place = session.videos.reserve();
            if (!place) {
                send_error(response, 409, "a video is rendering already; one at a time");
                return;
            }
            // The scene and the video share their name: both free when the scene is written.
            const ExportedScene exported = session.exporter.export_keys(keys, {".mp4"});
            const std::string video = session.exporter.output_dir() + "/" + exported.name + ".mp4";
            session.exporter.check_output("video", video);
            const int job = session.videos.start(std::move(*place), exported.path, exported.text, video);
            send_json(response, 200, {{"job", job},
                                      {"file", shown_name(video)},
                                      {"scene", shown_name(exported.path)},
                                      {"name", shown_name(exported.name)}});
        });
    });
    server.Get("/job", [&session](const Request& request, Response& response) {
        answer(response, [&] {
            // A job's number as /render-video gave it: 1.5 or 1e0 names no job.
            static const std::regex whole(R"([1-9][0-9]{0,8})");
            const QueryParameters parameters = query_parameters(request.target, kJobParameters);
            const auto id_text = parameters.find("id");
            if (id_text != parameters.end() && !std::regex_match(id_text->second, whole))
                throw ParameterError("id", "id must be a job number as /render-video answered it (1, 2, ...)");
            // Without an id, the session's last job: a page loaded again while a video renders
            // (whose own number it has lost) follows it.
            const std::optional<VideoJobState> job = id_text == parameters.end()
                                                         ? session.videos.latest()
                                                         : session.videos.state(std::stoi(id_text->second));
            if (!job) {
                send_error(response, 404, "no such job", "id");
                return;
            }
            nlohmann::json body = {{"id", job->id},
                                   {"state", job->state},
                                   {"done", job->done},
                                   {"frame", job->frame},
                                   {"total", job->total},
                                   {"file", shown_name(job->file)}};
            body["error"] = job->error.empty() ? nlohmann::json(nullptr) : nlohmann::json(job->error);
            send_json(response, 200, body);
        });
    });
}

// A route's path: its pattern, and the methods it answers (GET and HEAD, or POST).
struct RoutePath {
    std::string pattern;
    std::string allowed;
};

std::vector<RoutePath> route_paths() {
    std::vector<RoutePath> paths;
    for (const EmbeddedAsset& asset : embedded_viewer_assets()) paths.push_back({asset_pattern(asset.path), "GET, HEAD"});
    for (const char* pattern : {"/", "/frame\\.png", "/frame\\.rgba", "/explain", "/scene\\.json", "/camera\\.json", "/job"})
        paths.push_back({pattern, "GET, HEAD"});
    for (const char* pattern : {"/export", "/render-video"}) paths.push_back({pattern, "POST"});
    return paths;
}

// 405 naming the methods the path answers, rather than 404 (the path exists).
void refuse_method(const Request& request, Response& response, const std::string& allowed) {
    response.set_header("Allow", allowed);
    send_error(response, 405, request.method + " is not answered here; " + allowed + " is");
}

// Every other method cpp-httplib routes, on a route's path: 405.
void refuse_other_methods(httplib::Server& server, const std::string& pattern, const std::string& allowed) {
    const auto refuse = [allowed](const Request& request, Response& response) { refuse_method(request, response, allowed); };
    if (allowed == "POST")
        server.Get(pattern, refuse);
    else
        server.Post(pattern, refuse);
    server.Put(pattern, refuse);
    server.Patch(pattern, refuse);
    server.Delete(pattern, refuse);
    server.Options(pattern, refuse);
}

// Whether cpp-httplib 0.11.4 reads a body for `method` before routing: as long as its
// Content-Length says, or without one, to the end of the connection.
bool body_read_before_routing(const std::string& method) {
    return method == "POST" || method == "PUT" || method == "PATCH";
}

// A method that cpp-httplib parses but routes nowhere (TRACE, CONNECT, PRI), which it would
// answer 400 with nothing: 405 on a route's path, 404 elsewhere, as for any other method.
bool routed_method(const std::string& method) {
    for (const char* routed : {"GET", "HEAD", "POST", "PUT", "PATCH", "DELETE", "OPTIONS"})
        if (method == routed) return true;
    return false;
}

void refuse_unrouted_method(const Request& request, Response& response, const std::vector<RoutePath>& paths) {
    for (const RoutePath& path : paths) {
        if (std::regex_match(request.path, std::regex(path.pattern))) {
            refuse_method(request, response, path.allowed);
            return;
        }
    }
    response.status = 404;
}

// Whether cpp-httplib 0.11.4 would parse a body of `content_type` itself, before any route
// sees it: a form (it takes the fields into the request's parameters, and refuses one over
// 8 KiB with a bare 413) or a multipart body (a bare 400 when it cannot, files in memory when it
// can). cpp-httplib matches the start of the value, case and all; any case is refused here.
bool parsed_by_cpp_httplib(const std::string& content_type) {
    std::string type = content_type.substr(0, 64);
    std::transform(type.begin(), type.end(), type.begin(), [](unsigned char c) { return std::tolower(c); });
    type.erase(0, type.find_first_not_of(" \t"));
    return type.rfind("application/x-www-form-urlencoded", 0) == 0 || type.rfind("multipart/", 0) == 0;
}

// A header's value in a message: printable and short, whatever was sent.
std::string shown_value(const std::string& value) { return "'" + printable(shortened(value, 40)) + "'"; }

}  // namespace

bool refused_body_format(const Request& request, Response& response) {
    // cpp-httplib (built with zlib and brotli) inflates a gzip, deflate or br body before the
    // route sees it, counting only the bytes sent against the 2 MiB limit: 234 bytes of brotli
    // made 256 MiB in memory. The page never sends one, so every Content-Encoding is refused,
    // identity too (RFC 9110 reserves it for Accept-Encoding), before the body is read.
    if (request.has_header("Content-Encoding")) {
        response.set_header("Connection", "close");
        send_error(response, 415,
                   "Content-Encoding " + shown_value(request.get_header_value("Content-Encoding")) +
                       " is not accepted: request bodies are sent as they are, uncompressed",
                   "Content-Encoding");
        return true;
    }
    // Every Content-Type given: cpp-httplib reads the first, another program along the way may
    // read the last.
    const std::size_t types = request.get_header_value_count("Content-Type");
    for (std::size_t k = 0; k < types; ++k) {
        const std::string type = request.get_header_value("Content-Type", k);
        if (!parsed_by_cpp_httplib(type)) continue;
        response.set_header("Connection", "close");
        send_error(response, 415,
                   "Content-Type " + shown_value(type) + " is not accepted: request bodies are JSON (application/json)",
                   "Content-Type");
        return true;
    }
    return false;
}

httplib::Headers view_answer_headers() {
    // Nothing the viewer sends is for a cache, another site's frame, or a content sniffer; the
    // address holds the token, which no link may pass on.
    return {{"Cache-Control", "no-store"},
            {"X-Content-Type-Options", "nosniff"},
            {"X-Frame-Options", "DENY"},
            {"Referrer-Policy", "no-referrer"},
            {"Accept-Ranges", "none"},  // a Range header is ignored (view/bounded_server.h)
            {"Content-Security-Policy", kContentSecurityPolicy}};
}

RequestFacts request_facts(const Request& request) {
    RequestFacts facts;
    facts.method = request.method;
    facts.path = request.path;
    // A request has one Host and at most one Origin (RFC 9110). One given twice names no server
    // and no page: which of the two another program along the way would read is anyone's guess.
    if (request.get_header_value_count("Host") == 1) facts.host = request.get_header_value("Host");
    if (request.has_header("Origin"))
        facts.origin = request.get_header_value_count("Origin") == 1 ? request.get_header_value("Origin") : "";
    facts.arrived_on = request.local_addr;
    facts.query_tokens = query_tokens_as_sent(request.target);  // not request.params (query_tokens.h)
    return facts;
}

void add_view_routes(httplib::Server& server, ViewSession& session) {
    const std::vector<RoutePath> paths = route_paths();
    server.set_pre_routing_handler([&session, paths](const Request& request, Response& response) {
        const RequestVerdict verdict = session.guard.check(request_facts(request));
        // A refused request's body is never read, so the connection ends with the answer: its
        // body must not be taken for a next request, past the checks that refused it.
        if (verdict == RequestVerdict::Forbidden) {
            response.status = 403;
            response.set_header("Connection", "close");
            return httplib::Server::HandlerResponse::Handled;
        }
        if (refused_body_format(request, response)) return httplib::Server::HandlerResponse::Handled;
        // cpp-httplib limits a body by its Content-Length only: a chunked body would be read
        // whole, however large. The page sends none, so any Transfer-Encoding is refused here,
        // before the body is read, and the connection is closed (its body is never read).
        if (request.has_header("Transfer-Encoding")) {
            response.set_header("Connection", "close");
            send_error(response, 411, "request bodies must have a Content-Length (no Transfer-Encoding)");
            return httplib::Server::HandlerResponse::Handled;
        }
        // A Content-Length given twice, as a list or other than as digits ("+78") leaves unclear
        // where the body ends, and so where the next request starts: RFC 9112 has it answered
        // 400 and the connection closed. cpp-httplib would take the first number it could read.
        const std::optional<std::size_t> body_length = declared_body_length(request);
        if (!body_length) {
            response.set_header("Connection", "close");
            send_error(response, 400, "the Content-Length must be one number, given once");
            return httplib::Server::HandlerResponse::Handled;
        }
        // cpp-httplib would read a body over the limit to skip it, and a client that sends none
        // waited out the read timeout for its 413: refused before it is read.
        if (*body_length > kMostRequestBytes) {
            response.set_header("Connection", "close");
            const std::string limit = std::to_string(kMostRequestBytes);
            send_error(response, 413, "request bodies may have at most " + limit + " bytes");
            return httplib::Server::HandlerResponse::Handled;
        }
        // Such a request has no body (RFC 9112), but cpp-httplib reads one to the end of the
        // connection: the client waited out the read timeout, or its half-close made whatever
        // it had sent the body. The page always says its body's length.
        if (body_read_before_routing(request.method) && !request.has_header("Content-Length")) {
            response.set_header("Connection", "close");
            send_error(response, 411, "a " + request.method + " must give its body's length (Content-Length: 0 for none)");
            return httplib::Server::HandlerResponse::Handled;
        }
        if (!routed_method(request.method)) {
            refuse_unrouted_method(request, response, paths);
            return httplib::Server::HandlerResponse::Handled;
        }
        return httplib::Server::HandlerResponse::Unhandled;
    });
    add_assets(server, session.guard.token());
    add_frame_routes(server, session);
    add_path_routes(server, session);
    for (const RoutePath& path : paths) refuse_other_methods(server, path.pattern, path.allowed);
}

}  // namespace clr
