// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cassert>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>

namespace mpm {

/// `text` safe to print on a terminal: every byte that is not printable ASCII, '\n', '\t' or
/// part of a valid UTF-8 sequence of a printable character becomes `\xHH` (lower-case hex).
/// Valid UTF-8 (°, μ, ξ, …) is kept; C0 controls, DEL, C1 controls (U+0080–U+009F), overlong
/// forms, surrogates, code points above U+10FFFF and stray or truncated bytes are escaped. A
/// corrupted case file thus never sends raw bytes to the terminal through an error message.
/// Idempotent: escaping an escaped text changes nothing.
inline std::string escapeBytes(const std::string& text) {
    static constexpr char hex[] = "0123456789abcdef";
    std::string out;
    out.reserve(text.size());
    const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(text[i]); };
    const auto escape = [&](unsigned char b) {
        out += "\\x";
        out += hex[b >> 4];
        out += hex[b & 15];
    };
    const auto inRange = [&](std::size_t i, unsigned lo, unsigned hi) {
        return i < text.size() && byte(i) >= lo && byte(i) <= hi;
    };
    for (std::size_t i = 0; i < text.size();) {
        const unsigned char b = byte(i);
        if (b < 0x80) {
            if ((b >= 0x20 && b < 0x7f) || b == '\n' || b == '\t')
                out += static_cast<char>(b);
            else
                escape(b);
            ++i;
            continue;
        }
        // Length of a well-formed sequence starting here (Unicode Table 3-7), 0 if none.
        std::size_t n = 0;
        if (b >= 0xc2 && b <= 0xdf)
            n = inRange(i + 1, 0x80, 0xbf) ? 2 : 0;
        else if (b >= 0xe0 && b <= 0xef)
            n = inRange(i + 1, b == 0xe0 ? 0xa0 : 0x80, b == 0xed ? 0x9f : 0xbf) &&
                        inRange(i + 2, 0x80, 0xbf)
                    ? 3
                    : 0;
        else if (b >= 0xf0 && b <= 0xf4)
            n = inRange(i + 1, b == 0xf0 ? 0x90 : 0x80, b == 0xf4 ? 0x8f : 0xbf) &&
                        inRange(i + 2, 0x80, 0xbf) && inRange(i + 3, 0x80, 0xbf)
                    ? 4
                    : 0;
        const bool c1Control = n == 2 && b == 0xc2 && byte(i + 1) <= 0x9f;
        if (n == 0) {
            escape(b); // invalid here: this byte alone, then go on with the next
            ++i;
        } else if (c1Control) {
            escape(byte(i));
            escape(byte(i + 1));
            i += 2;
        } else {
            out.append(text, i, n);
            i += n;
        }
    }
    return out;
}

/// An error in what the user wrote: a case file, a command-line option, a value out of range.
/// Always checked (release builds too); reported as
/// `--> MPMFOAM FATAL IO ERROR: <file>:<line>: key '<key>': <message>` and exit code 1. The
/// message may quote the file (a value, a key, a YAML or VTK parser's text): what() has its
/// unprintable and invalid UTF-8 bytes escaped (escapeBytes); file(), key() are as given.
class InputError : public std::runtime_error {
public:
    InputError(std::string file, int line, std::string key, const std::string& message)
        : std::runtime_error(format(file, line, key, message)), file_(std::move(file)), line_(line),
          key_(std::move(key)) {}

    const std::string& file() const { return file_; }
    int line() const { return line_; }
    const std::string& key() const { return key_; }

private:
    static std::string format(const std::string& file, int line, const std::string& key,
                              const std::string& message) {
        std::ostringstream os;
        if (!file.empty()) {
            os << file;
            if (line > 0) os << ':' << line;
            os << ": ";
        }
        if (!key.empty()) os << "key '" << key << "': ";
        os << message;
        return escapeBytes(os.str());
    }

    std::string file_;
    int line_;
    std::string key_;
};

/// A run that went wrong numerically (NaN, energy blow-up, particle leaving the grid).
/// Reported as `--> MPMFOAM FATAL ERROR: ...`, exit code 1, after the last good state is written.
class RunError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// Run `body` (returning an exit code) and report what it throws as every mpmFoam program does:
/// `--> MPMFOAM FATAL IO ERROR` for input errors, `--> MPMFOAM FATAL ERROR` for the rest (bytes
/// escaped), then "MPMFOAM exiting" and exit code 1. Standard output is flushed first.
template <class Body> int reportingErrors(Body&& body) {
    const auto report = [](const char* kind, const std::string& what) {
        std::cout.flush();
        std::cerr << "\n--> MPMFOAM FATAL " << kind << ":\n" << what << "\n\nMPMFOAM exiting\n";
    };
    try {
        return body();
    } catch (const InputError& e) {
        report("IO ERROR", e.what());
    } catch (const std::exception& e) {
        report("ERROR", escapeBytes(e.what()));
    }
    return 1;
}

} // namespace mpm

/// Internal invariant: checked in debug builds only.
#define MPM_ASSERT(cond) assert(cond)
