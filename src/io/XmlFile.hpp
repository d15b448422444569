// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <vtkCommand.h>

#include <filesystem>
#include <string>

class vtkDataObject;
class vtkXMLWriter;

namespace mpm::io {

/// Collects the ErrorEvents of a VTK object (an observed object does not print them).
class ErrorObserver : public vtkCommand {
public:
    static ErrorObserver* New() { return new ErrorObserver; }
    void Execute(vtkObject* caller, unsigned long event, void* callData) override;
    bool failed() const { return failed_; }
    const std::string& message() const { return message_; }

private:
    ErrorObserver() = default;
    bool failed_ = false;
    bool fromExecutive_ = false; ///< message_ holds only the executive's text
    std::string message_;
};

/// `text` with XML's five special characters (& < > " ') replaced by their entities.
std::string escapeXml(const std::string& text);

/// `file` + ".tmp": where a file is written before it is renamed into place.
std::filesystem::path tmpName(const std::filesystem::path& file);
/// Remove a file, ignoring errors.
void removeQuietly(const std::filesystem::path& file);
/// Throw std::runtime_error("cannot write <file>: <why>").
[[noreturn]] void cannotWrite(const std::filesystem::path& file, const std::string& why = {});

/// Write `data` with a VTK XML writer in mpmFoam's format — appended raw binary, LZ4 (fastest),
/// UInt64 headers — to `<file>.tmp`, then rename it to `file`, so that a reader (ParaView)
/// never sees a half-written file. Throws std::runtime_error naming the file on failure.
void writeXmlAtomically(vtkXMLWriter& writer, vtkDataObject* data,
                        const std::filesystem::path& file);

} // namespace mpm::io
