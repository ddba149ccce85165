// cpp-httplib's server with limits on what one request may cost the viewer before a route
// sees it. cpp-httplib 0.11.4 (Debian 12) bounds a request's body by payload_max_length, but
// not its head: a request line that never ends grows in memory as fast as a client sends it,
// and a client that trickles a byte every few seconds keeps one of the server's threads for
// ever. BoundedServer reads every connection through a stream of its own (RequestStream) that
//   - ends the head of a request (request line and headers, every byte until cpp-httplib has
//     parsed them, whatever their lines end with) at kMostHeadBytes, answering 431;
//   - ends a request that has not arrived whole within kRequestSeconds of its first byte, or
//     that stops arriving (no byte for the read timeout), answering 408 (cpp-httplib answered
//     a stall with a bare 400);
//   - ends a request whose head has not arrived within kHeadWhileOthersWait (from the
//     connection's acceptance, or from the request's first byte on a kept-alive connection)
//     while other connections wait for a thread, answering 408: a client that trickles its
//     head held a thread for the whole kRequestSeconds, and 64 of them kept every other
//     client waiting 20 s;
//   - ends an answer that the client has not taken within kAnswerSeconds;
//   - closes the connection after an answer to a request whose body it did not read, since
//     cpp-httplib would take that body for the next request;
//   - lets a connection it closes after a refusal linger (what the client still sends is read
//     and dropped, so that the answer is not lost to a reset) in one thread that watches all
//     such connections at once (LingeringCloses), not in the thread that served it: each
//     refused connection of a client that neither reads nor closes held its thread for the
//     linger, and 3200 requests without the token kept every other client waiting 10 s;
//   - sends every answer whole, ignoring a Range header (cpp-httplib would build a part for
//     each range in memory);
//   - sends each piece of an answer at once (TCP_NODELAY): the head and the body are written
//     apart, and the body waited for the client's delayed acknowledgement of the head (40 ms);
//   - closes a connection that has not started its next request within kIdleWhileOthersWait
//     (from its acceptance, or from its last answer) while other connections wait for a
//     thread: cpp-httplib's pool queues connections without bound, and each connection that
//     sends nothing would hold a thread for the whole keep-alive wait;
// and otherwise serves the connection as cpp-httplib does (keep-alive, its timeouts).
// docs/command-line.md (Viewer, Limits) lists the figures.
#pragma once

#include <httplib.h>

#include <atomic>
#include <chrono>
#include <cstddef>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <utility>

namespace clr {

// Largest head of a request: its request line and headers together.
constexpr std::size_t kMostHeadBytes = 64 * 1024;
// Longest a request (head and body) may take to arrive, from its first byte.
constexpr int kRequestSeconds = 10;
// Longest an answer may take to leave, from its first byte.
constexpr int kAnswerSeconds = 60;
// Longest a connection keeps its thread without starting a request while others wait for one.
constexpr std::chrono::milliseconds kIdleWhileOthersWait{100};
// Longest a connection closed after a refusal lingers (LingeringCloses), and most connections
// that linger at once: beyond that the one that has lingered longest is closed, so that a flood
// of refused requests holds a bounded number of descriptors.
constexpr std::chrono::milliseconds kLingerTime{1000};
constexpr std::size_t kMostLingering = 256;
// Longest a request's head may take to arrive while other connections wait for a thread. A
// client sends its head at once (the page's are a few hundred bytes); one that takes longer
// is slow or trickling, and others are waiting.
constexpr std::chrono::milliseconds kHeadWhileOthersWait{1000};

// The length a request's body says it has: 0 without a Content-Length, nullopt where the
// header is given twice or is not a plain number.
std::optional<std::size_t> declared_body_length(const httplib::Request& request);

// One connection's bytes as cpp-httplib reads and writes them, within the limits above.
// `read_timeout` and `write_timeout` bound each wait, as cpp-httplib's own stream does.
class RequestStream : public httplib::Stream {
public:
    // While `serving` names the listening socket, the server runs; once the server stops, a
    // request still arriving is dropped, and an answer still leaving given up, at once (within
    // 50 ms), not waited for.
    // `answer_headers` are header lines ("Name: value\r\n" each) that its own refusals carry
    // (BoundedServer::set_answer_headers()). `others_waiting` counts the connections waiting
    // for a thread.
    RequestStream(int socket, std::chrono::milliseconds read_timeout, std::chrono::milliseconds write_timeout,
                  std::size_t most_body_bytes, const std::atomic<socket_t>& serving, const std::string& answer_headers,
                  const std::atomic<std::size_t>& others_waiting);

    // The next request starts: its limits count from here, but its head's from `head_since`
    // (the connection's acceptance for its first request: the time it waited for a thread
    // counts, as its bytes were arriving meanwhile).
    void start_request(std::chrono::steady_clock::time_point head_since);
    // Whether a limit ended the request (the client got 431 or 408 and the connection closes).
    bool limit_reached() const { return limit_reached_; }
    // Whether bytes that arrived are not read yet (a next request sent with the last one).
    bool has_buffered_bytes() const { return buffer_at_ < buffered_; }
    // Whether the last answer's head said `Connection: close` (a refusal whose body, if the
    // client sends it, is never read): the connection ends after it.
    bool answer_closes() const { return answer_closes_; }
    // cpp-httplib has parsed the request's head; its body is `declared_body` bytes long
    // (nullopt where its Content-Length is unclear).
    void head_parsed(std::optional<std::size_t> declared_body);
    // Whether bytes of the request may be left unread: a body not read (whole), or a request
    // refused before its head was parsed. What follows would be read as the next request.
    bool body_left_unread() const;

