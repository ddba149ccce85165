// The viewer's request checks, driven directly: the token (in the query; there is no cookie), the Host header
// against DNS rebinding, the Origin of requests that change something.
#include <gtest/gtest.h>

#include <set>

#include "view/access_token.h"
#include "view/request_guard.h"

namespace clr {
namespace {

const std::string kToken = "0123456789abcdef0123456789abcdef";

RequestFacts get(const std::string& path, const std::string& host = "127.0.0.1:8123") {
    RequestFacts facts;
    facts.method = "GET";
    facts.path = path;
    facts.host = host;
    facts.query_tokens = {kToken};
    facts.arrived_on = "127.0.0.1";
    return facts;
}

TEST(AccessToken, Has128RandomBitsAsHexAndDiffersEachTime) {
    std::set<std::string> seen;
    for (int i = 0; i < 50; ++i) {
        const std::string token = make_access_token();
        ASSERT_EQ(token.size(), 32u);
        EXPECT_EQ(token.find_first_not_of("0123456789abcdef"), std::string::npos) << token;
        seen.insert(token);
    }
    EXPECT_EQ(seen.size(), 50u);
}

TEST(AccessToken, MatchesOnlyTheWholeToken) {
    EXPECT_TRUE(token_matches(kToken, kToken));
    EXPECT_FALSE(token_matches("", kToken));
    EXPECT_FALSE(token_matches(kToken.substr(0, 31), kToken));
    EXPECT_FALSE(token_matches(kToken + "0", kToken));
    std::string last_differs = kToken;
    last_differs.back() = 'e';
    EXPECT_FALSE(token_matches(last_differs, kToken));
    EXPECT_FALSE(token_matches("", ""));  // a guard without a token admits nothing
}

TEST(RequestGuard, NeedsTheTokenInTheQuery) {
    const RequestGuard guard(kToken, "127.0.0.1", 8123);
    EXPECT_EQ(guard.check(get("/frame.png")), RequestVerdict::Allowed);
    RequestFacts none = get("/frame.png");
    none.query_tokens.clear();
    EXPECT_EQ(guard.check(none), RequestVerdict::Forbidden);
    RequestFacts wrong = get("/frame.png");
    wrong.query_tokens = {"0123456789abcdef0123456789abcdee"};
    EXPECT_EQ(guard.check(wrong), RequestVerdict::Forbidden);
    RequestFacts twice = get("/frame.png");
    twice.query_tokens = {kToken, kToken};
    EXPECT_EQ(guard.check(twice), RequestVerdict::Forbidden);
    RequestFacts empty = get("/frame.png");
    empty.query_tokens = {""};
    EXPECT_EQ(guard.check(empty), RequestVerdict::Forbidden);
}

TEST(RequestGuard, HostMustNameTheServerByAddressOrLocalhost) {
    const RequestGuard guard(kToken, "127.0.0.1", 8123);
    for (const char* host : {"127.0.0.1:8123", "localhost:8123", "LOCALHOST:8123", "[::1]:8123"})
        EXPECT_EQ(guard.check(get("/", host)), RequestVerdict::Allowed) << host;
    for (const char* host : {"evil.example:8123", "127.0.0.1", "127.0.0.1:8124", "localhost", "127.0.0.1:81230",
                             "10.0.0.1:8123", "", "127.0.0.1:8123 ", "localhost.evil.example:8123"})
        EXPECT_EQ(guard.check(get("/", host)), RequestVerdict::Forbidden) << host;
    RequestFacts no_host = get("/");
    no_host.host.reset();
    EXPECT_EQ(guard.check(no_host), RequestVerdict::Forbidden);
}

// Browsers leave HTTP's default port out of Host and Origin: on port 80 the bare forms name
// the server, and only there.
TEST(RequestGuard, OnPort80TheHostMayLeaveThePortOut) {
    const RequestGuard guard(kToken, "127.0.0.1", 80);
    for (const char* host : {"127.0.0.1", "localhost", "[::1]", "127.0.0.1:80", "LOCALHOST"})
        EXPECT_EQ(guard.check(get("/", host)), RequestVerdict::Allowed) << host;
    for (const char* host : {"evil.example", "127.0.0.1:8080", "127.0.0.1:", "10.0.0.1", "127.0.0.1.evil.example"})
        EXPECT_EQ(guard.check(get("/", host)), RequestVerdict::Forbidden) << host;
    RequestFacts post = get("/export", "127.0.0.1");
    post.method = "POST";
    post.origin = "http://127.0.0.1";
    EXPECT_EQ(guard.check(post), RequestVerdict::Allowed);
    post.origin = "http://127.0.0.1:8080";
    EXPECT_EQ(guard.check(post), RequestVerdict::Forbidden);
    const RequestGuard everywhere(kToken, "0.0.0.0", 80);
    EXPECT_EQ(everywhere.check(get("/", "192.168.1.20")), RequestVerdict::Allowed);
    EXPECT_EQ(everywhere.check(get("/", "[fe80::1]")), RequestVerdict::Allowed);
    EXPECT_EQ(everywhere.check(get("/", "attacker.example")), RequestVerdict::Forbidden);
    EXPECT_EQ(everywhere.check(get("/", "192.168.1.20:8080")), RequestVerdict::Forbidden);
}

TEST(RequestGuard, WildcardBindAdmitsAddressesButNoNames) {
    const RequestGuard guard(kToken, "0.0.0.0", 8123);
    EXPECT_EQ(guard.check(get("/scene.json", "192.168.1.20:8123")), RequestVerdict::Allowed);
    EXPECT_EQ(guard.check(get("/scene.json", "[fe80::1]:8123")), RequestVerdict::Allowed);
    EXPECT_EQ(guard.check(get("/scene.json", "attacker.example:8123")), RequestVerdict::Forbidden);
    EXPECT_EQ(guard.check(get("/scene.json", "192.168.1.20:8000")), RequestVerdict::Forbidden);
}

// Bound to every address, the page is served from whichever address the browser reached, and
// its requests arrive on that address. An Origin naming another address is another machine's
// page, another site, although a Host may name any address.
TEST(RequestGuard, WildcardBindAdmitsAsOriginOnlyTheAddressTheRequestArrivedOn) {
    for (const char* bind : {"0.0.0.0", "::"}) {
        const RequestGuard guard(kToken, bind, 8123);
        RequestFacts post = get("/export", "192.168.1.20:8123");
        post.method = "POST";
        const auto verdict = [&guard, &post](const std::string& origin, const std::string& arrived_on) {
            post.origin = origin;
            post.arrived_on = arrived_on;
            return guard.check(post);
        };
        EXPECT_EQ(verdict("http://192.168.1.20:8123", "192.168.1.20"), RequestVerdict::Allowed) << bind;
        // A loopback Origin on a request from outside is a page of the sending machine's own.
        for (const char* origin : {"http://203.0.113.5:8123", "http://[2001:db8::1]:8123", "http://192.168.1.21:8123",
                                   "http://192.168.1.20:8124", "http://[192.168.1.20]:8123", "http://evil.example:8123",
                                   "http://127.0.0.1:8123", "http://localhost:8123", "http://[::1]:8123"})
            EXPECT_EQ(verdict(origin, "192.168.1.20"), RequestVerdict::Forbidden) << bind << " " << origin;
        for (const char* arrived_on : {"127.0.0.1", "::1", "::ffff:127.0.0.1"})
            for (const char* origin : {"http://127.0.0.1:8123", "http://localhost:8123", "http://[::1]:8123"})
                EXPECT_EQ(verdict(origin, arrived_on), RequestVerdict::Allowed) << bind << " " << origin;
        // A socket bound to :: reports an IPv4 client's address mapped into IPv6.
        EXPECT_EQ(verdict("http://192.168.1.20:8123", "::ffff:192.168.1.20"), RequestVerdict::Allowed) << bind;
        EXPECT_EQ(verdict("http://[2001:db8::7]:8123", "2001:db8::7"), RequestVerdict::Allowed) << bind;
        EXPECT_EQ(verdict("http://2001:db8::7:8123", "2001:db8::7"), RequestVerdict::Forbidden) << bind << " no brackets";
        EXPECT_EQ(verdict("http://[2001:db8::1]:8123", "2001:db8::7"), RequestVerdict::Forbidden) << bind;
        EXPECT_EQ(verdict("http://192.168.1.20:8123", ""), RequestVerdict::Forbidden) << bind << " arrived on no address";
    }
}

TEST(RequestGuard, ChangesNeedTheServersOwnOrigin) {
    const RequestGuard guard(kToken, "127.0.0.1", 8123);
    RequestFacts post = get("/export");
    post.method = "POST";
    EXPECT_EQ(guard.check(post), RequestVerdict::Forbidden) << "no Origin";
    for (const char* origin : {"http://127.0.0.1:8123", "http://localhost:8123"}) {
        post.origin = origin;
        EXPECT_EQ(guard.check(post), RequestVerdict::Allowed) << origin;
    }
    for (const char* origin : {"http://evil.example", "http://evil.example:8123", "null", "https://127.0.0.1:8123",
                               "http://127.0.0.1:8124", "http://127.0.0.1", ""}) {
        post.origin = origin;
        EXPECT_EQ(guard.check(post), RequestVerdict::Forbidden) << origin;
    }
    post.origin = "http://127.0.0.1:8123";
    post.arrived_on = "";
    EXPECT_EQ(guard.check(post), RequestVerdict::Forbidden) << "a loopback Origin needs a loopback arrival";
    post.arrived_on = "127.0.0.1";
    // The token is still needed with the right Origin.
    post.origin = "http://127.0.0.1:8123";
    post.query_tokens.clear();
    EXPECT_EQ(guard.check(post), RequestVerdict::Forbidden);
}

TEST(RequestGuard, PrintedHostIsTheBoundAddress) {
    EXPECT_EQ(url_host("127.0.0.1"), "127.0.0.1");
    EXPECT_EQ(url_host("0.0.0.0"), "127.0.0.1");
    EXPECT_EQ(url_host("::"), "127.0.0.1");
    EXPECT_EQ(url_host("::1"), "[::1]");
    EXPECT_EQ(url_host("192.168.1.20"), "192.168.1.20");
}

// The printed address is the one bound, as the system spells it: a Host or Origin naming it
// with another spelling of the same address is this server (it was refused: 403 on the very
// address the viewer printed). Every address spelt otherwise ("0:0::0") is every address.
TEST(RequestGuard, TheBoundAddressIsRecognisedHoweverSpelt) {
    const RequestGuard v6("tok", "fd00:0::2", 8000);
    EXPECT_TRUE(v6.host_allowed("[fd00::2]:8000"));
    EXPECT_TRUE(v6.host_allowed("[FD00:0:0:0:0:0:0:2]:8000"));
    EXPECT_TRUE(v6.origin_allowed("http://[fd00::2]:8000", "fd00::2"));
    EXPECT_FALSE(v6.host_allowed("[fd00::3]:8000"));
    EXPECT_FALSE(v6.host_allowed("fd00::2:8000")) << "an IPv6 address without brackets";
    EXPECT_FALSE(v6.host_allowed("[fd00::2]:8001"));
    const RequestGuard mapped("tok", "::ffff:127.0.0.1", 8000);
    EXPECT_TRUE(mapped.host_allowed("[::ffff:7f00:1]:8000"));
    EXPECT_TRUE(mapped.origin_allowed("http://[::ffff:7f00:1]:8000", "::ffff:127.0.0.1"));
    EXPECT_TRUE(is_loopback_address("::ffff:127.0.0.1"));
    const RequestGuard every("tok", "0:0::0", 8000);
    EXPECT_TRUE(every.host_allowed("192.168.1.20:8000")) << "bound to every address";
    EXPECT_EQ(url_host("0:0::0"), "127.0.0.1");
}

}  // namespace
}  // namespace clr
