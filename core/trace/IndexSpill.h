// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstddef>
#include <string>

namespace coscope {

// Where a TraceStore with bounded memory keeps the full blocks of its per-COB-ID indexes
// (issue 16 "Bounded memory": 4 bytes a frame would otherwise grow without bound): an unlinked
// file in the journal's folder, mapped read-only in one reserved range, so a block written there
// keeps its address and costs the page cache (which the kernel reclaims) instead of the
// process's memory. Written by the store's writer thread only; read through the mapping by any
// thread. The file disappears with the process.
class IndexSpill {
public:
    explicit IndexSpill(const std::string& directory);
    ~IndexSpill();
    IndexSpill(const IndexSpill&) = delete;
    IndexSpill& operator=(const IndexSpill&) = delete;

    // False if the file or the mapping could not be made (then the index stays in RAM).
    bool ok() const { return base_ != nullptr; }
    const std::string& error() const { return error_; }
    // Appends `bytes` (a multiple of the page size) and returns where they can be read, or
    // nullptr if they could not be written (disk full): the caller keeps its copy.
    const void* write(const void* data, size_t bytes);
    // True if p points into the mapping (a block written here, not one in RAM).
    bool holds(const void* p) const { return base_ && p >= base_ && p < base_ + reserved_; }
    size_t bytesWritten() const { return used_; }

private:
    int fd_ = -1;
    char* base_ = nullptr;
    size_t reserved_ = 0;
    size_t used_ = 0;
    std::string error_;
};

}  // namespace coscope
