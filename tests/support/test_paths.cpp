#include "test_paths.h"

namespace sinew::test {
const char* data_dir() { return SINEW_TEST_DATA_DIR; }
const char* source_dir() { return SINEW_TEST_SOURCE_DIR; }
}  // namespace sinew::test
