// SPDX-License-Identifier: MIT
// What a file may make volpost spend: a memory budget (a setting) checked before large
// allocations, size arithmetic that cannot wrap, and the rule that models are regular
// files (a FIFO would block, a device would never end). Readers and the host use them so
// that a few hundred hostile bytes end in a clear refusal, never in gigabytes or a crash.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace volpost {

/// The most memory a model (its arrays, its derived data) may take, in bytes. Default: 3/4
/// of the machine's physical memory (half of an address-space limit such as `ulimit -v`
/// when that is smaller), or $VOLPOST_MEMORY_BUDGET ("512M", "8G", "1.5T", or bytes) when
/// set; setMemoryBudget overrides both (the window's and CLI's setting).
std::size_t memoryBudget();
void setMemoryBudget(std::size_t bytes);
/// The most GPU memory one volume's data may hold at once, in bytes: $VOLPOST_GPU_MEMORY_BUDGET
/// when set, else 0 (none: what the device reports, or no limit where it reports nothing);
/// setGpuMemoryBudget overrides it (the window's and CLI's setting; 0 goes back to the
/// default). Regular grids larger than it are drawn in bricks streamed through it.
std::size_t gpuMemoryBudget();
void setGpuMemoryBudget(std::size_t bytes);
/// The memory this process holds now (resident, bytes; /proc/self/statm), 0 where unknown.
std::size_t processResidentBytes();
/// Parses "512M", "8G", "1.5T", "1000000" (bytes); 0 when the text is not a size.
std::size_t parseByteSize(const std::string& text);
/// "3.2 GB", "512 MB", for messages.
std::string byteSizeText(double bytes);

/// Throws ReadError(file, ...) when `bytes` exceed the memory budget: "needs 4.5 GB for
/// `what`, more than the memory budget of 3 GB (VOLPOST_MEMORY_BUDGET)".
void requireMemory(double bytes, const std::string& file, const std::string& what);

/// a * b and a + b, or ReadError(file, "`what` is too large ...") when they overflow.
std::size_t checkedProduct(std::uint64_t a, std::uint64_t b, const std::string& file, const std::string& what);
std::size_t checkedSum(std::uint64_t a, std::uint64_t b, const std::string& file, const std::string& what);

/// Throws ReadError when `path` is not a regular file (missing, a folder, a FIFO, a
/// device), naming what it is.
void requireRegularFile(const std::string& path);

}  // namespace volpost
