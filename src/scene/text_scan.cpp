// The scan of a scene file's text before parsing (text_scan.h).
#include "scene/text_scan.h"

#include "scene/places.h"
#include "swell/gpu/limits.h"
#include "swell/scene/scene_file.h"

#include <fmt/format.h>

#include <vector>

namespace swell::detail::scenefile {

namespace {

// ---------------------------------------------------------------------------
// Step 1a: text. The parser would also find these, but only after the
// structure scan has run over them; checking first reports binary data as
// such, at its first bad byte.

// Length of the UTF-8 sequence at s[i], or 0 when it is not valid UTF-8.
std::size_t utf8Length(std::string_view s, std::size_t i)
{
    auto byte = [&](std::size_t k) { return k < s.size() ? static_cast<unsigned char>(s[k]) : 0u; };
    auto continuation = [&](std::size_t k, unsigned lo = 0x80, unsigned hi = 0xBF) {
        return byte(k) >= lo && byte(k) <= hi;
    };
    unsigned b = byte(i);
    if (b < 0x80)
        return 1;
    if (b >= 0xC2 && b <= 0xDF)
        return continuation(i + 1) ? 2 : 0;
    if (b >= 0xE0 && b <= 0xEF) {
        // No overlong forms (E0 80..9F) and no UTF-16 surrogates (ED A0..BF).
        unsigned lo = b == 0xE0 ? 0xA0 : 0x80;
        unsigned hi = b == 0xED ? 0x9F : 0xBF;
        return continuation(i + 1, lo, hi) && continuation(i + 2) ? 3 : 0;
    }
    if (b >= 0xF0 && b <= 0xF4) {
        // No overlong forms (F0 80..8F) and nothing past U+10FFFF (F4 90..).
        unsigned lo = b == 0xF0 ? 0x90 : 0x80;
        unsigned hi = b == 0xF4 ? 0x8F : 0xBF;
        return continuation(i + 1, lo, hi) && continuation(i + 2) && continuation(i + 3) ? 4 : 0;
    }
    return 0;
}

void checkText(std::string_view text, const std::string& path)
{
    int line = 1;
    int column = 1;
    for (std::size_t i = 0; i < text.size();) {
        if (text[i] == '\0')
            fail({path, line, column}, "the file contains a NUL byte; a scene file is UTF-8 TOML text, not binary data");
        std::size_t n = utf8Length(text, i);
        if (n == 0)
            fail({path, line, column},
                 fmt::format("byte 0x{:02X} is not UTF-8; a scene file is UTF-8 TOML text, not binary data",
                             static_cast<unsigned>(static_cast<unsigned char>(text[i]))));
        if (text[i] == '\n') {
            ++line;
            column = 1;
        } else {
            ++column;
        }
        i += n;
    }
}

// ---------------------------------------------------------------------------
// Step 1b: structure. toml++ recurses once per dotted key part and once per
// nested [ ] or { }, so a 4 MiB line of "a.a.a..." overflows the stack; and it
// builds a node for every array entry before the reader can count them, so
// "list = [{},{},...]" would allocate a million tables. This scan skips
// strings and comments and counts just those things (parts, nesting, array
// entries, [[ ]] headers); anything else, including broken syntax, is left
// for the parser to report.

class StructureScan {
public:
    StructureScan(std::string_view text, const std::string& path) : text_(text), path_(path) {}

    void run()
    {
        while (i_ < text_.size()) {
            char c = text_[i_];
            switch (mode_) {
            case Mode::LineStart: lineStart(c); break;
            case Mode::Key: key(c); break;
            case Mode::Value: value(c); break;
            }
        }
    }

private:
    enum class Mode { LineStart, Key, Value };

    SourcePlace here() const { return {path_, line_, column_}; }

    // Moves past one byte; columns count code points, as the parser's do.
    void step()
    {
        char c = text_[i_++];
        if (c == '\n') {
            ++line_;
            column_ = 1;
        } else if (i_ < text_.size() && (static_cast<unsigned char>(text_[i_]) & 0xC0) != 0x80) {
            ++column_;
        }
    }

    bool startsWith(std::string_view s) const { return text_.substr(i_, s.size()) == s; }

    void skipComment()
    {
        while (i_ < text_.size() && text_[i_] != '\n' && text_[i_] != '\0')
            step();
    }

