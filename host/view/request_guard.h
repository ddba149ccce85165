// Which requests `clrender view` answers (docs/command-line.md, Viewer: Security):
// - the Host header names this server by an address, never by a DNS name that a web page
//   could point at 127.0.0.1 (DNS rebinding), with its port (left out on port 80, as browsers
//   leave out HTTP's default port);
// - every request carries the access token in its query (token=...). There is no cookie:
//   cookies are not kept apart by port, so every other server on 127.0.0.1 would receive it,
//   and SameSite counts every port of 127.0.0.1 as the same site, so a page served from any
//   of them could have the browser load frames with it. The page passes the token itself
//   (view/view_routes.cpp writes it into the page's own file names);
// - a request that changes something (POST) comes from the viewer's own page: its Origin
//   header is the server's own origin, so another web site cannot drive the viewer (bound to
//   every address, an address in it must be the one the request arrived on; 127.0.0.1,
//   localhost and [::1] only for a request that arrived on loopback).
// Nothing here knows HTTP's wire format (cpp-httplib parses requests): the checks take the
// facts of a request, so that the fuzz target and the tests can drive them directly.
#pragma once

#include <optional>
#include <set>
#include <string>
#include <vector>

namespace clr {

struct RequestFacts {
    std::string method;                 // "GET", "POST", ...
    std::string path;                   // decoded, as routed: "/frame.png"
    std::optional<std::string> host;    // the Host header
    std::optional<std::string> origin;  // the Origin header
    std::vector<std::string> query_tokens;  // every token=... of the query
    std::string arrived_on;             // the numeric address the request came in on ("192.168.1.20")
};

enum class RequestVerdict {
    Forbidden,  // 403 and nothing else
    Allowed,
};

class RequestGuard {
public:
    // `bind` is the address the server listens on (--bind), `port` its port.
    RequestGuard(std::string token, std::string bind, int port);

    RequestVerdict check(const RequestFacts& request) const;

    // The token, for the page's own addresses.
    const std::string& token() const { return token_; }

    // Whether `host` (a Host header) names this server.
    bool host_allowed(const std::string& host) const;
    // Whether `origin` (an Origin header) is the server's own, for a request that came in on
    // the address `arrived_on`. Bound to every address, the server's pages are served from
    // whichever address a browser reached: the one its requests arrive on. Any other address
    // in an Origin is another machine's, another site, even where a Host may name it; so is a
    // loopback one (127.0.0.1, localhost, [::1]) on a request that came in from outside.
    bool origin_allowed(const std::string& origin, const std::string& arrived_on) const;

private:
    // Whether `host_and_port` names the bound address by its IP address, however spelt
    // ("[fd00::2]" for a bind of fd00:0::2, "[::ffff:7f00:1]" for ::ffff:127.0.0.1).
    bool names_bound_address(const std::string& host_and_port) const;

    std::string token_;
    int port_ = 0;
    bool wildcard_ = false;  // bound to every address: any IP address names the server
    std::string bound_bytes_;  // the bytes of the bound address where --bind gives one (IPv4-mapped: 4)
    std::set<std::string> hosts_;  // lowercase "name:port" forms of the server's own names
};

// The address for the printed URL, given the numeric address the server is bound to: that
// address, or 127.0.0.1 where the server listens on every address ("0.0.0.0", "::"); an IPv6
// address in brackets. Never a name: a browser looks a name up itself (localhost as ::1, say)
// and could reach another program listening on the same port there.
std::string url_host(const std::string& bound);

// Whether `text` is an IPv4 address in dotted form or an IPv6 address (without brackets).
bool is_ip_address(const std::string& text);

// Whether `bind` (a --bind value) is this machine only: localhost, 127.0.0.0/8, ::1 (with or
// without brackets).
bool is_loopback_address(const std::string& bind);

}  // namespace clr
