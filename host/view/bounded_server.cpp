#include "view/bounded_server.h"

#include <linux/sockios.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/ioctl.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <charconv>
#include <condition_variable>
#include <cstring>
#include <deque>
#include <functional>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "view/socket_address.h"

namespace clr {
namespace {

// The connection this thread serves: the post-routing handler, which cpp-httplib gives only the
// request and its answer, asks it what was read.
thread_local const RequestStream* stream_of_this_thread = nullptr;

// When the connection this thread is given was accepted (set by ConnectionQueue).
thread_local std::optional<std::chrono::steady_clock::time_point> accepted_for_this_thread;

// cpp-httplib's ThreadPool, which also counts the connections waiting for a thread and tells
// each thread when its connection was accepted.
class ConnectionQueue : public httplib::TaskQueue {
public:
    ConnectionQueue(std::size_t threads, std::atomic<std::size_t>& waiting) : waiting_(waiting) {
        for (std::size_t k = 0; k < threads; ++k) threads_.emplace_back([this] { work(); });
    }

    void enqueue(std::function<void()> serve) override {
        {
            std::lock_guard<std::mutex> lock(mutex_);
            connections_.push_back({std::move(serve), std::chrono::steady_clock::now()});
            waiting_ = connections_.size();
        }
        ready_.notify_one();
    }

    // Serves the connections still waiting, then joins the threads.
    void shutdown() override {
        {
            std::lock_guard<std::mutex> lock(mutex_);
            shutting_down_ = true;
        }
        ready_.notify_all();
        for (std::thread& thread : threads_) thread.join();
    }

private:
    struct Connection {
        std::function<void()> serve;
        std::chrono::steady_clock::time_point accepted;
    };

    void work() {
        for (;;) {
            Connection next;
            {
                std::unique_lock<std::mutex> lock(mutex_);
                ready_.wait(lock, [this] { return !connections_.empty() || shutting_down_; });
                if (connections_.empty()) return;  // shutting down
                next = std::move(connections_.front());
                connections_.pop_front();
                waiting_ = connections_.size();
            }
            accepted_for_this_thread = next.accepted;
            next.serve();
            accepted_for_this_thread.reset();
        }
    }

    std::atomic<std::size_t>& waiting_;
    std::mutex mutex_;
    std::condition_variable ready_;
    std::deque<Connection> connections_;
    bool shutting_down_ = false;
    std::vector<std::thread> threads_;
};

// Waits up to `ms` for `events` on `socket`: > 0 when ready, 0 when the time ran out, < 0 on
// an error.
int wait_for(int socket, short events, int ms) {
    pollfd entry{socket, events, 0};
    int ready;
    do ready = ::poll(&entry, 1, ms);
    while (ready < 0 && errno == EINTR);
    return ready;
}

// The bytes queued on `socket` that its peer has not yet taken (SIOCOUTQ); -1 where the system
// does not say.
int queued_bytes(int socket) {
    int queued = 0;
    return ::ioctl(socket, SIOCOUTQ, &queued) == 0 ? queued : -1;
}

// Waits, as cpp-httplib does between the requests of a kept-alive connection, until the next
// request's first bytes arrive (true), or the connection has been idle since `idle_since` for
// `idle` (for kIdleWhileOthersWait while other connections wait for a thread) or the server
// stops (false). Ten thousand connections that send nothing then cost the others a fraction
// of a second, not the keep-alive wait each.
bool next_request_arrives(int socket, std::chrono::steady_clock::time_point idle_since, std::chrono::milliseconds idle,
                          const std::atomic<socket_t>& listening, const std::atomic<std::size_t>& waiting) {
    while (listening != INVALID_SOCKET) {
        const auto limit = waiting > 0 ? std::min(idle, kIdleWhileOthersWait) : idle;
        const auto left = std::chrono::ceil<std::chrono::milliseconds>(idle_since + limit - std::chrono::steady_clock::now());
        const int ready = wait_for(socket, POLLIN, static_cast<int>(std::clamp<std::chrono::milliseconds::rep>(left.count(), 0, 50)));
        if (ready != 0) return ready > 0;  // bytes, or the client's end (read as such)
        if (left.count() <= 0) return false;
    }
    return false;
}

// Whether a Connection header of `answer` says close: a route's refusal sets one, and
// cpp-httplib adds its own where the request asked to close.
bool says_close(const httplib::Response& answer) {
    const auto [first, last] = answer.headers.equal_range("Connection");
    return std::any_of(first, last, [](const auto& header) { return header.second == "close"; });
}

// Makes `answer` say Connection: close once, and no Keep-Alive, which would contradict it.
void say_connection_closes(httplib::Response& answer) {
    answer.headers.erase("Connection");
    answer.set_header("Connection", "close");
    answer.headers.erase("Keep-Alive");
}

}  // namespace

// After a refusal the client may still be sending. Closing with its bytes unread makes the
// system reset the connection, and a reset can destroy the answer before the client reads it.
// So the server stops writing and drops what still comes for up to kLingerTime (64 KiB at most;
// what a web server calls a lingering close), then closes. One thread does that for every such
// connection at once: done by the thread that had served the connection, each refused request
// of a client that neither reads nor closes held a thread for the linger (0.1 s while others
// waited), and a local client without the token that sent 3200 of them at once kept every other
// client waiting 10 s, for as long as it went on sending.
class LingeringCloses {
public:
    LingeringCloses() : thread_([this] { run(); }) {}
    ~LingeringCloses() { stop(); }
    LingeringCloses(const LingeringCloses&) = delete;
    LingeringCloses& operator=(const LingeringCloses&) = delete;

