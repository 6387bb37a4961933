// sinew_regress: `sinew regress` without the front ends (viewer, renderer, Python),
// for the sanitizer build (scripts/validate), where building those would double the
// compile time for code the regression scenes never reach.
//
//   sinew_regress --data ROOT --list FILE [--filter REGEX]
//
// Same output and exit codes as `sinew regress`; 77 when ROOT is absent (CTest's skip).
#include <sys/stat.h>

#include <cstdio>
#include <string>

#include "runner/regress.h"

int main(int argc, char** argv) {
  sinew::runner::RegressListArgs args;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string a = argv[i];
    if (a == "--data") args.options.data_root = argv[i + 1];
    else if (a == "--list") args.list_file = argv[i + 1];
    else if (a == "--filter") args.filter = argv[i + 1];
    else {
      std::fprintf(stderr, "sinew_regress: unknown option %s\n", a.c_str());
      return 2;
    }
  }
  if (argc % 2 == 0 || args.options.data_root.empty() || args.list_file.empty()) {
    std::fprintf(stderr, "usage: sinew_regress --data ROOT --list FILE [--filter REGEX]\n");
    return 2;
  }
  struct stat st;
  if (::stat(args.options.data_root.c_str(), &st) != 0 || !S_ISDIR(st.st_mode)) {
    std::printf("sinew_regress: SOFA data folder not found (%s); skipped\n", args.options.data_root.c_str());
    return 77;
  }
  return sinew::runner::regress_list(args);
}
