#include <feran/io/output_files.hpp>

#include <array>
#include <atomic>
#include <cerrno>
#include <charconv>
#include <cstring>
#include <filesystem>
#include <optional>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <fmt/format.h>

#include <feran/core/error.hpp>

namespace feran {

namespace fs = std::filesystem;

namespace detail {
// A file's identity (device and inode), in a named namespace because the outputs'
// state (OutputFiles::Output) holds one.
struct FileId {
  dev_t dev = 0;
  ino_t ino = 0;
  bool operator==(const FileId& o) const { return dev == o.dev && ino == o.ino; }
};
}  // namespace detail

namespace {

using detail::FileId;

// The temporary files not yet renamed, for remove_temporary_outputs(): fixed slots
// of pointers to names owned by the outputs, so that a signal handler can read them
// without allocating or locking.
constexpr std::size_t max_registered = 64;
std::array<std::atomic<const char*>, max_registered> registered{};

int register_temporary(const char* name) {
  for (std::size_t i = 0; i < max_registered; ++i) {
    const char* expected = nullptr;
    if (registered[i].compare_exchange_strong(expected, name)) return static_cast<int>(i);
  }
  return -1;  // more than 64 at once: still removed by the destructor
}

void unregister_temporary(int slot) {
  if (slot >= 0) registered[static_cast<std::size_t>(slot)].store(nullptr);
}

// The umask, for the permissions of a new file (mkstemp makes 0600). Read once, by
// setting and restoring it, before any other thread runs an analysis.
mode_t process_umask() {
  static const mode_t mask = [] {
    const mode_t m = ::umask(0);
    ::umask(m);
    return m;
  }();
  return mask;
}

// The descriptor that /dev/stdout, /dev/stderr, /dev/fd/N or /proc/self/fd/N names.
std::optional<int> descriptor_alias(const std::string& path) {
  if (path == "/dev/stdout") return 1;
  if (path == "/dev/stderr") return 2;
  for (const std::string_view prefix : {std::string_view("/dev/fd/"), std::string_view("/proc/self/fd/")}) {
    if (path.size() > prefix.size() && path.compare(0, prefix.size(), prefix) == 0) {
      int fd = -1;
      const char* first = path.data() + prefix.size();
      const char* last = path.data() + path.size();
      const auto [end, ec] = std::from_chars(first, last, fd);
      if (ec == std::errc() && end == last && fd >= 0) return fd;
    }
  }
  return std::nullopt;
}

std::string system_reason(int error) { return std::strerror(error); }

// Writes all of @p data to @p fd; 0 or the errno of the failure.
int write_all(int fd, std::string_view data) {
  while (!data.empty()) {
    const ssize_t n = ::write(fd, data.data(), data.size());
    if (n < 0) {
      if (errno == EINTR) continue;
      return errno;
    }
    data.remove_prefix(static_cast<std::size_t>(n));
  }
  return 0;
}

std::optional<FileId> file_id(const struct stat& st) { return FileId{st.st_dev, st.st_ino}; }

bool is_null_device(const struct stat& st) {
  struct stat null_st {};
  return S_ISCHR(st.st_mode) && ::stat("/dev/null", &null_st) == 0 && st.st_rdev == null_st.st_rdev;
}

}  // namespace

struct OutputFiles::Output {
  enum class Kind { none, replace, descriptor, in_place };
  std::string option, path;  // as given
  Kind kind = Kind::none;
  bool streamed = false;
  std::string target;        // the file written (links followed)
  std::string identity;      // canonical name of the target (for a new file)
  std::optional<FileId> id;  // of an existing target
  bool null_device = false;
  std::string temporary;  // replace: the temporary file
  int fd = -1;            // replace: the temporary; descriptor: the alias; in_place: once opened
  bool own_fd = false;
  int slot = -1;
  mode_t mode = 0;
  std::string buffer;
  int error = 0;  // the first write error
  bool done = false;

  Error failure(const std::string& why) const {
    return Error(fmt::format("{} '{}': cannot write: {}", option, path, why));
  }

  // Writes the buffer out (streamed outputs when it is large, all at commit).
  void flush() {
    if (buffer.empty() || error != 0) return;
    if (kind == Kind::in_place && fd < 0) {
      fd = ::open(target.c_str(), O_WRONLY | O_CLOEXEC);
      if (fd < 0) {
        error = errno;
        return;
      }
      own_fd = true;
    }
    error = write_all(fd, buffer);
    buffer.clear();
  }

