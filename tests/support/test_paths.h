// Where the tests find SOFA's data and Sinew's sources. The paths are given
// to one small file per test program (support/test_paths.cpp) rather than to
// every test file as macros, so that the test objects do not depend on where
// the checkout lives and ccache shares them between checkouts.
#pragma once

namespace sinew::test {
const char* data_dir();    // SOFA's data folder (CMake's SINEW_DATA_DIR)
const char* source_dir();  // the checkout
}  // namespace sinew::test

#define SINEW_DATA_DIR (::sinew::test::data_dir())
#define SINEW_SOURCE_DIR (::sinew::test::source_dir())
