#include "solver/common/atomic_write.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <system_error>

namespace capsule {

namespace {

void remove_quietly(const std::filesystem::path& file) {
  std::error_code ec;
  std::filesystem::remove(file, ec);
}

void check_before_rename(const std::function<void()>& before_rename, const std::filesystem::path& temporary) {
  if (!before_rename) return;
  try {
    before_rename();
  } catch (...) {
    remove_quietly(temporary);
    throw;
  }
}

}  // namespace

std::string temporary_path(const std::string& path) { return path + ".tmp." + std::to_string(::getpid()); }

void write_file_atomically(const std::filesystem::path& path, const std::string& text,
                           const std::function<void()>& before_rename) {
  const std::filesystem::path temporary = temporary_path(path.string());
  // POSIX calls, so a failure names errno's reason and the temporary file never stays behind.
  const auto failed = [&](const char* what) {
    const int err = errno;
    ::unlink(temporary.c_str());
    throw std::runtime_error("cannot write " + path.string() + " (" + what + " " + temporary.filename().string() +
                             "): " + std::strerror(err));
  };
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) {
    const int err = errno;
    throw std::runtime_error("cannot write " + path.string() + " (creating " + temporary.filename().string() +
                             "): " + std::strerror(err));
  }
  for (std::size_t done = 0; done < text.size();) {
    const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      const int err = errno;
      ::close(fd);
      errno = err;
      failed("writing");
    }
    done += static_cast<std::size_t>(n);
  }
  if (::close(fd) != 0) failed("closing");
  check_before_rename(before_rename, temporary);
  if (::rename(temporary.c_str(), path.c_str()) != 0) failed("renaming");
}

void replace_atomically(const std::string& path, const std::function<void(const std::string& temporary)>& write,
                        const std::function<void()>& before_rename) {
  const std::string temporary = temporary_path(path);
  errno = 0;
  try {
    write(temporary);
  } catch (const std::runtime_error& e) {
    const int err = errno;
    remove_quietly(temporary);
    if (err != 0) throw std::system_error(err, std::generic_category(), e.what());  // the cause stays a code
    throw;
  } catch (...) {
    remove_quietly(temporary);
    throw;
  }
  check_before_rename(before_rename, temporary);
  std::error_code ec;
  std::filesystem::rename(temporary, path, ec);
  if (ec) {
    remove_quietly(temporary);
    throw std::filesystem::filesystem_error("cannot rename the new " + path + " into place", temporary, path, ec);
  }
}

}  // namespace capsule
