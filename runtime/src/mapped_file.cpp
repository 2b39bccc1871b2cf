// MappedFile: POSIX mmap where available, else one std::malloc'd buffer read with std::fread.
#include "hullcook/runtime.h"

#include <cstdio>
#include <cstdlib>

#if defined(__unix__) || defined(__APPLE__)
#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>
#define HULLCOOK_HAVE_MMAP 1
#endif

namespace hullcook::runtime {

MappedFile::~MappedFile() { close(); }

MappedFile::MappedFile(MappedFile&& other) noexcept
    : data_(other.data_), size_(other.size_), mapped_(other.mapped_) {
  other.data_ = nullptr;
  other.size_ = 0;
  other.mapped_ = false;
}

MappedFile& MappedFile::operator=(MappedFile&& other) noexcept {
  if (this != &other) {
    close();
    data_ = other.data_;
    size_ = other.size_;
    mapped_ = other.mapped_;
    other.data_ = nullptr;
    other.size_ = 0;
    other.mapped_ = false;
  }
  return *this;
}

void MappedFile::close() noexcept {
#ifdef HULLCOOK_HAVE_MMAP
  if (mapped_ && data_) munmap(data_, size_);
#endif
  if (!mapped_) std::free(data_);
  data_ = nullptr;
  size_ = 0;
  mapped_ = false;
}

namespace {

// Reads a whole stream into one malloc'd buffer; false on any error.
bool read_all(std::FILE* file, void*& data, std::size_t& size) {
  if (std::fseek(file, 0, SEEK_END) != 0) return false;
  const long length = std::ftell(file);
  if (length < 0 || std::fseek(file, 0, SEEK_SET) != 0) return false;
  size = static_cast<std::size_t>(length);
  if (size == 0) return true;
  data = std::malloc(size);
  if (!data) return false;
  if (std::fread(data, 1, size, file) != size) {
    std::free(data);
    data = nullptr;
    return false;
  }
  return true;
}

}  // namespace

Status MappedFile::open(const char* path) noexcept {
  close();
  if (path == nullptr) return Status::invalid_argument;
#ifdef HULLCOOK_HAVE_MMAP
  // O_NONBLOCK: a pipe without a writer is refused below instead of blocking the open.
  const int fd = ::open(path, O_RDONLY | O_CLOEXEC | O_NONBLOCK);
  if (fd < 0) return Status::io_error;
  struct stat info {};
  if (fstat(fd, &info) != 0 || !S_ISREG(info.st_mode)) {
    ::close(fd);
    return Status::io_error;
  }
  size_ = static_cast<std::size_t>(info.st_size);
  if (size_ > 0) {
    void* mapping = mmap(nullptr, size_, PROT_READ, MAP_PRIVATE, fd, 0);
    if (mapping != MAP_FAILED) {
      data_ = mapping;
      mapped_ = true;
      ::close(fd);
      return Status::ok;
    }
  }
  ::close(fd);
  size_ = 0;
  if (info.st_size == 0) return Status::ok;
#endif
  // No mmap (or it failed): read the file instead.
  std::FILE* file = std::fopen(path, "rb");
  if (!file) return Status::io_error;
  const bool ok = read_all(file, data_, size_);
  std::fclose(file);
  if (!ok) {
    data_ = nullptr;
    size_ = 0;
    return Status::io_error;
  }
  return Status::ok;
}

}  // namespace hullcook::runtime