    // Takes `socket` over: it is shut for writing now and closed after its linger.
    void add(int socket) {
        ::shutdown(socket, SHUT_WR);
        {
            std::lock_guard<std::mutex> lock(mutex_);
            if (!stopping_) {
                added_.push_back({socket, std::chrono::steady_clock::now() + kLingerTime, 0});
                changed_.notify_one();
                return;
            }
        }
        close_now(socket);  // the server has stopped: nothing is waited for any more
    }

    // Closes every connection at once and ends the thread.
    void stop() {
        {
            std::lock_guard<std::mutex> lock(mutex_);
            stopping_ = true;
        }
        changed_.notify_one();
        if (thread_.joinable()) thread_.join();
    }

private:
    struct Lingering {
        int socket;
        std::chrono::steady_clock::time_point until;
        std::size_t dropped;
    };

    static void close_now(int socket) {
        ::shutdown(socket, SHUT_RDWR);
        ::close(socket);
    }

    // Reads and drops what `entry`'s client sent; false when the connection is done with (the
    // client's end, an error, or more than it may send).
    static bool drain(Lingering& entry) {
        char scratch[4096];
        while (entry.dropped < 64 * 1024) {
            const ssize_t got = ::recv(entry.socket, scratch, sizeof scratch, MSG_DONTWAIT);
            if (got < 0 && errno == EINTR) continue;
            if (got < 0) return errno == EAGAIN || errno == EWOULDBLOCK;
            if (got == 0) return false;
            entry.dropped += static_cast<std::size_t>(got);
        }
        return false;
    }

    // Only this thread closes the sockets it watches (add() only hands them over), so that no
    // descriptor is closed, and its number taken by a new connection, while poll() watches it.
    void run() {
        std::vector<Lingering> watched;
        for (;;) {
            {
                std::unique_lock<std::mutex> lock(mutex_);
                changed_.wait(lock, [&] { return stopping_ || !added_.empty() || !watched.empty(); });
                watched.insert(watched.end(), added_.begin(), added_.end());
                added_.clear();
                if (stopping_) break;
            }
            close_beyond_the_most(watched);
            watch_a_slice(watched);
        }
        for (const Lingering& entry : watched) close_now(entry.socket);
    }

    // A flood of refused connections: the ones that have lingered longest go first.
    static void close_beyond_the_most(std::vector<Lingering>& watched) {
        if (watched.size() <= kMostLingering) return;
        const auto over = static_cast<std::ptrdiff_t>(watched.size() - kMostLingering);
        for (auto entry = watched.begin(); entry != watched.begin() + over; ++entry) close_now(entry->socket);
        watched.erase(watched.begin(), watched.begin() + over);
    }

    // Drops what came for up to 20 ms (connections handed over meanwhile are watched from the
    // next slice), and closes the connections that are done with or whose linger is over.
    static void watch_a_slice(std::vector<Lingering>& watched) {
        std::vector<pollfd> ready;
        for (const Lingering& entry : watched) ready.push_back({entry.socket, POLLIN, 0});
        if (::poll(ready.data(), ready.size(), 20) < 0 && errno != EINTR)
            for (pollfd& each : ready) each.revents = POLLERR;  // no poll (no memory): closed at once
        const auto now = std::chrono::steady_clock::now();
        std::size_t kept = 0;
        for (std::size_t k = 0; k < watched.size(); ++k) {
            const short events = ready[k].revents;
            const bool done = now >= watched[k].until || (events & (POLLERR | POLLNVAL)) != 0 ||
                              ((events & (POLLIN | POLLHUP)) != 0 && !drain(watched[k]));
            if (done)
                close_now(watched[k].socket);
            else
                watched[kept++] = watched[k];
        }
        watched.resize(kept);
    }

