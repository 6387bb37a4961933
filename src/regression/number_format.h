// Number text as SOFA writes it: C++ default stream formatting of a double,
// i.e. printf("%g") with 6 significant digits.
//
// Every scalar of a reference file went through this formatting, and SOFA's
// comparer formats the live values the same way before comparing, so these
// functions sit on the hot path of every state comparison: they use
// std::to_chars / std::from_chars, never iostreams.
#pragma once

#include <cstddef>
#include <string>

namespace sinew::regression {

// Largest output of format_g6 ("-2.22507e-308" is 13 chars; "-nan" 4).
inline constexpr std::size_t kG6MaxChars = 16;

// Formats like `std::ostream << x` with default flags and precision 6
// (== printf "%.6g"): "0", "1.98", "-0.979259", "2.77556e-17", "1e-09",
// "-0", "nan", "-nan" (negative NaN, as glibc prints it), "inf", "-inf".
std::string format_g6(double x);

// Appends format_g6(x) to `out` without a temporary string.
void append_g6(std::string& out, double x);

// Writes format_g6(x) at `first`; returns the end. Precondition: at least
// kG6MaxChars bytes are writable at `first`. No terminating NUL is written.
char* write_g6(char* first, double x);

// The value SOFA's comparer sees for a live scalar: format_g6(x) read back
// with C++ stream rules. Finite values come back rounded to 6 significant
// digits. Non-finite values are returned unchanged; note that their text does
// not read back as a number, which is why a comparison stops at them.
double round_g6(double x);

}  // namespace sinew::regression
