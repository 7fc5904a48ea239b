// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/trace/IndexSpill.h"

#include <fcntl.h>
#include <sys/mman.h>
#include <unistd.h>
#include <cerrno>
#include <cstdlib>
#include <cstring>

namespace coscope {

namespace {
// 2^32 frames of 4 bytes: the most a TraceStore's indexes hold together.
constexpr size_t kReserve = size_t{1} << 34;
}  // namespace

IndexSpill::IndexSpill(const std::string& directory) {
#ifdef O_TMPFILE
    fd_ = ::open(directory.c_str(), O_TMPFILE | O_RDWR | O_CLOEXEC, 0600);
#endif
    if (fd_ < 0) {  // a file system without O_TMPFILE: a named file, unlinked at once
        std::string name = directory + "/.coscope-index-XXXXXX";
        fd_ = ::mkostemp(name.data(), O_CLOEXEC);
        if (fd_ >= 0) ::unlink(name.c_str());
    }
    if (fd_ < 0) {
        error_ = directory + ": " + std::strerror(errno);
        return;
    }
    void* p = ::mmap(nullptr, kReserve, PROT_READ, MAP_SHARED | MAP_NORESERVE, fd_, 0);
    if (p == MAP_FAILED) {
        error_ = std::string("mmap: ") + std::strerror(errno);
        ::close(fd_);
        fd_ = -1;
        return;
    }
    base_ = static_cast<char*>(p);
    reserved_ = kReserve;
}

IndexSpill::~IndexSpill() {
    if (base_) ::munmap(base_, reserved_);
    if (fd_ >= 0) ::close(fd_);
}

const void* IndexSpill::write(const void* data, size_t bytes) {
    if (!base_ || used_ + bytes > reserved_) return nullptr;
    const char* from = static_cast<const char*>(data);
    size_t done = 0;
    while (done < bytes) {
        const ssize_t n = ::pwrite(fd_, from + done, bytes - done, static_cast<off_t>(used_ + done));
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            error_ = std::string("write: ") + std::strerror(n < 0 ? errno : ENOSPC);
            return nullptr;
        }
        done += static_cast<size_t>(n);
    }
    const char* at = base_ + used_;
    used_ += bytes;
    return at;
}

}  // namespace coscope
