// Snell runtime: the one way Snell writes files (PNG images, benchmark JSON, test and docs
// pictures). A file is written all or nothing: never half-written, never reported as written
// when a write or the close failed.
#pragma once

#include <snell/result.hpp>

#include <cstddef>
#include <filesystem>
#include <string_view>

namespace snell {

/// An output file, written all or nothing (POSIX).
///
/// - A regular file (existing or new) is written to a temporary file in the destination's
///   folder, `.<name>.<pid>-<n>.snell-tmp`; commit() flushes it to disk (fsync), closes it and
///   renames it over the destination, so readers see the old file or the whole new one. An
///   existing destination keeps its permission bits; a new one gets 0666 minus the umask. A
///   symbolic link is followed: the file it points to is replaced, the link stays.
/// - Anything else that exists and is not a folder (a device such as /dev/full or /dev/null, a
///   FIFO, /dev/stdout on a pipe) cannot be replaced by a rename: it is opened and written
///   directly, every write and the close checked. Nothing can be undone there.
/// - On any failure (open, write, flush, close, rename) the error names the destination and the
///   system's reason (io_error; file_not_found when the folder does not exist; invalid_argument
///   when the destination is a folder), the temporary file is removed and an existing
///   destination is untouched. Destroying an OutputFile that was not committed discards it.
class OutputFile {
public:
  /// Opens `destination` for writing (see the class comment). Errors: see check_output_path,
  /// and io_error when the temporary file (or the device) cannot be opened.
  [[nodiscard]] static Result<OutputFile> open(const std::filesystem::path& destination);

  OutputFile() = default; ///< Not open: write() and commit() fail.
  OutputFile(OutputFile&& other) noexcept;
  OutputFile& operator=(OutputFile&& other) noexcept;
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;
  ~OutputFile(); ///< discard() unless committed.

  /// Appends `size` bytes (short writes and EINTR are retried). After a failure the file is
  /// discarded and every later call fails.
  [[nodiscard]] Result<void> write(const void* data, std::size_t size);
  /// Appends text.
  [[nodiscard]] Result<void> write(std::string_view text) {
    return write(text.data(), text.size());
  }
  /// Finishes the file: fsync, close, rename over the destination (regular files); close
  /// (devices). On failure the file is discarded. Committing twice fails.
  [[nodiscard]] Result<void> commit();
  /// Closes and removes the temporary file without touching the destination. Idempotent.
  void discard() noexcept;

  /// The path given to open().
  [[nodiscard]] const std::filesystem::path& destination() const noexcept { return destination_; }
  /// True between a successful open() and commit() or discard().
  [[nodiscard]] bool is_open() const noexcept { return fd_ >= 0; }

private:
  std::filesystem::path destination_{}; // as given, for messages
  std::filesystem::path target_{};      // destination with a symbolic link resolved
  std::filesystem::path temporary_{};   // empty when writing directly (devices)
  int fd_ = -1;
};

/// Writes `size` bytes to `path` through OutputFile (all or nothing).
[[nodiscard]] Result<void> write_file(const std::filesystem::path& path, const void* data,
                                      std::size_t size);
/// Writes `text` to `path` through OutputFile (all or nothing).
[[nodiscard]] Result<void> write_file(const std::filesystem::path& path, std::string_view text);

/// Checks what can be known before writing `path`, so that a tool refuses a bad output before
/// long work: the path is not empty, is not a folder (invalid_argument, "is a folder"), and its
/// folder exists and is a folder (file_not_found). Whether the folder is writable and has room
/// is only known when writing.
[[nodiscard]] Result<void> check_output_path(const std::filesystem::path& path);

} // namespace snell
