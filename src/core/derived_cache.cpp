#include "core/derived_cache.h"

#include <dlfcn.h>
#include <gnu/libc-version.h>
#include <sys/stat.h>
#include <unistd.h>

#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <string>
#include <system_error>

namespace swell::detail {

namespace fs = std::filesystem;

namespace {

// "SWELLDC" and the format's version: a file of another layout is not read.
constexpr char kMagic[8] = {'S', 'W', 'E', 'L', 'L', 'D', 'C', '1'};
constexpr std::uint64_t kSecondSeed = 0x9e3779b97f4a7c15ull;
constexpr double kDefaultBound_mb = 512.0;

std::atomic<std::uint64_t> hits{0};

// The file holding the code or data at `address`, as the identity of its
// build: its path, device, inode, size and modification time, which change
// whenever it is built or installed again. Empty when it cannot be found.
std::string fileIdentityOf(const void* address)
{
    Dl_info info{};
    if (address == nullptr || ::dladdr(address, &info) == 0 || info.dli_fname == nullptr)
        return {};
    struct stat st {};
    if (::stat(info.dli_fname, &st) != 0)
        return {};
    return fmt::format("{}:{}:{}:{}:{}.{};", info.dli_fname, std::uint64_t(st.st_dev), std::uint64_t(st.st_ino),
                       std::int64_t(st.st_size), std::int64_t(st.st_mtim.tv_sec), std::int64_t(st.st_mtim.tv_nsec));
}

// This build: the library's file, the FFT library's and the maths library's
// (the derivations' arithmetic), and the C library's version. Empty when the
// library's own file cannot be found: the cache is off then.
const std::string& buildIdentity()
{
    static const std::string identity = [] {
        const std::string own = fileIdentityOf(reinterpret_cast<const void*>(&fnv1a64));
        if (own.empty())
            return std::string();
        return own + fileIdentityOf(::dlsym(RTLD_DEFAULT, "kiss_fft")) + fileIdentityOf(::dlsym(RTLD_DEFAULT, "exp"))
               + ::gnu_get_libc_version();
    }();
    return identity;
}

// The folder, or empty: the cache is off.
fs::path cacheFolder()
{
    const char* dir = std::getenv("SWELL_CACHE_DIR");
    if (dir == nullptr || *dir == '\0' || buildIdentity().empty())
        return {};
    return fs::path(dir);
}

double boundBytes()
{
    double mb = kDefaultBound_mb;
    if (const char* v = std::getenv("SWELL_CACHE_MAX_MB"); v != nullptr && *v != '\0') {
        char* end = nullptr;
        const double parsed = std::strtod(v, &end);
        if (end != v && *end == '\0' && parsed >= 0.0)
            mb = parsed;
    }
    return mb * 1024.0 * 1024.0;
}

// The header every entry starts with: the magic, the build, the kind and
// the key, so a file is read only for exactly what it was written for.
std::vector<std::byte> headerOf(std::string_view kind, std::span<const std::byte> key)
{
    CacheBytes h;
    for (const char c : kMagic)
        h.add(c);
    const std::string& identity = buildIdentity();
    h.addSpan(std::span<const char>(identity.data(), identity.size()));
    h.addSpan(std::span<const char>(kind.data(), kind.size()));
    h.addSpan(key);
    const std::span<const std::byte> b = h.bytes();
    return {b.begin(), b.end()};
}

fs::path entryPath(const fs::path& folder, std::string_view kind, std::span<const std::byte> header)
{
    return folder / fmt::format("{}-{:016x}{:016x}.bin", kind, fnv1a64(header), fnv1a64(header, kSecondSeed));
}

struct FileBytes {
    std::unique_ptr<std::byte[]> bytes;
    std::size_t size = 0;
};

std::optional<FileBytes> readFile(const fs::path& path)
{
    std::ifstream in(path, std::ios::binary | std::ios::ate);
    if (!in)
        return std::nullopt;
    const std::streamoff size = in.tellg();
    if (size < 0)
        return std::nullopt;
    FileBytes file{std::make_unique_for_overwrite<std::byte[]>(static_cast<std::size_t>(size)), static_cast<std::size_t>(size)};
    in.seekg(0);
    if (!in.read(reinterpret_cast<char*>(file.bytes.get()), size))
        return std::nullopt;
    return file;
}

// Removes the least recently used entries (by modification time, which a
// read renews) until the folder holds at most three quarters of the bound.
void keepUnderBound(const fs::path& folder)
{
    const double bound = boundBytes();
    struct Entry {
        fs::path path;
        fs::file_time_type used;
        std::uintmax_t size;
    };
    std::vector<Entry> entries;
    double total = 0.0;
    std::error_code ec;
    for (const fs::directory_entry& e : fs::directory_iterator(folder, ec)) {
        if (e.path().extension() != ".bin")
            continue;
        std::error_code ignored;
        const std::uintmax_t size = e.file_size(ignored);
        const fs::file_time_type used = e.last_write_time(ignored);
        if (ignored)
            continue;
        entries.push_back({e.path(), used, size});
        total += double(size);
    }
    if (total <= bound)
        return;
    std::sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) { return a.used < b.used; });
    for (const Entry& e : entries) {
        if (total <= 0.75 * bound)
            break;
        std::error_code ignored;
        if (fs::remove(e.path, ignored))
            total -= double(e.size);
    }
}

} // namespace

