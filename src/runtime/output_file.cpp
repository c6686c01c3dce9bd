// OutputFile: temporary file + checked writes + fsync + checked close + rename (POSIX).
#include <snell/output_file.hpp>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <string>
#include <system_error>
#include <utility>

namespace snell {
namespace {

namespace fs = std::filesystem;

/// The system's text for errno value `err` (thread-safe, unlike strerror).
std::string reason(int err) {
  return std::error_code(err, std::generic_category()).message();
}

Error io_failure(const fs::path& destination, const std::string& what, int err) {
  return Error{ErrorCode::io_error, destination.string() + ": " + what + ": " + reason(err)};
}

/// The folder a new file at `path` goes into ("." for a bare file name).
fs::path folder_of(const fs::path& path) {
  const fs::path parent = path.parent_path();
  return parent.empty() ? fs::path(".") : parent;
}

} // namespace

Result<void> check_output_path(const fs::path& path) {
  if (path.empty()) {
    return fail(ErrorCode::invalid_argument, "the output path is empty");
  }
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec); // follows symbolic links
  if (fs::is_directory(status)) {
    return fail(ErrorCode::invalid_argument, path.string() +
                                                 ": is a folder; give a file name (e.g. " +
                                                 (path / "out.png").string() + ")");
  }
  if (fs::exists(status)) {
    return {};
  }
  const fs::path folder = folder_of(path);
  const fs::file_status folder_status = fs::status(folder, ec);
  if (!fs::exists(folder_status)) {
    return fail(ErrorCode::file_not_found,
                path.string() + ": the folder '" + folder.string() + "' does not exist");
  }
  if (!fs::is_directory(folder_status)) {
    return fail(ErrorCode::file_not_found,
                path.string() + ": '" + folder.string() + "' is not a folder");
  }
  return {};
}

Result<OutputFile> OutputFile::open(const fs::path& destination) {
  if (auto ok = check_output_path(destination); !ok) {
    return ok.error();
  }
  OutputFile file;
  file.destination_ = destination;
  file.target_ = destination;
  std::error_code ec;
  if (fs::is_symlink(fs::symlink_status(destination, ec))) {
    // Replace the file the link points to, not the link (a dangling link is replaced itself).
    const fs::path resolved = fs::weakly_canonical(destination, ec);
    if (!ec) {
      file.target_ = resolved;
    }
  }
  const fs::file_status status = fs::status(file.target_, ec);
  if (fs::exists(status) && !fs::is_regular_file(status)) {
    // A device, FIFO or socket: renaming over it would be wrong; write it directly.
    file.fd_ = ::open(file.target_.c_str(), O_WRONLY | O_CLOEXEC | O_NOCTTY);
    if (file.fd_ < 0) {
      return io_failure(destination, "cannot open for writing", errno);
    }
    return file;
  }
  static std::atomic<unsigned> counter{0};
  const fs::path folder = folder_of(file.target_);
  std::string prefix(1, '.'); // built by appending: GCC 12 -Wrestrict misfires on "." + string
  prefix.append(file.target_.filename().string())
      .append(1, '.')
      .append(std::to_string(static_cast<long>(::getpid())))
      .append(1, '-');
  for (int attempt = 0; attempt < 100 && file.fd_ < 0; ++attempt) {
    file.temporary_ = folder / (prefix + std::to_string(counter.fetch_add(1)) + ".snell-tmp");
    file.fd_ =
        ::open(file.temporary_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC | O_NOCTTY, 0666);
    if (file.fd_ < 0 && errno != EEXIST) {
      const int err = errno;
      file.temporary_.clear();
      return io_failure(destination, "cannot create a temporary file in '" + folder.string() + "'",
                        err);
    }
  }
  if (file.fd_ < 0) {
    file.temporary_.clear();
    return fail(ErrorCode::io_error, destination.string() +
                                         ": cannot create a temporary file in '" + folder.string() +
                                         "' (100 names taken)");
  }
  if (fs::is_regular_file(status)) {
    struct stat st {};
    if (::stat(file.target_.c_str(), &st) == 0) {
      (void)::fchmod(file.fd_, st.st_mode & 07777); // best effort: keep the old file's mode
    }
  }
  return file;
}

OutputFile::OutputFile(OutputFile&& other) noexcept
    : destination_(std::move(other.destination_)), target_(std::move(other.target_)),
      temporary_(std::move(other.temporary_)), fd_(std::exchange(other.fd_, -1)) {
  other.temporary_.clear();
}

OutputFile& OutputFile::operator=(OutputFile&& other) noexcept {
  if (this != &other) {
    discard();
    destination_ = std::move(other.destination_);
    target_ = std::move(other.target_);
    temporary_ = std::move(other.temporary_);
    other.temporary_.clear();
    fd_ = std::exchange(other.fd_, -1);
  }
  return *this;
}

OutputFile::~OutputFile() {
  discard();
}

void OutputFile::discard() noexcept {
  if (fd_ >= 0) {
    (void)::close(fd_);
    fd_ = -1;
  }
  if (!temporary_.empty()) {
    (void)::unlink(temporary_.c_str());
    temporary_.clear();
  }
}

Result<void> OutputFile::write(const void* data, std::size_t size) {
  if (fd_ < 0) {
    return fail(ErrorCode::io_error, destination_.string() + ": the file is not open for writing");
  }
  const auto* bytes = static_cast<const unsigned char*>(data);
  while (size > 0) {
    const ::ssize_t n = ::write(fd_, bytes, size);
    if (n < 0 && errno == EINTR) {
      continue;
    }
    if (n <= 0) {
      const int err = n < 0 ? errno : EIO;
      discard();
      return io_failure(destination_, "write failed", err);
    }
    bytes += n;
    size -= static_cast<std::size_t>(n);
  }
  return {};
}

Result<void> OutputFile::commit() {
  if (fd_ < 0) {
    return fail(ErrorCode::io_error, destination_.string() + ": the file is not open for writing");
  }
  if (!temporary_.empty() && ::fsync(fd_) != 0) {
    const int err = errno;
    discard();
    return io_failure(destination_, "flushing to disk failed", err);
  }
  const int fd = std::exchange(fd_, -1);
  if (::close(fd) != 0) {
    const int err = errno;
    discard();
    return io_failure(destination_, "closing failed", err);
  }
  if (temporary_.empty()) {
    return {}; // written directly (a device)
  }
  if (::rename(temporary_.c_str(), target_.c_str()) != 0) {
    const int err = errno;
    discard();
    return io_failure(destination_, "cannot replace it with the new file", err);
  }
  temporary_.clear();
  // Make the rename itself durable (best effort: not every file system syncs folders).
  const int dir = ::open(folder_of(target_).c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dir >= 0) {
    (void)::fsync(dir);
    (void)::close(dir);
  }
  return {};
}

Result<void> write_file(const fs::path& path, const void* data, std::size_t size) {
  auto file = OutputFile::open(path);
  if (!file) {
    return file.error();
  }
  if (auto r = file->write(data, size); !r) {
    return r;
  }
  return file->commit();
}

Result<void> write_file(const fs::path& path, std::string_view text) {
  return write_file(path, text.data(), text.size());
}

} // namespace snell
