// A cache on disk of what a scene derives at a cost of seconds: the coast
// field's solve and the breaking ramps' calibration (docs/LIBRARY.md,
// "The cache of derived data"). Every process that builds a renderer for
// an island or a spectral sea pays them again otherwise: each still the
// `swell` executable renders, each test, each Dask worker.
//
// Off unless the folder is named: the environment's SWELL_CACHE_DIR (the
// `swell` executable names one by default). What it keeps is exactly what
// the derivation returns, so a process reads the same bits it would have
// computed: an entry is keyed by its inputs' full bytes (or a 128-bit hash
// of them, where those are megabytes of seeded spectra) and by the build
// that computed it (the identity of the library's own file and of the FFT
// library's, and the C library's version: another build may round
// differently). An entry that is not whole and sound (cut short, a byte
// changed, another build's) is computed again and replaced; a folder that
// cannot be written leaves the cache off, never an error. Entries are
// written to a temporary file and renamed, so two processes never read
// half of one. The folder is kept under a bound (SWELL_CACHE_MAX_MB,
// default 512), the least recently used entries removed first.
// Library-internal.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <memory>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

namespace swell::detail {

// Bytes an entry is keyed by or holds, appended field by field (no
// padding, so equal values give equal bytes).
class CacheBytes {
public:
    template <class T> void add(const T& value)
    {
        const auto* p = reinterpret_cast<const std::byte*>(&value);
        bytes_.insert(bytes_.end(), p, p + sizeof(T));
    }
    template <class T> void addSpan(std::span<const T> values)
    {
        add(std::uint64_t(values.size()));
        const auto* p = reinterpret_cast<const std::byte*>(values.data());
        bytes_.insert(bytes_.end(), p, p + values.size_bytes());
    }
    std::span<const std::byte> bytes() const { return bytes_; }

private:
    std::vector<std::byte> bytes_;
};

// Reads back what CacheBytes appended, in the same order; every read
// checks that the bytes are there (ok() false once one was not).
class CacheReader {
public:
    explicit CacheReader(std::span<const std::byte> bytes) : bytes_(bytes) {}
    template <class T> T get()
    {
        T value{};
        if (bytes_.size() - at_ < sizeof(T) || !ok_) {
            ok_ = false;
            return value;
        }
        std::memcpy(&value, bytes_.data() + at_, sizeof(T));
        at_ += sizeof(T);
        return value;
    }
    template <class T> std::vector<T> getVector(std::size_t most)
    {
        const auto count = get<std::uint64_t>();
        if (!ok_ || count > most || (bytes_.size() - at_) / sizeof(T) < count) {
            ok_ = false;
            return {};
        }
        std::vector<T> values(count);
        std::memcpy(values.data(), bytes_.data() + at_, count * sizeof(T));
        at_ += count * sizeof(T);
        return values;
    }
    // Every byte read, none missing.
    bool ok() const { return ok_ && at_ == bytes_.size(); }

private:
    std::span<const std::byte> bytes_;
    std::size_t at_ = 0;
    bool ok_ = true;
};

// FNV-1a, 64 bits, from `seed`.
std::uint64_t fnv1a64(std::span<const std::byte> bytes, std::uint64_t seed = 1469598103934665603ull);
// A 128-bit key for inputs too large to keep in an entry: fnv1a64 from two
// seeds, the first half fnv1a64's own.
std::array<std::uint64_t, 2> hash128(std::span<const std::byte> bytes);
// An entry's checksum: FNV-1a's step on 8 bytes at a time (eight times
// fewer multiplies than fnv1a64; each step is a bijection of the state, so
// any one word changed changes the sum), the last bytes zero-padded.
std::uint64_t wordChecksum(std::span<const std::byte> bytes);

// An entry read back: the file's bytes, read into memory not zeroed first
// (the island's field is 28 MB), and where its payload lies in them.
class DerivedEntry {
public:
    DerivedEntry(std::unique_ptr<std::byte[]> file, std::size_t payloadAt, std::size_t payloadSize)
        : file_(std::move(file)), at_(payloadAt), size_(payloadSize)
    {
    }
    std::span<const std::byte> payload() const { return {file_.get() + at_, size_}; }

private:
    std::unique_ptr<std::byte[]> file_;
    std::size_t at_, size_;
};

// The entry of `kind` ("coast", "ramps") whose key is `key`, if the cache
// is on and holds a sound one of this build.
std::optional<DerivedEntry> loadDerived(std::string_view kind, std::span<const std::byte> key);
// Keeps `payload` under `key`; does nothing when the cache is off or its
// folder cannot be written.
void storeDerived(std::string_view kind, std::span<const std::byte> key, std::span<const std::byte> payload);

// How many entries loadDerived has read back in this process (for tests).
std::uint64_t derivedCacheHits();

} // namespace swell::detail
