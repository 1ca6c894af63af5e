#include "x_screen.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <thread>

namespace glimmer_viewer {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

VirtualScreen::VirtualScreen(int width, int height) {
    int fds[2];
    if (::pipe(fds) != 0) {
        why_ = "pipe failed";
        return;
    }
    // -displayfd: the server takes the first free display itself and writes
    // its number once it accepts connections, so there is no race with
    // other X servers on this machine and no sleep.
    std::string fd = std::to_string(fds[1]);
    std::string screen = std::to_string(width) + "x" + std::to_string(height) + "x24";
    std::vector<std::string> argv = {"Xvfb", "-displayfd", fd, "-screen", "0", screen, "-nolisten", "tcp", "-br"};
    pid_ = ::fork();
    if (pid_ == 0) {
        ::setpgid(0, 0);
        ::close(fds[0]);
        int null = ::open("/dev/null", O_RDWR);
        ::dup2(null, 0);
        ::dup2(null, 1);
        ::dup2(null, 2);
        std::vector<char*> cargs;
        for (auto& a : argv) cargs.push_back(a.data());
        cargs.push_back(nullptr);
        ::execvp(cargs[0], cargs.data());
        ::_exit(127);
    }
    ::close(fds[1]);
    std::string number;
    auto end = Clock::now() + std::chrono::seconds(20);
    while (Clock::now() < end) {
        pollfd p{fds[0], POLLIN, 0};
        if (::poll(&p, 1, 100) <= 0) continue;
        char c = 0;
        if (::read(fds[0], &c, 1) != 1) break;  // the server died (Xvfb not installed?)
        if (c == '\n') {
            display_ = ":" + number;
            break;
        }
        number += c;
    }
    ::close(fds[0]);
    if (display_.empty()) why_ = "Xvfb did not report a display (is the xvfb package installed?)";
}

VirtualScreen::~VirtualScreen() {
    if (pid_ <= 0) return;
    ::kill(pid_, SIGTERM);
    auto end = Clock::now() + std::chrono::seconds(5);
    while (Clock::now() < end) {
        if (::waitpid(pid_, nullptr, WNOHANG) == pid_) return;
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    ::kill(pid_, SIGKILL);
    ::waitpid(pid_, nullptr, 0);
}

bool VirtualScreen::capture(glimmer::Image& out, std::string& error) const {
    if (display_.empty()) {
        error = why_;
        return false;
    }
    static int counter = 0;
    fs::path file = fs::temp_directory_path() /
                    ("glimmer_xwd_" + std::to_string(::getpid()) + "_" + std::to_string(counter++) + ".xwd");
    std::string cmd = "xwd -root -silent -display " + display_ + " -out " + file.string() + " 2>&1";
    int status = std::system(cmd.c_str());
    std::vector<std::uint8_t> bytes;
    {
        std::ifstream f(file, std::ios::binary);
        bytes.assign(std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>());
    }
    std::error_code ec;
    fs::remove(file, ec);
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
        error = "xwd failed (is the x11-apps package installed?)";
        return false;
    }
    return decodeXwd(bytes, out, error);
}

namespace {

std::uint32_t be32(const std::vector<std::uint8_t>& b, size_t at) {
    return std::uint32_t(b[at]) << 24 | std::uint32_t(b[at + 1]) << 16 | std::uint32_t(b[at + 2]) << 8 | b[at + 3];
}

// A mask's value scaled to 0..255.
std::uint8_t channel(std::uint32_t pixel, std::uint32_t mask) {
    if (mask == 0) return 0;
    int shift = 0;
    while (!((mask >> shift) & 1u)) ++shift;
    std::uint32_t max = mask >> shift;
    return std::uint8_t(((pixel & mask) >> shift) * 255u / max);
}

}  // namespace

bool decodeXwd(const std::vector<std::uint8_t>& b, glimmer::Image& out, std::string& error) {
    // XWDFileHeader: 25 big-endian CARD32s, then the window's name up to
    // header_size, then ncolors 12-byte XWDColor entries, then the pixels.
    if (b.size() < 100) {
        error = "not an XWD file: shorter than its header";
        return false;
    }
    auto field = [&](int i) { return be32(b, size_t(i) * 4); };
    std::uint32_t headerSize = field(0), version = field(1), format = field(2), width = field(4), height = field(5),
                  byteOrder = field(7), bitsPerPixel = field(11), bytesPerLine = field(12), visualClass = field(13),
                  red = field(14), green = field(15), blue = field(16), ncolors = field(19);
    if (version != 7 || headerSize < 100) {
        error = "not an XWD version 7 file";
        return false;
    }
    if (format != 2 || (visualClass != 4 && visualClass != 5) ||
        (bitsPerPixel != 8 && bitsPerPixel != 16 && bitsPerPixel != 24 && bitsPerPixel != 32)) {
        error = "XWD: only ZPixmap TrueColor/DirectColor dumps are read (format " + std::to_string(format) +
                ", class " + std::to_string(visualClass) + ", " + std::to_string(bitsPerPixel) + " bits)";
        return false;
    }
    if (width == 0 || height == 0 || width > 16384 || height > 16384 || bytesPerLine < width * bitsPerPixel / 8) {
        error = "XWD: bad size";
        return false;
    }
    size_t pixels = size_t(headerSize) + size_t(ncolors) * 12;
    if (b.size() < pixels + size_t(bytesPerLine) * height) {
        error = "XWD: truncated pixels";
        return false;
    }
    out = glimmer::Image::rgba8(int(width), int(height));
    size_t bytes = bitsPerPixel / 8;
    for (std::uint32_t y = 0; y < height; ++y) {
        const std::uint8_t* row = b.data() + pixels + size_t(y) * bytesPerLine;
        for (std::uint32_t x = 0; x < width; ++x) {
            const std::uint8_t* p = row + x * bytes;
            std::uint32_t v = 0;
            for (size_t i = 0; i < bytes; ++i) v |= std::uint32_t(p[byteOrder == 0 ? i : bytes - 1 - i]) << (8 * i);
            std::uint8_t* o = &out.u8[(size_t(y) * width + x) * 4];
            o[0] = channel(v, red);
            o[1] = channel(v, green);
            o[2] = channel(v, blue);
            o[3] = 255;
        }
    }
    return true;
}

}  // namespace glimmer_viewer
