#include "protocol/link.hpp"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <termios.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>

#include "protocol/frame.hpp"

namespace bridge {

namespace {

[[noreturn]] void fail(const std::string& what) {
    throw LinkError(what + ": " + std::strerror(errno));
}

sockaddr_in address(const std::string& host, std::uint16_t port) {
    sockaddr_in a{};
    a.sin_family = AF_INET;
    a.sin_port = htons(port);
    const std::string h = host == "localhost" ? "127.0.0.1" : host;
    if (inet_pton(AF_INET, h.c_str(), &a.sin_addr) != 1)
        throw LinkError("'" + host + "' is not an IPv4 address (give e.g. 127.0.0.1)");
    return a;
}

// Milliseconds left until the deadline, for poll(); 0 once it has passed.
int remaining_ms(Clock::time_point deadline) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
    return left > 0 ? static_cast<int>(left) + 1 : 0;
}

bool wait_readable(int fd, Clock::time_point deadline) {
    for (;;) {
        pollfd p{fd, POLLIN, 0};
        const int r = ::poll(&p, 1, remaining_ms(deadline));
        if (r < 0 && errno == EINTR) continue;
        if (r < 0) fail("poll");
        if (r == 0) return false;
        if (p.revents & (POLLIN | POLLHUP | POLLERR)) return true;
    }
}

speed_t baud_constant(int baud) {
    switch (baud) {
        case 9600:
            return B9600;
        case 19200:
            return B19200;
        case 38400:
            return B38400;
        case 57600:
            return B57600;
        case 115200:
            return B115200;
        case 230400:
            return B230400;
        case 460800:
            return B460800;
        case 921600:
            return B921600;
        default:
            throw LinkError("unsupported baud rate " + std::to_string(baud));
    }
}

}  // namespace

FileDescriptor::~FileDescriptor() {
    if (fd_ >= 0) ::close(fd_);
}

std::unique_ptr<UdpLink> UdpLink::connect(const std::string& host, std::uint16_t port) {
    const sockaddr_in a = address(host, port);
    FileDescriptor fd(::socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0));
    if (fd.get() < 0) fail("socket");
    if (::connect(fd.get(), reinterpret_cast<const sockaddr*>(&a), sizeof a) != 0)
        fail("udp " + host + ":" + std::to_string(port));
    return std::unique_ptr<UdpLink>(new UdpLink(std::move(fd), true));
}

std::unique_ptr<UdpLink> UdpLink::bind(const std::string& host, std::uint16_t port) {
    const sockaddr_in a = address(host, port);
    FileDescriptor fd(::socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0));
    if (fd.get() < 0) fail("socket");
    if (::bind(fd.get(), reinterpret_cast<const sockaddr*>(&a), sizeof a) != 0)
        fail("bind udp " + host + ":" + std::to_string(port));
    return std::unique_ptr<UdpLink>(new UdpLink(std::move(fd), false));
}

std::uint16_t UdpLink::port() const {
    sockaddr_in a{};
    socklen_t len = sizeof a;
    if (::getsockname(fd_.get(), reinterpret_cast<sockaddr*>(&a), &len) != 0) fail("getsockname");
    return ntohs(a.sin_port);
}

void UdpLink::send(std::span<const std::uint8_t> frame) {
    ssize_t r;
    if (connected_) {
        r = ::send(fd_.get(), frame.data(), frame.size(), 0);
    } else {
        if (peer_.empty()) throw LinkError("udp: no peer to answer yet");
        r = ::sendto(fd_.get(), frame.data(), frame.size(), 0, reinterpret_cast<const sockaddr*>(peer_.data()),
                     static_cast<socklen_t>(peer_.size()));
    }
    // A refused datagram (nobody listening yet) is a lost frame, not an error of the link.
    if (r < 0 && errno != ECONNREFUSED) fail("udp send");
}

std::optional<std::vector<std::uint8_t>> UdpLink::receive(Clock::time_point deadline) {
    // Room for one byte more than the largest frame, so an oversized datagram is seen as such.
    std::vector<std::uint8_t> buffer(max_frame_size + 1);
    while (wait_readable(fd_.get(), deadline)) {
        sockaddr_storage from{};
        socklen_t len = sizeof from;
        const ssize_t r =
            ::recvfrom(fd_.get(), buffer.data(), buffer.size(), MSG_TRUNC, reinterpret_cast<sockaddr*>(&from), &len);
        if (r < 0) {
            if (errno == EINTR || errno == ECONNREFUSED || errno == EAGAIN) continue;
            fail("udp receive");
        }
        if (!connected_)
            peer_.assign(reinterpret_cast<const std::uint8_t*>(&from),
                         reinterpret_cast<const std::uint8_t*>(&from) + len);
        // MSG_TRUNC gives the datagram's real length: an oversized one keeps it, so the codec refuses it.
        buffer.resize(static_cast<std::size_t>(r), 0);
        return buffer;
    }
    return std::nullopt;
}

