#include "file_watch.h"

#include <poll.h>
#include <sys/inotify.h>
#include <unistd.h>

#include <filesystem>

namespace kiln::cli {

Watcher::Watcher() : fd_(inotify_init1(IN_CLOEXEC | IN_NONBLOCK)) {}

Watcher::~Watcher() {
    if (fd_ >= 0)
        close(fd_);
}

std::string Watcher::Normal(const std::string& path) {
    std::error_code ec;
    const std::filesystem::path p = std::filesystem::absolute(path, ec);
    return (ec ? std::filesystem::path(path) : p).lexically_normal().string();
}

void Watcher::Add(const std::string& file) {
    const std::string path = Normal(file);
    if (!files_.insert(path).second)
        return;
    const std::string dir = std::filesystem::path(path).parent_path().string();
    if (folders_.count(dir))
        return;
    const int wd = inotify_add_watch(fd_, dir.c_str(),
                                     IN_CLOSE_WRITE | IN_MOVED_TO | IN_MOVED_FROM | IN_CREATE |
                                         IN_DELETE | IN_ATTRIB | IN_ONLYDIR);
    if (wd >= 0) {
        folders_.insert(dir);
        by_wd_[wd] = dir;
    }
}

std::set<std::string> Watcher::WaitForChange() {
    std::set<std::string> changed;
    while (!Wait(-1, changed)) {
    }
    return changed;
}

void Watcher::Settle(std::set<std::string>& changed) {
    while (Wait(kQuietMs, changed)) {
    }
}

bool Watcher::Wait(int timeout_ms, std::set<std::string>& changed) {
    pollfd p{fd_, POLLIN, 0};
    if (poll(&p, 1, timeout_ms) <= 0)
        return false;
    alignas(inotify_event) char buffer[16384];
    bool any = false;
    for (;;) {
        const ssize_t n = read(fd_, buffer, sizeof buffer);
        if (n <= 0)
            break;
        for (ssize_t at = 0; at < n;) {
            const auto* e = reinterpret_cast<const inotify_event*>(buffer + at);
            at += static_cast<ssize_t>(sizeof(inotify_event) + e->len);
            const auto dir = by_wd_.find(e->wd);
            if (dir == by_wd_.end() || e->len == 0)
                continue;
            const std::string path = (std::filesystem::path(dir->second) / e->name).string();
            if (files_.count(path)) {
                changed.insert(path);
                any = true;
            }
        }
    }
    return any;
}

}  // namespace kiln::cli
