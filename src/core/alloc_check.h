// Sizes read from a scene (a state's `size`, a grid's `n`, resolutions) are
// checked against what they would allocate before allocating: an absurd size
// is a message naming the component and the field, never std::bad_alloc.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace sinew {

class Component;

// The memory a scene may ask for, in bytes: this machine's physical memory
// (sysconf; 64 GiB when unknown), or less when the environment variable
// SINEW_MEMORY_LIMIT_MB is a positive number of megabytes (read once). The fuzz
// targets and scripts/mutate lower it so that a huge count is refused at once
// instead of being allocated and touched.
std::uint64_t physical_memory_bytes();

// Whether `count` items of about `bytes_each` bytes fit in that memory.
bool allocation_fits(double count, double bytes_each);

// "1.5 GB", "96 GB": a byte count for messages.
std::string format_bytes(double bytes);

// When `count` items of `bytes_each` bytes would not fit, reports on `c`
// "<field> = <value> would need N GB, more than this machine's M GB of memory"
// (an error) and returns false. `value_text` is the size as the scene gave it.
bool check_allocation(const Component& c, std::string_view field, std::string_view value_text, double count,
                      double bytes_each);

}  // namespace sinew