StreamLink::StreamLink(FileDescriptor fd, std::string path)
    : fd_(std::move(fd)), path_(std::move(path)), decoder_(max_frame_size) {}

std::unique_ptr<StreamLink> StreamLink::open_serial(const std::string& device, int baud) {
    const speed_t speed = baud_constant(baud);
    FileDescriptor fd(::open(device.c_str(), O_RDWR | O_NOCTTY | O_CLOEXEC));
    if (fd.get() < 0) fail("serial " + device);
    termios tio{};
    if (::tcgetattr(fd.get(), &tio) != 0) fail("tcgetattr " + device);
    ::cfmakeraw(&tio);  // 8 bits, no parity, no echo, no line editing: every byte as sent
    tio.c_cflag |= CLOCAL | CREAD;
    tio.c_cc[VMIN] = 0;
    tio.c_cc[VTIME] = 0;
    ::cfsetispeed(&tio, speed);
    ::cfsetospeed(&tio, speed);
    if (::tcsetattr(fd.get(), TCSANOW, &tio) != 0) fail("tcsetattr " + device);
    ::tcflush(fd.get(), TCIOFLUSH);
    return std::unique_ptr<StreamLink>(new StreamLink(std::move(fd), device));
}

std::unique_ptr<StreamLink> StreamLink::open_pty() {
    FileDescriptor fd(::posix_openpt(O_RDWR | O_NOCTTY | O_CLOEXEC));
    if (fd.get() < 0) fail("posix_openpt");
    if (::grantpt(fd.get()) != 0) fail("grantpt");
    if (::unlockpt(fd.get()) != 0) fail("unlockpt");
    const char* name = ::ptsname(fd.get());
    if (!name) fail("ptsname");
    // Raw on the terminal side too, before anyone opens it: no echo, no CR/LF translation.
    std::string path = name;
    FileDescriptor slave(::open(name, O_RDWR | O_NOCTTY | O_CLOEXEC));
    if (slave.get() < 0) fail("open " + path);
    {
        termios tio{};
        if (::tcgetattr(slave.get(), &tio) == 0) {
            ::cfmakeraw(&tio);
            ::tcsetattr(slave.get(), TCSANOW, &tio);
        }
    }
    auto link = std::unique_ptr<StreamLink>(new StreamLink(std::move(fd), std::move(path)));
    link->keep_open_ = std::move(slave);
    return link;
}

void StreamLink::send(std::span<const std::uint8_t> frame) {
    const auto bytes = slip_encode(frame);
    std::size_t done = 0;
    while (done < bytes.size()) {
        const ssize_t r = ::write(fd_.get(), bytes.data() + done, bytes.size() - done);
        if (r < 0 && errno == EINTR) continue;
        if (r < 0) fail("write " + path_);
        done += static_cast<std::size_t>(r);
    }
}

std::optional<std::vector<std::uint8_t>> StreamLink::receive(Clock::time_point deadline) {
    std::uint8_t chunk[256];
    while (wait_readable(fd_.get(), deadline)) {
        // One byte per read: nothing after a frame's closing END is taken off the line before it is
        // needed (frames are small and the link slow, so this costs nothing that matters).
        const ssize_t r = ::read(fd_.get(), chunk, 1);
        if (r < 0 && (errno == EINTR || errno == EAGAIN)) continue;
        if (r < 0 && errno == EIO) return std::nullopt;  // pty whose other side is closed
        if (r < 0) fail("read " + path_);
        if (r == 0) return std::nullopt;
        if (auto frame = decoder_.feed(chunk[0])) return frame;
    }
    return std::nullopt;
}

std::unique_ptr<Link> open_link(const LinkSettings& s) {
    if (s.transport == "udp") return UdpLink::connect(s.host, s.port);
    if (s.transport == "serial") return StreamLink::open_serial(s.device, s.baud);
    throw LinkError("unknown transport '" + s.transport + "' (udp or serial)");
}

}  // namespace bridge
