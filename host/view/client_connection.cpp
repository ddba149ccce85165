#include "view/client_connection.h"

#include <dirent.h>
#include <netdb.h>
#include <poll.h>
#include <sys/socket.h>
#include <sys/stat.h>

#include <cstdlib>

namespace clr {
namespace {

// The numeric address and port of a socket address, as cpp-httplib writes them (getnameinfo).
bool address_is(const sockaddr_storage& address, socklen_t length, const std::string& host, int port) {
    char text[NI_MAXHOST];
    char service[NI_MAXSERV];
    if (::getnameinfo(reinterpret_cast<const sockaddr*>(&address), length, text, sizeof text, service, sizeof service,
                      NI_NUMERICHOST | NI_NUMERICSERV) != 0)
        return false;
    return std::atoi(service) == port && host == text;
}

bool socket_connects(int descriptor, const std::string& local_addr, int local_port, const std::string& remote_addr,
                     int remote_port) {
    struct stat status;
    if (::fstat(descriptor, &status) != 0 || !S_ISSOCK(status.st_mode)) return false;
    sockaddr_storage address{};
    socklen_t length = sizeof address;
    if (::getsockname(descriptor, reinterpret_cast<sockaddr*>(&address), &length) != 0 ||
        !address_is(address, length, local_addr, local_port))
        return false;
    length = sizeof address;
    return ::getpeername(descriptor, reinterpret_cast<sockaddr*>(&address), &length) == 0 &&
           address_is(address, length, remote_addr, remote_port);
}

}  // namespace

ClientConnection::ClientConnection(const std::string& local_addr, int local_port, const std::string& remote_addr,
                                   int remote_port) {
    if (local_port <= 0 || remote_port <= 0) return;
    DIR* folder = ::opendir("/proc/self/fd");
    if (!folder) return;
    const int own = ::dirfd(folder);
    while (const dirent* entry = ::readdir(folder)) {
        char* end = nullptr;
        const long descriptor = std::strtol(entry->d_name, &end, 10);
        if (end == entry->d_name || *end != '\0' || descriptor == own) continue;
        if (socket_connects(static_cast<int>(descriptor), local_addr, local_port, remote_addr, remote_port)) {
            socket_ = static_cast<int>(descriptor);
            break;
        }
    }
    ::closedir(folder);
}

bool ClientConnection::gone() const {
    if (socket_ < 0) return false;
    pollfd state{socket_, POLLRDHUP, 0};
    if (::poll(&state, 1, 0) <= 0) return false;
    return (state.revents & (POLLRDHUP | POLLHUP | POLLERR)) != 0;
}

}  // namespace clr
