// Reading inputs and writing outputs the way every part of Kiln must (docs/architecture.md,
// "Files"): inputs are regular files of bounded size, opened so that a FIFO or device never blocks
// or streams without end; outputs replace a regular file atomically (a unique temporary file in the
// same directory, fsync, rename, fsync of the directory), never a device, FIFO or directory, and
// never one of the inputs.
#ifndef KILN_BASE_FILES_H_
#define KILN_BASE_FILES_H_

#include <cstdint>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "kiln/result.h"

namespace kiln::base {

// "-", the command-line spelling of standard input (as a path to read) and standard output (as a
// path to write), as glslc and gcc take it.
inline constexpr std::string_view kStandardStream = "-";

// The whole of a regular file of at most `max_bytes`. The error says what the path is when it is
// not a regular file ("is a directory", "is a FIFO"), or that it is over the limit. The path "-"
// is standard input, read to its end once (later reads of "-" give the same bytes), under the
// same limit: a pipe is the one stream Kiln reads, and only when asked to by that name.
// `kCache`: a file the process reads in order to replace it later (a compile-cache entry, the
// pipeline cache), which the input guard (GuardInputFiles) does not remember.
enum class ReadAs : uint8_t { kInput, kCache };
Result<std::string> ReadRegularFile(const std::string& path,
                                    uint64_t max_bytes,
                                    ReadAs as = ReadAs::kInput);

struct WriteOptions {
    std::vector<std::string> inputs;  // an output that is one of them is refused
    // fsync the file before the rename and the directory after it. Off only for files whose
    // damage is detected and repaired (compile-cache entries carry a hash).
    bool durable = true;
    // Off for files in a directory Kiln creates and fills (kiln render --frame-debug): a symbolic
    // link at the output path is replaced by the new file, never written through, so a link
    // planted in the directory cannot aim the write at another file.
    bool follow_symlinks = true;
};

// The output-safety rule for a whole process, which the kiln tools turn on first thing: from then
// on every file read through ReadRegularFile (or named to NoteInputFile) is remembered by device
// and inode, and CheckOutputPath and WriteFileAtomically refuse to replace any of them, whichever
// reader read it (a scene's buffers and images, a material's textures, a sky image). Off in a
// library's host by default: an engine may save a file it loaded.
void GuardInputFiles();
// Remembers a file read outside ReadRegularFile (a mapped pack, a file a library reads itself)
// for the guard; nothing when the guard is off or the file does not exist.
void NoteInputFile(const std::string& path);
// Forgets the files read so far; the guard stays on. For a process that runs its command again
// (kiln watch): an input replaced since (an editor's save) frees its inode, which a new file,
// such as the output itself, may then get.
void ForgetInputFiles();

// A temporary file name beside `target`: "<target>.tmp.<pid>.<n>", unique within the process
// (callers create it with O_EXCL and try another on EEXIST).
std::string TempName(const std::string& target);

// Writes all of `bytes` to the descriptor, again after an interrupted write; false on an error.
bool WriteAll(int fd, std::string_view bytes);

// Writes `bytes` to `path` atomically. An output that is one of the inputs (the same file, by
// device and inode) is refused. An output that is a symbolic link is written through: the file it
// points to is replaced and the link is kept. The path "-" is standard output: the bytes are
// written whole in one go after the work is done, so a failed command writes nothing there.
Status WriteFileAtomically(const std::string& path,
                           std::span<const uint8_t> bytes,
                           const WriteOptions& options = {});
Status WriteFileAtomically(const std::string& path,
                           std::string_view text,
                           const WriteOptions& options = {});

// The checks WriteFileAtomically makes before it writes, for a command that wants to refuse a bad
// output before doing the work: `path` (or the file its symbolic link names) is absent or a
// regular file, none of `inputs` and none of the files read so far under the input guard. Gives
// the file that will be replaced ("-" for standard output).
Result<std::string> CheckOutputPath(const std::string& path,
                                    const std::vector<std::string>& inputs);

// Two outputs of one command may not be one file (`-o X -MF X`, `-o X --exr X`): an error naming
// both when two of `outputs` (flag, path) are the same file, by path after resolving symbolic
// links or, for files that exist, by device and inode. Empty paths and "-" are skipped.
Status CheckDistinctOutputs(const std::vector<std::pair<std::string, std::string>>& outputs);

// "a directory", "a FIFO", "a character device", ... for a path that exists but is no regular
// file; "" for a regular file or a path that does not exist.
std::string NotRegularFileKind(const std::string& path);

}  // namespace kiln::base

#endif  // KILN_BASE_FILES_H_