    // A string starting at i_ (on its opening quote): basic or literal, one
    // line or multi-line. Single-line strings also end at a newline, so that
    // a stray quote cannot hide the rest of the file from the scan.
    void skipString()
    {
        char q = text_[i_];
        const std::string triple(3, q);
        if (startsWith(triple)) {
            for (int k = 0; k < 3; ++k)
                step();
            while (i_ < text_.size() && !startsWith(triple)) {
                if (text_[i_] == '\0')
                    return;
                if (q == '"' && text_[i_] == '\\' && i_ + 1 < text_.size())
                    step();
                step();
            }
            // The closing delimiter may be preceded by up to two more quotes.
            for (int k = 0; k < 5 && i_ < text_.size() && text_[i_] == q; ++k)
                step();
            return;
        }
        step();
        while (i_ < text_.size() && text_[i_] != q && text_[i_] != '\n') {
            if (text_[i_] == '\0')
                return;
            if (q == '"' && text_[i_] == '\\' && i_ + 1 < text_.size() && text_[i_ + 1] != '\n')
                step();
            step();
        }
        if (i_ < text_.size() && text_[i_] == q)
            step();
    }

    void pop()
    {
        nest_.pop_back();
        items_.pop_back();
    }

    void startKey()
    {
        mode_ = Mode::Key;
        keyParts_ = 1;
    }

    void lineStart(char c)
    {
        if (c == ' ' || c == '\t' || c == '\r' || c == '\n') {
            step();
        } else if (c == '#') {
            skipComment();
        } else if (c == '[') { // table header, [name] or [[name]]
            step();
            if (i_ < text_.size() && text_[i_] == '[') {
                if (++tableArrayHeaders_ > kMaxSceneTableArrayHeaders)
                    fail(here(), fmt::format("more than {} [[...]] headers; a scene holds at most {} camera keys, {} "
                                             "objects and {} waves",
                                             kMaxSceneTableArrayHeaders, kMaxCameraKeys, kMaxSceneObjects, SWELL_MAX_WAVES));
                step();
            }
            startKey();
        } else {
            startKey();
        }
    }

    void key(char c)
    {
        switch (c) {
        case '"':
        case '\'': skipString(); return;
        case '#': skipComment(); return;
        case '.':
            if (++keyParts_ > kMaxSceneKeyParts)
                fail(here(), fmt::format("a key with more than {} dotted parts; scene keys have at most 3",
                                         kMaxSceneKeyParts));
            step();
            return;
        case '=':
        case ']': // end of a table header; the rest of its line reads like a value's
            mode_ = Mode::Value;
            step();
            return;
        case '}': // an empty inline table
            if (!nest_.empty() && nest_.back() == '{')
                pop();
            mode_ = Mode::Value;
            step();
            return;
        case '\n':
            mode_ = nest_.empty() ? Mode::LineStart : Mode::Value;
            step();
            return;
        default: step(); return;
        }
    }

    void value(char c)
    {
        switch (c) {
        case '"':
        case '\'': skipString(); return;
        case '#': skipComment(); return;
        case '[':
        case '{':
            nest_.push_back(c);
            items_.push_back(1);
            if (static_cast<int>(nest_.size()) > kMaxSceneNesting)
                fail(here(), fmt::format("values nested more than {} deep in [ ] and {{ }}; scene values nest at most 3 deep",
                                         kMaxSceneNesting));
            step();
            if (c == '{')
                startKey();
            return;
        case ']':
        case '}':
            if (!nest_.empty() && nest_.back() == (c == ']' ? '[' : '{'))
                pop();
            step();
            return;
        case ',':
            // TOML allows a comma after the last entry: n commas hold at least n entries.
            if (!nest_.empty() && nest_.back() == '[' && ++items_.back() > kMaxSceneArrayItems + 1)
                fail(here(), fmt::format("an array with more than {} entries; the longest list in a scene "
                                         "(camera.path) has at most {}",
                                         kMaxSceneArrayItems, kMaxCameraKeys));
            step();
            if (!nest_.empty() && nest_.back() == '{')
                startKey();
            return;
        case '\n':
            if (nest_.empty())
                mode_ = Mode::LineStart;
            step();
            return;
        default: step(); return;
        }
    }