std::uint64_t fnv1a64(std::span<const std::byte> bytes, std::uint64_t seed)
{
    std::uint64_t h = seed;
    for (const std::byte b : bytes)
        h = (h ^ std::uint64_t(b)) * 1099511628211ull;
    return h;
}

std::optional<DerivedEntry> loadDerived(std::string_view kind, std::span<const std::byte> key)
{
    const fs::path folder = cacheFolder();
    if (folder.empty())
        return std::nullopt;
    const std::vector<std::byte> header = headerOf(kind, key);
    const fs::path path = entryPath(folder, kind, header);
    std::optional<FileBytes> file = readFile(path);
    // header, payload size, payload, checksum of all before it.
    constexpr std::size_t kWord = sizeof(std::uint64_t);
    if (!file || file->size < header.size() + 2 * kWord)
        return std::nullopt;
    const std::span<const std::byte> all(file->bytes.get(), file->size);
    const std::span<const std::byte> body = all.first(all.size() - kWord);
    if (!std::equal(header.begin(), header.end(), body.begin())
        || CacheReader(all.last(kWord)).get<std::uint64_t>() != wordChecksum(body))
        return std::nullopt;
    CacheReader sizeOf(body.subspan(header.size(), kWord));
    const auto payloadSize = sizeOf.get<std::uint64_t>();
    if (payloadSize != body.size() - header.size() - kWord)
        return std::nullopt;
    // Renewed, so the bound removes the entries not used for longest.
    std::error_code ignored;
    fs::last_write_time(path, fs::file_time_type::clock::now(), ignored);
    ++hits;
    return DerivedEntry(std::move(file->bytes), header.size() + kWord, payloadSize);
}

std::array<std::uint64_t, 2> hash128(std::span<const std::byte> bytes)
{
    return {fnv1a64(bytes), fnv1a64(bytes, kSecondSeed)};
}

std::uint64_t wordChecksum(std::span<const std::byte> bytes)
{
    std::uint64_t h = 1469598103934665603ull;
    std::size_t at = 0;
    for (; at + 8 <= bytes.size(); at += 8) {
        std::uint64_t word;
        std::memcpy(&word, bytes.data() + at, 8);
        h = (h ^ word) * 1099511628211ull;
    }
    std::uint64_t last = 0;
    std::memcpy(&last, bytes.data() + at, bytes.size() - at);
    return (h ^ last ^ (std::uint64_t(bytes.size()) << 56)) * 1099511628211ull;
}

std::uint64_t derivedCacheHits() { return hits.load(); }

void storeDerived(std::string_view kind, std::span<const std::byte> key, std::span<const std::byte> payload)
{
    const fs::path folder = cacheFolder();
    if (folder.empty())
        return;
    std::error_code ec;
    fs::create_directories(folder, ec);
    if (ec)
        return;
    const std::vector<std::byte> header = headerOf(kind, key);
    // As loadDerived reads it: header, payload size, payload, checksum.
    std::vector<std::byte> file;
    file.reserve(header.size() + payload.size() + 2 * sizeof(std::uint64_t));
    auto append = [&file](std::span<const std::byte> b) { file.insert(file.end(), b.begin(), b.end()); };
    const std::uint64_t payloadSize = payload.size();
    append(header);
    append(std::as_bytes(std::span(&payloadSize, 1)));
    append(payload);
    const std::uint64_t checksum = wordChecksum(file);
    append(std::as_bytes(std::span(&checksum, 1)));

    const fs::path path = entryPath(folder, kind, header);
    static std::mutex mutex; // one temporary name per process at a time
    const std::lock_guard lock(mutex);
    const fs::path temporary = path.string() + fmt::format(".{}.tmp", ::getpid());
    {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        if (!out || !out.write(reinterpret_cast<const char*>(file.data()), std::streamsize(file.size()))) {
            out.close();
            fs::remove(temporary, ec);
            return;
        }
    }
    fs::rename(temporary, path, ec);
    if (ec) {
        fs::remove(temporary, ec);
        return;
    }
    keepUnderBound(folder);
}

} // namespace swell::detail
