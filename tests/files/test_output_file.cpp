// OutputFile / write_file: all or nothing. A failed write (a full device, a file-size limit, a
// bad destination) exits with an error naming the path and the system's reason, removes its
// temporary file and leaves an existing destination untouched; a successful one leaves nothing
// but the destination.
#include <snell/output_file.hpp>

#include <doctest/doctest.h>

#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <csignal>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

/// A fresh empty folder under the system's temporary folder, removed with its contents.
class TempFolder {
public:
  TempFolder() {
    static std::atomic<unsigned> counter{0};
    path_ = fs::temp_directory_path() /
            ("snell-files-test-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
    fs::remove_all(path_);
    fs::create_directories(path_);
  }
  ~TempFolder() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  TempFolder(const TempFolder&) = delete;
  TempFolder& operator=(const TempFolder&) = delete;
  const fs::path& path() const { return path_; }
  /// Names of everything in the folder (hidden files included), sorted.
  std::vector<std::string> entries() const {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(path_)) {
      names.push_back(e.path().filename().string());
    }
    std::sort(names.begin(), names.end());
    return names;
  }

private:
  fs::path path_;
};

std::string read_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void write_text(const fs::path& p, const std::string& text) {
  std::ofstream(p, std::ios::binary) << text;
}

/// Lowers the file-size limit (RLIMIT_FSIZE) for its lifetime, with SIGXFSZ ignored, so that a
/// write past `bytes` fails with EFBIG ("File too large"): a write failure on a regular file that
/// works even as root (who ignores permissions).
class FileSizeLimit {
public:
  explicit FileSizeLimit(rlim_t bytes) {
    getrlimit(RLIMIT_FSIZE, &old_);
    old_handler_ = std::signal(SIGXFSZ, SIG_IGN);
    rlimit lower = old_;
    lower.rlim_cur = bytes;
    ok_ = setrlimit(RLIMIT_FSIZE, &lower) == 0;
  }
  ~FileSizeLimit() {
    setrlimit(RLIMIT_FSIZE, &old_);
    std::signal(SIGXFSZ, old_handler_);
  }
  FileSizeLimit(const FileSizeLimit&) = delete;
  FileSizeLimit& operator=(const FileSizeLimit&) = delete;
  bool ok() const { return ok_; }

private:
  rlimit old_{};
  void (*old_handler_)(int) = SIG_DFL;
  bool ok_ = false;
};

} // namespace

TEST_CASE("output file: a new file is written whole and nothing is left beside it") {
  TempFolder dir;
  const fs::path out = dir.path() / "out.json";
  REQUIRE(snell::write_file(out, std::string_view("{\"a\": 1}\n")));
  CHECK(read_text(out) == "{\"a\": 1}\n");
  CHECK(dir.entries() == std::vector<std::string>{"out.json"});
}

TEST_CASE("output file: an existing file is replaced whole and keeps its permission bits") {
  TempFolder dir;
  const fs::path out = dir.path() / "out.txt";
  write_text(out, "old contents, longer than the new ones");
  REQUIRE(::chmod(out.c_str(), 0640) == 0);
  REQUIRE(snell::write_file(out, std::string_view("new")));
  CHECK(read_text(out) == "new");
  struct stat st {};
  REQUIRE(::stat(out.c_str(), &st) == 0);
  CHECK((st.st_mode & 07777) == 0640);
  CHECK(dir.entries() == std::vector<std::string>{"out.txt"});
}

TEST_CASE("output file: /dev/full fails with the path and the system's reason") {
  if (!fs::exists("/dev/full")) {
    MESSAGE("no /dev/full on this system");
    return;
  }
  const std::vector<char> bytes(100000, 'x');
  const snell::Result<void> r = snell::write_file("/dev/full", bytes.data(), bytes.size());
  REQUIRE_FALSE(r);
  INFO(r.error().message);
  CHECK(r.error().code == snell::ErrorCode::io_error);
  CHECK(contains(r.error().message, "/dev/full"));
  CHECK(contains(r.error().message, "No space left on device"));
}

