#include "output/tev_connection.h"

#include <fcntl.h>
#include <netdb.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <memory>

#include "core/interruption.h"

namespace clr {
namespace {

using Clock = std::chrono::steady_clock;

// Waits up to `timeout` for `events` on `socket`, in slices, so that a signal is acted upon
// within a tenth of a second. Returns false on timeout; throws on a signal.
bool wait_for(int socket, short events, std::chrono::milliseconds timeout) {
    const Clock::time_point end = Clock::now() + timeout;
    for (;;) {
        if (interruption_requested()) throw TevConnectionError("interrupted");
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(end - Clock::now());
        if (left.count() <= 0) return false;
        pollfd waiting{socket, events, 0};
        const int ready = ::poll(&waiting, 1, static_cast<int>(std::min<long long>(left.count(), 100)));
        if (ready > 0) return true;
        if (ready < 0 && errno != EINTR) throw TevConnectionError(std::string("poll: ") + std::strerror(errno));
    }
}

// A non-blocking socket connected to `address` within `timeout`, or -1 with `problem` set.
int connect_to(const addrinfo& address, std::chrono::milliseconds timeout, std::string& problem) {
    const int socket = ::socket(address.ai_family, address.ai_socktype | SOCK_CLOEXEC | SOCK_NONBLOCK, address.ai_protocol);
    if (socket < 0) {
        problem = std::strerror(errno);
        return -1;
    }
    if (::connect(socket, address.ai_addr, address.ai_addrlen) == 0) return socket;
    if (errno != EINPROGRESS) {
        problem = std::strerror(errno);
        ::close(socket);
        return -1;
    }
    try {
        if (!wait_for(socket, POLLOUT, timeout)) {
            problem = "no answer within " + std::to_string(timeout.count()) + " ms";
            ::close(socket);
            return -1;
        }
    } catch (...) {
        ::close(socket);
        throw;
    }
    int error = 0;
    socklen_t length = sizeof error;
    if (::getsockopt(socket, SOL_SOCKET, SO_ERROR, &error, &length) != 0) error = errno;
    if (error != 0) {
        problem = std::strerror(error);
        ::close(socket);
        return -1;
    }
    return socket;
}

struct AddressListDeleter {
    void operator()(addrinfo* list) const { ::freeaddrinfo(list); }
};

}  // namespace

TevConnection::TevConnection(const std::string& host, const std::string& port, std::chrono::milliseconds timeout)
    : timeout_(timeout) {
    addrinfo hints{};
    hints.ai_family = AF_UNSPEC;
    hints.ai_socktype = SOCK_STREAM;
    hints.ai_flags = AI_NUMERICSERV;
    addrinfo* found = nullptr;
    const int resolved = ::getaddrinfo(host.c_str(), port.c_str(), &hints, &found);
    if (resolved != 0) throw TevConnectionError(std::string("cannot resolve the host: ") + ::gai_strerror(resolved));
    const std::unique_ptr<addrinfo, AddressListDeleter> addresses(found);
    std::string problem = "no address";
    for (const addrinfo* address = addresses.get(); address; address = address->ai_next) {
        socket_ = connect_to(*address, timeout, problem);
        if (socket_ >= 0) return;
    }
    throw TevConnectionError("cannot connect: " + problem);
}

TevConnection::~TevConnection() {
    if (socket_ >= 0) ::close(socket_);
}

void TevConnection::send(const TevPacket& packet) {
    std::size_t sent = 0;
    while (sent < packet.size()) {
        const ssize_t written = ::send(socket_, packet.data() + sent, packet.size() - sent, MSG_NOSIGNAL);
        if (written > 0) {
            sent += static_cast<std::size_t>(written);
            continue;
        }
        if (written < 0 && errno == EINTR) continue;
        if (written < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) {
            if (!wait_for(socket_, POLLOUT, timeout_))
                throw TevConnectionError("the viewer took no data for " + std::to_string(timeout_.count()) + " ms");
            continue;
        }
        throw TevConnectionError(std::string("the connection ended: ") + std::strerror(errno));
    }
}

}  // namespace clr