    std::mutex mutex_;
    std::condition_variable changed_;
    std::vector<Lingering> added_;  // handed over, not watched yet
    bool stopping_ = false;
    std::thread thread_;  // last: it starts once the members above are made
};

std::optional<std::size_t> declared_body_length(const httplib::Request& request) {
    const std::size_t given = request.get_header_value_count("Content-Length");
    if (given == 0) return 0;
    if (given > 1) return std::nullopt;
    const std::string text = request.get_header_value("Content-Length");
    std::size_t length = 0;
    const auto [stop, error] = std::from_chars(text.data(), text.data() + text.size(), length);
    if (text.empty() || error != std::errc() || stop != text.data() + text.size()) return std::nullopt;
    return length;
}

RequestStream::RequestStream(int socket, std::chrono::milliseconds read_timeout,
                             std::chrono::milliseconds write_timeout, std::size_t most_body_bytes,
                             const std::atomic<socket_t>& serving, const std::string& answer_headers,
                             const std::atomic<std::size_t>& others_waiting)
    : socket_(socket),
      read_timeout_(read_timeout),
      write_timeout_(write_timeout),
      most_body_bytes_(most_body_bytes),
      serving_(serving),
      answer_headers_(answer_headers),
      others_waiting_(others_waiting) {
    start_request(Clock::now());
}

int RequestStream::wait_while_serving(short events, int ms) const {
    const auto give_up = Clock::now() + std::chrono::milliseconds(ms);
    for (;;) {
        const bool stopping = serving_ == INVALID_SOCKET;
        const auto left = std::chrono::ceil<std::chrono::milliseconds>(give_up - Clock::now()).count();
        const int ready = wait_for(socket_, events, stopping ? 0 : static_cast<int>(std::clamp<decltype(left)>(left, 0, 50)));
        if (ready != 0) return ready;
        if (stopping) return -1;
        if (left <= 50) return 0;
    }
}

void RequestStream::start_request(Clock::time_point head_since) {
    request_deadline_ = Clock::now() + std::chrono::seconds(kRequestSeconds);
    head_since_ = head_since;
    answering_ = false;
    answer_head_.clear();
    answer_head_done_ = answer_closes_ = false;
    head_bytes_ = body_bytes_ = 0;
    head_parsed_ = false;
    declared_body_ = 0;
}

void RequestStream::head_parsed(std::optional<std::size_t> declared_body) {
    head_parsed_ = true;
    declared_body_ = declared_body;
}

// cpp-httplib reads a body exactly to its length, and reads none where no route reads it (a
// refusal before routing, a GET): the bytes it was handed after the head tell.
bool RequestStream::body_left_unread() const {
    return !head_parsed_ || !declared_body_ || *declared_body_ > body_bytes_;
}

int RequestStream::wait_ms(std::chrono::milliseconds timeout, Clock::time_point deadline) const {
    const auto left = std::chrono::ceil<std::chrono::milliseconds>(deadline - Clock::now());
    return static_cast<int>(std::max<std::chrono::milliseconds::rep>(0, std::min(timeout, left).count()));
}

bool RequestStream::is_readable() const {
    return buffer_at_ < buffered_ || wait_while_serving(POLLIN, wait_ms(read_timeout_, request_deadline_)) > 0;
}

bool RequestStream::is_writable() const {
    if (answering_) return wait_for_room();
    return wait_while_serving(POLLOUT, wait_ms(write_timeout_, Clock::now() + std::chrono::seconds(kAnswerSeconds))) > 0;
}

// A byte is the head's until cpp-httplib has parsed the head, whatever its lines end with:
// cpp-httplib skips a line that does not end in CR LF and ends the head only at an empty line
// that does, so a rule of the stream's own (an empty line of a bare line feed, say) would count
// headers that cpp-httplib still parses, and holds in memory, as body. cpp-httplib reads a head
// a byte at a time, so no read holds bytes of both.
bool RequestStream::take(std::size_t count) {
    if (!head_parsed_) {
        head_bytes_ += count;
        return head_bytes_ <= kMostHeadBytes;
    }
    body_bytes_ += count;
    return body_bytes_ <= most_body_bytes_;
}

ssize_t RequestStream::refuse(const char* status_line, const std::string& message) {
    limit_reached_ = true;
    if (!answering_) {
        const std::string body = "{\"error\":\"" + message + "\"}";  // the messages below need no escaping
        const std::string answer = std::string(status_line) + "\r\n" + answer_headers_ +
                                   "Connection: close\r\nContent-Type: application/json\r\nContent-Length: " +
                                   std::to_string(body.size()) + "\r\n\r\n" + body;
        if (wait_for(socket_, POLLOUT, 1000) > 0) (void)::send(socket_, answer.data(), answer.size(), MSG_NOSIGNAL);
        answering_ = true;
    }
    return -1;
}

std::pair<RequestStream::Clock::time_point, RequestStream::Late> RequestStream::next_limit(
    Clock::time_point waiting_since) const {
    std::pair<Clock::time_point, Late> limit{request_deadline_, Late::Deadline};
    if (waiting_since + read_timeout_ < limit.first) limit = {waiting_since + read_timeout_, Late::Stalled};
    const Clock::time_point head_limit = head_since_ + kHeadWhileOthersWait;
    if (!head_parsed_ && others_waiting_ > 0 && head_limit < limit.first)
        limit = {head_limit, Late::HeadWhileOthersWait};
    return limit;
}

std::string RequestStream::late_message(Late why) const {
    const auto in_seconds = [](std::chrono::milliseconds time) {
        const auto count = time.count();
        return count % 1000 == 0 ? std::to_string(count / 1000) + " s" : std::to_string(count) + " ms";
    };
    switch (why) {
        case Late::Deadline:
            return "the request did not arrive whole within " + std::to_string(kRequestSeconds) +
                   " s of its first byte";
        case Late::Stalled:
            return "the request stopped arriving: nothing came for " + in_seconds(read_timeout_);
        case Late::HeadWhileOthersWait:
            return "the request's head did not arrive within " + in_seconds(kHeadWhileOthersWait) +
                   ", while other clients waited";
    }
    return "the request did not arrive in time";
}

ssize_t RequestStream::fill_buffer() {
    // However steadily a client trickles its bytes, its request ends at the deadline.
    if (Clock::now() >= request_deadline_) return refuse("HTTP/1.1 408 Request Timeout", late_message(Late::Deadline));
    const Clock::time_point waiting_since = Clock::now();
    for (;;) {
        const auto [limit, why] = next_limit(waiting_since);
        const auto left = std::chrono::ceil<std::chrono::milliseconds>(limit - Clock::now()).count();
        // In slices: other connections may start to wait meanwhile, which shortens the head's
        // limit. A limit that has passed still takes the bytes that are there: a request whose
        // head arrived whole while it waited for a thread is read.
        const int ready = wait_while_serving(POLLIN, static_cast<int>(std::clamp<decltype(left)>(left, 0, 50)));
        if (ready < 0) return -1;
        if (ready > 0) break;
        if (left <= 0) return refuse("HTTP/1.1 408 Request Timeout", late_message(why));
    }
    ssize_t got;
    do got = ::recv(socket_, buffer_, sizeof buffer_, 0);
    while (got < 0 && errno == EINTR);
    if (got <= 0) return got;
    buffered_ = static_cast<std::size_t>(got);
    buffer_at_ = 0;
    return got;
}

ssize_t RequestStream::read(char* ptr, std::size_t size) {
    if (limit_reached_) return -1;
    if (buffer_at_ == buffered_) {
        const ssize_t got = fill_buffer();
        if (got <= 0) return got;
    }
    const std::size_t count = std::min(size, buffered_ - buffer_at_);
    const char* bytes = buffer_ + buffer_at_;
    if (!take(count)) {
        if (head_parsed_)
            return refuse("HTTP/1.1 413 Payload Too Large",
                          "request bodies may have at most " + std::to_string(most_body_bytes_) + " bytes");
        return refuse("HTTP/1.1 431 Request Header Fields Too Large",
                      "a request's head (its request line and headers) may have at most " +
                          std::to_string(kMostHeadBytes) + " bytes");
    }
    std::memcpy(ptr, bytes, count);
    buffer_at_ += count;
    return static_cast<ssize_t>(count);
}

ssize_t RequestStream::write(const char* ptr, std::size_t size) {
    // A refusal has answered the request: cpp-httplib, whose read failed, answers it again (400,
    // or its own 413), and a second answer would be paired with the client's next request.
    if (limit_reached_) return static_cast<ssize_t>(size);
    if (!answering_) {
        answering_ = true;
        answer_deadline_ = Clock::now() + std::chrono::seconds(kAnswerSeconds);
    }
    bool interim = false;
    if (!answer_head_done_) {
        // cpp-httplib writes a head in pieces, and writes `Connection: close` as set.
        constexpr std::size_t kMostAnswerHead = 16 * 1024;
        answer_head_.append(ptr, std::min(size, kMostAnswerHead - answer_head_.size()));
        const std::size_t end = answer_head_.find("\r\n\r\n");
        if (end != std::string::npos || answer_head_.size() == kMostAnswerHead) {
            answer_head_done_ = true;
            const std::string head = answer_head_.substr(0, end == std::string::npos ? end : end + 2);
            answer_closes_ = head.find("\r\nConnection: close\r\n") != std::string::npos;
            // "100 Continue" (written whole, in one piece) only invites the body: the answer
            // proper, its head and its deadline, follow.
            interim = head.rfind("HTTP/1.1 1", 0) == 0 || head.rfind("HTTP/1.0 1", 0) == 0;
        }
    }
    // Never a send that blocks: a blocking one waits inside the system for a client that does
    // not read (up to the write timeout each time), where a stop could not end the wait.
    for (std::size_t sent = 0; sent < size;) {
        if (!wait_for_room()) return -1;
        const ssize_t now = ::send(socket_, ptr + sent, size - sent, MSG_NOSIGNAL | MSG_DONTWAIT);
        if (now >= 0)
            sent += static_cast<std::size_t>(now);
        else if (errno != EINTR && errno != EAGAIN && errno != EWOULDBLOCK)
            return -1;
    }
    if (interim) {
        answering_ = answer_head_done_ = answer_closes_ = false;
        answer_head_.clear();
    }
    return static_cast<ssize_t>(size);
}

// The system says a socket is writable only once a third of its send buffer is free, which a
// client reading a large answer slowly but steadily (200 KB/s against 4 MB of buffer) takes
// longer than the write timeout to make: the client is given up only when it has taken nothing
// (the bytes queued for it have not shrunk) for the write timeout.
bool RequestStream::wait_for_room() const {
    int queued = queued_bytes(socket_);
    auto taken_at = Clock::now();
    for (;;) {
        const int ms = std::min(wait_ms(write_timeout_, answer_deadline_), 250);
        const int ready = wait_while_serving(POLLOUT, ms);
        if (ready != 0) return ready > 0;
        const auto now = Clock::now();
        if (now >= answer_deadline_) return false;
        const int still = queued_bytes(socket_);
        if (still >= 0 && still < queued) taken_at = now;
        queued = still;
        if (now - taken_at >= write_timeout_) return false;
    }
}

void RequestStream::get_remote_ip_and_port(std::string& ip, int& port) const {
    if (const std::optional<SocketAddress> remote = remote_address_of(socket_)) {
        ip = remote->ip;
        port = remote->port;
    }
}

void RequestStream::get_local_ip_and_port(std::string& ip, int& port) const {
    if (const std::optional<SocketAddress> local = local_address_of(socket_)) {
        ip = local->ip;
        port = local->port;
    }
}

// An answer to a request whose body was not read says Connection: close, and the connection
// closes after it. cpp-httplib would keep it open and parse the body as the next request, one
// that no refusal had seen: the body of a request refused for its Host or Origin could carry a
// request with the Host and Origin the refusal was about. Any answer that closes says so once
// and offers no keep-alive: a route's Connection: close and cpp-httplib's stood side by side,
// or beside cpp-httplib's Keep-Alive.
BoundedServer::BoundedServer(std::size_t threads) : lingering_(std::make_unique<LingeringCloses>()) {
    new_task_queue = [this, threads] { return new ConnectionQueue(threads, waiting_connections_); };
    httplib::Server::set_post_routing_handler([](const httplib::Request&, httplib::Response& answer) {
        const bool body_unread = stream_of_this_thread != nullptr && stream_of_this_thread->body_left_unread();
        if (body_unread || says_close(answer)) say_connection_closes(answer);
    });
}

BoundedServer::~BoundedServer() {
    if (kept_listening_ >= 0) ::close(kept_listening_);
}

void BoundedServer::listen_until_stopped() {
    {
        std::lock_guard<std::mutex> lock(stop_mutex_);
        if (stopping_ || svr_sock_ == INVALID_SOCKET) return;
        kept_listening_ = ::fcntl(svr_sock_, F_DUPFD_CLOEXEC, 0);
    }
    for (;;) {
        listen_after_bind();
        // Ended by stop(), or by a failed accept() after which cpp-httplib closed its descriptor
        // of the socket (and left its number in svr_sock_). The kept duplicate still listens.
        for (;;) {
            {
                std::lock_guard<std::mutex> lock(stop_mutex_);
                if (stopping_ || kept_listening_ < 0) return;
                const int again = ::fcntl(kept_listening_, F_DUPFD_CLOEXEC, 0);
                if (again >= 0) {
                    svr_sock_ = again;
                    break;
                }
            }
            // No descriptor to be had (the shortage that failed the accept): wait, as cpp-httplib
            // waits out EMFILE.
            std::this_thread::sleep_for(std::chrono::milliseconds(10));
        }
        // The shortage may not be over: the next round's first accept() may fail as well, and
        // each round starts a pool of threads.
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
}

void BoundedServer::set_answer_headers(const httplib::Headers& headers) {
    answer_header_lines_.clear();
    for (const auto& [name, value] : headers) answer_header_lines_ += name + ": " + value + "\r\n";
    set_default_headers(headers);
}

void BoundedServer::stop() {
    std::lock_guard<std::mutex> lock(stop_mutex_);
    stopping_ = true;
    httplib::Server::stop();
    // A round about to start (not running yet, so Server::stop() did nothing) finds the socket
    // shut down: its accept() fails at once and the round ends.
    if (kept_listening_ >= 0) ::shutdown(kept_listening_, SHUT_RDWR);
    lingering_->stop();  // a connection lingering after a refusal is closed at once
}

// cpp-httplib's own loop over a connection's requests (process_server_socket in 0.11.4), with
// one RequestStream for the whole connection: bytes of a next request that arrived with the
// last one stay in its buffer.
bool BoundedServer::process_and_close_socket(socket_t socket) {
    using std::chrono::milliseconds;
    // Each piece of an answer leaves at once. cpp-httplib writes an answer's head and its body
    // apart, and Nagle's algorithm held the body until the client acknowledged the head, which
    // its system delays by 40 ms (delayed ACK): every answer under about 64 KiB on a kept-alive
    // connection (a small scene's live frames, /camera.json at each step of the time slider,
    // /job, the page's files) took 40 ms rather than a fraction of one.
    const int no_delay = 1;
    ::setsockopt(socket, IPPROTO_TCP, TCP_NODELAY, &no_delay, sizeof no_delay);
    RequestStream stream(socket, milliseconds(read_timeout_sec_ * 1000 + read_timeout_usec_ / 1000),
                         milliseconds(write_timeout_sec_ * 1000 + write_timeout_usec_ / 1000), payload_max_length_,
                         svr_sock_, answer_header_lines_, waiting_connections_);
    stream_of_this_thread = &stream;
    const auto parsed = [&stream](httplib::Request& request) {
        stream.head_parsed(declared_body_length(request));
        // Every answer is sent whole: a Range header is ignored, as HTTP lets a server do.
        // cpp-httplib would build the answer to each range in memory, a thousand ranges of a
        // frame a thousand copies of it, without bound.
        request.ranges.clear();
    };
    bool served = false;
    const auto accepted = accepted_for_this_thread.value_or(std::chrono::steady_clock::now());
    auto idle_since = accepted;
    for (std::size_t left = keep_alive_max_count_; left > 0; --left) {
        if (!stream.has_buffered_bytes() && !next_request_arrives(socket, idle_since, milliseconds(keep_alive_timeout_sec_ * 1000),
                                                                  svr_sock_, waiting_connections_))
            break;
        stream.start_request(left == keep_alive_max_count_ ? accepted : std::chrono::steady_clock::now());
        bool connection_closed = false;
        served = process_request(stream, left == 1, connection_closed, parsed);
        if (!served || connection_closed || stream.limit_reached() || stream.answer_closes()) break;
        idle_since = std::chrono::steady_clock::now();
    }
    stream_of_this_thread = nullptr;
    if (stream.limit_reached() || stream.answer_closes()) {
        lingering_->add(socket);  // closed by LingeringCloses; this thread serves the next connection
        return served;
    }
    ::shutdown(socket, SHUT_RDWR);
    ::close(socket);
    return served;
}

}  // namespace clr
