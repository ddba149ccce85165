// Work the viewer is doing when its client leaves or a signal arrives: it ends within a
// fraction of a second, so that no core works for nobody, and the stop is the orderly one
// (128 + signal, "view stopped by ...", every thread joined), never the watchdog's, which
// would leave the page that opens the browser behind.
#include <gtest/gtest.h>

#include <arpa/inet.h>
#include <poll.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <mutex>
#include <sstream>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "support/loopback_client.h"
#include "support/temp_folder.h"
#include "view/viewer_process.h"

namespace clr {
namespace {

using testing::TempFolder;
using testing::ViewerProcess;

// Two mirrors facing each other and 40 spheres tested on every ray: a sample of 64 reflections
// takes milliseconds to explain, so 4096 samples take seconds to minutes.
void write_deep_mirrors(const TempFolder& folder) {
    std::string spheres;
    for (int i = 0; i < 40; ++i)
        spheres += std::string(i ? ", " : "") + "{\"center\": [" + std::to_string(-20 + i) +
                   ", 6, 0], \"radius\": 0.3, \"ambient\": [0.5, 0.5, 0.5]}";
    folder.write("mirrors.json", R"({
      "eye": [0, 0, 0], "lookat": [0, 0, -1], "up": [0, 1, 0], "fov_angle": 30,
      "width": 8, "height": 8, "MaxDepth": 64, "DefaultColor": [0.1, 0.1, 0.1],
      "billboards": [
        {"UpperLeft": [-50, 50, -5], "LowerLeft": [-50, -50, -5], "UpperRight": [50, 50, -5], "ambient": [1, 1, 1], "IsMirror": 1},
        {"UpperLeft": [-50, 50, 5], "LowerLeft": [50, 50, 5], "UpperRight": [-50, -50, 5], "ambient": [1, 1, 1], "IsMirror": 1}],
      "spheres": [)" + spheres + "]}");
}

// A connection to the viewer that has sent `path`'s GET; -1 when it cannot connect. With
// `receive_buffer`, the connection's receive buffer is that small.
int send_request(const ViewerProcess& viewer, const std::string& path, int receive_buffer = 0) {
    const int socket = testing::connect_to_loopback(viewer.port(), receive_buffer);
    if (socket < 0) return -1;
    const std::string request = "GET " + viewer.with_token(path) + " HTTP/1.1\r\nHost: 127.0.0.1:" +
                                std::to_string(viewer.port()) + "\r\n\r\n";
    (void)::send(socket, request.data(), request.size(), MSG_NOSIGNAL);
    return socket;
}

// The processor time `pid` has used so far, in seconds.
double processor_seconds(pid_t pid) {
    std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
    std::string text((std::istreambuf_iterator<char>(stat)), std::istreambuf_iterator<char>());
    std::istringstream fields(text.substr(text.rfind(')') + 2));  // after the command's name
    std::string field;
    unsigned long long user = 0, system = 0;
    for (int k = 3; k <= 15 && fields >> field; ++k) {
        if (k == 14) user = std::stoull(field);
        if (k == 15) system = std::stoull(field);
    }
    return static_cast<double>(user + system) / static_cast<double>(::sysconf(_SC_CLK_TCK));
}

// Sends `signal` and returns the exit code and the seconds the viewer took to end.
std::pair<int, double> timed_stop(ViewerProcess& viewer, int signal) {
    const auto signalled = std::chrono::steady_clock::now();
    const int code = viewer.stop(signal, 30);
    return {code, std::chrono::duration<double>(std::chrono::steady_clock::now() - signalled).count()};
}

constexpr const char* kLongExplanation = "/explain?x=4&y=4&spp=4096";

TEST(ViewWorkInFlight, AnExplanationStopsWhenItsClientLeaves) {
    TempFolder folder;
    write_deep_mirrors(folder);
    ViewerProcess viewer("mirrors.json", folder.path());
    ASSERT_TRUE(viewer.started()) << viewer.output();
    const int socket = send_request(viewer, kLongExplanation);
    ASSERT_GE(socket, 0);
    std::this_thread::sleep_for(std::chrono::seconds(1));  // explaining
    ::close(socket);
    std::this_thread::sleep_for(std::chrono::milliseconds(500));  // a look at the client, 50 ms apart
    const double before = processor_seconds(viewer.pid());
    std::this_thread::sleep_for(std::chrono::milliseconds(1500));
    const double used = processor_seconds(viewer.pid()) - before;
    EXPECT_LT(used, 0.3) << "the explanation went on for a client that is gone";
    EXPECT_EQ(viewer.stop(SIGTERM), 143) << viewer.output();
}

TEST(ViewWorkInFlight, AnExplanationStopsAtASignal) {
    TempFolder folder;
    write_deep_mirrors(folder);
    ViewerProcess viewer("mirrors.json", folder.path());
    ASSERT_TRUE(viewer.started()) << viewer.output();
    const int socket = send_request(viewer, kLongExplanation);
    ASSERT_GE(socket, 0);
    std::this_thread::sleep_for(std::chrono::seconds(1));  // explaining; the client waits
    const auto [code, seconds] = timed_stop(viewer, SIGTERM);
    ::close(socket);
    EXPECT_EQ(code, 143);
    EXPECT_LT(seconds, 3.0) << "the watchdog ended it (5 s), not the orderly stop";
    EXPECT_NE(viewer.output().find("clrender: view stopped by SIGTERM"), std::string::npos) << viewer.output();
    EXPECT_EQ(viewer.output().find("cannot be interrupted"), std::string::npos) << viewer.output();
}

// A client that asked for a large frame and does not read it (a frozen tab, a stopped script):
// the answer waits for room, and the stop does not wait with it.
TEST(ViewWorkInFlight, AnAnswerNobodyReadsDoesNotHoldUpTheStop) {
    TempFolder folder;
    ViewerProcess viewer("'" + std::string(CLRENDER_SOURCE_DIR) + "/scenes/demo/demo.json'", folder.path());
    ASSERT_TRUE(viewer.started()) << viewer.output();
    // 8 MB of RGBA, far more than the two ends' buffers hold.
    const int socket = send_request(viewer, "/frame.rgba?size=1920x1080&spp=1", 4096);
    ASSERT_GE(socket, 0);
    pollfd answer_begun{socket, POLLIN, 0};
    ASSERT_GT(::poll(&answer_begun, 1, 60000), 0) << "the frame is rendered and its answer begun";
    std::this_thread::sleep_for(std::chrono::milliseconds(300));  // the buffers fill
    const auto [code, seconds] = timed_stop(viewer, SIGTERM);
    ::close(socket);
    EXPECT_EQ(code, 143);
    EXPECT_LT(seconds, 3.0) << "the watchdog ended it (5 s), not the orderly stop";
    EXPECT_NE(viewer.output().find("clrender: view stopped by SIGTERM"), std::string::npos) << viewer.output();
}

// The first line of the answer on `socket` (read within `seconds`), with its headers.
std::string answer_head(int socket, int seconds) {
    std::string head;
    const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(seconds);
    while (head.find("\r\n\r\n") == std::string::npos && std::chrono::steady_clock::now() < give_up) {
        pollfd ready{socket, POLLIN, 0};
        char byte = 0;
        if (::poll(&ready, 1, 1000) <= 0) continue;
        if (::recv(socket, &byte, 1, 0) != 1) break;
        head += byte;
    }
    return head;
}

// Frames held for clients that take them slowly are bounded (view/answer_budget.h): while one
// client holds the largest frame, another is answered 503 with Retry-After before anything is
// rendered for it, and once the first has gone the next is served (8 slow clients held 3.9 GB).
TEST(ViewWorkInFlight, FramesHeldForSlowClientsAreBounded) {
    TempFolder folder;
    ViewerProcess viewer("'" + std::string(CLRENDER_SOURCE_DIR) + "/scenes/demo/demo.json'", folder.path());
    ASSERT_TRUE(viewer.started()) << viewer.output();
    const std::string largest = "/frame.rgba?size=8145x8145&spp=1";  // 265 MB of RGBA
    const int holding = send_request(viewer, largest, 4096);
    ASSERT_GE(holding, 0);
    pollfd answer_begun{holding, POLLIN, 0};
    ASSERT_GT(::poll(&answer_begun, 1, 60000), 0) << "the frame is rendered and its answer begun";
    const int refused = send_request(viewer, largest);
    ASSERT_GE(refused, 0);
    const std::string head = answer_head(refused, 10);
    ::close(refused);
    EXPECT_EQ(head.rfind("HTTP/1.1 503", 0), 0u) << head;
    EXPECT_NE(head.find("Retry-After: 1\r\n"), std::string::npos) << head;
    ::close(holding);  // the answer is given up at its next write: the budget is free again
    std::string served;
    for (int attempt = 0; attempt < 20 && served.rfind("HTTP/1.1 200", 0) != 0; ++attempt) {
        std::this_thread::sleep_for(std::chrono::milliseconds(250));
        const int next = send_request(viewer, largest, 4096);
        ASSERT_GE(next, 0);
        served = answer_head(next, 60);
        ::close(next);
    }
    EXPECT_EQ(served.rfind("HTTP/1.1 200", 0), 0u) << served;
    EXPECT_EQ(viewer.stop(SIGTERM), 143) << viewer.output();
}

// Reads the answer on `socket` slowly but steadily (a client on a slow link) until `stop`: its
// status line, then a kilobyte every 200 ms, so that the server keeps the answer for it.
class SlowReader {
public:
    explicit SlowReader(int socket) : socket_(socket), thread_([this] { run(); }) {}
    ~SlowReader() {
        stop_ = true;
        thread_.join();
        ::close(socket_);
    }
    // The answer's status line, or "" until it has arrived.
    std::string status() {
        const std::lock_guard<std::mutex> lock(mutex_);
        const std::size_t end = read_.find("\r\n");
        return end == std::string::npos ? "" : read_.substr(0, end);
    }

private:
    void run() {
        while (!stop_) {
            pollfd ready{socket_, POLLIN, 0};
            if (::poll(&ready, 1, 200) > 0) {
                char bytes[1024];
                const ssize_t got = ::recv(socket_, bytes, status().empty() ? 1 : sizeof bytes, 0);
                if (got <= 0) return;
                const std::lock_guard<std::mutex> lock(mutex_);
                if (read_.size() < 4096) read_.append(bytes, static_cast<std::size_t>(got));
            }
            if (!status().empty()) std::this_thread::sleep_for(std::chrono::milliseconds(200));
        }
    }
    int socket_;
    std::atomic<bool> stop_{false};
    std::mutex mutex_;
    std::string read_;
    std::thread thread_;  // last: it starts once the members above are made
};

// The answers to exports that clients take slowly are bounded with the frames' (view/
// answer_budget.h): each keeps its scene's text until its client has it. Of five exports of a
// scene of 45 MB sent at once and taken slowly, four are answered and the fifth is answered 503
// with Retry-After, before its file is written. Unbounded, 16 clients that took their answers to
// exports of a 20 MB scene slowly held 16 texts (352 MB with one malloc arena; now 10, 195 MB),
// and 32 of a scene of the largest size (64 MiB) would hold 2 GB.
TEST(ViewWorkInFlight, ExportAnswersHeldForSlowClientsAreBounded) {
    TempFolder folder;
    folder.write("notes.json", R"({"eye": [0, 0, 5], "lookat": [0, 0, 0], "up": [0, 1, 0], "fov_angle": 60,
                                   "width": 8, "height": 8, "notes": ")" + std::string(45000000, 'x') + "\"}");
    ::mkdir(folder.file("out").c_str(), 0755);
    ViewerProcess viewer("notes.json --output-dir out", folder.path());
    ASSERT_TRUE(viewer.started()) << viewer.output();
    const std::string body = R"({"keys": [{"eye": [0, 1, 5], "lookat": [0, 0, 0]}], "name": "e"})";
    const std::string request = "POST " + viewer.with_token("/export") + " HTTP/1.1\r\nHost: 127.0.0.1:" +
                                std::to_string(viewer.port()) + "\r\nOrigin: http://127.0.0.1:" +
                                std::to_string(viewer.port()) + "\r\nContent-Type: application/json\r\n" +
                                "Content-Length: " + std::to_string(body.size()) + "\r\n\r\n" + body;
    std::vector<std::unique_ptr<SlowReader>> clients;
    for (int i = 0; i < 5; ++i) {
        const int socket = testing::connect_to_loopback(viewer.port(), 4096);
        ASSERT_GE(socket, 0);
        ASSERT_EQ(::send(socket, request.data(), request.size(), MSG_NOSIGNAL), static_cast<ssize_t>(request.size()));
        clients.push_back(std::make_unique<SlowReader>(socket));
    }
    int answered = 0, refused = 0;
    std::string statuses;
    const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(120);
    while (answered + refused < 5 && std::chrono::steady_clock::now() < give_up) {
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
        answered = refused = 0;
        statuses.clear();
        for (const auto& client : clients) {
            const std::string status = client->status();
            answered += status.rfind("HTTP/1.1 200", 0) == 0;
            refused += status.rfind("HTTP/1.1 503", 0) == 0;
            statuses += "'" + status + "' ";
        }
    }
    EXPECT_EQ(answered, 4) << statuses;
    EXPECT_EQ(refused, 1) << statuses;
    int written = 0;
    for (const auto& entry : std::filesystem::directory_iterator(folder.file("out")))
        written += entry.is_regular_file();
    EXPECT_EQ(written, 4) << "the refused export wrote nothing";
    clients.clear();
    EXPECT_EQ(viewer.stop(SIGTERM), 143) << viewer.output();
}

}  // namespace
}  // namespace clr
