#include "constraint/correction/compliance_cache.h"

#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <new>
#include <sstream>

namespace sinew::compliance_cache {

namespace {

namespace fs = std::filesystem;

constexpr char kMagic[8] = {'S', 'I', 'N', 'E', 'W', 'C', 'C', '1'};
constexpr std::size_t kTrailer = 32;

std::uint64_t fnv1a(const unsigned char* p, std::size_t bytes) {
  std::uint64_t h = 14695981039346656037ull;
  for (std::size_t i = 0; i < bytes; ++i) {
    h ^= p[i];
    h *= 1099511628211ull;
  }
  return h;
}

// The owner-write bit of `p` (a folder whose mode lost it is read-only for
// everybody, root included, by convention).
bool owner_writable(const fs::path& p) {
  struct stat st {};
  if (::stat(p.c_str(), &st) != 0) return false;
  return (st.st_mode & S_IWUSR) != 0;
}

}  // namespace

std::string file_name(const std::string& node_name, std::size_t rows, double dt) {
  std::ostringstream s;
  s << node_name << "-" << rows << "-" << dt << ".comp";
  return s.str();
}

bool writable_dir(const std::string& dir) {
  if (dir.empty()) return false;
  std::error_code ec;
  fs::path p = fs::absolute(dir, ec);
  if (ec || !fs::is_directory(p, ec)) return false;
  p = p.lexically_normal();
  for (fs::path q = p;; q = q.parent_path()) {
    if (!owner_writable(q)) return false;
    if (q == q.root_path() || q.parent_path() == q) break;
  }
  return ::access(p.c_str(), W_OK) == 0;
}

std::string fallback_dir() {
  std::error_code ec;
  fs::path t = fs::temp_directory_path(ec);
  if (ec) t = "/tmp";
  t /= "sinew-compliance";
  fs::create_directories(t, ec);
  return fs::is_directory(t, ec) ? t.string() : std::string();
}

std::string write_path(const std::string& dir, const std::string& name, bool& used_fallback) {
  used_fallback = false;
  if (writable_dir(dir)) return (fs::path(dir) / name).string();
  used_fallback = true;
  const std::string f = fallback_dir();
  if (f.empty() || !writable_dir(f)) return {};
  return (fs::path(f) / name).string();
}

bool write(const std::string& path, const double* c, std::size_t n, double dt, std::string& why) {
  const std::size_t bytes = n * n * sizeof(double);
  unsigned char trailer[kTrailer];
  std::memcpy(trailer, kMagic, 8);
  const std::uint64_t n64 = n;
  std::memcpy(trailer + 8, &n64, 8);
  std::memcpy(trailer + 16, &dt, 8);
  const std::uint64_t h = fnv1a(reinterpret_cast<const unsigned char*>(c), bytes);
  std::memcpy(trailer + 24, &h, 8);

  // Unique per process and call, so concurrent writers never share a temporary.
  static std::atomic<int> counter{0};
  const std::string tmp = path + ".tmp" + std::to_string(::getpid()) + "-" + std::to_string(++counter);
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) {
      why = "cannot create " + tmp;
      return false;
    }
    out.write(reinterpret_cast<const char*>(c), static_cast<std::streamsize>(bytes));
    out.write(reinterpret_cast<const char*>(trailer), kTrailer);
    out.close();
    if (!out) {
      std::error_code ec;
      fs::remove(tmp, ec);
      why = "cannot write " + tmp + " (disk full?)";
      return false;
    }
  }
  std::error_code ec;
  fs::rename(tmp, path, ec);
  if (ec) {
    fs::remove(tmp, ec);
    why = "cannot rename the temporary file to " + path;
    return false;
  }
  return true;
}

Read read(const std::string& path, std::size_t n, double dt, std::vector<double>& out, std::string& why) {
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) return Read::missing;
  const std::uintmax_t size = fs::file_size(path, ec);
  const std::size_t bytes = n * n * sizeof(double);
  if (ec || (size != bytes && size != bytes + kTrailer)) {
    std::ostringstream s;
    s << "it holds " << size << " bytes, expected " << bytes << " (" << n << "×" << n << " doubles)";
    if (!ec && size % sizeof(double) == 0) {
      const double m = std::sqrt(static_cast<double>(size / sizeof(double)));
      if (m == std::floor(m)) s << "; it is a " << m << "×" << m << " compliance";
    }
    why = s.str();
    return Read::invalid;
  }
  std::ifstream in(path, std::ios::binary);
  try {
    out.assign(n * n, 0.0);
  } catch (const std::bad_alloc&) {
    why = "not enough memory to read it";
    return Read::invalid;
  }
  in.read(reinterpret_cast<char*>(out.data()), static_cast<std::streamsize>(bytes));
  unsigned char trailer[kTrailer];
  if (size == bytes + kTrailer) in.read(reinterpret_cast<char*>(trailer), kTrailer);
  if (!in) {
    why = "it could not be read";
    return Read::invalid;
  }
  if (size == bytes + kTrailer) {
    std::uint64_t n64 = 0, h = 0;
    double file_dt = 0;
    std::memcpy(&n64, trailer + 8, 8);
    std::memcpy(&file_dt, trailer + 16, 8);
    std::memcpy(&h, trailer + 24, 8);
    if (std::memcmp(trailer, kMagic, 8) != 0 || n64 != n) {
      why = "its trailer is not Sinew's or names another size";
      return Read::invalid;
    }
    if (h != fnv1a(reinterpret_cast<const unsigned char*>(out.data()), bytes)) {
      why = "its checksum does not match its values (corrupt file)";
      return Read::invalid;
    }
    if (file_dt != dt) {
      std::ostringstream s;
      s << "it was computed for dt = " << file_dt << ", not " << dt;
      why = s.str();
      return Read::invalid;
    }
  }
  for (std::size_t k = 0; k < out.size(); ++k)
    if (!std::isfinite(out[k])) {
      why = "value " + std::to_string(k) + " is not finite";
      return Read::invalid;
    }
  return Read::ok;
}

}  // namespace sinew::compliance_cache
