#include "view/request_guard.h"

#include <arpa/inet.h>

#include <algorithm>
#include <cctype>
#include <utility>

#include "view/access_token.h"

namespace clr {
namespace {

std::string lowercase(std::string text) {
    std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::tolower(c); });
    return text;
}

std::string without_brackets(const std::string& address) {
    if (address.size() >= 2 && address.front() == '[' && address.back() == ']') return address.substr(1, address.size() - 2);
    return address;
}

// Every address, however spelt ("0.0.0.0", "::", "[::]", "0:0::0").
bool is_wildcard(const std::string& bind) {
    const std::string address = without_brackets(bind);
    unsigned char buffer[16];
    if (inet_pton(AF_INET, address.c_str(), buffer) == 1) return std::all_of(buffer, buffer + 4, [](unsigned char b) { return b == 0; });
    return inet_pton(AF_INET6, address.c_str(), buffer) == 1 &&
           std::all_of(buffer, buffer + 16, [](unsigned char b) { return b == 0; });
}

// HTTP's default port, which browsers leave out of Host and Origin ("127.0.0.1", not
// "127.0.0.1:80").
constexpr int kDefaultHttpPort = 80;

// Whether `host` has no port: a name, an IPv4 address, or an IPv6 address in brackets.
bool has_no_port(const std::string& host) {
    const std::size_t colon = host.rfind(':');
    return colon == std::string::npos || (host.front() == '[' && host.back() == ']');
}

// "host:port" -> host, when the port is exactly `port` (or left out, where `port` is 80);
// nullopt otherwise (a Host header without a port or with another one does not name this
// server).
std::optional<std::string> host_of(const std::string& host_and_port, int port) {
    if (port == kDefaultHttpPort && !host_and_port.empty() && has_no_port(host_and_port)) return host_and_port;
    const std::string suffix = ":" + std::to_string(port);
    if (host_and_port.size() <= suffix.size() ||
        host_and_port.compare(host_and_port.size() - suffix.size(), suffix.size(), suffix) != 0)
        return std::nullopt;
    return host_and_port.substr(0, host_and_port.size() - suffix.size());
}

// The 4 or 16 bytes of a numeric address; an IPv4 address mapped into IPv6 (::ffff:a.b.c.d, as
// a socket bound to :: reports an IPv4 client) gives its IPv4 bytes. Empty for no address.
std::string address_bytes(std::string text) {
    text = text.substr(0, text.find('%'));  // an IPv6 zone ("fe80::1%eth0") names no other address
    unsigned char buffer[16];
    if (inet_pton(AF_INET, text.c_str(), buffer) == 1) return std::string(reinterpret_cast<char*>(buffer), 4);
    if (inet_pton(AF_INET6, text.c_str(), buffer) != 1) return "";
    static const unsigned char mapped[12] = {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0xff, 0xff};
    if (std::equal(mapped, mapped + 12, buffer)) return std::string(reinterpret_cast<char*>(buffer + 12), 4);
    return std::string(reinterpret_cast<char*>(buffer), 16);
}

// The bytes of the IP address a Host or Origin names (without its port): an IPv6 address only in
// brackets, as a URL writes it, an IPv4 address without. Empty for a name or anything else.
std::string named_address_bytes(const std::string& address) {
    if (address.empty()) return "";
    const bool bracketed = address.front() == '[' && address.back() == ']';
    const std::string inner = without_brackets(address);
    if (bracketed != (inner.find(':') != std::string::npos)) return "";
    return address_bytes(inner);
}

}  // namespace

bool is_ip_address(const std::string& text) {
    unsigned char buffer[16];
    return inet_pton(AF_INET, text.c_str(), buffer) == 1 || inet_pton(AF_INET6, text.c_str(), buffer) == 1;
}

bool is_loopback_address(const std::string& bind) {
    if (bind == "localhost") return true;
    const std::string bytes = address_bytes(without_brackets(bind));  // an IPv4-mapped address as IPv4
    if (bytes.size() == 4) return static_cast<unsigned char>(bytes[0]) == 127;
    static const char loopback6[16] = {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1};
    return bytes == std::string(loopback6, 16);
}

std::string url_host(const std::string& bound) {
    if (is_wildcard(bound)) return "127.0.0.1";
    const std::string address = without_brackets(bound);
    unsigned char buffer[16];
    if (inet_pton(AF_INET6, address.c_str(), buffer) == 1) return "[" + address + "]";
    return address;
}

RequestGuard::RequestGuard(std::string token, std::string bind, int port)
    : token_(std::move(token)), port_(port), wildcard_(is_wildcard(bind)),
      bound_bytes_(wildcard_ ? std::string() : address_bytes(without_brackets(bind))) {
    const std::string suffix = ":" + std::to_string(port);
    for (const std::string& name : {std::string("127.0.0.1"), std::string("localhost"), std::string("[::1]"), url_host(bind)}) {
        hosts_.insert(lowercase(name) + suffix);
        if (port == kDefaultHttpPort) hosts_.insert(lowercase(name));
    }
}

bool RequestGuard::names_bound_address(const std::string& host_and_port) const {
    const std::optional<std::string> address = host_of(host_and_port, port_);
    return address && !bound_bytes_.empty() && named_address_bytes(*address) == bound_bytes_;
}

bool RequestGuard::host_allowed(const std::string& host) const {
    const std::string name = lowercase(host);
    if (hosts_.count(name) > 0 || names_bound_address(name)) return true;
    if (!wildcard_) return false;
    // Bound to every address: the machine's own addresses, but still no names.
    const std::optional<std::string> address = host_of(name, port_);
    return address && !named_address_bytes(*address).empty();
}

bool RequestGuard::origin_allowed(const std::string& origin, const std::string& arrived_on) const {
    const std::string scheme = "http://";
    if (origin.size() <= scheme.size() || lowercase(origin.substr(0, scheme.size())) != scheme) return false;
    const std::string host = lowercase(origin.substr(scheme.size()));
    const std::optional<std::string> address = host_of(host, port_);
    // A page from 127.0.0.1, localhost or [::1] is one this machine served only where the
    // request came in on loopback: one that came in from outside was sent by a browser on
    // another machine, whose loopback is its own, another site.
    if (address && is_loopback_address(*address) && !is_loopback_address(arrived_on)) return false;
    if (hosts_.count(host) > 0 || names_bound_address(host)) return true;
    if (!wildcard_) return false;
    const std::string bytes = address ? named_address_bytes(*address) : std::string();
    return !bytes.empty() && bytes == address_bytes(arrived_on);
}

RequestVerdict RequestGuard::check(const RequestFacts& request) const {
    if (!request.host || !host_allowed(*request.host)) return RequestVerdict::Forbidden;
    // Every method but GET and HEAD may change something: it must come from the page itself.
    const bool reads_only = request.method == "GET" || request.method == "HEAD";
    if (!reads_only && (!request.origin || !origin_allowed(*request.origin, request.arrived_on)))
        return RequestVerdict::Forbidden;
    // Exactly one token=, the right one (given twice: which one would count?).
    if (request.query_tokens.size() != 1 || !token_matches(request.query_tokens.front(), token_))
        return RequestVerdict::Forbidden;
    return RequestVerdict::Allowed;
}

}  // namespace clr
