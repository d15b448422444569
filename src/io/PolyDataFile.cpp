// SPDX-License-Identifier: GPL-3.0-or-later
#include "io/PolyDataFile.hpp"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCommand.h>
#include <vtkDoubleArray.h>
#include <vtkExecutive.h>
#include <vtkIdTypeArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkXMLPolyDataWriter.h>

#include <cstring>
#include <stdexcept>
#include <system_error>

namespace mpm::io {

namespace {

/// Records whether a VTK object raised an ErrorEvent (an observed object does not print it).
class ErrorFlag : public vtkCommand {
public:
    static ErrorFlag* New() { return new ErrorFlag; }
    void Execute(vtkObject*, unsigned long event, void* callData) override {
        if (event != vtkCommand::ErrorEvent) return;
        failed_ = true;
        if (callData != nullptr && message_.empty()) {
            message_ = static_cast<const char*>(callData);
            while (!message_.empty() && (message_.back() == '\n' || message_.back() == ' ')) {
                message_.pop_back();
            }
        }
    }
    bool failed() const { return failed_; }
    const std::string& message() const { return message_; }

private:
    ErrorFlag() = default;
    bool failed_ = false;
    std::string message_;
};

[[noreturn]] void cannotWrite(const std::filesystem::path& file, const std::string& why) {
    throw std::runtime_error("cannot write " + file.string() + (why.empty() ? "" : ": " + why));
}

void removeQuietly(const std::filesystem::path& file) {
    std::error_code ec;
    std::filesystem::remove(file, ec);
}

vtkSmartPointer<vtkDoubleArray> makeArray(const std::filesystem::path& file, const DataArray& a,
                                          std::size_t tuples) {
    if (a.components < 1) cannotWrite(file, "array '" + a.name + "' has no components");
    const std::size_t expected = tuples * static_cast<std::size_t>(a.components);
    if (a.values.size() != expected) {
        cannotWrite(file, "array '" + a.name + "' has " + std::to_string(a.values.size()) +
                              " values, expected " + std::to_string(expected));
    }
    auto array = vtkSmartPointer<vtkDoubleArray>::New();
    array->SetName(a.name.c_str());
    array->SetNumberOfComponents(a.components);
    array->SetNumberOfTuples(static_cast<vtkIdType>(tuples));
    if (!a.values.empty()) {
        std::memcpy(array->GetPointer(0), a.values.data(), a.values.size() * sizeof(double));
    }
    return array;
}

} // namespace

void writeVtp(const std::filesystem::path& file, const std::vector<Vec3>& points,
              const std::vector<std::vector<int>>& cells, bool lines,
              const std::vector<DataArray>& pointData, const std::vector<DataArray>& cellData) {
    vtkNew<vtkDoubleArray> coordinates;
    coordinates->SetNumberOfComponents(3);
    coordinates->SetNumberOfTuples(static_cast<vtkIdType>(points.size()));
    for (std::size_t i = 0; i < points.size(); ++i) {
        for (int d = 0; d < 3; ++d) {
            coordinates->SetTypedComponent(static_cast<vtkIdType>(i), d, points[i][d]);
        }
    }
    vtkNew<vtkPoints> vtkPts;
    vtkPts->SetData(coordinates);

    vtkNew<vtkIdTypeArray> offsets;
    vtkNew<vtkIdTypeArray> connectivity;
    offsets->InsertNextValue(0);
    for (const std::vector<int>& cell : cells) {
        for (const int p : cell) {
            if (p < 0 || static_cast<std::size_t>(p) >= points.size()) {
                cannotWrite(file, "cell point index " + std::to_string(p) + " out of range");
            }
            connectivity->InsertNextValue(p);
        }
        offsets->InsertNextValue(connectivity->GetNumberOfValues());
    }
    vtkNew<vtkCellArray> cellArray;
    cellArray->SetData(offsets, connectivity);

    vtkNew<vtkPolyData> poly;
    poly->SetPoints(vtkPts);
    if (lines) {
        poly->SetLines(cellArray);
    } else {
        poly->SetPolys(cellArray);
    }
    for (const DataArray& a : pointData) {
        poly->GetPointData()->AddArray(makeArray(file, a, points.size()));
    }
    for (const DataArray& a : cellData) {
        poly->GetCellData()->AddArray(makeArray(file, a, cells.size()));
    }

    std::filesystem::path tmp = file;
    tmp += ".tmp";
    vtkNew<ErrorFlag> errors;
    vtkNew<vtkXMLPolyDataWriter> writer;
    writer->AddObserver(vtkCommand::ErrorEvent, errors);
    writer->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, errors);
    writer->SetDataModeToAppended();
    writer->EncodeAppendedDataOff();
    writer->SetCompressorTypeToZLib();
    writer->SetCompressionLevel(1);
    writer->SetHeaderTypeToUInt64();
    writer->SetFileName(tmp.string().c_str());
    writer->SetInputData(poly);

    const int ok = writer->Write();
    std::error_code ec;
    if (ok != 1 || errors->failed() || writer->GetErrorCode() != 0 ||
        !std::filesystem::is_regular_file(tmp, ec)) {
        removeQuietly(tmp);
        cannotWrite(file, errors->message());
    }
    std::filesystem::rename(tmp, file, ec);
    if (ec) {
        removeQuietly(tmp);
        cannotWrite(file, ec.message());
    }
}

} // namespace mpm::io
