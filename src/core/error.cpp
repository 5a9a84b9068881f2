#include "swell/error.h"

namespace swell {

std::string SourcePlace::str() const
{
    std::string s = path.empty() ? std::string("<input>") : path;
    if (line > 0) {
        s += ':' + std::to_string(line);
        if (column > 0)
            s += ':' + std::to_string(column);
    }
    return s;
}

InputError::InputError(SourcePlace place, const std::string& message)
    : Error(place.str() + ": " + message), place_(std::move(place)), message_(message)
{
}

} // namespace swell