    bool is_readable() const override;
    bool is_writable() const override;
    ssize_t read(char* ptr, std::size_t size) override;
    ssize_t write(const char* ptr, std::size_t size) override;
    void get_remote_ip_and_port(std::string& ip, int& port) const override;
    void get_local_ip_and_port(std::string& ip, int& port) const override;
    int socket() const override { return socket_; }

private:
    using Clock = std::chrono::steady_clock;
    // Milliseconds to wait for the socket: `timeout`, or less where `deadline` comes first.
    int wait_ms(std::chrono::milliseconds timeout, Clock::time_point deadline) const;
    // Answers `status_line` with {"error": message} and fails: the connection closes, and
    // nothing more is written to it (write() drops cpp-httplib's own answer to the failed read).
    ssize_t refuse(const char* status_line, const std::string& message);
    // Waits for the request's next bytes and reads them into the buffer: their count, 0 at the
    // client's end, -1 when the server stops or a limit ended the request (408).
    ssize_t fill_buffer();
    // Why a request is answered 408: its deadline passed, no byte came for the read timeout,
    // or its head took kHeadWhileOthersWait while others waited.
    enum class Late { Deadline, Stalled, HeadWhileOthersWait };
    // The first limit that a request, whose next bytes are waited for since `waiting_since`,
    // meets, and why it is one.
    std::pair<Clock::time_point, Late> next_limit(Clock::time_point waiting_since) const;
    std::string late_message(Late why) const;  // the 408's
    // Waits up to `ms` for `events` (POLLIN: bytes to read; POLLOUT: room to write), as
    // wait_for() answers, in slices of 50 ms: -1 once the server stops and the socket is not
    // ready at once. A request still arriving is then dropped, and an answer that the client
    // does not take is given up, rather than waited for: the stop joins this thread.
    int wait_while_serving(short events, int ms) const;
    // Waits for room to write more of the answer: false once the server stops, the answer's
    // deadline passes, or the client has taken nothing of it for the write timeout.
    bool wait_for_room() const;
    // Counts `count` bytes handed to cpp-httplib against the head's limit until the head is
    // parsed, then against the body's; false beyond one of them.
    bool take(std::size_t count);

    int socket_;
    std::chrono::milliseconds read_timeout_, write_timeout_;
    std::size_t most_body_bytes_;
    const std::atomic<socket_t>& serving_;
    const std::string& answer_headers_;
    const std::atomic<std::size_t>& others_waiting_;
    char buffer_[4096];
    std::size_t buffered_ = 0, buffer_at_ = 0;
    // This request's progress.
    Clock::time_point request_deadline_, answer_deadline_;
    Clock::time_point head_since_;
    bool answering_ = false;
    std::size_t head_bytes_ = 0, body_bytes_ = 0;
    bool head_parsed_ = false;
    std::optional<std::size_t> declared_body_;
    bool limit_reached_ = false;
    std::string answer_head_;  // the answer's head as written, until its empty line
    bool answer_head_done_ = false, answer_closes_ = false;
};

class LingeringCloses;

// httplib::Server whose connections are read through RequestStream.
class BoundedServer : public httplib::Server {
public:
    // Connections are served by `threads` threads of the server's own pool (new_task_queue is
    // set here and must stay), which counts the connections waiting for one.
    explicit BoundedServer(std::size_t threads);
    ~BoundedServer() override;

    // listen_after_bind(), until stop(): cpp-httplib 0.11.4 closes the listening socket and
    // returns at the first accept() that fails with anything but EMFILE (ENFILE or ENOBUFS: the
    // system's files or socket memory exhausted for a moment), and nothing would listen again.
    // A duplicate of the socket, kept here, keeps it listening (connections wait in its
    // backlog) and the server listens on it again, so that a passing shortage does not end it.
    void listen_until_stopped();
    // Server::stop(), also between two rounds of listen_until_stopped().
    void stop();
    // Headers that every answer carries: cpp-httplib's (set_default_headers(), also on its bare
    // 400 for a request line it cannot parse) and the refusals of the stream's own limits (408,
    // 413, 431), which cpp-httplib never sees.
    void set_answer_headers(const httplib::Headers& headers);

private:
    // Its own post-routing handler closes connections (see the constructor): not replaceable.
    using httplib::Server::set_post_routing_handler;

    bool process_and_close_socket(socket_t socket) override;

    std::atomic<std::size_t> waiting_connections_{0};  // accepted, not yet taken by a thread
    std::mutex stop_mutex_;
    bool stopping_ = false;
    int kept_listening_ = -1;  // the duplicate of the listening socket (listen_until_stopped)
    std::string answer_header_lines_;  // set_answer_headers(), as lines of an answer's head
    std::unique_ptr<LingeringCloses> lingering_;  // closes refused connections after their linger
};

}  // namespace clr
