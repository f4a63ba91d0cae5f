// Testbed renderer — implementation of gif_writer.hpp (see there).
#include "render/gif_writer.hpp"

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <sstream>

extern char** environ;

namespace tb {

std::string findInPath(const std::string& program) {
    const char* path = std::getenv("PATH");
    if (!path) return {};
    std::stringstream dirs(path);
    std::string dir;
    while (std::getline(dirs, dir, ':')) {
        if (dir.empty()) continue;
        std::string candidate = dir + "/" + program;
        if (::access(candidate.c_str(), X_OK) == 0) return candidate;
    }
    return {};
}

bool writeGifWithImageMagick(const std::vector<std::string>& pngFiles, const std::string& outPath,
                             int delayCentiseconds, int maxWidth, std::string& message) {
    if (pngFiles.empty()) {
        message = "no frames to assemble";
        return false;
    }
    std::string convert = findInPath("convert");
    if (convert.empty()) {
        message = "ImageMagick 'convert' not found in PATH (Debian package imagemagick); no GIF written";
        return false;
    }
    std::vector<std::string> args = {"convert", "-delay", std::to_string(delayCentiseconds > 0 ? delayCentiseconds : 2),
                                     "-loop", "0"};
    args.insert(args.end(), pngFiles.begin(), pngFiles.end());
    if (maxWidth > 0) {
        args.push_back("-resize");
        args.push_back(std::to_string(maxWidth) + "x>");
    }
    // Ordered, fixed processing: no dithering noise, frame differences only.
    args.insert(args.end(), {"+dither", "-layers", "Optimize", outPath});
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);

    pid_t pid = 0;
    int rc = posix_spawn(&pid, convert.c_str(), nullptr, nullptr, argv.data(), environ);
    if (rc != 0) {
        message = "could not start " + convert + ": " + std::strerror(rc);
        return false;
    }
    int status = 0;
    while (waitpid(pid, &status, 0) < 0) {
        if (errno != EINTR) {
            message = "waiting for convert failed";
            return false;
        }
    }
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
        message = "convert failed (exit status " + std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : -1) + ")";
        return false;
    }
    message = "written with " + convert;
    return true;
}

}  // namespace tb
