// Byte links that carry whole frames: UDP (one frame per datagram) and byte streams (a serial
// device or a pseudo-terminal, frames in SLIP). Used by both ends, so the emulator talks exactly as
// firmware would. Errors of the operating system are thrown as LinkError.
#pragma once

#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "protocol/slip.hpp"

namespace bridge {

class LinkError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

using Clock = std::chrono::steady_clock;

class Link {
public:
    virtual ~Link() = default;
    virtual void send(std::span<const std::uint8_t> frame) = 0;
    // The next frame's raw bytes, or nothing when the deadline passes first.
    virtual std::optional<std::vector<std::uint8_t>> receive(Clock::time_point deadline) = 0;
    // Frames the framing layer dropped (SLIP noise, oversized), with the last reason.
    virtual long framing_errors() const { return 0; }
    virtual std::string last_framing_error() const { return {}; }
};

// A file descriptor closed on destruction.
class FileDescriptor {
public:
    explicit FileDescriptor(int fd = -1) : fd_(fd) {}
    ~FileDescriptor();
    FileDescriptor(FileDescriptor&& o) noexcept : fd_(o.fd_) { o.fd_ = -1; }
    FileDescriptor& operator=(FileDescriptor&& o) noexcept {
        std::swap(fd_, o.fd_);
        return *this;
    }
    FileDescriptor(const FileDescriptor&) = delete;
    int get() const { return fd_; }

private:
    int fd_;
};

class UdpLink final : public Link {
public:
    // The master's end: sends to host:port (IPv4 dotted address or "localhost").
    static std::unique_ptr<UdpLink> connect(const std::string& host, std::uint16_t port);
    // The board's end: listens on host:port (port 0: any free one, see port()); replies go to the
    // sender of the last frame received.
    static std::unique_ptr<UdpLink> bind(const std::string& host, std::uint16_t port);

    std::uint16_t port() const;  // the local port
    void send(std::span<const std::uint8_t> frame) override;
    std::optional<std::vector<std::uint8_t>> receive(Clock::time_point deadline) override;

private:
    UdpLink(FileDescriptor fd, bool connected) : fd_(std::move(fd)), connected_(connected) {}
    FileDescriptor fd_;
    bool connected_;
    std::vector<std::uint8_t> peer_;  // sockaddr of the last sender (bound end)
};

class StreamLink final : public Link {
public:
    // A serial device set to raw 8N1 at `baud` (one of the standard rates).
    static std::unique_ptr<StreamLink> open_serial(const std::string& device, int baud);
    // A new pseudo-terminal (the board's end is the master side); path() names the terminal to open.
    static std::unique_ptr<StreamLink> open_pty();

    const std::string& path() const { return path_; }
    void send(std::span<const std::uint8_t> frame) override;
    std::optional<std::vector<std::uint8_t>> receive(Clock::time_point deadline) override;
    long framing_errors() const override { return decoder_.dropped(); }
    std::string last_framing_error() const override { return decoder_.error(); }

private:
    StreamLink(FileDescriptor fd, std::string path);
    FileDescriptor fd_;
    std::string path_;
    SlipDecoder decoder_;
    // The pty's terminal side held open by its creator, so the master never reads a hang-up
    // between one user closing the terminal and the next opening it.
    FileDescriptor keep_open_;
};

// "udp" links need host and port, "serial" links device and baud.
struct LinkSettings {
    std::string transport = "udp";
    std::string host = "127.0.0.1";
    std::uint16_t port = 0;
    std::string device;
    int baud = 115200;
};
std::unique_ptr<Link> open_link(const LinkSettings& settings);

}  // namespace bridge
