// Watching the files a command read, for kiln watch and kiln render --watch.
#ifndef KILN_TOOLS_CLI_FILE_WATCH_H_
#define KILN_TOOLS_CLI_FILE_WATCH_H_

#include <map>
#include <set>
#include <string>

namespace kiln::cli {

// Files watched for changes with inotify on their folders (each folder watched once), so that a
// file saved by renaming a new one over it, or deleted and made again, is seen.
class Watcher {
  public:
    Watcher();
    ~Watcher();
    Watcher(const Watcher&) = delete;
    Watcher& operator=(const Watcher&) = delete;
    bool ok() const { return fd_ >= 0; }

    // Watches `file` (its absolute, normal path) from now on; a file that does not exist yet is
    // watched for being made.
    void Add(const std::string& file);
    // Waits until a watched file changes; returns the changed files' paths.
    std::set<std::string> WaitForChange();
    // Returns once no watched file has changed for kQuietMs, adding what changed meanwhile to
    // `changed`: changes closer together than that (an editor's save, a compiler writing its
    // output) are one change.
    void Settle(std::set<std::string>& changed);
    static constexpr int kQuietMs = 100;

    // The absolute, normal form of `path` that Add and the changed sets use.
    static std::string Normal(const std::string& path);

  private:
    // Waits up to `timeout_ms` (-1: for ever); adds the watched files that changed to `changed`.
    bool Wait(int timeout_ms, std::set<std::string>& changed);

    int fd_;
    std::set<std::string> files_;
    std::set<std::string> folders_;
    std::map<int, std::string> by_wd_;
};

}  // namespace kiln::cli

#endif  // KILN_TOOLS_CLI_FILE_WATCH_H_
