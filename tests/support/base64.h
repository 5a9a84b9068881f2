// Base64 (RFC 4648, with padding) for the data URIs of glTF files that tests write.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace swell::test {

inline std::string base64(const std::vector<std::uint8_t>& data)
{
    static const char* chars = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (std::size_t i = 0; i < data.size(); i += 3) {
        const std::uint32_t n = std::uint32_t(data[i]) << 16 | (i + 1 < data.size() ? data[i + 1] << 8 : 0) |
                                (i + 2 < data.size() ? data[i + 2] : 0);
        out += chars[n >> 18 & 63];
        out += chars[n >> 12 & 63];
        out += i + 1 < data.size() ? chars[n >> 6 & 63] : '=';
        out += i + 2 < data.size() ? chars[n & 63] : '=';
    }
    return out;
}

} // namespace swell::test