  void discard() noexcept {
    if (own_fd && fd >= 0) ::close(fd);
    fd = -1;
    if (!temporary.empty() && !done) ::unlink(temporary.c_str());
    unregister_temporary(slot);
    slot = -1;
  }
};

OutputFiles::OutputFiles(std::string model_path) { inputs_.push_back({std::move(model_path), "the model file"}); }

void OutputFiles::add_input(std::string path, std::string what) {
  struct stat st {};
  if (!path.empty() && ::stat(path.c_str(), &st) == 0)
    for (const auto& o : outputs_)
      if (o->id && *o->id == *file_id(st)) throw o->failure(fmt::format("it is {} '{}'", what, path));
  inputs_.push_back({std::move(path), std::move(what)});
}

OutputFiles::~OutputFiles() {
  for (auto& o : outputs_) o->discard();
}

int OutputFiles::add(std::string option, std::string path, bool streamed) {
  auto o = std::make_unique<Output>();
  o->option = std::move(option);
  o->path = std::move(path);
  o->streamed = streamed;
  const int number = static_cast<int>(outputs_.size());
  if (o->path.empty()) {
    outputs_.push_back(std::move(o));
    return number;
  }

  // Follow symbolic links to the file they name; stop at a descriptor alias.
  fs::path p = o->path;
  std::optional<int> alias;
  for (int hop = 0;; ++hop) {
    if ((alias = descriptor_alias(p.lexically_normal().string()))) break;
    struct stat lst {};
    if (::lstat(p.c_str(), &lst) != 0 || !S_ISLNK(lst.st_mode)) break;
    if (hop == 40) throw o->failure("too many levels of symbolic links");
    std::error_code ec;
    const fs::path to = fs::read_symlink(p, ec);
    if (ec) throw o->failure(ec.message());
    p = to.is_absolute() ? to : p.parent_path() / to;
  }
  o->target = p.string();

  struct stat st {};
  if (alias) {
    o->kind = Output::Kind::descriptor;
    o->fd = *alias;
    const int flags = ::fcntl(*alias, F_GETFL);
    if (flags < 0) throw o->failure(fmt::format("descriptor {} is not open", *alias));
    if ((flags & O_ACCMODE) == O_RDONLY) throw o->failure(fmt::format("descriptor {} is not open for writing", *alias));
    if (::fstat(*alias, &st) == 0) {
      o->id = file_id(st);
      o->null_device = is_null_device(st);
    }
  } else if (::stat(p.c_str(), &st) == 0) {
    if (S_ISDIR(st.st_mode)) throw o->failure("it is a directory");
    o->id = file_id(st);
    if (S_ISREG(st.st_mode)) {
      o->kind = Output::Kind::replace;
      o->mode = st.st_mode & 07777;
      if (::access(p.c_str(), W_OK) != 0) throw o->failure(system_reason(errno));
    } else {
      o->kind = Output::Kind::in_place;
      o->null_device = is_null_device(st);
    }
  } else if (errno == ENOENT || errno == ENOTDIR) {
    const fs::path dir = p.has_parent_path() ? p.parent_path() : fs::path(".");
    struct stat dst {};
    if (::stat(dir.c_str(), &dst) != 0)
      throw o->failure(fmt::format("the directory '{}' does not exist", dir.string()));
    if (!S_ISDIR(dst.st_mode)) throw o->failure(fmt::format("'{}' is not a directory", dir.string()));
    o->kind = Output::Kind::replace;
    o->mode = 0666 & ~process_umask();
    std::error_code ec;
    o->identity = (fs::canonical(dir, ec) / p.filename()).string();
  } else {
    throw o->failure(system_reason(errno));
  }

  // Never an input, never a file an earlier output writes.
  for (const auto& input : inputs_) {
    struct stat input_st {};
    if (o->id && ::stat(input.path.c_str(), &input_st) == 0 && *o->id == *file_id(input_st))
      throw o->failure(fmt::format("it is {} '{}'", input.what, input.path));
  }
  for (const auto& other : outputs_) {
    if (other->kind == Output::Kind::none || (o->null_device && other->null_device)) continue;
    const bool same =
        (o->id && other->id && *o->id == *other->id) || (!o->identity.empty() && o->identity == other->identity);
    if (same) throw o->failure(fmt::format("{} already writes '{}'", other->option, other->path));
  }

  if (o->kind == Output::Kind::replace) {
    std::string name = o->target + ".part-XXXXXX";
    const int fd = ::mkostemp(name.data(), O_CLOEXEC);
    if (fd < 0) throw o->failure(system_reason(errno));
    o->temporary = std::move(name);
    o->fd = fd;
    o->own_fd = true;
    o->slot = register_temporary(o->temporary.c_str());
  }
  outputs_.push_back(std::move(o));
  return number;
}

bool OutputFiles::wanted(int id) const { return outputs_.at(static_cast<std::size_t>(id))->kind != Output::Kind::none; }

void OutputFiles::write(int id, std::string content) {
  Output& o = *outputs_.at(static_cast<std::size_t>(id));
  if (o.kind != Output::Kind::none) o.buffer = std::move(content);
}

void OutputFiles::append(int id, std::string_view text) {
  Output& o = *outputs_.at(static_cast<std::size_t>(id));
  if (o.kind == Output::Kind::none) return;
  o.buffer.append(text);
  constexpr std::size_t chunk = std::size_t{1} << 20;
  if (o.buffer.size() >= chunk) o.flush();
}

void OutputFiles::commit() {
  if (committed_) return;
  // Every temporary file complete first: nothing is renamed unless all are.
  for (auto& o : outputs_) {
    if (o->kind != Output::Kind::replace) continue;
    o->flush();
    if (o->error == 0 && ::fchmod(o->fd, o->mode) != 0) o->error = errno;
    if (o->error == 0 && ::fsync(o->fd) != 0 && errno != EINVAL) o->error = errno;
    if (::close(o->fd) != 0 && o->error == 0) o->error = errno;
    o->fd = -1;
    if (o->error != 0) throw o->failure(system_reason(o->error));
  }
  // Then what is written in place (a failure there still leaves every regular target
  // as it was), and last the renames.
  for (auto& o : outputs_) {
    if (o->kind != Output::Kind::descriptor && o->kind != Output::Kind::in_place) continue;
    o->flush();
    if (o->error != 0) throw o->failure(system_reason(o->error));
  }
  for (auto& o : outputs_) {
    if (o->kind != Output::Kind::replace) continue;
    if (::rename(o->temporary.c_str(), o->target.c_str()) != 0) throw o->failure(system_reason(errno));
    o->done = true;
    unregister_temporary(o->slot);
    o->slot = -1;
  }
  committed_ = true;
}

void remove_temporary_outputs() noexcept {
  for (auto& slot : registered)
    if (const char* name = slot.load()) ::unlink(name);
}

}  // namespace feran