TEST_CASE("output file: a device is written directly (no temporary file beside it)") {
  // /dev/null accepts everything; the writer must not try to create /dev/.null.*.snell-tmp
  // (which as root would succeed and then replace the device by a rename).
  REQUIRE(snell::write_file("/dev/null", std::string_view("discarded")));
  CHECK(fs::is_character_file("/dev/null"));
  for (const auto& e : fs::directory_iterator("/dev")) {
    CHECK_FALSE(contains(e.path().filename().string(), "snell-tmp"));
  }
}

TEST_CASE("output file: a failed write keeps the existing file and removes the temporary one") {
  TempFolder dir;
  const fs::path out = dir.path() / "image.png";
  write_text(out, "the previous image");
  const std::vector<char> big(64 * 1024, 'x');
  snell::Result<void> r;
  {
    FileSizeLimit limit(4096);
    REQUIRE(limit.ok());
    r = snell::write_file(out, big.data(), big.size());
  }
  REQUIRE_FALSE(r);
  INFO(r.error().message);
  CHECK(r.error().code == snell::ErrorCode::io_error);
  CHECK(contains(r.error().message, out.string()));
  CHECK(contains(r.error().message, "File too large"));
  CHECK(read_text(out) == "the previous image");
  CHECK(dir.entries() == std::vector<std::string>{"image.png"});
}

TEST_CASE("output file: an OutputFile not committed is discarded") {
  TempFolder dir;
  const fs::path out = dir.path() / "partial.txt";
  write_text(out, "kept");
  {
    auto file = snell::OutputFile::open(out);
    REQUIRE(file);
    REQUIRE(file->write(std::string_view("half of the new conte")));
    CHECK(dir.entries().size() == 2); // the destination and the temporary file
  }                                   // destroyed without commit: an error path of the caller
  CHECK(read_text(out) == "kept");
  CHECK(dir.entries() == std::vector<std::string>{"partial.txt"});
  // Moving keeps one owner: the moved-from file discards nothing of the moved-to one.
  auto a = snell::OutputFile::open(out);
  REQUIRE(a);
  snell::OutputFile b = std::move(*a);
  CHECK_FALSE(a->is_open());
  REQUIRE(b.write(std::string_view("moved")));
  REQUIRE(b.commit());
  CHECK(read_text(out) == "moved");
  CHECK_FALSE(b.commit()); // twice: refused
  CHECK(dir.entries() == std::vector<std::string>{"partial.txt"});
}

TEST_CASE("output file: bad destinations are refused before anything is written") {
  TempFolder dir;
  SUBCASE("a folder") {
    const snell::Result<void> r = snell::write_file(dir.path(), std::string_view("x"));
    REQUIRE_FALSE(r);
    INFO(r.error().message);
    CHECK(r.error().code == snell::ErrorCode::invalid_argument);
    CHECK(contains(r.error().message, dir.path().string() + ": is a folder"));
    CHECK(dir.entries().empty());
  }
  SUBCASE("a folder that does not exist") {
    const fs::path out = dir.path() / "missing" / "out.png";
    const snell::Result<void> r = snell::check_output_path(out);
    REQUIRE_FALSE(r);
    INFO(r.error().message);
    CHECK(r.error().code == snell::ErrorCode::file_not_found);
    CHECK(contains(r.error().message, out.string()));
    CHECK(contains(r.error().message, "does not exist"));
  }
  SUBCASE("a file used as a folder") {
    write_text(dir.path() / "file", "x");
    const snell::Result<void> r = snell::write_file(dir.path() / "file" / "out.png", "x", 1);
    REQUIRE_FALSE(r);
    CHECK(contains(r.error().message, "is not a folder"));
  }
  SUBCASE("an empty path") {
    CHECK_FALSE(snell::check_output_path(""));
  }
}

TEST_CASE("output file: a symbolic link is followed, the link stays") {
  TempFolder dir;
  write_text(dir.path() / "target.txt", "old");
  fs::create_symlink("target.txt", dir.path() / "link.txt");
  REQUIRE(snell::write_file(dir.path() / "link.txt", std::string_view("new")));
  CHECK(fs::is_symlink(dir.path() / "link.txt"));
  CHECK(read_text(dir.path() / "target.txt") == "new");
  CHECK(dir.entries() == std::vector<std::string>{"link.txt", "target.txt"});
}
