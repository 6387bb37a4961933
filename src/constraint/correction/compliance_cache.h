// The file cache of PrecomputedConstraintCorrection's dense compliance
// (spec/interaction.md §5.3): its name, the folder it goes to, and reading
// it back with validation.
//
// Format: SOFA's, n·n doubles in native byte order, row-major, nothing else
// (SOFA reads exactly that many bytes and ignores what follows). Sinew
// appends a 32-byte trailer after them: "SINEWCC1", n (uint64), dt (double)
// and a 64-bit FNV-1a hash of the matrix bytes. A file with the trailer is
// checked against it; a bare SOFA file is accepted when its size is n·n
// doubles and every value is finite. Anything else is refused with a reason,
// and the caller recomputes.
//
// Where it goes (SOFA: `fileDir`, else the first folder of its data
// repository): the same folder when it is writable, else a fallback folder
// in the system temp dir. A folder is writable when it exists, neither it nor
// any folder above it has lost its owner-write permission bit (a shared data
// tree is marked read-only at some level, and root ignores the bit in
// access(2)), and access(W_OK) agrees.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace sinew::compliance_cache {

// SOFA's file name: "<node name>-<rows>-<dt>.comp", dt printed as C++ streams
// print a double by default (6 significant digits: 0.02, 1e-05).
std::string file_name(const std::string& node_name, std::size_t rows, double dt);

// Whether files can be created in `dir` under the rule above.
bool writable_dir(const std::string& dir);

// $TMPDIR/sinew-compliance (created when absent); "" when it cannot be created.
std::string fallback_dir();

// `dir`/`name` when `dir` is writable, else fallback_dir()/`name`; "" when
// neither can be written. `used_fallback` tells which.
std::string write_path(const std::string& dir, const std::string& name, bool& used_fallback);

// Writes `c` (n×n) with the trailer, through a temporary file renamed into
// place (a reader never sees half a file). False with `why` on failure.
bool write(const std::string& path, const double* c, std::size_t n, double dt, std::string& why);

enum class Read { ok, missing, invalid };
// Reads an n×n compliance computed for `dt` into `out` (resized).
// missing: no such file; invalid: wrong size, bad trailer, hash mismatch,
// another dt, unreadable or non-finite values (`why` says which).
Read read(const std::string& path, std::size_t n, double dt, std::vector<double>& out, std::string& why);

}  // namespace sinew::compliance_cache
