// Errors Swell reports. Bad input (scene files, arguments, assets, shader
// sources) throws InputError with the place it happened; the apps turn it
// into exit code 2. Anything else (no GL context, out of memory) is Error, 1.
#pragma once

#include "swell/export.h"

#include <stdexcept>
#include <string>

namespace swell {

// A place in a file: path and 1-based line and column (0 when unknown).
struct SWELL_API SourcePlace {
    std::string path;
    int line = 0;
    int column = 0;
    // "path:line:column", dropping the parts that are unknown.
    std::string str() const;
};

class SWELL_API Error : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Something the user gave us is wrong. what() reads "path:line:column: message".
class SWELL_API InputError : public Error {
public:
    InputError(SourcePlace place, const std::string& message);
    const SourcePlace& place() const { return place_; }
    const std::string& message() const { return message_; }

private:
    SourcePlace place_;
    std::string message_;
};

// Process exit codes used by the swell executable.
inline constexpr int kExitOk = 0;
inline constexpr int kExitFailure = 1;
inline constexpr int kExitBadInput = 2;

} // namespace swell