    std::string_view text_;
    const std::string& path_;
    std::size_t i_ = 0;
    int line_ = 1;
    int column_ = 1;
    Mode mode_ = Mode::LineStart;
    int keyParts_ = 1;
    std::vector<char> nest_;
    // 1 + the commas so far of each open [ ] or { } in nest_ (counted for [ ] only).
    std::vector<std::size_t> items_;
    int tableArrayHeaders_ = 0;
};

} // namespace

void scanSceneText(std::string_view text, const std::string& path)
{
    checkText(text, path);
    StructureScan(text, path).run();
}

std::optional<SourcePlace> unclosedArrayBefore(std::string_view text, int errorLine, int errorColumn,
                                               const std::string& path)
{
    std::vector<std::pair<int, std::size_t>> open; // line and offset of each '[' still open
    int line = 1;
    std::size_t lineStart = 0;
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (line > errorLine || (line == errorLine && i - lineStart + 1 >= std::size_t(errorColumn)))
            break;
        const char c = text[i];
        if (c == '\n') {
            ++line;
            lineStart = i + 1;
        } else if (c == '#') {
            while (i + 1 < text.size() && text[i + 1] != '\n')
                ++i;
        } else if (c == '"' || c == '\'') {
            // A basic or literal string on one line; multi-line strings are not
            // looked into (an error inside one is reported where the parser says).
            while (i + 1 < text.size() && text[i + 1] != c && text[i + 1] != '\n')
                i += text[i + 1] == '\\' && c == '"' ? 2 : 1;
            ++i;
        } else if (c == '[') {
            open.emplace_back(line, i);
        } else if (c == ']' && !open.empty()) {
            open.pop_back();
        }
    }
    if (open.empty() || open.back().first >= errorLine)
        return std::nullopt;
    // Only where the parser stopped at the first thing on its line, and the
    // array's line goes on after its '[' (an array written one element a line
    // has its '[' last: there the missing piece is more likely a comma).
    const std::size_t errorLineStart = lineStart;
    const std::size_t firstToken = text.find_first_not_of(" \t", errorLineStart);
    if (firstToken == std::string_view::npos || firstToken - errorLineStart + 1 != std::size_t(errorColumn))
        return std::nullopt;
    // The end of the opening line, comments and trailing blanks left out.
    const std::size_t from = open.back().second;
    std::size_t end = text.find('\n', from);
    if (end == std::string_view::npos)
        end = text.size();
    std::string_view rest = text.substr(from, end - from);
    if (const std::size_t hash = rest.find('#'); hash != std::string_view::npos)
        rest = rest.substr(0, hash);
    while (!rest.empty() && (rest.back() == ' ' || rest.back() == '\t' || rest.back() == '\r'))
        rest.remove_suffix(1);
    if (rest.size() <= 1)
        return std::nullopt;
    const std::size_t start = text.rfind('\n', from) == std::string_view::npos ? 0 : text.rfind('\n', from) + 1;
    return SourcePlace{path, open.back().first, int(from - start + rest.size()) + 1};
}


std::optional<OpenString> unclosedStringOn(std::string_view text, int errorLine, const std::string& path)
{
    // The error line's text.
    std::size_t start = 0;
    for (int line = 1; line < errorLine; ++line) {
        start = text.find('\n', start);
        if (start == std::string_view::npos)
            return std::nullopt;
        ++start;
    }
    std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos)
        end = text.size();
    const std::string_view line = text.substr(start, end - start);
    for (std::size_t i = 0; i < line.size(); ++i) {
        const char c = line[i];
        if (c == '#')
            return std::nullopt;
        if (c != '"' && c != '\'')
            continue;
        if (line.substr(i, 3) == std::string_view(c == '"' ? "\"\"\"" : "'''"))
            return std::nullopt; // a multi-line string: left to the parser
        std::size_t j = i + 1;
        while (j < line.size() && line[j] != c && line[j] != '\r')
            j += (line[j] == '\\' && c == '"') ? 2 : 1;
        if (j >= line.size() || line[j] == '\r')
            return OpenString{{path, errorLine, int(i) + 1}, c};
        i = j;
    }
    return std::nullopt;
}

} // namespace swell::detail::scenefile
